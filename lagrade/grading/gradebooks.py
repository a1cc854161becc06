"""Gradebooks in the form a learning-management system imports, beside lagrade's own
`gradebook.csv`: `grade --export canvas|moodle`. Each is a CSV and a README that says how to
import it and what the importer will do with it (`lagrade.grading.canvas`,
`lagrade.grading.moodle`).

The assignment file may say which Canvas assignment to fill:

    [lms]
    canvas_assignment_id = 12345   # the number in the assignment's Canvas address
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
from lagrade.assign import assignment_table
from lagrade.errors import AssignmentError, LagradeError
from lagrade.grading.canvas import canvas_gradebook
from lagrade.grading.lms import ExportOptions, LmsFile
from lagrade.grading.moodle import moodle_gradebook

EXPORTS: dict[
    str, Callable[[Mapping[str, Any], Sequence[Mapping[str, Any]], ExportOptions], LmsFile]
] = {"canvas": canvas_gradebook, "moodle": moodle_gradebook}
_LMS_KEYS = ("canvas_assignment_id",)


def export_file_name(kind: str) -> str:
    return f"gradebook-{kind}.csv"


def readme_file_name(kind: str) -> str:
    return f"gradebook-{kind}.README.txt"


def canvas_assignment_id(value: Any, where: str) -> str:
    """A Canvas assignment id as written in a header (`Title (12345)`): digits only, since
    Canvas finds the id with `\\((\\d+)\\)` at the end of the header."""
    text = (
        str(value).strip() if isinstance(value, int | str) and not isinstance(value, bool) else ""
    )
    if not (text.isascii() and text.isdigit() and int(text) > 0):
        raise AssignmentError(
            f"{where}: {value!r} is not a Canvas assignment id (the number in the assignment's "
            "address, …/assignments/12345)"
        )
    return str(int(text))


def resolve_options(assignment_file: Path, given: ExportOptions | None) -> ExportOptions:
    """The export options: what the command line gave, else the assignment file's `[lms]`
    table. Raises AssignmentError for a malformed table or id, before anything is graded."""
    given = given or ExportOptions()
    table: Any = None
    if assignment_file.exists():
        try:
            table = assignment_table(assignment_file).get("lms")
        except LagradeError as error:
            raise AssignmentError(str(error)) from None
    if table is not None and not isinstance(table, Mapping):
        raise AssignmentError("[lms] in the assignment file must be a table")
    unknown = sorted(set(table or {}) - set(_LMS_KEYS))
    if unknown:
        raise AssignmentError(
            f"[lms]: unknown field {unknown[0]!r} (known: {', '.join(_LMS_KEYS)})"
        )
    canvas_id = given.canvas_assignment_id
    if canvas_id is not None:
        canvas_id = canvas_assignment_id(canvas_id, "--canvas-assignment-id")
    elif table and "canvas_assignment_id" in table:
        canvas_id = canvas_assignment_id(
            table["canvas_assignment_id"], "[lms] canvas_assignment_id"
        )
    return dataclasses.replace(given, canvas_assignment_id=canvas_id)


def write_exports(
    out: Path,
    manifest: Mapping[str, Any],
    results: Sequence[Mapping[str, Any]],
    kinds: Sequence[str],
    options: ExportOptions | None = None,
) -> list[LmsFile]:
    """Write each asked-for gradebook and its README into `out` (atomically)."""
    written = []
    for kind in kinds:
        book = EXPORTS[kind](manifest, results, options or ExportOptions())
        atomic.write_text(out / export_file_name(kind), book.csv)
        atomic.write_text(out / readme_file_name(kind), book.readme)
        written.append(book)
    return written
