"""The domains an expression part judges on are made once per question structure, not per
answer, and are the ones made afresh: equal, keyed by the question's own symbols, a copy for
each caller."""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from lagrade.judge.parts import expression
from lagrade.judge.problem import build_problem

KEPT = expression._DOMAINS


def _problem(text: str, coordinates=("theta",)):
    return build_problem(
        {
            "expression": text,
            "parameters": {"m": "positive", "alpha": "(0, pi/2)"},
            "coordinates": coordinates if isinstance(coordinates, dict) else list(coordinates),
        }
    )


def test_domains_are_made_once_per_structure_and_equal_to_fresh_ones(monkeypatch):
    made = []
    make = expression._made_domains
    monkeypatch.setattr(expression, "_made_domains", lambda p: made.append(p) or make(p))
    problem = _problem("m*sin(alpha)*theta")
    first = expression._domains_for(problem)
    second = expression._domains_for(problem)
    assert made == [problem]  # the second answer's domains are the first's
    kept = problem.shared[KEPT]
    assert first == second == kept == make(problem)
    assert first is not kept and second is not kept and first is not second  # each its own copy
    mine = (*problem.domains, *(j.q for j in problem.jets))
    assert all(a is b for a, b in zip(second, mine, strict=True))


def test_a_structure_of_other_coordinate_domains_has_its_own():
    plain = _problem("m*theta")
    ranged = _problem("m*theta", {"theta": "(0, 1)"})
    assert expression._domains_for(plain) != expression._domains_for(ranged)


def test_equal_symbols_that_are_other_objects_get_their_own_domains():
    one = _problem("m*theta")
    expression._domains_for(one)
    m = next(iter(one.domains))
    other = sp.Symbol.__xnew__(sp.Symbol, m.name, **m.assumptions0)  # sympy's cache bypassed
    assert other == m and other is not m
    two = replace(one, domains={other if s is m else s: d for s, d in one.domains.items()})
    assert two.shared is one.shared  # the same structure's store
    assert next(iter(expression._domains_for(two))) is other
