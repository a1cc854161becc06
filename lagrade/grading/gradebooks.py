"""Gradebooks in the columns a learning-management system imports, beside lagrade's own
`gradebook.csv`: `grade --export canvas|moodle`.

Canvas reads a column by its header: Student, ID, SIS User ID, SIS Login ID and Section identify
the student, and every other column is taken for an assignment (an unknown header creates one).
So the Canvas file carries only those five and one column for this assignment, with the
"Points Possible" row Canvas exports; the roster's own extra columns stay in gradebook.csv.
Moodle's grade import maps one identifier column to a user field and each other column to a
grade item, or to nothing, at import time; so its file keeps every roster column.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import lagrade.grading.report as report

#: Roster columns (compared ignoring case, spaces and _) that hold what Canvas calls ...
_CANVAS_ID = ("canvas_id", "canvasid", "canvas user id", "id_canvas")
_CANVAS_LOGIN = ("sis_login_id", "sis login id", "login", "login_id", "email", "e-mail")
_CANVAS_SECTION = ("section", "sections")


def canvas_csv(manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]]) -> str:
    """Canvas's gradebook import: Student, ID, SIS User ID (the roster id), SIS Login ID,
    Section, then the assignment's points; the second row holds the points possible."""
    info = manifest["assignment"]
    title = _assignment_title(info)
    extras = _extras(manifest)
    rows: list[list[str]] = [
        ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", title],
        ["Points Possible", "", "", "", "", report.format_number(_total(manifest, results))],
    ]
    for r in results:
        extra = extras.get(r["student"]["id"], {})
        rows.append(
            [
                r["student"]["name"],
                _pick(extra, _CANVAS_ID),
                r["student"]["id"],
                _pick(extra, _CANVAS_LOGIN),
                _pick(extra, _CANVAS_SECTION),
                report.format_number(r["score"]),
            ]
        )
    return _csv(rows)


def moodle_csv(manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]]) -> str:
    """Moodle's grade import: "ID number" (match it to the user field *ID number* at import),
    the name and every roster column, one grade item named after the assignment, and its
    feedback (the status and reason of a student who was not graded)."""
    title = _assignment_title(manifest["assignment"])
    extras = _extras(manifest)
    columns = report.roster_columns(manifest)
    rows: list[list[str]] = [["ID number", "Full name", *columns, title, f"{title} (feedback)"]]
    for r in results:
        extra = extras.get(r["student"]["id"], {})
        feedback = "" if r["status"] == "graded" else f"{r['status']}: {r['reason']}"
        rows.append(
            [
                r["student"]["id"],
                r["student"]["name"],
                *(extra.get(c, "") for c in columns),
                report.format_number(r["score"]),
                feedback,
            ]
        )
    return _csv(rows)


EXPORTS: dict[str, Callable[[Mapping[str, Any], Sequence[Mapping[str, Any]]], str]] = {
    "canvas": canvas_csv,
    "moodle": moodle_csv,
}


def export_file_name(kind: str) -> str:
    return f"gradebook-{kind}.csv"


def _csv(rows: list[list[str]]) -> str:
    """Every text cell neutralised as in gradebook.csv (formulas, line breaks)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    for row in rows:
        writer.writerow([report.csv_cell(cell) for cell in row])
    return buffer.getvalue()


def _assignment_title(info: Mapping[str, Any]) -> str:
    return str(info.get("title") or "lagrade assignment")


def _total(manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]]) -> float:
    if results:
        return float(results[0]["max_score"])
    return float(manifest["assignment"].get("total_points") or 0)


def _extras(manifest: Mapping[str, Any]) -> dict[str, Mapping[str, str]]:
    return {s["id"]: s.get("extra") or {} for s in manifest["students"]}


def _pick(extra: Mapping[str, str], names: Sequence[str]) -> str:
    """The first roster column whose header is one of `names` (ignoring case, spaces, _)."""

    def norm(text: str) -> str:
        return text.casefold().replace("_", " ").strip()

    wanted = [norm(n) for n in names]
    for name in wanted:
        for header, value in extra.items():
            if norm(header) == name and value:
                return str(value)
    return ""
