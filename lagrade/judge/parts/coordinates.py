"""The `coordinates` part: the problem's generalized coordinates, by name, in any order."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict


def check_coordinates(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    """Exactly the problem's coordinates, separated by commas, semicolons or spaces."""
    text = answer if isinstance(answer, str) else " ".join(map(str, answer))
    named = [n for n in text.replace(";", ",").replace(",", " ").split() if n]
    wanted = list(problem.coordinates)
    if sorted(named) == sorted(wanted):
        return Verdict("coordinates", "correct", 1.0, (), ", ".join(named), "exact")
    feedback = f"This problem uses {len(wanted)} generalized coordinates ({', '.join(wanted)})."
    return Verdict("coordinates", "incorrect", 0.0, (feedback,), ", ".join(named), "exact")
