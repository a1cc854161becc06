"""A counter-example is a point where both sides are defined, when the answers differ at one;
where they differ only where one side is undefined, the feedback says which side (issue 30)."""

from __future__ import annotations

from lagrade.judge.check import check

HOOP = {"scene": "hoop", "seed": 3}
T = "1/2 m R^2 phi_dot^2 + 1/2 m R^2 omega^2 sin(phi)^2"


def test_a_point_where_both_are_defined_is_preferred():
    """sqrt(phi) is undefined for phi < 0 and wrong for phi > 0: quote a phi > 0."""
    v = check(HOOP, "T", T + " + m R^2 sqrt(phi)", time_limit=None)
    assert v.status == "incorrect" and v.witness["phi"] > 0, (v.witness, v.feedback)
    assert "undefined" not in v.feedback[0] and "where your T is" in v.feedback[0]


def test_where_only_the_answer_is_undefined_it_says_so():
    v = check(HOOP, "T", T + " + m R^2 sqrt(phi - 100)", time_limit=None)
    assert v.status == "incorrect" and "where your T is undefined" in v.feedback[0], v.feedback


def test_an_undefined_lagrangian_says_so():
    L = T + " + m g R cos(phi) + m g R sqrt(phi - 100)"
    v = check(HOOP, "lagrangian", L, time_limit=None)
    assert v.status == "incorrect" and "where your L is undefined" in v.feedback[-1], v.feedback
