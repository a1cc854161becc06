"""The `[answer_page]` table of an assignment file: whether a save shows the student their
feedback at once, how many such graded saves each student has, and what happens to a save
after the assignment's `due` date.

    [answer_page]
    feedback = true     # grade on save and show the feedback (default: false, save only)
    attempts = 3        # graded saves per student (default: no limit); saves beyond it are
                        # still written, they are just not graded on the page
    late = false        # after `due`: false refuses saves (default); true accepts them,
                        # recorded as late; a date and time accepts them as late until then
    timezone = "Europe/Berlin"   # the zone of `due`, `late` and `grade --as-of` times written
                        # without an offset (default: the computer's own)
"""

from __future__ import annotations

import datetime as dt
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from lagrade.assign import assignment_table
from lagrade.errors import RequestError
from lagrade.grading.instants import read_instant, zone

_KNOWN = ("feedback", "attempts", "late", "timezone")


@dataclass(frozen=True)
class PageSettings:
    feedback: bool = False
    attempts: int | None = None  # None: no limit
    late: bool = False  # saves after the due date accepted (recorded as late)
    late_until: dt.datetime | None = None  # … until this instant (None: for ever)
    timezone: str | None = None  # None: the computer's own

    @property
    def zone(self) -> dt.tzinfo | None:
        return zone(self.timezone)


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
    timezone = table.get("timezone")
    where = None
    if timezone is not None:
        try:
            if not isinstance(timezone, str):
                raise RequestError(f"{timezone!r} is not the name of a time zone")
            where = zone(timezone)
        except RequestError as error:
            problems.append(f"timezone: {error}")
            timezone = None
    late, late_until = _late(table.get("late", False), where, problems)
    if problems:
        raise RequestError("[answer_page] is not valid:\n  - " + "\n  - ".join(problems))
    return PageSettings(bool(feedback), attempts, late, late_until, timezone)


def _late(value: Any, where: dt.tzinfo | None, problems: list[str]):
    """`late` as (accepted, until): true, false, or the instant late saves end."""
    if isinstance(value, bool):
        return value, None
    if isinstance(value, dt.datetime | dt.date | str):
        text = value.isoformat() if isinstance(value, dt.date) else value
        try:
            return True, read_instant(text, where)
        except RequestError as error:
            problems.append(f"late: {error}")
            return False, None
    problems.append(f"late: {value!r} is not true, false or a date and time")
    return False, None


def load_settings(assignment_file: Path) -> PageSettings:
    """The answer-page settings of an assignment file."""
    return settings_from_table(assignment_table(assignment_file).get("answer_page"))
