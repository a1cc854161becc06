"""The `dof` part: the number of degrees of freedom, 3N − k, as a whole number."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.errors import ParseError
from lagrade.judge.parts.items import single_text
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict, invalid
from lagrade.notation import Vocabulary, parse_expression

#: The longest whole number read as a count of degrees of freedom.
MAX_DIGITS = 30
#: What a `dof` answer that is not a whole number is told.
WHOLE_NUMBER = "Write the number of degrees of freedom as a whole number, e.g. 2."
#: What a worked count may be labelled with before its '=': `DOF = 2`, `3N − k = 6 − 4 = 2`.
_LABEL = re.compile(r"\s*(?:dof|f|n|s|3\s*n\s*[-−]\s*k)\s*", re.IGNORECASE)
#: The longest side of a worked count read as arithmetic.
_MAX_SIDE = 80


def read_dof(problem: Problem, answer: Any) -> str:
    """The whole number a `dof` answer gives, as typed (its sign kept)."""
    if not isinstance(answer, int):
        answer = single_text(answer, "dof")
    text = str(answer).strip()
    if isinstance(answer, str) and "=" in text:
        text = _worked_count(text)
    if isinstance(answer, bool) or not (isinstance(answer, int) or re.fullmatch(r"[+-]?\d+", text)):
        raise ParseError(WHOLE_NUMBER, (0, len(text)), text)
    return text


def _worked_count(text: str) -> str:
    """The count a worked line ends with, as students write it on paper: `3N − k = 6 − 4 = 2`
    (each side before the last a label or whole-number arithmetic giving the same count), so
    that a right count is not refused for its working; the text itself when it is no such
    line (then `WHOLE_NUMBER` is said). Arithmetic that gives another number is named."""
    *sides, last = text.split("=")
    last = last.strip()
    if not re.fullmatch(rf"[+-]?\d{{1,{MAX_DIGITS}}}", last):
        return text
    for side in sides:
        if _LABEL.fullmatch(side):
            continue
        if len(side) > _MAX_SIDE:
            return text
        try:
            value = parse_expression(side, Vocabulary((), {})).lhs
        except ParseError:
            return text
        if value != int(last):
            shown = side.strip()
            raise ParseError(
                f"{shown} is {value}, not {last}; write the number of degrees of freedom "
                "alone, e.g. 2.",
                (0, len(shown)),
                text,
            )
    return last


def check_dof(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    try:
        text = read_dof(problem, answer)
    except ParseError as error:
        return invalid("dof", error.message, error.source)
    if len(text.lstrip("+-")) > MAX_DIGITS:  # int() of 4,300+ digits raises; no system needs it
        return Verdict(
            "dof",
            "incorrect",
            0.0,
            ("That number is far too large to be a number of degrees of freedom.",),
            untrusted.clip(text, 40),
            "exact",
        )
    n = int(text)
    if n == problem.dof:
        return Verdict("dof", "correct", 1.0, (), str(n), "exact")
    feedback = [f"{n} is not the number of degrees of freedom."]
    mistakes: tuple[str, ...] = ()
    v = problem.variant
    if v is not None:
        freedoms = sum(b.freedoms for b in v.bodies)
        implied = sum(1 for label, _ in v.constraints if label != "declared")
        if n == freedoms:
            feedback.append(
                f"You counted {freedoms} freedoms of the bodies but subtracted no "
                "constraints (DOF = 3N − k)."
            )
            mistakes = ("no_constraints",)
        elif implied and n == problem.dof + implied:
            feedback.append(
                "Motion in a plane is a constraint too (z = 0 for each body); "
                "count it among the k constraints."
            )
            mistakes = ("forgot_planarity",)
    return Verdict("dof", "incorrect", 0.0, tuple(feedback), str(n), "exact", mistakes=mistakes)
