"""How an answer is read, for the page's live preview: the grader's own reading (the same
checker `lagrade grade` runs, so the preview never disagrees with the grade about what was
read), shown as MathML, or the parser's message with its caret. Whether the answer is right
is not shown here: that is the grade's, and only when the assignment allows it.

Runs inside the server's worker processes (`judging`: the checker's time limit is a signal,
which only a process's main thread can take, and C code that ignores it is killed)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.errors import LagradeError, ParseError
from lagrade.grading.manifest import entry_spec
from lagrade.grading.rubric import Rubric
from lagrade.grading.student import grade_part, question
from lagrade.judge.parts.reading import heard_notes
from lagrade.notation import Vocabulary
from lagrade.notation.parse import parse_answer

#: Seconds one preview may take (a preview is asked at every pause in typing).
PREVIEW_TIME_LIMIT = 3.0
_RUBRIC = Rubric()


def preview(entry: Mapping[str, Any], part: Mapping[str, Any], text: str) -> dict[str, Any]:
    """{"status": "empty"|"read"|"unreadable"|"timeout", "lines": [{"plain", "mathml"}],
    "message": the parser's error (caret included) when unreadable, "warnings": the parser's
    notes on how it read the answer}."""
    if not text.strip():
        return {"status": "empty", "lines": [], "message": "", "warnings": []}
    with heard_notes() as notes:
        result = grade_part(entry, part, text, {}, _RUBRIC, PREVIEW_TIME_LIMIT)
    if result["verdict"] == "timeout":
        return timed_out()
    if result["verdict"] == "invalid":
        message = "\n".join(result["feedback"])
        return {"status": "unreadable", "lines": [], "message": message, "warnings": notes}
    shown = result["interpreted"]
    lines = [line for line in (shown if isinstance(shown, list) else [shown]) if line]
    unread = [f for f in result["feedback"] if "could not be read" in f]
    return {
        "status": "read",
        "lines": [
            {"plain": str(line), "mathml": _mathml(entry, part, str(line))} for line in lines
        ],
        "message": "\n".join(unread),
        "warnings": list(notes),
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


def _mathml(entry: Mapping[str, Any], part: Mapping[str, Any], line: str) -> str:
    """The echo of one read line typeset in the student's order, every product shown
    (`lagrade.notation.typeset`), or "" where it is not a formula (a list of names, a number of
    degrees of freedom). The echo is the grader's own output in the plain grammar, parsed again
    by the project's parser, never evaluated."""
    if part["part"] in ("dof", "cyclic", "coordinates") or not line.strip():
        return ""
    spec = entry_spec(entry)
    if part["part"] == "expression":
        spec["quantity"] = part["quantity"]
    try:
        problem = question(spec)
        labels = [f"p_{c}" for c in problem.coordinates] + (
            [part["quantity"]] if part.get("quantity") else []
        )
        if part["part"] in ("hamiltonian", "hamilton_equations"):  # on phase space: p_q, ṗ_q
            momenta = tuple(f"p_{c}" for c in problem.coordinates)
            vocabulary = Vocabulary(
                problem.coordinates, dict(problem.parameters), ["H"], momenta=True
            )
            parsed = parse_answer(line, vocabulary)
            return str(parsed.mathml((*problem.coordinates, *momenta)))
        parsed = parse_answer(line, problem.vocabulary(labels))
        return str(parsed.mathml(problem.coordinates))
    except (ParseError, LagradeError, ValueError, TypeError):
        return ""
