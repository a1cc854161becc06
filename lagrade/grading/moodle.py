"""The gradebook as Moodle's CSV grade import reads it (Grades → Import → CSV file), with the
settings to choose there written beside it.

How Moodle reads it (`grade/import/csv/classes/load_data.php` and `grade/import/lib.php` in
Moodle's source): the instructor maps one column ("Map from") to a user field ("Map to": email
address, ID number, username or user id) and each other column to a grade item, a feedback or
"Ignore". A row whose identifier matches no Moodle user stops the whole import; a row whose
identifier is blank keeps the previous row's student (its grades go to that student); a blank
or `-` grade clears the grade Moodle holds; a grade item created by the import gets Moodle's
default maximum, 100. So the file has a row only for a student with both a grade to send and an
identifier, the identifier first (Moodle's default "Map from"), and the grade out of the
assignment's own maximum, which the README asks the instructor to give the grade item.
"""

from __future__ import annotations

import csv
import io
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

#: Roster headers (ignoring case, spaces, `_`, `-`) read for Moodle's user fields.
EMAIL = ("email", "e-mail", "email address", "mail")
ID_NUMBER = ("idnumber", "id number")
#: Moodle's own labels for the user fields, as its mapping form shows them.
FIELDS = {"Email address": "Email address", "ID number": "ID number", "lagrade id": "Username"}
#: Moodle refuses a grade above this unless the site allows more (`unlimitedgrades`).
GRADE_POINT_MAX = 100


def moodle_gradebook(
    manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]], options: ExportOptions
) -> LmsFile:
    """gradebook-moodle.csv and gradebook-moodle.README.txt (see the module docstring)."""
    name = title(manifest)
    values, warnings = _identifiers(manifest)
    to_send = [(r, g) for r in results if (g := grade_cell(r, options)) is not None]
    key = _identifier(values, [r for r, _ in to_send])
    headers = [key] + [
        h for h in values if h != key and (h == "lagrade id" or any(values[h].values()))
    ]
    rows: list[list[str]] = [[*headers, "Full name", name, f"{name} (feedback)"]]
    no_identifier = []
    for r, grade in to_send:
        sid = r["student"]["id"]
        if not values[key][sid]:
            no_identifier.append(r["student"])
            continue
        rows.append(
            [
                *(values[h][sid] for h in headers),
                report.csv_cell(r["student"]["name"]),
                grade,
                report.csv_cell(_feedback(r)),
            ]
        )
    no_grade = [r["student"] for r in results if grade_cell(r, options) is None]
    if no_identifier:
        warnings.append(
            f"{len(no_identifier)} student(s) with a grade have no {key} in the roster and are "
            f"not in the file (enter their grades by hand): {names(no_identifier)}"
        )
    total = total_points(manifest, results)
    if total > GRADE_POINT_MAX:
        warnings.append(
            f"the assignment is worth {report.format_number(total)} points; Moodle refuses "
            f"grades above {GRADE_POINT_MAX} unless Site administration > Grades > General "
            "settings allows unlimited grades (unlimitedgrades) up to gradepointmax"
        )
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    readme = _readme(name, key, total, len(rows) - 1, no_grade, options, warnings)
    return LmsFile("moodle", buffer.getvalue(), readme, tuple(warnings))


def _identifiers(manifest: Mapping[str, Any]) -> tuple[dict[str, dict[str, str]], list[str]]:
    """Each student's email, ID number and lagrade id; a value shared by two students or unsafe
    to write is blanked (a blank identifier keeps that student out of the file) and named."""
    extras = roster_extras(manifest)
    values = {
        "Email address": {sid: roster_value(e, EMAIL) for sid, e in extras.items()},
        "ID number": {sid: roster_value(e, ID_NUMBER) for sid, e in extras.items()},
        "lagrade id": {sid: sid for sid in extras},
    }
    warnings = []
    for header, column in values.items():
        for sid in sorted(repeated(column)):
            warnings.append(
                f"{sid}: {header} {column[sid]!r} is shared with another student; "
                "Moodle would give both grades to one user, so it is left out"
            )
            column[sid] = ""
        for sid, value in column.items():
            if value and not writable_identifier(value):
                warnings.append(
                    f"{sid}: {header} {value!r} would be read as a spreadsheet formula; left out"
                )
                column[sid] = ""
    return values, warnings


def _identifier(values: Mapping[str, Mapping[str, str]], sending: Sequence[Mapping]) -> str:
    """The column Moodle should match users by: the one that identifies most of the students
    with a grade (email first on a tie); the lagrade id when the roster has neither."""
    ids = [r["student"]["id"] for r in sending]
    emails = sum(1 for sid in ids if values["Email address"][sid])
    numbers = sum(1 for sid in ids if values["ID number"][sid])
    if emails or numbers:
        return "Email address" if emails >= numbers else "ID number"
    if any(values["Email address"].values()):
        return "Email address"
    return "ID number" if any(values["ID number"].values()) else "lagrade id"


def _feedback(result: Mapping[str, Any]) -> str:
    score = (
        f"{report.format_number(result['score'])} of {report.format_number(result['max_score'])}"
    )
    if result["status"] == "graded":
        return f"Graded by lagrade: {score} points."
    return f"{result['status']}: {result['reason']} ({score} points)"


def _readme(
    name: str,
    key: str,
    total: float,
    rows: int,
    no_grade: Sequence[Mapping[str, Any]],
    options: ExportOptions,
    warnings: Sequence[str],
) -> str:
    points = report.format_number(total)
    lines = [
        "gradebook-moodle.csv: how to import it into Moodle",
        "",
        "1. Once, before the first import: Grades > Gradebook setup > Add grade item, named",
        f"   {name!r}, Maximum grade {points} (the assignment's total). A grade item that the",
        '   import creates itself ("New grade item") gets Moodle\'s default maximum, 100.',
        "2. Grades > Import > CSV file: choose gradebook-moodle.csv, Encoding UTF-8,",
        "   Separator Comma, then Upload grades.",
        f'3. Identify user by: Map from "{key}", Map to "{FIELDS[key]}".',
    ]
    if key == "lagrade id":
        lines += [
            "   (The roster has no email or ID number column: this works only if your lagrade",
            "   ids are the students' Moodle usernames. Otherwise add an email column to the",
            "   roster and generate again.)",
        ]
    lines += [
        f'4. Grade item mappings: "{name}" -> the grade item {name!r} from step 1;',
        f'   "{name} (feedback)" -> Ignore, or "Feedback for {name}" to replace the feedback',
        "   Moodle holds with lagrade's summary; every other column -> Ignore.",
        "5. Upload grades.",
        "",
        f"The file has {rows} row(s). Moodle stops the whole import at a row whose {key}",
        "belongs to no Moodle user and names it: delete that row and import again. Moodle",
        "compares the value exactly (on some databases even the case of an email, MDL-29315),",
        "so the roster should spell it as Moodle has it.",
    ]
    if no_grade:
        lines += [
            "",
            f"Not in the file, so Moodle keeps whatever it holds for them ({len(no_grade)}; a",
            "blank grade would clear a grade entered in Moodle):",
            f"  {names(no_grade, 50)}",
        ]
    if options.missing_as_zero:
        lines += [
            "",
            "--missing-as-zero: students who handed in nothing readable (missing, invalid) get 0",
            "with the reason as feedback; a student the grader could not finish is left out.",
        ]
    if warnings:
        lines += ["", "Before importing:", *(f"  - {w}" for w in warnings)]
    return "\n".join(lines) + "\n"
