"""How an answer is read, for the page's live preview: the reading step of the one door
(`lagrade.judge.read.read_answer`, the reader the part's checker reads with, so the preview never
disagrees with the grade about what was read), shown as MathML, or the parser's message with its
caret. Reading judges nothing: no reference is derived and no mistake is looked for, so a preview
of a wrong answer costs what a preview of a right one does. Whether the answer is right is the
grade's, and only when the assignment allows it.

Runs inside the server's worker processes (`judging`: the time limit is a signal, which only a
process's main thread can take, and C code that ignores it is killed)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.grading.student import part_spec, question
from lagrade.judge import GRACE, PartTimeout, deadline, read_answer, time_limit

#: Seconds one preview may take (a preview is asked at every pause in typing).
PREVIEW_TIME_LIMIT = 3.0


def preview(entry: Mapping[str, Any], part: Mapping[str, Any], text: str) -> dict[str, Any]:
    """{"status": "empty"|"read"|"unreadable"|"timeout", "lines": [{"plain", "mathml"}],
    "message": the parser's error (caret included) when unreadable, or one per unreadable line,
    "warnings": the parser's notes on how it read the answer}."""
    deadline(PREVIEW_TIME_LIMIT + GRACE)  # the parent kills C code that ignores the alarm
    try:
        with time_limit(PREVIEW_TIME_LIMIT):
            reading = read_answer(question(part_spec(entry, part)), part["part"], text)
    except PartTimeout:
        return timed_out()
    if reading.status == "empty":
        return {"status": "empty", "lines": [], "message": "", "warnings": []}
    if reading.status == "unreadable":
        return {
            "status": "unreadable",
            "lines": [],
            "message": reading.message,
            "warnings": list(reading.notes),
        }
    return {
        "status": "read",
        "lines": [
            {"plain": line.plain, "mathml": line.mathml} for line in reading.lines if line.plain
        ],
        "message": reading.message,
        "warnings": list(reading.notes),
    }


def timed_out() -> dict[str, Any]:
    """The reply for an answer whose reading ran out of time, stopped by the alarm or by the
    kill of its worker at the limit + grace."""
    return {
        "status": "timeout",
        "lines": [],
        "message": "Reading this answer took too long.",
        "warnings": [],
    }
