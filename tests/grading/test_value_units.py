"""A numeric follow-up with a unit (issue 12): `5.35 m/s^2` is checked against the quantity's
unit; the same dimension in another unit is converted, a wrong unit is incorrect and the feedback
names it."""

from __future__ import annotations

import pytest

from lagrade.judge.check import check

WEDGE_A = {"scene": "wedge", "seed": 2, "quantity": "block_acceleration"}  # 5.3509 m/s^2
HOOP = {"scene": "hoop", "seed": 1, "quantity": "equilibrium_angle"}  # 1.2232 rad


def judge(problem, answer):
    return check(problem, "expression", answer, time_limit=None)


@pytest.mark.parametrize(
    "answer",
    ["5.351 m/s^2", "5.351 m s^-2", "5.351 [m/s^2]", "5351 mm/s^2", "5.351 m/s/s", "5.351"],
)
def test_a_value_in_the_quantity_unit(answer):
    assert judge(WEDGE_A, answer).status == "correct"


@pytest.mark.parametrize("unit", ["m/s", "kg", "N", "s", "J"])
def test_a_wrong_unit_is_named(unit):
    verdict = judge(WEDGE_A, f"5.351 {unit}")
    assert verdict.status == "incorrect" and verdict.mistakes == ("wrong_unit",), verdict
    assert f"given in {unit}," in verdict.feedback[0] and "m/s^2" in verdict.feedback[0]


def test_closed_form_and_value_with_a_wrong_unit():
    verdict = judge(HOOP, "acos(g/(R omega^2)) = 1.223 s")
    assert verdict.status == "incorrect" and verdict.score == 0.5, verdict
    assert any("given in s," in f for f in verdict.feedback), verdict.feedback


def test_a_closed_form_in_a_parameter_is_not_a_unit():
    """`g m` is not a unit; `2 g` is twice g, not two grams (grams are not read)."""
    assert judge(WEDGE_A, "2 g").status == "incorrect"
    assert judge(WEDGE_A, "2 g").mistakes != ("wrong_unit",)


def test_a_parameter_name_after_a_number_is_read_as_the_parameter():
    """`5.351 m` for an acceleration is 5.351 times the mass m (wrong), not a wrong unit."""
    verdict = judge(WEDGE_A, "5.351 m")
    assert verdict.status == "incorrect" and verdict.mistakes != ("wrong_unit",)
