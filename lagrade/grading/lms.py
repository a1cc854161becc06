"""What the Canvas and Moodle gradebooks share: which roster columns identify a student to each
system, which students have a grade to send, and the cells an importer can match on.

An importer matches a row to a user by comparing one cell with what it stores, byte for byte, so
an identifier is written as the roster has it or not at all: a value that gradebook.csv would
neutralise (a leading `=`, `+`, `-`, `@`) cannot be both safe in a spreadsheet and matched, and
is left out with a warning instead.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import lagrade.grading.report as report

#: Statuses whose score is a grade for the LMS: parts were judged.
_GRADED = frozenset({"graded", "timeout"})
#: Statuses where the student handed in nothing gradable; `--missing-as-zero` makes them 0.
#: `error` (our bug) and a timeout before any part was judged are never sent as 0.
STUDENT_FAULT = frozenset({"missing", "invalid"})


@dataclass(frozen=True)
class ExportOptions:
    """How the LMS gradebooks are written: the Canvas assignment to fill (its numeric id, from
    the assignment's `[lms]` table or `--canvas-assignment-id`), and whether students without a
    graded submission get 0 instead of no grade."""

    canvas_assignment_id: str | None = None
    missing_as_zero: bool = False


@dataclass(frozen=True)
class LmsFile:
    """One gradebook for one system: the CSV, the import instructions written beside it, and
    the warnings the instructor should read before importing (also printed by `grade`)."""

    kind: str
    csv: str
    readme: str
    warnings: tuple[str, ...] = ()


def has_grade(result: Mapping[str, Any]) -> bool:
    """Whether a result carries a grade: graded, or timed out after some parts were judged."""
    return result["status"] in _GRADED and bool(result.get("problems"))


def grade_cell(result: Mapping[str, Any], options: ExportOptions) -> str | None:
    """The points to send, or None when the student has no grade to send."""
    if has_grade(result):
        return report.format_number(result["score"])
    if options.missing_as_zero and result["status"] in STUDENT_FAULT:
        return "0"
    return None


def _norm(header: str) -> str:
    return re.sub(r"[\s_\-]+", " ", str(header).casefold()).strip()


def roster_value(extra: Mapping[str, Any], headers: Sequence[str]) -> str:
    """The first non-blank roster cell under one of `headers` (ignoring case, spaces, `_` and
    `-`), stripped; "" when the roster has none."""
    wanted = [_norm(h) for h in headers]
    for name in wanted:
        for header, value in extra.items():
            if _norm(header) == name and str(value).strip():
                return str(value).strip()
    return ""


def writable_identifier(value: str) -> bool:
    """Whether an identifier can go into the file verbatim (see the module docstring)."""
    return report.csv_cell(value) == value


def roster_extras(manifest: Mapping[str, Any]) -> dict[str, Mapping[str, Any]]:
    return {s["id"]: s.get("extra") or {} for s in manifest["students"]}


def repeated(values: Mapping[str, str]) -> set[str]:
    """Student ids whose (non-blank) value, compared ignoring case, another student shares."""
    counts = Counter(v.casefold() for v in values.values() if v)
    return {sid for sid, v in values.items() if v and counts[v.casefold()] > 1}


def title(manifest: Mapping[str, Any]) -> str:
    return str(manifest["assignment"].get("title") or "lagrade assignment")


def total_points(manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]]) -> float:
    if results:
        return float(results[0]["max_score"])
    return float(manifest["assignment"].get("total_points") or 0)


def names(students: Sequence[Mapping[str, Any]], limit: int = 10) -> str:
    """`s001 (Ada Lovelace), s002 (…)`, at most `limit` of them, then how many more."""
    shown = [f"{s['id']} ({s['name']})" for s in students[:limit]]
    more = f" and {len(students) - limit} more" if len(students) > limit else ""
    return ", ".join(shown) + more
