"""A named mistake points at the equation that is wrong (issue 12): a Kepler set whose θ equation
lacks 2 m r ṙ θ̇ was told "your equation for r lacks the term m r̈", because that θ equation lies
in the span of {r equation without m r̈, θ equation}. Every scene with several coordinates is
tried with one term of one equation dropped or sign-flipped (the equations derived here with
sympy's diff, not by the judge): feedback that names an equation names that one."""

from __future__ import annotations

import re

import pytest
import sympy as sp

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.judge.check import check
from lagrade.mechanics.lagrange import t
from lagrade.notation.printer import plain


def _el(L, jets):
    rows = []
    for j in jets:
        p = sp.diff(L, j.dot)
        dt = sp.diff(p, t) + sum(sp.diff(p, k.q) * k.dot + sp.diff(p, k.dot) * k.ddot for k in jets)
        rows.append(sp.expand(dt - sp.diff(L, j.q)))
    return rows


@pytest.mark.parametrize(
    ("problem", "eom", "named"),
    [
        (
            {"scene": "kepler"},
            ["G*M*m/r^2 - m*r*theta_dot^2 + m*r_ddot = 0", "m*r^2*theta_ddot = 0"],
            "your equation for theta lacks the term 2*m*r*r_dot*theta_dot",
        ),
        (
            {"scene": "spherical_pendulum"},
            [
                "g l m sin(theta) - l^2 m phi_dot^2 sin(theta) cos(theta) + l^2 m theta_ddot = 0",
                "l^2 m phi_ddot sin(theta)^2 = 0",
            ],
            "your equation for phi lacks the term",
        ),
    ],
)
def test_the_wrong_equation_is_named(problem, eom, named):
    verdict = check(problem, "eom", eom, time_limit=None)
    assert verdict.status == "incorrect"
    assert any(named in f for f in verdict.feedback), verdict.feedback
    assert not any("equation for r lacks the term m*r_ddot" in f for f in verdict.feedback)


def _cases():
    for scene_id in scene_ids():
        variant = get_scene(scene_id).default
        if len(variant.jets) < 2:
            continue
        rows = _el(variant.lagrangian, variant.jets)
        for i, row in enumerate(rows):
            for k, _term in enumerate(sp.Add.make_args(row)):
                yield pytest.param(scene_id, i, k, id=f"{scene_id}-{i}-{k}")


@pytest.mark.parametrize(("scene_id", "i", "k"), list(_cases()))
def test_a_dropped_or_flipped_term_is_named_in_its_own_equation(scene_id, i, k):
    variant = get_scene(scene_id).default
    jets = variant.jets
    rows = _el(variant.lagrangian, jets)
    terms = sp.Add.make_args(rows[i])
    for changed in (rows[i] - terms[k], rows[i] - 2 * terms[k]):
        answer = [f"{plain(r if n != i else changed)} = 0" for n, r in enumerate(rows)]
        verdict = check({"scene": scene_id}, "eom", answer, time_limit=None)
        # (a row of one term, or m_1 + m_2 without m_1, can stay right: nothing is named then)
        for f in verdict.feedback:
            for name in re.findall(r"equation for (\w+)", f):
                assert name == jets[i].name, (answer, verdict.feedback)
