"""The `coordinates` part: the problem's generalized coordinates, by name, in any order and in any
spelling the grammar reads (θ, \\theta and theta are one name)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.judge.parts.items import list_items
from lagrade.judge.parts.reading import read_names
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict
from lagrade.notation import NameRead


def read_coordinates(problem: Problem, answer: Any) -> list[NameRead]:
    """The names a `coordinates` answer gives, listed like any list or separated by spaces."""
    example = ", ".join(problem.coordinates)
    expected = f"Name the generalized coordinates, separated by commas, as in {example}."
    return read_names(problem, list_items(answer, "coordinates"), expected)


def check_coordinates(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    """Exactly the problem's coordinates, listed like any list (commas, semicolons, lines,
    "and") or separated by spaces. A name the problem does not use is a wrong coordinate, not
    an unreadable answer: another set of coordinates is a wrong answer to this question."""
    wanted = list(problem.coordinates)
    example = ", ".join(wanted)
    read = read_coordinates(problem, answer)
    named = [name.name for name in read]
    right = [name.coordinate for name in read if name.coordinate is not None and name.order == 0]
    if len(right) == len(named) and sorted(right) == sorted(wanted):
        return Verdict("coordinates", "correct", 1.0, (), ", ".join(named), "exact")
    feedback = [f"This problem uses {len(wanted)} generalized coordinates ({example})."]
    velocities = [name.name for name in read if name.coordinate is not None and name.order > 0]
    if velocities:
        shown = ", ".join(velocities)
        feedback.append(f"A coordinate's velocity or acceleration is not a coordinate ({shown}).")
    missing = [name for name in wanted if name not in right]
    if missing and len(right) == len(named):
        # said only where adding them makes the list right: every name given is a coordinate
        feedback.append(f"Your list lacks {', '.join(missing)}.")
    return Verdict("coordinates", "incorrect", 0.0, tuple(feedback), ", ".join(named), "exact")
