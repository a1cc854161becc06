"""A count of degrees of freedom written with its working, as the lecture counts them on paper
(the count 3N − k of Goldstein, Classical Mechanics, §1.3, worked as "3N − k = 6 − 4 = 2"):
found on the round trip of issue 38, where `6 - 4 = 2` scored 0 as "not a whole number". The
count at the end is read when every side before it is a label or whole-number arithmetic that
gives it; arithmetic that gives another number is named, never guessed."""

from __future__ import annotations

import pytest

from lagrade.judge.check import check

KEPLER = {"scene": "kepler"}  # a planet in its orbital plane: 2 degrees of freedom


@pytest.mark.parametrize(
    "answer", ["6 - 4 = 2", "3N − k = 6 − 4 = 2", "DOF = 2", "3 \\cdot 2 - 4 = 2", " 2 "]
)
def test_a_worked_count_is_read_at_its_end(answer):
    verdict = check(KEPLER, "dof", answer, time_limit=10)
    assert verdict.status == "correct", verdict.feedback
    assert verdict.interpreted == "2"


def test_a_wrong_count_with_its_working_is_judged_as_a_count():
    verdict = check(KEPLER, "dof", "3N - k = 6 - 3 = 3", time_limit=10)
    assert verdict.status == "incorrect"
    assert verdict.feedback[0] == "3 is not the number of degrees of freedom."


def test_arithmetic_that_gives_another_number_is_named():
    verdict = check(KEPLER, "dof", "6 - 4 = 3", time_limit=10)
    assert verdict.status == "invalid"
    assert verdict.feedback == (
        "6 - 4 is 2, not 3; write the number of degrees of freedom alone, e.g. 2.",
    )


@pytest.mark.parametrize("answer", ["x = 2", "2 = two", "DOF = m", "1/2 = 2", "two"])
def test_anything_else_is_asked_for_a_whole_number(answer):
    verdict = check(KEPLER, "dof", answer, time_limit=10)
    assert verdict.status == "invalid"
    feedback = " ".join(verdict.feedback)
    assert "whole number" in feedback or "is 1/2, not 2" in feedback, feedback
