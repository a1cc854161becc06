"""A line of a list answer that only an ambiguity left unread (`m l cos psi psi_dot`: cos(ψ·ψ̇)
or cos(ψ)·ψ̇?) is judged under each of its readings, and the part takes the reading that scores
best, saying so. In batch grading the student cannot add the brackets any more, and
notation.md's rule holds: an ambiguity alone never zeroes a part. No reading is taken silently:
the note names the reading and asks for the brackets; a line unreadable for any other reason
still counts as a wrong one."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, replace
from typing import Any

from lagrade.errors import ParseError
from lagrade.judge.parts.items import Piece, list_items
from lagrade.judge.tolerances import ROUNDING
from lagrade.judge.verdict import Verdict

#: Ambiguous lines judged together at most (their readings multiply: 2 lines, 4 runs).
MAX_AMBIGUOUS_LINES = 2


@dataclass(frozen=True)
class Ambiguous:
    """A line of a list answer that does not parse only because it is ambiguous: its text and
    each reading as (the ambiguous part so read, the whole line so read, in the plain grammar)."""

    text: str
    readings: tuple[tuple[str, str], ...]


_found: ContextVar[list[Ambiguous] | None] = ContextVar("ambiguous_lines", default=None)


@contextmanager
def ambiguous_lines() -> Iterator[list[Ambiguous]]:
    """Collect, while the block runs, the lines `note_ambiguous` is told of."""
    token = _found.set([])
    try:
        yield _found.get()  # type: ignore[misc]
    finally:
        _found.reset(token)


def note_ambiguous(item: Any, error: ParseError) -> None:
    """Record a list line that failed with an ambiguity (an error that carries readings)."""
    found = _found.get()
    if found is not None and error.readings and isinstance(item, str):
        found.append(Ambiguous(str(item), error.readings))


def best_reading(
    run: Callable[[Any], tuple[Verdict, list[str]]],
    answer: Any,
    part: str,
    found: list[Ambiguous],
    verdict: Verdict,
) -> tuple[Verdict, list[str]] | None:
    """The verdict (and reading notes) of the answer with its ambiguous lines read the way that
    scores best, with a sentence per line naming the reading taken; None when no reading scores
    better than the lines counted wrong. `run(answer)` judges an answer in a fresh context."""
    ambiguous = found[:MAX_AMBIGUOUS_LINES]
    items = list_items(answer, part)
    best: tuple[Verdict, list[str]] | None = None
    chosen: tuple[tuple[str, str], ...] = ()
    for combination in itertools.product(*(a.readings for a in ambiguous)):
        replaced = list(items)
        for line, reading in zip(ambiguous, combination, strict=True):
            k = next((k for k, item in enumerate(replaced) if item == line.text), None)
            if k is not None:
                replaced[k] = Piece(reading[1], latex=False)
        judged = run(replaced)
        score = (best or (verdict, []))[0].score
        if judged[0].status != "invalid" and judged[0].score > score + ROUNDING:
            best, chosen = judged, combination
    if best is None:
        return None
    said = [
        f"{' or '.join(r[0] for r in line.readings)}? In '{line.text.strip()}' it was read as "
        f"{reading[0]}, the reading under which your answer scores best; write the brackets to "
        "say which you mean."
        for line, reading in zip(ambiguous, chosen, strict=True)
    ]
    judged, notes = best
    return replace(judged, feedback=(*said, *judged.feedback)), notes
