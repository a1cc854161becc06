"""The domains an expression part judges on are made once per what they are made of, and are
the ones made afresh: equal, keyed by the question's own symbols, a copy for each caller."""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from lagrade.judge.parts import expression
from lagrade.judge.problem import build_problem


def _problem(text: str, coordinates=("theta",)):
    return build_problem(
        {
            "expression": text,
            "parameters": {"m": "positive", "alpha": "(0, pi/2)"},
            "coordinates": coordinates if isinstance(coordinates, dict) else list(coordinates),
        }
    )


def test_domains_are_made_once_and_equal_to_fresh_ones():
    expression._DOMAINS.clear()
    one, two = _problem("m*sin(alpha)*theta"), _problem("m*cos(alpha)*theta^2")
    first = expression._domains_for(one)
    assert len(expression._DOMAINS) == 1
    (kept,) = expression._DOMAINS.values()
    second = expression._domains_for(two)  # the same domains: a hit, not made again
    assert len(expression._DOMAINS) == 1 and next(iter(expression._DOMAINS.values())) is kept
    assert first == second == expression._made_domains(two)
    assert first is not kept and second is not kept  # each caller its own copy
    assert all(
        a is b for a, b in zip(second, (*two.domains, *(j.q for j in two.jets)), strict=True)
    )


def test_other_coordinate_domains_are_other_domains():
    expression._DOMAINS.clear()
    plain = expression._domains_for(_problem("m*theta"))
    ranged = expression._domains_for(_problem("m*theta", {"theta": "(0, 1)"}))
    assert len(expression._DOMAINS) == 2
    assert plain != ranged


def test_equal_symbols_that_are_other_objects_get_their_own_domains():
    expression._DOMAINS.clear()
    one = _problem("m*theta")
    expression._domains_for(one)
    m = next(iter(one.domains))
    other = sp.Symbol.__xnew__(sp.Symbol, m.name, **m.assumptions0)  # sympy's cache bypassed
    assert other == m and other is not m
    two = replace(one, domains={other if s is m else s: d for s, d in one.domains.items()})
    assert next(iter(expression._domains_for(two))) is other
