"""A numeric follow-up whose prompt asks for "a closed form in the parameters (or its value)"
accepts both at once, `acos(g/(R omega^2)) = 1.223`, judging each side by its own rule (issue 12:
this was refused as "Write this answer as an expression")."""

from __future__ import annotations

import pytest

from lagrade.judge.check import check

HOOP = {"scene": "hoop", "seed": 1, "quantity": "equilibrium_angle"}  # R = 0.2, ω = 12: 1.2232


@pytest.mark.parametrize(
    "answer",
    [
        "acos(g/(R omega^2)) = 1.223",
        "acos(g/(R omega^2)) = 1.223 rad",
        "1.223 = acos(g/(R omega^2))",
        "equilibrium_angle = acos(g/(R omega^2))",
    ],
)
def test_closed_form_and_value_both_right(answer):
    verdict = check(HOOP, "expression", answer, time_limit=None)
    assert verdict.status == "correct", verdict


@pytest.mark.parametrize(
    ("answer", "wrong"),
    [
        ("acos(g/(R omega^2)) = 1.5", "Your value"),
        ("asin(g/(R omega^2)) = 1.223", "Your closed form"),
    ],
)
def test_one_wrong_side_is_named_and_half_the_score(answer, wrong):
    verdict = check(HOOP, "expression", answer, time_limit=None)
    assert verdict.status == "incorrect" and verdict.score == 0.5
    assert all(f.startswith(wrong) for f in verdict.feedback), verdict.feedback
