"""How verdicts become points: the `[rubric]` table of the assignment file.

    [rubric]
    partial_credit = true     # per-equation / per-momentum / cyclic shares count (false: none)
    follow_through = 0.5      # share of a part's points when it follows correctly from the
                              # student's own wrong earlier answer (EOM from their own L)
    convention = 0.5          # share for the right dynamics in the wrong convention (L = V − T)
    numeric_tolerance = 0.01  # relative tolerance of numeric follow-ups (3 significant figures)
    own_coordinates = 0.0     # share deducted from a right `transformation` in other coordinates
                              # than the statement's (the later parts are judged in them)

Every field is optional; the defaults are those above.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from lagrade.assign import assignment_table
from lagrade.errors import RequestError
from lagrade.judge import NUMERIC_TOLERANCE, OWN_COORDINATES

_FIELDS = {"partial_credit", "follow_through", "convention", "numeric_tolerance", "own_coordinates"}


@dataclass(frozen=True)
class Rubric:
    partial_credit: bool = True
    follow_through: float = 0.5
    convention: float = 0.5
    numeric_tolerance: float = NUMERIC_TOLERANCE
    own_coordinates: float = 0.0

    def fraction(
        self, status: str, score: float, mistakes: tuple[str, ...], follows: bool
    ) -> float:
        """The share of a part's points a verdict earns."""
        if status == "correct":
            return 1.0 - self.own_coordinates if OWN_COORDINATES in mistakes else 1.0
        if "V_minus_T" in mistakes:
            return self.convention
        if follows:
            return self.follow_through
        if status != "incorrect":
            return 0.0
        return score if self.partial_credit else 0.0

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def rubric_from_table(table: Any) -> Rubric:
    """A Rubric from the `[rubric]` table; a RequestError lists every bad field."""
    if table is None:
        return Rubric()
    if not isinstance(table, dict):
        raise RequestError("[rubric] must be a table")
    problems = [
        f"rubric.{k}: unknown field (known: {', '.join(sorted(_FIELDS))})"
        for k in sorted(set(table) - _FIELDS)
    ]
    values: dict[str, Any] = {}
    if "partial_credit" in table:
        if not isinstance(table["partial_credit"], bool):
            problems.append(
                f"rubric.partial_credit: must be true or false, got {table['partial_credit']!r}"
            )
        values["partial_credit"] = table["partial_credit"]
    for name in ("follow_through", "convention", "own_coordinates"):
        if name in table:
            v = table[name]
            if isinstance(v, bool) or not isinstance(v, int | float) or not 0 <= v <= 1:
                problems.append(f"rubric.{name}: must be a share between 0 and 1, got {v!r}")
            values[name] = float(v) if isinstance(v, int | float) else v
    if "numeric_tolerance" in table:
        v = table["numeric_tolerance"]
        if (
            isinstance(v, bool)
            or not isinstance(v, int | float)
            or not (0 < v < 1)
            or math.isnan(v)
        ):
            problems.append(f"rubric.numeric_tolerance: must be between 0 and 1, got {v!r}")
        values["numeric_tolerance"] = v
    if problems:
        raise RequestError("the assignment's rubric is not valid:\n  - " + "\n  - ".join(problems))
    return Rubric(**values)


def load_rubric(assignment_file: Path) -> Rubric:
    """The rubric of an assignment file (defaults when it has no [rubric] table)."""
    return rubric_from_table(assignment_table(assignment_file).get("rubric"))
