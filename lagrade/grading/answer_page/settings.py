"""The `[answer_page]` table of an assignment file: whether a save shows the student their
feedback at once, and how many such graded saves each student has.

    [answer_page]
    feedback = true     # grade on save and show the feedback (default: false, save only)
    attempts = 3        # graded saves per student (default: no limit); saves beyond it are
                        # still written, they are just not graded on the page
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from lagrade.assign.assignment import assignment_table
from lagrade.errors import RequestError

_KNOWN = ("feedback", "attempts")


@dataclass(frozen=True)
class PageSettings:
    feedback: bool = False
    attempts: int | None = None  # None: no limit


def settings_from_table(table: Any) -> PageSettings:
    """PageSettings from the `[answer_page]` table (defaults when absent); a RequestError lists
    every bad field."""
    if table is None:
        return PageSettings()
    if not isinstance(table, Mapping):
        raise RequestError("[answer_page] must be a table")
    problems = [
        f"{key}: unknown field (known: {', '.join(_KNOWN)})" for key in table if key not in _KNOWN
    ]
    feedback = table.get("feedback", False)
    if not isinstance(feedback, bool):
        problems.append(f"feedback: {feedback!r} is not true or false")
    attempts = table.get("attempts")
    if attempts is not None and (
        not isinstance(attempts, int) or isinstance(attempts, bool) or not 1 <= attempts <= 1000
    ):
        problems.append(f"attempts: {attempts!r} is not a whole number from 1 to 1000")
    if problems:
        raise RequestError("[answer_page] is not valid:\n  - " + "\n  - ".join(problems))
    return PageSettings(bool(feedback), attempts)


def load_settings(assignment_file: Path) -> PageSettings:
    """The answer-page settings of an assignment file."""
    return settings_from_table(assignment_table(assignment_file).get("answer_page"))
