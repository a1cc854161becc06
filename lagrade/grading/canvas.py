"""The gradebook as Canvas imports it (Grades → Import), and how Canvas will read it.

Canvas's importer (`GradebookImporter` in Canvas's source) takes the first row as the header:
`Student`, `ID`, then `SIS User ID` and `SIS Login ID` when present, then `Section`; every
later column is an assignment, matched by the id in a trailing ` (12345)` and else by its exact
title (an unknown title creates a new assignment). A row whose first cell holds
"Points Possible" gives the points of a new assignment. A student is found by `ID` (Canvas's
own user id), else `SIS User ID`, else `SIS Login ID`, else by name. A blank cell is "no grade":
nothing changes for a student without one, and it removes a grade typed in Canvas since (the
import's review page marks each such removal before anything is saved).
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Mapping, Sequence
from typing import Any

import lagrade.grading.report as report
from lagrade.grading.lms import (
    ExportOptions,
    LmsFile,
    grade_cell,
    names,
    repeated,
    roster_extras,
    roster_value,
    title,
    total_points,
    writable_identifier,
)

#: Roster headers (ignoring case, spaces, `_`, `-`) read for each identity column.
CANVAS_USER_ID = ("canvas_user_id", "canvas_id")
SIS_USER_ID = ("sis_user_id", "sis_id")
SIS_LOGIN_ID = ("sis_login_id", "login_id", "login")
EMAIL = ("email", "e-mail", "email address")
SECTION = ("section", "sections", "section name")
IDENTITY_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
#: Header words Canvas drops from the assignment columns wherever they appear in a header.
NOT_ASSIGNMENT = (
    "Current Score",
    "Current Points",
    "Current Grade",
    "Final Score",
    "Final Points",
    "Final Grade",
    "Override Score",
    "Override Grade",
    "Override Status",
)
_TRAILING_ID = re.compile(r"\s\(\d+\)\Z")


def canvas_gradebook(
    manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]], options: ExportOptions
) -> LmsFile:
    """gradebook-canvas.csv and its README: the five identity columns, one column for this
    assignment (named `Title (ID)` when the Canvas assignment id is known), the Points Possible
    row, and a blank grade for a student without a graded submission (0 with
    `missing_as_zero`)."""
    name = title(manifest)
    column = f"{name} ({options.canvas_assignment_id})" if options.canvas_assignment_id else name
    identities, warnings = _identities(manifest)
    rows: list[list[str]] = [
        [*IDENTITY_COLUMNS, report.csv_cell(column)],
        ["Points Possible", "", "", "", "", report.format_number(total_points(manifest, results))],
    ]
    blank = []
    for r in results:
        sid = r["student"]["id"]
        user_id, sis, login, section = identities[sid]
        grade = grade_cell(r, options)
        if grade is None:
            blank.append(r["student"])
        rows.append(
            [
                report.csv_cell(r["student"]["name"]),
                user_id,
                sis,
                login,
                report.csv_cell(section),
                "" if grade is None else grade,
            ]
        )
    unmatched = [r["student"] for r in results if not any(identities[r["student"]["id"]][:3])]
    if unmatched:
        warnings.append(
            f"{len(unmatched)} student(s) have no Canvas user id, SIS User ID or SIS Login ID in "
            f"the roster, so Canvas matches them by name only: {names(unmatched)}"
        )
    warnings += _title_warnings(name, options)
    return LmsFile(
        "canvas", _write(rows), _readme(column, options, blank, warnings), tuple(warnings)
    )


def _identities(
    manifest: Mapping[str, Any],
) -> tuple[dict[str, tuple[str, str, str, str]], list[str]]:
    """Each student's ID, SIS User ID, SIS Login ID and Section from the roster; a value that
    is malformed, unsafe to write or shared with another student is left blank and named."""
    warnings: list[str] = []
    extras = roster_extras(manifest)
    columns = {
        "ID": {sid: roster_value(e, CANVAS_USER_ID) for sid, e in extras.items()},
        "SIS User ID": {sid: roster_value(e, SIS_USER_ID) for sid, e in extras.items()},
        "SIS Login ID": {
            sid: roster_value(e, SIS_LOGIN_ID) or roster_value(e, EMAIL)
            for sid, e in extras.items()
        },
    }
    for header, values in columns.items():
        for sid in sorted(repeated(values)):
            warnings.append(
                f"{sid}: {header} {values[sid]!r} is shared with another student; left blank"
            )
            values[sid] = ""
        for sid, value in values.items():
            if value and not writable_identifier(value):
                warnings.append(
                    f"{sid}: {header} {value!r} would be read as a spreadsheet formula; left blank"
                )
                values[sid] = ""
    for sid, value in columns["ID"].items():
        if value and not (value.isascii() and value.isdigit()):
            # Canvas reads the ID as a number (`"12abc".to_i` is 12): a wrong user, silently.
            warnings.append(f"{sid}: Canvas user id {value!r} is not a number; left blank")
            columns["ID"][sid] = ""
    identities = {
        sid: (
            columns["ID"][sid],
            columns["SIS User ID"][sid],
            columns["SIS Login ID"][sid],
            roster_value(extras[sid], SECTION),
        )
        for sid in extras
    }
    return identities, warnings


def _title_warnings(name: str, options: ExportOptions) -> list[str]:
    found = []
    if not options.canvas_assignment_id:
        found.append(
            f"no Canvas assignment id: Canvas fills the assignment titled exactly {name!r}, or "
            "creates a new one (give --canvas-assignment-id, or canvas_assignment_id in the "
            "assignment file's [lms] table)"
        )
        if _TRAILING_ID.search(name):
            found.append(
                f"the title {name!r} ends in a number in parentheses, which Canvas reads as an "
                "assignment id; give the real one"
            )
    dropped = [w for w in NOT_ASSIGNMENT if w in name]
    if dropped:
        found.append(
            f"Canvas ignores a column whose header contains {dropped[0]!r}: rename the "
            "assignment, or rename the column before importing"
        )
    return found


def _write(rows: list[list[str]]) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


def _readme(
    column: str,
    options: ExportOptions,
    blank: Sequence[Mapping[str, Any]],
    warnings: Sequence[str],
) -> str:
    lines = [
        "gradebook-canvas.csv: how to import it into Canvas",
        "",
        "In the course: Grades > Import > choose gradebook-canvas.csv > Upload Data.",
        "Canvas then shows each change (From / To) before you confirm.",
        "",
        f"Assignment column: {column!r}. "
        + (
            f"Canvas fills the assignment with id {options.canvas_assignment_id}, whatever "
            "its title."
            if options.canvas_assignment_id
            else "Canvas fills the assignment with exactly this title, or creates a new one "
            "worth the points in the 'Points Possible' row."
        ),
        "",
        "Students are matched by ID (Canvas's user id), else SIS User ID, else SIS Login ID,",
        "else by name; lagrade fills them from the roster columns canvas_user_id/canvas_id,",
        "sis_user_id/sis_id, and sis_login_id/login_id/login (or email when the roster has no",
        "login column). Section is shown, not matched.",
        "",
    ]
    if blank:
        lines += [
            f"{len(blank)} student(s) have no graded submission; their cell is blank (no grade):",
            f"  {names(blank, 50)}",
            "A blank leaves a student who has no grade in Canvas as they are; where Canvas has a",
            "grade for them (typed in by hand), the review page shows it being removed: keep it",
            "by deleting that student's row before importing.",
            "",
        ]
    if options.missing_as_zero:
        lines += [
            "--missing-as-zero: students who handed in nothing readable (missing, invalid) get 0;",
            "a student the grader itself could not finish stays blank (see gradebook.csv).",
            "",
        ]
    if warnings:
        lines += ["Before importing:", *(f"  - {w}" for w in warnings), ""]
    return "\n".join(lines)
