"""The first step of the one door from what a student typed to its verdict: the raw answer — a
string, or the list of strings a TOML sheet or a JSON request holds — split into the items a part
judges. Every command (`check`, `check --batch`, `grade`, key verification, the answer page,
PrairieLearn) hands the raw answer to the part's checker, and every checker splits it here, so
one answer is read one way whoever asks.

Items of a list (equations, momenta, conserved quantities, names) are separated by a line break,
`;`, LaTeX's `\\\\`, a comma or the word "and" between two items. A comma or "and" inside brackets
(`atan2(y, x)`, `Max(a, b)`, `x_{1,2}`), LaTeX spacing (`\\,`, `\\;`) and a decimal comma between
two digits (`9,81`, refused by the parser with its message) never split.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.notation import MAX_TOTAL_LENGTH, is_latex

#: What a student writes for an empty list (no cyclic coordinate, no conserved quantity).
NONE_WORDS = frozenset({"none", "no", "-", "", "∅", "nothing"})
#: Items of one list answer; no mechanics answer comes near (feedback keeps 100 items).
MAX_ITEMS = 200
_OPENING, _CLOSING = "({[", ")}]"


class Piece(str):
    """One item's text, remembering whether the whole answer it came from was LaTeX: a LaTeX
    answer split at its line breaks is LaTeX in every line (`e^x` is exp(x) there, `{…}` a
    group), even in a line without a backslash."""

    latex: bool

    def __new__(cls, text: str, latex: bool) -> Piece:
        piece = super().__new__(cls, text)
        piece.latex = latex
        return piece

    def __reduce__(self):  # crosses to and from worker processes inside errors and verdicts
        return (Piece, (str(self), self.latex))


def raw_items(answer: Any, part: str) -> list[Any]:
    """The strings of a raw answer: one string, or a list of them (sympy objects from Python
    callers pass through). Anything else is a malformed request."""
    if isinstance(answer, str | sp.Basic):
        return [answer]
    if isinstance(answer, Sequence) and not isinstance(answer, bytes):
        return list(answer)
    raise RequestError(f"the answer to {part!r} must be a string or a list of strings")


def single_text(answer: Any, part: str) -> Any:
    """The answer of a one-item part (L, T, V, an expression, a number) as one text: a list of
    strings is its lines (TOML's multi-line form), joined by line breaks, which read as spaces."""
    items = raw_items(answer, part)
    if items and all(isinstance(item, str) for item in items):
        return "\n".join(items)
    if len(items) == 1:
        return items[0]
    raise RequestError(f"the answer to {part!r} is a single expression")


def list_items(answer: Any, part: str) -> list[Any]:
    """The items of a list part, in order: each string split at its separators, blank pieces
    dropped. More than MAX_ITEMS items, or more than MAX_TOTAL_LENGTH characters, is refused
    with a message (the part is `invalid`)."""
    items = raw_items(answer, part)
    strings = [item for item in items if isinstance(item, str)]
    total = sum(len(s) for s in strings)
    if total > MAX_TOTAL_LENGTH:
        whole = "\n".join(strings)
        raise ParseError(
            f"The answer is too long ({total} characters; the limit is {MAX_TOTAL_LENGTH}).",
            (MAX_TOTAL_LENGTH, len(whole)),
            whole,
        )
    pieces: list[Any] = []
    for item in items:
        if isinstance(item, str):  # a Piece keeps what its answer was (a rewritten line's)
            latex = item.latex if isinstance(item, Piece) else is_latex(item)
            pieces += [Piece(text, latex) for text in split_item(item)]
        else:
            pieces.append(item)
    if len(pieces) > MAX_ITEMS:
        whole = "\n".join(strings)
        raise ParseError(
            f"The answer lists {len(pieces)} items; at most {MAX_ITEMS} are read.",
            (0, len(whole)),
            whole,
        )
    return pieces


def is_none(items: Sequence[Any]) -> bool:
    """Whether a list answer says "none" (or nothing at all)."""
    return all(isinstance(item, str) and item.strip().lower() in NONE_WORDS for item in items)


def without_none(items: Sequence[Any]) -> list[Any]:
    return [i for i in items if not (isinstance(i, str) and i.strip().lower() in NONE_WORDS)]


def split_item(text: str) -> list[str]:
    """The non-blank pieces of one string between separators (see the module docstring),
    without the spaces around them."""
    pieces: list[str] = []
    start, depth, i, n = 0, 0, 0, len(text)
    while i < n:
        c = text[i]
        cut = 0  # length of a separator at i
        if c == "\\":
            if text.startswith("\\\\", i):
                cut = 2  # LaTeX's line break
            else:
                i += 2  # a LaTeX command's first character (\, \; \{) is never a separator
                continue
        elif c in _OPENING:
            depth += 1
        elif c in _CLOSING:
            depth = max(0, depth - 1)
        elif c in "\n;":
            cut = 1
        elif depth == 0 and c == "," and not _decimal_comma(text, i):
            cut = 1
        elif depth == 0 and _word_and(text, i):
            cut = 3
        if cut:
            pieces.append(text[start:i])
            start = i + cut
            i += cut
            continue
        i += 1
    pieces.append(text[start:])
    return [piece.strip() for piece in pieces if piece.strip()]


def _decimal_comma(text: str, i: int) -> bool:
    """9,81: a comma between two digits is a decimal comma (or a thousands separator), not a
    separator of items; the parser refuses it with its own message."""
    return 0 < i < len(text) - 1 and text[i - 1].isdigit() and text[i + 1].isdigit()


def _word_and(text: str, i: int) -> bool:
    """The word "and" at i, standing alone (not part of a name such as `band` or `and_1`)."""
    if not text.startswith("and", i):
        return False
    before = text[i - 1] if i > 0 else " "
    after = text[i + 3] if i + 3 < len(text) else " "
    return not (before.isalnum() or before in "_\\") and not (after.isalnum() or after == "_")
