"""The `cyclic` part's default score gives nothing for a blind guess (issue 30): `none` or every
coordinate earns 0 (a per-coordinate score gave `none` half of a two-coordinate part); finding
some of the cyclic coordinates and naming no other earns that share. Partial credit stays the
rubric's choice (`partial_credit = false`: all or nothing)."""

from __future__ import annotations

import pytest

from lagrade.bank import get_scene, scene_ids
from lagrade.grading.rubric import Rubric
from lagrade.judge.check import check


def _score(scene: str, claimed: list[str]) -> float:
    answer = ", ".join(claimed) if claimed else "none"
    return check({"scene": scene}, "cyclic", answer, time_limit=None).score


@pytest.mark.parametrize("scene", scene_ids())
def test_none_and_everything_earn_nothing_unless_right(scene):
    variant = get_scene(scene).default
    coordinates = list(variant.coordinates)
    truth = set(variant.cyclic_coordinates)
    if truth:
        assert _score(scene, []) == 0, "none"
    if truth != set(coordinates):
        assert _score(scene, coordinates) == 0, "every coordinate"


def test_finding_some_and_naming_no_other_earns_that_share():
    variant = get_scene("two_body_spring").default
    truth = sorted(variant.cyclic_coordinates)
    assert len(truth) >= 2
    assert _score("two_body_spring", truth[:1]) == pytest.approx(1 / len(truth))


def test_the_rubric_still_chooses_partial_credit():
    verdict = check({"scene": "two_body_spring"}, "cyclic", "X", time_limit=None)
    assert verdict.status == "incorrect" and verdict.score > 0
    args = (verdict.status, verdict.score, verdict.mistakes, False)
    assert Rubric().fraction(*args) == verdict.score  # the default counts it
    assert Rubric(partial_credit=False).fraction(*args) == 0
