"""LaTeX that a string escape ate: in a double-quoted TOML (or JSON) string `\\theta` is a tab
and "heta", `\\frac` a form feed and "rac", `\\beta` a backspace and "eta", `\\rho` a carriage
return and "ho", `\\nu` a line break and "u". The one rule for such answers: where the raw
sheet holds the backslash sequence and the restored word is a command the notation reads, the
answer is read as the student meant it; either way the student is told to use single quotes."""

from __future__ import annotations

import re

from lagrade.notation.latex import COMMANDS

#: The escapes TOML and JSON share that turn a backslash and a letter into a control character.
_ESCAPES = {"\b": "b", "\t": "t", "\n": "n", "\f": "f", "\r": "r"}
_NAMES = {"\b": "a backspace", "\t": "a tab", "\n": "a line break", "\f": "a form feed"}
_NAMES["\r"] = "a carriage return"
#: A control character and the letters after it.
_CONTROL = re.compile(r"([\x00-\x1f\x7f])([A-Za-z]*)")
#: Control characters a sheet's string may hold raw: a tab and a line break (TOML allows both
#: in multi-line strings); any other came from an escape.
_RAW_ALLOWED = frozenset("\t\n")


def repair(answer: str, raw: str) -> tuple[str, list[str], list[str]]:
    """(the answer as meant, the LaTeX commands restored, the control characters left in it
    that came from an escape). `raw` is the sheet's text, where an escape shows as its
    backslash sequence (`\\theta`)."""
    restored: list[str] = []
    kept: list[str] = []

    def fix(m: re.Match) -> str:
        char, letters = m.group(1), m.group(2)
        letter = _ESCAPES.get(char)
        if letter is not None and letters:
            command = letter + letters
            if command in COMMANDS and "\\" + command in raw:
                restored.append("\\" + command)
                return "\\" + command
            if char in _RAW_ALLOWED and "\\" + command not in raw:
                return m.group()  # a real tab or line break (a multi-line answer)
        elif char in _RAW_ALLOWED:
            return m.group()
        kept.append(_NAMES.get(char, f"the control character U+{ord(char):04X}"))
        return m.group()

    text = _CONTROL.sub(fix, answer)
    return text, restored, kept


def warning(where: str, restored: list[str], kept: list[str]) -> str:
    """The sentence for the student: what was read, and the fix (single quotes)."""
    fix = "write LaTeX in single quotes ('...' or '''...'''), where a backslash stays a backslash"
    if restored and not kept:
        shown = ", ".join(dict.fromkeys(restored))
        return (
            f"{where}: in a double-quoted string {shown} is read as an escape (\\t is a tab, "
            f"\\f a form feed); it was read as {shown} as you meant, but {fix}."
        )
    shown = ", ".join(dict.fromkeys(kept))
    also = f" ({', '.join(dict.fromkeys(restored))} was restored)" if restored else ""
    return (
        f"{where}: the answer holds {shown}, which a double-quoted string makes of a backslash "
        f"(\\theta becomes a tab and 'heta'){also}; {fix}."
    )
