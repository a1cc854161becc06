"""The typeset "read as" echo — LaTeX and presentation MathML — written from the parser's tree like
the plain echo (`echo`): the student's own terms in the student's order, every product shown
with a centred dot (`g·m·q·sin α`, so that `mgq` read as m·g·q is plain to see), velocities and
accelerations dotted, a division as a fraction of what the parser divided (`g/2 l` shows
(g/2)·l). sympy would reorder the terms and run the letters together.

Symbols are written by the one printer (`lagrade.notation.printer`), so a name looks here as it
does in the handout."""

from __future__ import annotations

from collections.abc import Iterable
from functools import lru_cache
from html import escape
from typing import Any

from markupsafe import Markup

import lagrade.notation.printer as printer
from lagrade.notation.echo import DECIMAL

_SUM, _PRODUCT, _SIGNED, _POWER, _ATOM = range(5)
_MATHML_NS = "http://www.w3.org/1998/Math/MathML"

#: The one name each function is typeset by (a student's spelling → its usual name).
_CANONICAL = {
    "asin": "arcsin", "acos": "arccos", "atan": "arctan", "asinh": "arsinh", "acosh": "arcosh",
    "atanh": "artanh", "arcsinh": "arsinh", "arccosh": "arcosh", "arctanh": "artanh",
    "log": "ln", "sgn": "sign", "Abs": "abs", "arctan2": "atan2", "Max": "max", "Min": "min",
}  # fmt: skip
#: Functions LaTeX has a command for (the others are set upright with \\operatorname).
_COMMANDS = frozenset(
    {"sin", "cos", "tan", "sec", "csc", "cot", "sinh", "cosh", "tanh", "arcsin", "arccos"}
    | {"arctan", "ln", "max", "min"}
)


def latex(node: Any, text: str) -> str:
    """LaTeX of one parsed side (a `nodes.Node`); `text` is the text it was read from."""
    return _Latex(text).render(node)[0]


def mathml(
    sides: Iterable[Any], text: str, coordinates: Iterable[str] = (), alternative: str = ""
) -> Markup:
    """A complete `<math>` element for the sides of an answer (one side, or lhs and rhs of an
    equation), safe to put in HTML; `alternative` is its text for a screen reader (the plain
    echo, as `printer.mathml` gives every formula its plain text)."""
    writer = _MathML(text, tuple(coordinates))
    rows = [writer.render(side)[0] for side in sides]
    inner = "<mo>=</mo>".join(rows)
    label = escape(alternative, quote=True)
    return Markup(
        f'<math xmlns="{_MATHML_NS}" display="inline" aria-label="{label}"><mrow>{inner}</mrow>'
        "</math>"
    )


class _Writer:
    """What the LaTeX and MathML writers share: the walk, binding strength, brackets."""

    def __init__(self, text: str):
        self.text = text

    def render(self, node: Any) -> tuple[str, int]:
        kind = node.kind
        if kind == "sym":
            return self.symbol(node), _ATOM
        if kind == "pi":
            return self.pi(), _ATOM
        if kind == "num":
            return self.number(node)
        if kind == "add":
            return self.sum(node.value), _SUM
        if kind == "mul":
            return self.product(node.value)
        if kind == "neg":
            return self.minus() + self.negated(node.value), _SIGNED
        if kind == "pow":
            return self.power(self.at_least(node.value, _ATOM), self.render(node.extra)[0]), _POWER
        if kind == "ddt":
            return self.time_derivative(node.extra[0], self.render(node.value)[0]), _ATOM
        if kind == "call":
            argument, power = node.extra
            arguments = (argument,) if hasattr(argument, "kind") else argument
            name = _CANONICAL.get(node.value, node.value)
            return self.call(name, [self.render(a)[0] for a in arguments], power), _ATOM
        raise AssertionError(f"unknown node kind {kind!r}")

    def at_least(self, node: Any, strength: int) -> str:
        shown, own = self.render(node)
        return shown if own >= strength else self.brackets(shown)

    def negated(self, node: Any) -> str:
        """What a minus sign stands before: bracketed where it binds more loosely than a
        product, or where it begins with a minus of its own (−(−q), not −−q)."""
        if _leading_minus(node):
            return self.brackets(self.render(node)[0])
        return self.at_least(node, _PRODUCT)

    def written(self, node: Any) -> str | None:
        """A number as typed (9.81, 1.6e-19), when it was typed as a decimal."""
        written = self.text[node.start : node.end].strip("() \t")
        return written if DECIMAL.fullmatch(written) else None

    def sum(self, terms: list) -> str:
        pieces = []
        for k, term in enumerate(terms):
            if term.kind == "neg":
                inner = self.negated(term.value)
                pieces.append(self.minus() + inner if k == 0 else self.op("-") + inner)
            elif k and _leading_minus(term):  # a + (−b·c), not a + −b·c
                pieces.append(self.op("+") + self.brackets(self.render(term)[0]))
            else:
                shown = self.render(term)[0]
                pieces.append(shown if k == 0 else self.op("+") + shown)
        return "".join(pieces)

    def product(self, factors: list) -> tuple[str, int]:
        """Factors left to right, each `inv` dividing what stands before it: a/b c is (a/b)·c.
        A product that is one fraction needs no brackets around it."""
        if factors[0].kind == "neg" and any(f.kind == "inv" for f in factors):
            # (−q)/l is shown −q/l, as its plain echo `-q/l` reads back: the sign before the bar
            shown = self.product([factors[0].value, *factors[1:]])[0]
            if _leading_minus(factors[0].value):
                shown = self.brackets(shown)
            return self.minus() + shown, _SIGNED
        # pieces as (shown, own binding strength, strength needed among dots)
        numerator: list[tuple[str, int, int]] = []
        denominator: list[tuple[str, int, int]] = []
        for factor in factors:
            if factor.kind == "inv":
                denominator.append((*self.render(factor.value), _PRODUCT))
                continue
            if denominator:
                numerator = [(self.over(numerator, denominator), _POWER, _POWER)]
                denominator = []
            # a number typed as 1.6e-19 shows as 1.6·10⁻¹⁹: a product, yet one among the dots
            needed = _PRODUCT if factor.kind == "num" else _SIGNED if not numerator else _POWER
            numerator.append((*self.render(factor), needed))
        if denominator:
            return self.over(numerator, denominator), _POWER
        return self.dotted(numerator), _PRODUCT

    def over(self, numerator: list, denominator: list) -> str:
        """A fraction: the bar groups, so one piece above or below it needs no brackets."""
        return self.fraction(self.dotted(numerator, alone=True), self.dotted(denominator, True))

    def dotted(self, pieces: list, alone: bool = False) -> str:
        if alone and len(pieces) == 1:
            return self.times([pieces[0][0]])
        return self.times([s if own >= needed else self.brackets(s) for s, own, needed in pieces])


class _Latex(_Writer):
    def symbol(self, node: Any) -> str:
        name = getattr(node.value, "name", None)
        if name is None:  # the declared imaginary unit, as the student spelled it
            return self.text[node.start : node.end]
        return _symbol_latex(name)

    def pi(self) -> str:
        return r"\pi"

    def number(self, node: Any) -> tuple[str, int]:
        written = self.written(node)
        if written is not None:
            mantissa, _, exponent = written.lower().partition("e")
            if not exponent:
                return written, _ATOM
            return rf"{mantissa} \cdot 10^{{{int(exponent)}}}", _PRODUCT
        p, q = node.value
        return (str(p), _ATOM) if q == 1 else (rf"\frac{{{p}}}{{{q}}}", _POWER)

    def minus(self) -> str:
        return "-"

    def op(self, sign: str) -> str:
        return f" {sign} "

    def brackets(self, shown: str) -> str:
        return rf"\left({shown}\right)"

    def times(self, factors: list[str]) -> str:
        return r" \cdot ".join(factors)

    def fraction(self, top: str, bottom: str) -> str:
        return rf"\frac{{{top}}}{{{bottom}}}"

    def power(self, base: str, exponent: str) -> str:
        return f"{base}^{{{exponent}}}"

    def time_derivative(self, order: int, inner: str) -> str:
        top, bottom = ("d", "dt") if order == 1 else (f"d^{{{order}}}", f"dt^{{{order}}}")
        return rf"\frac{{{top}}}{{{bottom}}}\left({inner}\right)"

    def call(self, name: str, arguments: list[str], power: int | None) -> str:
        if name == "sqrt":
            shown = rf"\sqrt{{{arguments[0]}}}"
        elif name == "cbrt":
            shown = rf"\sqrt[3]{{{arguments[0]}}}"
        elif name == "abs":
            shown = rf"\left|{arguments[0]}\right|"
        elif name == "exp":
            shown = f"e^{{{arguments[0]}}}"
        else:
            head = f"\\{name}" if name in _COMMANDS else rf"\operatorname{{{name}}}"
            if power is not None:
                return rf"{head}^{{{power}}}\left({', '.join(arguments)}\right)"
            return rf"{head}\left({', '.join(arguments)}\right)"
        return shown if power is None else rf"\left({shown}\right)^{{{power}}}"


class _MathML(_Writer):
    def __init__(self, text: str, coordinates: tuple[str, ...]):
        super().__init__(text)
        self.coordinates = coordinates

    def symbol(self, node: Any) -> str:
        name = getattr(node.value, "name", None)
        if name is None:
            return f"<mi>{escape(self.text[node.start : node.end])}</mi>"
        return _symbol_mathml(name, self.coordinates)

    def pi(self) -> str:
        return "<mi>&#960;</mi>"

    def number(self, node: Any) -> tuple[str, int]:
        written = self.written(node)
        if written is not None:
            mantissa, _, exponent = written.lower().partition("e")
            if not exponent:
                return f"<mn>{escape(written)}</mn>", _ATOM
            power = f"<msup><mn>10</mn><mn>{int(exponent)}</mn></msup>".replace("-", "&#8722;")
            return f"<mrow><mn>{mantissa}</mn><mo>&#183;</mo>{power}</mrow>", _PRODUCT
        p, q = node.value
        if q == 1:
            return f"<mn>{p}</mn>", _ATOM
        return f"<mfrac><mn>{p}</mn><mn>{q}</mn></mfrac>", _POWER

    def minus(self) -> str:
        return "<mo>&#8722;</mo>"

    def op(self, sign: str) -> str:
        return "<mo>&#8722;</mo>" if sign == "-" else "<mo>+</mo>"

    def brackets(self, shown: str) -> str:
        return f"<mrow><mo>(</mo>{shown}<mo>)</mo></mrow>"

    def times(self, factors: list[str]) -> str:
        return "<mrow>" + "<mo>&#183;</mo>".join(factors) + "</mrow>"

    def fraction(self, top: str, bottom: str) -> str:
        return f"<mfrac>{top}{bottom}</mfrac>"  # each one <mrow> (`times`)

    def power(self, base: str, exponent: str) -> str:
        return f"<msup><mrow>{base}</mrow><mrow>{exponent}</mrow></msup>"

    def time_derivative(self, order: int, inner: str) -> str:
        top, bottom = "<mi>d</mi>", "<mrow><mi>d</mi><mi>t</mi></mrow>"
        if order != 1:
            top = f"<msup><mi>d</mi><mn>{order}</mn></msup>"
            bottom = f"<mrow><mi>d</mi><msup><mi>t</mi><mn>{order}</mn></msup></mrow>"
        return f"<mfrac>{top}{bottom}</mfrac>" + self.brackets(inner)

    def call(self, name: str, arguments: list[str], power: int | None) -> str:
        if name == "sqrt":
            shown = f"<msqrt>{arguments[0]}</msqrt>"
        elif name == "cbrt":
            shown = f"<mroot><mrow>{arguments[0]}</mrow><mn>3</mn></mroot>"
        elif name == "abs":
            shown = f"<mrow><mo>|</mo>{arguments[0]}<mo>|</mo></mrow>"
        elif name == "exp":
            shown = f"<msup><mi>e</mi><mrow>{arguments[0]}</mrow></msup>"
        else:
            head = f"<mi>{escape(name)}</mi>"
            if power is not None:
                head = f"<msup>{head}<mn>{power}</mn></msup>"
            inner = "<mo>,</mo>".join(arguments)
            return f"<mrow>{head}{self.brackets(inner)}</mrow>"
        return shown if power is None else f"<msup>{self.brackets(shown)}<mn>{power}</mn></msup>"


def _leading_minus(node: Any) -> bool:
    """Whether a node is typeset beginning with a minus sign."""
    while node.kind == "mul":
        node = node.value[0]
    return node.kind == "neg"


@lru_cache(maxsize=1024)
def _symbol_latex(name: str) -> str:
    return printer.jet_name_latex(name)


@lru_cache(maxsize=1024)
def _symbol_mathml(name: str, coordinates: tuple[str, ...]) -> str:
    return printer.symbol_mathml(name, coordinates)
