"""Prose with formulas in it, as each format sets it: a scene's statement, a quantity's or a
parameter's description. Names of coordinates and parameters become math, and a power written
with a caret (`x^2`, `omega^2 R`, `(x^2 + y^2)/2`) becomes a superscript — never the raw caret,
which LaTeX's text mode prints as a circumflex accent (`xˆ2`). One renderer for all prose, so
no statement or description can slip past it."""

from __future__ import annotations

import re
import string
from collections.abc import Iterable, Mapping

import sympy as sp
from markupsafe import Markup, escape

from lagrade.assign.templating import md_escape, tex_escape
from lagrade.assign.units import SUPERSCRIPT
from lagrade.notation import printer as rm

#: A name in prose: a whole word, not part of a possessive or a contraction ("pendulum's"),
#: with the power it is raised to, if any (`x^2`, `omega^2`, `z^-1`).
_WORD = re.compile(
    r"(?<![\w'\u2019])(?P<name>[A-Za-z][A-Za-z0-9_]*)(?![\w'\u2019])(?:\^(?P<power>-?\d+))?"
)
#: A power that follows something other than a name: `(x + y)^2`.
_POWER = re.compile(r"\^(?P<power>-?\d+|[A-Za-z])")
_ENGLISH = frozenset({"a", "A", "I"})
#: After a name that is also an English word, what shows it is the name: the sentence goes on
#: with punctuation ("of radius a?", "a (Kepler's third law)") or a preposition ("inertia I about
#: its axle"), never with the noun an article or a pronoun would take.
_AFTER_A_NAME = re.compile(r"\s*(?:[^\w\s]|$|(?:about|and|or|of|in)\b)")


class Prose(str):
    """Plain text (the `str` itself, so `{{ text | tex }}` in an older template still works)
    that also knows itself in each format: `.md`, `.html` (safe markup) and `.tex`."""

    md: str
    html: Markup
    tex: str

    def __new__(cls, text: str, md: str, html: str, tex: str) -> Prose:
        self = super().__new__(cls, text)
        self.md, self.html, self.tex = md, Markup(html), tex
        return self

    def __reduce__(self):  # a view crosses process boundaries: keep every format
        return (Prose, (str(self), self.md, str(self.html), self.tex))


class _Builder:
    def __init__(self) -> None:
        self.md: list[str] = []
        self.html: list[str] = []
        self.tex: list[str] = []

    def text(self, chunk: str) -> None:
        """Prose, with any caret power in it (`)^2`) set as a superscript."""
        last = 0
        for m in _POWER.finditer(chunk):
            self._plain(chunk[last : m.start()])
            power = m.group("power")
            self.md.append(power.translate(SUPERSCRIPT) if power[-1].isdigit() else f"^{power}")
            self.html.append(f"<sup>{escape(power)}</sup>")
            self.tex.append(f"$^{{{power}}}$")
            last = m.end()
        self._plain(chunk[last:])

    def _plain(self, chunk: str) -> None:
        self.md.append(md_escape(chunk))
        self.html.append(str(escape(chunk)))
        self.tex.append(tex_escape(chunk))

    def math(self, name: str, power: str | None = None) -> None:
        symbol = sp.Symbol(name)
        expr = symbol if power is None else sp.Pow(symbol, int(power), evaluate=False)
        rendered = rm.render(expr)
        self.md.append(f"${rendered.latex}$")
        self.html.append(str(rendered.mathml))
        self.tex.append(f"${rendered.latex}$")

    def prose(self, literal: str, names: frozenset[str], english: frozenset[str] = frozenset()):
        """Free text: the given names, and any word raised to a power, set as math; a name in
        `english` (a parameter called a or I) only where the words after it show it is one."""
        last = 0
        for match in _WORD.finditer(literal):
            name, power = match.group("name"), match.group("power")
            named = name in english and _AFTER_A_NAME.match(literal, match.end()) is not None
            if name in names or power is not None or named:
                self.text(literal[last : match.start()])
                self.math(name, power)
                last = match.end()
        self.text(literal[last:])


def render_prose(
    template: str,
    names: Iterable[str] = (),
    fill: Mapping[str, str] | None = None,
    math_fields: Iterable[str] = (),
) -> Prose:
    """`template` with its `{field}`s filled from `fill` (a field in `math_fields` set as
    math, any other read as prose), the whole words in `names` set as math, and every caret
    power as a superscript."""
    fill = fill or {}
    fields = set(math_fields)
    words = frozenset(names) - _ENGLISH
    english = frozenset(names) & _ENGLISH
    out = _Builder()
    plain: list[str] = []
    parsed = string.Formatter().parse(template) if fill else [(template, None, None, None)]
    for literal, field_name, _spec, _conversion in parsed:
        plain.append(literal)
        out.prose(literal, words, english)
        if field_name is not None:
            value = fill[field_name]
            plain.append(value)
            if field_name in fields:
                out.math(value)
            else:  # an option's wording is prose too ("the potential V = m g z")
                out.prose(value, words, english)
    return Prose("".join(plain), "".join(out.md), "".join(out.html), "".join(out.tex))
