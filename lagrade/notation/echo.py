"""The plain "interpreted as" echo, written from the parser's own tree: the student's terms in the
student's order, with every product made explicit (`*`), powers as `^`, and brackets exactly
where the reading needs them — `1/2 m x_dot^2` echoes `1/2*m*x_dot^2`, `(g/R) sin θ` echoes
`g/R*sin(theta)`, `θ̇` echoes `theta_dot`.

Why from the tree and not from sympy: the echo exists so that a student can check how the text
was read, which sympy's reordered, simplified printout hides; and printing a sympy tree costs
about half a millisecond per answer, more than judging it. The echo reads back to the same
expression (a property test checks this).
"""

from __future__ import annotations

import re
from typing import Any

from lagrade.notation.build import TUPLE_ARGUMENTS

# Binding strength: a sub-expression is bracketed when it binds more loosely than its place needs.
_SUM, _PRODUCT, _SIGNED, _POWER, _ATOM = range(5)
DECIMAL = re.compile(r"\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?")


def echo(node: Any, text: str) -> str:
    """The plain echo of one parsed side (a `nodes.Node`); `text` is the text it was read from."""
    return _render(node, text)[0]


def _render(node: Any, text: str) -> tuple[str, int]:
    """(text, binding strength) of a node."""
    kind = node.kind  # the kinds by how often they occur
    if kind == "sym":  # a symbol, or the declared imaginary unit as the student spelled it
        return getattr(node.value, "name", None) or text[node.start : node.end], _ATOM
    if kind == "num":
        return _number(node, text)
    if kind == "pow":
        base = _at_least(node.value, text, _ATOM)
        exponent = _at_least(node.extra, text, _ATOM)
        return f"{base}^{exponent}", _POWER
    if kind == "mul":
        return _product(node.value, text), _PRODUCT
    if kind == "add":
        return _sum(node.value, text), _SUM
    if kind == "neg":
        return "-" + _negated(node.value, text), _SIGNED
    if kind == "call":
        argument, power = node.extra
        arguments = argument if node.value in TUPLE_ARGUMENTS else (argument,)
        call = f"{node.value}({', '.join(_render(a, text)[0] for a in arguments)})"
        return (f"{call}^{power}", _POWER) if power is not None else (call, _ATOM)
    if kind == "pi":
        return "pi", _ATOM
    if kind == "ddt":
        operator = "d/dt" if node.extra[0] == 1 else f"d^{node.extra[0]}/dt^{node.extra[0]}"
        return f"{operator}({_render(node.value, text)[0]})", _ATOM
    raise AssertionError(f"unknown node kind {kind!r}")


def _at_least(node: Any, text: str, strength: int) -> str:
    if node.kind == "sym":  # the commonest factor, an atom: never bracketed
        return getattr(node.value, "name", None) or text[node.start : node.end]
    shown, own = _render(node, text)
    return shown if own >= strength else f"({shown})"


def _negated(node: Any, text: str) -> str:
    """What a minus sign stands before: bracketed where it binds more loosely than a product,
    or where it begins with a minus of its own (`-(-x*y)`: `--x*y` would read as -((-(-x))*y))."""
    shown, own = _render(node, text)
    return f"({shown})" if own < _PRODUCT or shown.startswith("-") else shown


def _number(node: Any, text: str) -> tuple[str, int]:
    """A number as written (9.81, 1.6e-19, 1E100), else p or p/q (from a translation)."""
    p, q = node.value
    written = text[node.start : node.end].strip("() \t")
    if written.isdecimal() or DECIMAL.fullmatch(written):  # isdecimal: what \d+ matches
        return written, _ATOM
    return (str(p), _ATOM) if q == 1 else (f"{p}/{q}", _PRODUCT)


def _sum(terms: list, text: str) -> str:
    pieces = []
    for k, term in enumerate(terms):
        if term.kind == "neg":
            inner = _negated(term.value, text)
            pieces.append(f"-{inner}" if k == 0 else f" - {inner}")
        else:
            shown = _render(term, text)[0]
            pieces.append(shown if k == 0 else f" + {shown}")
    return "".join(pieces)


def _product(factors: list, text: str) -> str:
    pieces = []
    for k, factor in enumerate(factors):
        if factor.kind == "inv":
            pieces.append("/" + _at_least(factor.value, text, _POWER))
        elif k == 0 and factor.kind == "neg" and factor.value.kind in ("add", "neg", "mul"):
            # `(-(a + b))*c` is not `-(a + b)*c` once read: sympy distributes the sign over the
            # sum in the first and not in the second, so the echo would read back differently;
            # and `-(-q)*q` reads back as -((-q)*q), another tree from (-(-q))*q.
            pieces.append(f"({_render(factor, text)[0]})")
        elif k == 0:
            pieces.append(_at_least(factor, text, _SIGNED))
        else:
            pieces.append("*" + _at_least(factor, text, _POWER))
    return "".join(pieces)
