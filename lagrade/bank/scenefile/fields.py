"""The reading of one field of a scene file, every problem collected (`Problems`) rather than
raised at the first: names, one-line texts, expressions' texts, tables and lists, each refused
with a sentence naming its key."""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from lagrade.notation import FUNCTIONS

#: A name in a scene file: a coordinate, parameter, body, option, choice, let or quantity.
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}\Z")
#: Names that mean something already: time, pi, the functions, and `gravity` in a potential.
RESERVED = frozenset({"t", "pi", "gravity"}) | FUNCTIONS
MAX_TEXT = 5_000  # characters of a title, statement, wording or description


@dataclass(frozen=True)
class Text:
    """An expression's text and the key it sits under (`bodies.bead.position[2]`)."""

    key: str
    text: str


class Problems:
    """The problems found in one file, each as `key: message`, in the order found."""

    def __init__(self) -> None:
        self.items: list[str] = []
        self.blocking = 0

    def add(self, key: str, message: str, blocking: bool = True) -> None:
        """Record a problem; a `blocking` one leaves too little to derive the scene from (an
        unknown key does not: the scene is still checked against itself, to report all)."""
        self.items.append(f"{key}: {message}" if key else message)
        self.blocking += blocking

    def __bool__(self) -> bool:
        return bool(self.items)


def shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:60] + "…"


def unknown_keys(table: Mapping, known: tuple[str, ...], where: str, problems: Problems) -> None:
    for key in table:
        if key not in known:
            prefix = f"{where}." if where else ""
            problems.add(f"{prefix}{key}", f"unknown key (known: {', '.join(known)})", False)


#: Kinds of names that enter expressions, so cannot be a name that means something already.
_IN_EXPRESSIONS = frozenset({"coordinate", "parameter", "let", "quantity"})


def name_field(value: Any, key: str, what: str, problems: Problems) -> bool:
    """Whether `value` is a usable name; the problem says why not."""
    if not isinstance(value, str) or not NAME.match(value):
        problems.add(
            key,
            f"{shown(value)} is not a {what} name (a letter, then letters, digits or _, at "
            "most 32 characters)",
        )
        return False
    if what in _IN_EXPRESSIONS and (value in RESERVED or value.endswith(("_dot", "_ddot"))):
        problems.add(key, f"{value!r} is reserved (t, pi, gravity, the functions, *_dot, *_ddot)")
        return False
    return True


#: What no text of a scene file may hold: C0 and C1 control characters, DEL, Unicode's line
#: and paragraph separators, and the bidirectional overrides that reorder what is shown. A
#: statement may break lines and hold tabs; a title, unit, description or wording is one line
#: (a line break in a unit ends the answer sheet's comment it is written into, or hides a
#: line in it).
_NOT_IN_TEXT = re.compile(
    "[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]"
)
_NOT_IN_ONE_LINE = re.compile("[\t\n\r]")


def text_field(
    table: Mapping,
    key: str,
    where: str,
    problems: Problems,
    required: bool = False,
    lines: bool = False,
) -> str | None:
    """A text of the file; one line unless `lines` (see _NOT_IN_TEXT)."""
    value = table.get(key)
    at = f"{where}.{key}" if where else key
    if value is None:
        if required:
            problems.add(at, "missing")
        return None
    if not isinstance(value, str):
        problems.add(at, f"{shown(value)} is not a string")
        return None
    if len(value) > MAX_TEXT:
        problems.add(at, f"longer than {MAX_TEXT:,} characters")
        return None
    bad = _NOT_IN_TEXT.search(value) or (None if lines else _NOT_IN_ONE_LINE.search(value))
    if bad:
        char = bad.group()
        kind = (
            "a line break"
            if char in "\n\r\u2028\u2029\x85\x0b\x0c"
            else ("a tab" if char == "\t" else "an invisible control character")
        )
        text = "text" if lines else "one line of text"
        problems.add(
            at,
            f"holds {kind} ({char.encode('unicode_escape').decode()}) at character "
            f"{bad.start() + 1}: write it as {text} without control characters",
        )
        return None
    return value


def expression(value: Any, key: str, problems: Problems) -> Text | None:
    """An expression's text: a string, or a number written as one (`0`, `-1.2`)."""
    if isinstance(value, bool) or not isinstance(value, str | int | float):
        problems.add(key, f"{shown(value)} is not an expression (write it as a string)")
        return None
    if isinstance(value, float) and not math.isfinite(value):
        problems.add(key, f"{value!r} is not a finite number")
        return None
    return Text(key, value if isinstance(value, str) else repr(value))


def table_field(value: Any, key: str, problems: Problems, what: str = "a table") -> dict | None:
    if not isinstance(value, dict):
        problems.add(key, f"{shown(value)} is not {what}")
        return None
    return value


def list_field(value: Any, key: str, problems: Problems, limit: int) -> list | None:
    if not isinstance(value, list):
        problems.add(key, f"{shown(value)} is not a list")
        return None
    if len(value) > limit:
        problems.add(key, f"{len(value)} entries; at most {limit}")
        return None
    return value
