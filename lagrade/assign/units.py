"""SI units as each format sets them: `m/s^2` is m/s² in Markdown and HTML and `\\mathrm{m/s^{2}}`
in LaTeX, never the raw caret (which LaTeX's text mode turns into a circumflex accent)."""

from __future__ import annotations

import re
from typing import Any

from markupsafe import Markup, escape

from lagrade.assign.templating import md_escape, tex_escape

#: A unit's tokens: a factor with an optional exponent (`s^2`, `s**-1`), `/`, `*`, parentheses,
#: or the space that multiplies two factors (`kg s^2`).
_TOKEN = re.compile(r"([A-Za-z]+)(?:\^|\*\*)?(-?\d+)?|([/*()])|(\s+)")
SUPERSCRIPT = str.maketrans(
    "-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079"
)


def _tokens(unit: str) -> list[tuple[str, str, str]] | None:
    """(kind, name, exponent) per token: a `factor`, `times`, `over`, `open` or `close`; None
    when the text is not a unit we can read (it is then shown as written, without carets)."""
    out: list[tuple[str, str, str]] = []
    position = 0
    for m in _TOKEN.finditer(unit):
        if m.start() != position:
            return None
        position = m.end()
        factor, op = m.group(1), m.group(3)
        if factor or op == "(":
            if out and out[-1][0] in ("factor", "close"):  # juxtaposition multiplies
                out.append(("times", "", ""))
        if factor:
            out.append(("factor", factor, m.group(2) or ""))
        elif op:
            out.append(({"*": "times", "/": "over", "(": "open", ")": "close"}[op], "", ""))
    return out if position == len(unit) else None


def unit_formats(unit: str) -> dict[str, Any]:
    """The unit in each format: `plain` as declared, `text` with Unicode superscripts (plain
    text), `md` the same made inert for Markdown (a unit is an instructor's text: `<img …>` in
    one is shown, never run, where the handout is pasted), `html` (safe markup), `tex` (a
    math-mode `\\mathrm{…}` for LaTeX)."""
    tokens = _tokens(unit.strip()) if unit.strip() else None
    if not tokens:
        fallback = unit.replace("^", "")
        return {
            "plain": unit,
            "text": fallback,
            "md": md_escape(fallback),
            "html": escape(fallback),
            "tex": tex_escape(fallback),
        }
    text, html, tex = [], [], []
    for kind, name, exponent in tokens:
        if kind == "factor":
            text.append(name + exponent.translate(SUPERSCRIPT))
            html.append(str(escape(name)) + (f"<sup>{exponent}</sup>" if exponent else ""))
            tex.append(name + (f"^{{{exponent}}}" if exponent else ""))
        else:
            mark = {"times": "\u00b7", "over": "/", "open": "(", "close": ")"}[kind]
            text.append(mark)
            html.append(mark)
            tex.append({"times": r"\cdot ", "over": "/", "open": "(", "close": ")"}[kind])
    return {
        "plain": unit,
        "text": "".join(text),
        "md": md_escape("".join(text)),
        "html": Markup("".join(html)),
        "tex": rf"$\mathrm{{{''.join(tex)}}}$",
    }


class Number(str):
    """A handout value as each format sets it: the plain text as the grader reads it back
    (`6.42e+23`, the `str` itself) and, for print, 6.42×10²³ (`.text`, Markdown), the same with
    <sup> in HTML and `6.42\\times10^{23}` (math mode) in LaTeX — never `e+23` on a page."""

    text: str
    html: Markup
    tex: str

    def __new__(cls, value: float) -> Number:
        plain = f"{value:g}"
        self = super().__new__(cls, plain)
        mantissa, _, exponent = plain.partition("e")
        if exponent:
            power = str(int(exponent))
            self.text = f"{mantissa}×10{power.translate(SUPERSCRIPT)}"
            self.html = Markup(f"{escape(mantissa)}×10<sup>{escape(power.replace('-', '−'))}</sup>")
            self.tex = f"{mantissa}\\times10^{{{power}}}"
        else:
            self.text, self.html, self.tex = plain, Markup(escape(plain)), plain
        return self
