"""The due date on the answer page: before the assignment's `due`, a save is on time; after
it, it is refused with a sentence, or recorded as late when the assignment takes late work
(`[answer_page] late`). The page says which, before the student types and on every save.

A `due` that names no instant (a TOML time alone, or prose such as "Friday in class") cannot be
kept: the page then takes saves at any time, and `lagrade serve` says so when it starts."""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass
from pathlib import Path

from lagrade.errors import RequestError
from lagrade.grading.answer_page.settings import PageSettings, load_settings
from lagrade.grading.instants import read_instant, shown

OPEN, LATE, CLOSED = "open", "late", "closed"


@dataclass(frozen=True)
class DueRule:
    """When saves are on time, late, or refused."""

    due: dt.datetime | None = None
    late: bool = False
    late_until: dt.datetime | None = None
    #: Why the assignment's `due` cannot be kept (it names no instant); "" when it can.
    unread: str = ""

    def state(self, now: dt.datetime) -> str:
        """OPEN (no due date, or not yet past), LATE (past, late work taken) or CLOSED."""
        if self.due is None or now <= self.due:
            return OPEN
        if self.late and (self.late_until is None or now <= self.late_until):
            return LATE
        return CLOSED

    def notice(self, now: dt.datetime) -> str:
        """The page's sentence about the due date, "" when there is none to keep."""
        if self.due is None:
            return ""
        state = self.state(now)
        due = shown(self.due)
        if state == OPEN:
            if not self.late:
                after = "after it, saving is closed."
            elif self.late_until is None:
                after = "after it, saves are still accepted and recorded as late."
            else:
                after = f"after it, saves are recorded as late until {shown(self.late_until)}."
            return f"Due {due}; {after}"
        if state == LATE:
            until = f" until {shown(self.late_until)}" if self.late_until else ""
            return (
                f"The due date ({due}) has passed. Saves are still accepted{until}, and each "
                "is recorded as late."
            )
        return self.refusal()

    def refusal(self) -> str:
        """Why a save after the due date was not written."""
        due = shown(self.due) if self.due else ""
        if self.late and self.late_until is not None:
            return (
                f"The due date ({due}) and the time for late work ({shown(self.late_until)}) "
                "have passed: saving is closed. Your last save stands."
            )
        return (
            f"The due date ({due}) has passed, and this assignment takes no late work: saving "
            "is closed. Your last save stands."
        )

    def late_note(self) -> str:
        """What a late save's reply says."""
        return f"Recorded as late: the due date ({shown(self.due)}) had passed."


def due_rule(due: str, settings: PageSettings) -> DueRule:
    """The rule of an assignment's `due` (as the assignment file reader keeps it, ISO text or
    prose) and its `[answer_page]` settings."""
    if not str(due).strip():
        return DueRule()
    if ":" in due and "-" not in due:  # a TOML time of day alone: no day to keep
        return DueRule(unread=f"due = {due!r} is a time of day without a date")
    try:
        instant = read_instant(due, settings.zone)
    except RequestError as error:
        return DueRule(unread=f"due: {error}")
    return DueRule(instant, settings.late, settings.late_until)


def as_of_instant(text: str, manifest_path: Path) -> dt.datetime:
    """The instant of `lagrade grade --as-of TEXT`: a date and time read in the assignment's
    zone (`[answer_page] timezone`), or `due` for the assignment's due date."""
    from lagrade.grading.manifest import load_manifest

    manifest = load_manifest(Path(manifest_path))
    copy = Path(manifest_path).parent / manifest["assignment"].get("file", "assignment.toml")
    settings = load_settings(copy) if copy.is_file() else PageSettings()
    if text.strip().lower() != "due":
        return read_instant(text, settings.zone)
    rule = due_rule(str(manifest["assignment"].get("due", "")), settings)
    if rule.due is None:
        raise RequestError(
            "--as-of due: the assignment has no due date to grade at"
            + (f" ({rule.unread})" if rule.unread else "")
        )
    return rule.due
