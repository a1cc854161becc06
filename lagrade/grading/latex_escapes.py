"""LaTeX that a string escape ate: in a double-quoted TOML (or JSON) string `\\theta` is a tab
and "heta", `\\frac` a form feed and "rac", `\\beta` a backspace and "eta", `\\rho` a carriage
return and "ho", `\\nu` a line break and "u". The one rule for such answers: where the raw
sheet holds the backslash sequence and the restored word is a command the notation reads, the
answer is read as the student meant it; either way the student is told to use single quotes."""

from __future__ import annotations

import functools
import re

from lagrade.notation import COMMANDS

#: The escapes TOML and JSON share that turn a backslash and a letter into a control character.
_ESCAPES = {"\b": "b", "\t": "t", "\n": "n", "\f": "f", "\r": "r"}
_NAMES = {"\b": "a backspace", "\t": "a tab", "\n": "a line break", "\f": "a form feed"}
_NAMES["\r"] = "a carriage return"
#: A control character and the letters after it.
_CONTROL = re.compile(r"([\x00-\x1f\x7f])([A-Za-z]*)")


def repair(answer: str, raw: str) -> tuple[str, list[str], list[str]]:
    """(the answer as meant, the LaTeX commands restored, the control characters left in it
    that came from an escape). `raw` is the sheet's text, where an escape shows as its
    backslash sequence (`\\theta`) inside a double-quoted string; a tab or line break typed
    raw (or written as `\\u0009`) is not an escape and is left alone, without a warning."""
    restored: list[str] = []
    kept: list[str] = []
    escaped = escaped_words(raw)

    def fix(m: re.Match) -> str:
        char, letters = m.group(1), m.group(2)
        letter = _ESCAPES.get(char)
        if letter is None or letter + letters not in escaped:
            return m.group()  # no `\\t…` escape in a "…" string of the sheet made it
        if not letters and char in "\t\n":
            return m.group()  # `\\t` or `\\n` before a non-letter: white space, meant or not
        command = letter + letters
        if letters and command in COMMANDS:
            restored.append("\\" + command)
            return "\\" + command
        kept.append(_NAMES[char])
        return m.group()

    text = _CONTROL.sub(fix, answer)
    return text, restored, kept


#: The strings and comments of a TOML or JSON text: comments and literal strings hold no escape;
#: only double-quoted ("…" or """…""") strings do.
_STRINGS = re.compile(
    r"#[^\n]*|'''.*?'''|'[^'\n]*'?|(\"\"\"(?:\\.|[^\\])*?\"\"\"|\"(?:\\.|[^\"\\\n])*\"?)",
    re.DOTALL,
)
_ESCAPE = re.compile(r"\\([A-Za-z]+|.)", re.DOTALL)


@functools.lru_cache(maxsize=4)
def escaped_words(raw: str) -> frozenset[str]:
    """The letters after each backslash escape inside the double-quoted strings of `raw`
    (`"\\theta"` gives "theta"; `"\\\\theta"`, an escaped backslash, gives none), so that a tab
    is taken for an eaten `\\t` only where the sheet holds that escape."""
    words = set()
    for string in _STRINGS.finditer(raw):
        if string.group(1):
            words.update(m.group(1) for m in _ESCAPE.finditer(string.group(1)))
    return frozenset(words)


def warning(where: str, restored: list[str], kept: list[str], unknown: list[str] = ()) -> str:
    """The sentence for the student: what was read, and the fix (single quotes). `unknown`:
    the sequences the format could not read at all (\\dot, which voided the sheet before)."""
    fix = "write LaTeX in single quotes ('...' or '''...'''), where a backslash stays a backslash"
    if unknown and not restored and not kept:
        shown = ", ".join(dict.fromkeys(unknown))
        return (
            f"{where}: in a double-quoted string a backslash begins an escape, and {shown} is "
            f"none the sheet's format knows; it was read as {shown} as you meant, but {fix}."
        )
    if restored and not kept:
        shown = ", ".join(dict.fromkeys(restored))
        if unknown:  # one sentence for both kinds of escape
            shown = ", ".join(dict.fromkeys([*unknown, *restored]))
            return (
                f"{where}: in a double-quoted string a backslash begins an escape ({shown}); "
                f"it was read as {shown} as you meant, but {fix}."
            )
        return (
            f"{where}: in a double-quoted string {shown} is read as an escape (\\t is a tab, "
            f"\\f a form feed); it was read as {shown} as you meant, but {fix}."
        )
    shown = ", ".join(dict.fromkeys(kept))
    read = [*unknown, *restored]
    also = f" ({', '.join(dict.fromkeys(read))} was read as typed)" if read else ""
    return (
        f"{where}: the answer holds {shown}, which a double-quoted string makes of a backslash "
        f"(\\theta becomes a tab and 'heta'){also}; {fix}."
    )


#: The backslash sequences each format reads in a double-quoted string (TOML 1.0, JSON).
_KNOWN = {
    "toml": re.compile(r'\\(?:[btnfr"\\]|u[0-9A-Fa-f]{4}|U[0-9A-Fa-f]{8}|[ \t]*\r?\n)'),
    "json": re.compile(r'\\(?:[btnfr"\\/]|u[0-9A-Fa-f]{4})'),
}
#: What `escape_unknown` puts for a backslash the format cannot read: an escape both formats
#: decode, to a private-use character no keyboard types, so that `unmark` finds, per answer,
#: where the sheet held such a backslash.
MARK = "\ue000"
_MARKED = re.compile(MARK + "([A-Za-z]+|.?)", re.DOTALL)


def escape_unknown(raw: str, form: str) -> tuple[str, bool]:
    """(`raw` with each backslash that begins no escape `form` ("toml" or "json") knows replaced,
    inside the double-quoted strings, by the escape of `MARK`; whether there was one):
    `"\\dot{q}"` is an error that voids the whole sheet, where the student meant the LaTeX
    command \\dot. Known escapes are left to `repair` (`"\\dot{\\theta}"` keeps \\dot here and
    has \\theta restored there)."""
    known = _KNOWN[form]
    found = False

    def string(m: re.Match) -> str:
        nonlocal found
        text = m.group(1)
        if not text:
            return m.group()
        out, k = [], 0
        while k < len(text):
            escape = known.match(text, k) if text[k] == "\\" else None
            if escape is not None:
                out.append(escape.group())
                k = escape.end()
                continue
            if text[k] == "\\":
                found = True
                out.append("\\uE000")
            else:
                out.append(text[k])
            k += 1
        return "".join(out)

    return _STRINGS.sub(string, raw), found


def unmark(answer: str) -> tuple[str, list[str]]:
    """(the answer with each `MARK` a backslash again, the LaTeX sequences so read: \\dot)."""
    if MARK not in answer:
        return answer, []
    kept = ["\\" + m.group(1) for m in _MARKED.finditer(answer)]
    return answer.replace(MARK, "\\"), kept
