"""The mistake catalogue as fingerprints names what the symbolic catalogue names: for every bank
scene (its declared form and a seeded variant) and ad-hoc Lagrangians, the Lagrangian, equation
and momentum mistakes the arrays list are the symbolic generators' (`mutations`), in order, with
the same sentences, and the arrays keep exactly the mutants the symbolic keepers (`keepers.keeper`,
`keepers.row_keeper`, one mutant at a time) keep."""

from __future__ import annotations

from itertools import chain

import numpy as np
import pytest

from lagrade.bank.registry import scene_ids
from lagrade.judge.compiled import Compiled
from lagrade.judge.mutations import iter_equation_mutants, iter_momentum_mutants
from lagrade.judge.problem import build_problem

SPECS = [{"scene": s} for s in scene_ids()] + [{"scene": s, "seed": 3} for s in scene_ids()]
ADHOC = [
    {  # a pendulum on a cart, as an instructor types it
        "lagrangian": "(M+m)/2 x_dot^2 + m l x_dot theta_dot cos(theta) + m l^2/2 theta_dot^2"
        " + m g l cos(theta)",
        "coordinates": ["x", "theta"],
        "parameters": {"M": "positive", "m": "positive", "l": "positive", "g": "positive"},
    },
    {  # a central force in polar coordinates, with a constant that changes no motion
        "lagrangian": "m/2 (r_dot^2 + r^2 phi_dot^2) + k/r + 7 m g",
        "coordinates": ["r", "phi"],
        "parameters": {"m": "positive", "k": "positive", "g": "positive"},
    },
]


def _problem(spec):
    problem = build_problem(spec)
    if problem.lagrangian is None:
        pytest.skip("a closed-form quantity has no Lagrangian mistakes")
    return problem


@pytest.mark.parametrize("spec", SPECS + ADHOC, ids=lambda s: str(s.get("scene", "adhoc")))
def test_lagrangian_fingerprints_keep_what_the_symbolic_keeper_keeps(spec):
    problem = _problem(spec)
    cat = problem.catalogue
    table = cat.lagrangian_fingerprints
    every = list(chain(cat._lagrangian_early, cat._lagrangian_late()))
    assert [s.kind for s in table.specs] == [m.kind for m in every]
    with np.errstate(all="ignore"):
        symbolic = cat.lagrangian.all()  # kept one at a time by keepers.keeper
    assert [table.mutant(int(k)) for k in table.kept] == symbolic


@pytest.mark.parametrize("spec", SPECS + ADHOC, ids=lambda s: str(s.get("scene", "adhoc")))
def test_row_fingerprints_list_and_keep_the_symbolic_equation_mutants(spec):
    problem = _problem(spec)
    cat = problem.catalogue
    with np.errstate(all="ignore"):
        table = cat.row_fingerprints
        mine = [table.mutant(m) for m in range(len(table.specs))]
        early = [m for m in cat.lagrangian.all() if m in cat._lagrangian_early]
        theirs = list(iter_equation_mutants(problem.system, problem.jets, early, cat.parameters))
        # a numerically unchanged row is listed here and dropped by both keepers
        listed = [(i, m.kind, m.message, m.expr) for i, m in mine]
        assert [(i, m.kind, m.message, m.expr) for i, m in theirs] == [
            x for x in listed if x in {(i, m.kind, m.message, m.expr) for i, m in theirs}
        ]
        symbolic = cat.rows.all()  # kept one at a time by keepers.row_keeper
    assert [table.mutant(int(m)) for m in table.kept] == symbolic


@pytest.mark.parametrize("spec", SPECS + ADHOC, ids=lambda s: str(s.get("scene", "adhoc")))
def test_momentum_fingerprints_list_keep_and_match_what_the_symbolic_catalogue_does(spec):
    problem = _problem(spec)
    cat = problem.catalogue
    points = problem.points("momenta")
    with np.errstate(all="ignore"):
        early = [m for m in cat.lagrangian.all() if m in cat._lagrangian_early]
        for k in range(len(problem.jets)):
            table = cat.momentum_fingerprints(k)
            mine = [table.mutant(m) for m in range(len(table.specs))]
            theirs = iter_momentum_mutants(problem.system, problem.jets, k, early, cat.parameters)
            assert [(m.kind, m.message, m.expr) for m in mine] == [
                (m.kind, m.message, m.expr) for m in theirs
            ]
            symbolic = cat.momentum(k).all()  # kept one at a time by keepers.keeper
            assert [table.mutant(int(m)) for m in table.kept] == symbolic
            for m in symbolic:  # each named as the one-stack-at-a-time matching names it
                for e in (m.expr, 2 * m.expr):
                    answer = Compiled.of(e)
                    slow = cat.match_plain(symbolic, answer, points)
                    assert cat.match_momentum(k, answer, points) is slow, e
