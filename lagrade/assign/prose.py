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
        #: Markdown is assembled at the end (`markdown`): ("text", prose) and ("math", LaTeX)
        #: pieces, so that a formula's pieces become one $…$ span.
        self.pieces: list[tuple[str, str]] = []
        self.html: list[str] = []
        self.tex: list[str] = []

    def text(self, chunk: str) -> None:
        """Prose, with any caret power in it (`)^2`) set as a superscript."""
        self.pieces.append(("text", chunk))
        last = 0
        for m in _POWER.finditer(chunk):
            self._plain(chunk[last : m.start()])
            power = m.group("power")
            self.html.append(f"<sup>{escape(power)}</sup>")
            self.tex.append(f"$^{{{power}}}$")
            last = m.end()
        self._plain(chunk[last:])

    def _plain(self, chunk: str) -> None:
        self.html.append(str(escape(chunk)))
        self.tex.append(tex_escape(chunk))

    def markdown(self) -> str:
        """The Markdown: each formula one $…$ span (`$\\omega^{2} R > g$`, not `$\\omega^{2}$
        $R$ \\> $g$`), the prose around it escaped, caret powers in prose as superscripts."""
        return "".join(
            f"${latex}$" if kind == "math" else _md_prose(latex)
            for kind, latex in _formulas(self.pieces)
        )

    def math(self, name: str, power: str | None = None) -> None:
        symbol = sp.Symbol(name)
        expr = symbol if power is None else sp.Pow(symbol, int(power), evaluate=False)
        rendered = rm.render(expr)
        self.pieces.append(("math", rendered.latex))
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
    return Prose("".join(plain), out.markdown(), "".join(out.html), "".join(out.tex))


#: What joins the names of one formula in prose: spaces, digits, operators and brackets
#: (`omega^2 R > g`, `k (x^2 + y^2)/2`), never words or sentence punctuation.
_GLUE = re.compile(r"[ 0-9+\-*/=<>()^\u2212]*")


def _formulas(pieces: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """`pieces` with each formula joined into one math piece: a run of math pieces and the glue
    between them (prose of spaces, digits, operators, brackets), with a minus sign or opening
    bracket just before it, grown over the closing brackets and a trailing `/2` that its own
    brackets need; a run whose brackets cannot be closed so is shortened until they can (`$z$
    (z up)` stays apart)."""
    pieces = [p for p in pieces if p[1]]
    out: list[tuple[str, str]] = []
    i = 0
    while i < len(pieces):
        kind, text = pieces[i]
        if kind != "math":
            out.append((kind, text))
            i += 1
            continue
        before = out[-1][1] if out and out[-1][0] == "text" else ""
        lead = re.search(r"(?:^|(?<=[ =(]))[-\u2212]?\(*$", before)
        last, prefix, latex, end = _run(pieces, i, lead.group() if lead else "")
        if prefix:
            out[-1] = ("text", before[: len(before) - len(prefix)])
        out.append(("math", latex))
        i = last + 1
        if end:
            pieces[i] = ("text", pieces[i][1][end:])
    return [p for p in out if p[1]]


def _run(pieces: list[tuple[str, str]], first: int, lead: str) -> tuple[int, str, str, int]:
    """The longest formula from pieces[first] (math): (index of its last piece, the prose
    before it that it took, its LaTeX, how many characters of the next piece it took). With
    `lead` (a minus sign and brackets just before it) when its brackets close with it."""
    last = first
    while last + 2 < len(pieces) and pieces[last + 2][0] == "math":
        if not _GLUE.fullmatch(pieces[last + 1][1]):
            break
        last += 2
    for prefix in dict.fromkeys((lead, "")):
        for end_at in range(last, first - 1, -2):
            body = "".join(
                t if k == "math" else _glue_latex(t) for k, t in pieces[first : end_at + 1]
            )
            latex = _glue_latex(prefix) + body
            opened = latex.count("(") - latex.count(")")
            after = pieces[end_at + 1][1] if end_at + 1 < len(pieces) else ""
            end = _balanced_end(after, opened) if opened > 0 else 0
            if opened == 0 or end:
                return end_at, prefix, latex + _glue_latex(after[:end]), end
    return first, "", pieces[first][1], 0


def _balanced_end(text: str, opened: int) -> int:
    """How much of `text` (glue only) closes `opened` brackets, with a `/2` or `^2` after;
    0 when it cannot."""
    for at, ch in enumerate(text):
        if not _GLUE.fullmatch(ch):
            return 0
        opened += (ch == "(") - (ch == ")")
        if opened == 0:
            tail = re.match(r"(?:[/^]-?\d+)?", text[at + 1 :])
            return at + 1 + (tail.end() if tail else 0)
    return 0


def _glue_latex(glue: str) -> str:
    """Prose glue inside a formula: a caret power braced, a minus sign as LaTeX's."""
    glue = glue.replace("\u2212", "-")
    return re.sub(r"\^(-?\d+)", r"^{\1}", glue)


def _md_prose(chunk: str) -> str:
    """Prose in Markdown: escaped, with a caret power as a superscript (`(x + y)²`)."""
    out, last = [], 0
    for m in _POWER.finditer(chunk):
        out.append(md_escape(chunk[last : m.start()]))
        power = m.group("power")
        out.append(power.translate(SUPERSCRIPT) if power[-1].isdigit() else f"^{power}")
        last = m.end()
    out.append(md_escape(chunk[last:]))
    return "".join(out)
