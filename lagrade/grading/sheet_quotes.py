"""Primes inside a one-line answer: `lagrangian = '1/2 m x'^2'`. The answer sheet asks for
answers between single quotes (TOML literal strings, where a backslash stays a backslash), and
a prime, which the notation reads as a time derivative, ends such a string: the whole sheet
would be unreadable and score 0 on every part. The one rule: when a sheet is not valid TOML,
each line `key = '…'` whose answer holds a quote is read as `key = '''…'''`, which may hold
one, with a note for the student; if the sheet is still not valid, the first error stands."""

from __future__ import annotations

import re

#: `key = '…'` on one line (a comment after it without a quote), the answer holding a quote.
_LINE = re.compile(
    r"^(?P<head>[ \t]*(?P<key>[A-Za-z0-9_-]+)[ \t]*=[ \t]*)'(?P<body>[^'\n][^\n]*'[^\n]*)'"
    r"(?P<tail>[ \t]*(?:#[^'\n]*)?)$"
)
_TABLE = re.compile(r"^[ \t]*\[(?P<name>[^\[\]\n]+)\][ \t]*(?:#.*)?$")
_MULTI = ("'''", '"""')


def quote_primes(raw: str) -> tuple[str, list[str]]:
    """(`raw` with each one-line literal answer that holds a quote rewritten as a multi-line
    literal string, the places so rewritten as "[problem1] lagrangian"). Lines inside a
    multi-line string are left alone (a quote is allowed there)."""
    out, places = [], []
    inside: str | None = None  # the delimiter of the multi-line string the line is in
    table = ""
    for line in raw.split("\n"):
        if inside is None:
            if (header := _TABLE.match(line)) is not None:
                table = header["name"].strip()
            m = _LINE.match(line)
            if m is not None and "'''" not in m["body"]:
                line = f"{m['head']}'''{m['body']}'''{m['tail']}"
                places.append(f"[{table}] {m['key']}" if table else m["key"])
        for delimiter in _MULTI:
            if inside in (None, delimiter) and line.count(delimiter) % 2:
                inside = None if inside else delimiter
        out.append(line)
    return "\n".join(out), places


def warning(where: str) -> str:
    """The sentence for the student: what was read, and how to write it next time."""
    return (
        f"{where}: the answer holds a quote (a prime, θ'), which ends a '...' string; it was "
        "read as you meant, but write an answer with primes between ''' and ''' "
        "(or use _dot: theta_dot)."
    )
