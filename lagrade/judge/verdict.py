"""The judgement of one answer part, the one result type every checker returns."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import lagrade.untrusted as untrusted

STATUSES = ("correct", "incorrect", "invalid", "timeout", "error")  # error: a bug of ours


@dataclass(frozen=True)
class Verdict:
    """The judgement of one answer part: status (correct | incorrect | invalid | timeout), score
    in [0, 1], feedback sentences, the parser's echo of what was read, the method that decided,
    the time it took, and when wrong a point where the answer and the reference differ.

    Two times, so that no benchmark can hide either: `ms`, the student's part (reading and
    judging the answer, under its time limit), and `prepare_ms`, the question's part that this
    request paid for (deriving the reference and sample points on first use, the mistake
    catalogue as far as a wrong answer's diagnosis needed it; 0 when all was cached)."""

    part: str
    status: str
    score: float
    feedback: tuple[str, ...] = ()
    interpreted: str | list[str] = ""
    method: str = ""
    ms: float = 0.0
    witness: Mapping[str, float] | None = None
    follows_from_own_answer: bool = False
    mistakes: tuple[str, ...] = field(default=())
    prepare_ms: float = 0.0

    def __post_init__(self) -> None:
        assert self.status in STATUSES, self.status
        assert 0.0 <= self.score <= 1.0, self.score
        # What a student typed comes back in the echo and the feedback: bounded in size (a
        # 100 MB answer must not make a 100 MB result line) and encodable as UTF-8.
        object.__setattr__(self, "feedback", _bounded(self.feedback))
        if isinstance(self.interpreted, str):
            object.__setattr__(self, "interpreted", untrusted.bounded(self.interpreted))
        else:
            object.__setattr__(self, "interpreted", list(_bounded(self.interpreted)))

    def to_dict(self, timings: bool = True) -> dict[str, Any]:
        """The JSON form of a part's result (without the request id), in the documented key
        order: the one serialiser of a verdict, for a `check --batch` result line and a graded
        part alike. `timings=False` leaves `ms` and `prepare_ms` out (a graded class's files
        are the same bytes whenever and wherever they are graded)."""
        shown: dict[str, Any] = {
            "verdict": self.status,
            "score": self.score,
            "feedback": list(self.feedback),
            "interpreted": self.interpreted,
            "method": self.method,
        }
        if timings:
            shown |= {"ms": round(self.ms, 3), "prepare_ms": round(self.prepare_ms, 3)}
        return shown | {
            "part": self.part,
            "witness": dict(self.witness) if self.witness else None,
            "follows_from_own_answer": self.follows_from_own_answer,
            "mistakes": list(self.mistakes),
        }


def _bounded(texts) -> tuple[str, ...]:
    kept = tuple(untrusted.bounded(str(t)) for t in list(texts)[: untrusted.MAX_ITEMS])
    left = len(texts) - len(kept)
    return kept + ((f"… and {left} more",) if left > 0 else ())


def invalid(part: str, message: str, interpreted: str | list[str] = "") -> Verdict:
    return Verdict(part, "invalid", 0.0, (message,), interpreted, "parse")


def timeout_verdict(part: str, seconds: float, what: str = "judging the answer") -> Verdict:
    """The verdict of a part whose time ran out: one wording wherever the limit struck."""
    return Verdict(
        part,
        "timeout",
        0.0,
        (f"The check ran out of time ({what} took longer than {seconds:g} s).",),
        "",
        "timeout",
    )


def unreadable_line(number: int, error: object) -> str:
    """The feedback sentence on line `number` (1-based) of an answer, which does not parse:
    named, with the parser's message and its caret."""
    return f"Line {number} could not be read: {error}"


#: How `unreadable_line` begins its sentence.
_UNREADABLE_LINE = re.compile(r"Line \d+ could not be read: ")


def is_unreadable_line(sentence: str) -> bool:
    """Whether a verdict's feedback sentence is `unreadable_line`'s: for a caller that must
    refuse such an answer rather than grade it (PrairieLearn's format errors)."""
    return _UNREADABLE_LINE.match(sentence) is not None
