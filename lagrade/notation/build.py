"""Tree → sympy, through one whitelist: `SYMPY_CONSTRUCTORS` maps the tree's node kinds and the
function names a student may write to sympy constructors, and nothing else in the parser builds
sympy objects."""

from __future__ import annotations

import math
from collections.abc import Callable

import sympy as sp

from lagrade.notation.lexer import Source
from lagrade.notation.limits import MAX_EXPANDED_TERMS, MAX_EXPONENT, MAX_NUMBER_BITS
from lagrade.notation.nodes import Node

#: The only door from the parser to sympy: tree node kinds and function names → constructors.
SYMPY_CONSTRUCTORS: dict[str, Callable[..., sp.Expr]] = {
    "add": sp.Add,
    "mul": sp.Mul,
    "pow": sp.Pow,
    "integer": sp.Integer,
    "rational": sp.Rational,
    "pi": lambda: sp.pi,
    "sin": sp.sin,
    "cos": sp.cos,
    "tan": sp.tan,
    "sec": sp.sec,
    "csc": sp.csc,
    "cot": sp.cot,
    "sinh": sp.sinh,
    "cosh": sp.cosh,
    "tanh": sp.tanh,
    "asin": sp.asin,
    "acos": sp.acos,
    "atan": sp.atan,
    "arcsin": sp.asin,
    "arccos": sp.acos,
    "arctan": sp.atan,
    "exp": sp.exp,
    "ln": sp.log,
    "log": sp.log,  # the natural logarithm, as in physics texts (a warning says so)
    "sqrt": sp.sqrt,
    "abs": sp.Abs,
    "Abs": sp.Abs,
    "sign": sp.sign,
    "sgn": sp.sign,
    "asinh": sp.asinh,
    "acosh": sp.acosh,
    "atanh": sp.atanh,
    "arcsinh": sp.asinh,
    "arccosh": sp.acosh,
    "arctanh": sp.atanh,
    "arsinh": sp.asinh,
    "arcosh": sp.acosh,
    "artanh": sp.atanh,
    # x^(1/3), the principal root, as sympy's and mpmath's cbrt (not real for x < 0: the real
    # cube root of a negative x is -cbrt(-x))
    "cbrt": sp.cbrt,
    "atan2": sp.atan2,  # atan2(y, x): the angle of the point (x, y), in (-pi, pi]
    "arctan2": sp.atan2,
}
FUNCTIONS = frozenset(SYMPY_CONSTRUCTORS) - {"add", "mul", "pow", "integer", "rational", "pi"}
#: Functions of two arguments, written f(a, b); every other function takes one.
TWO_ARGUMENTS = frozenset({"atan2", "arctan2"})

NOT_FINITE = "The answer is not a finite real expression."
_BAD_VALUES = (sp.zoo, sp.nan, sp.oo, -sp.oo, sp.I)


def build(node: Node, src: Source) -> sp.Expr:
    """The sympy expression of a tree; a power too large to compute fails at its node."""
    kind = node.kind
    make = SYMPY_CONSTRUCTORS
    if kind == "sym":
        return node.value  # type: ignore[return-value]
    if kind == "num":
        p, q = node.value  # type: ignore[misc]
        return make["integer"](p) if q == 1 else make["rational"](p, q)
    if kind == "add":
        return make["add"](*[build(term, src) for term in node.value])  # type: ignore[union-attr]
    if kind == "mul":
        return make["mul"](*[_factor(f, src) for f in node.value])  # type: ignore[union-attr]
    if kind == "neg":
        inner = node.value
        if inner.kind == "mul":  # type: ignore[union-attr]
            return make["mul"](sp.S.NegativeOne, *[_factor(f, src) for f in inner.value])  # type: ignore[union-attr]
        return make["mul"](sp.S.NegativeOne, build(inner, src))  # type: ignore[arg-type]
    if kind == "pow":
        return _power(build(node.value, src), build(node.extra, src), node, src)  # type: ignore[arg-type]
    if kind == "call":
        argument, power = node.extra  # type: ignore[misc]
        if node.value in TWO_ARGUMENTS:  # atan2(y, x): a pair of nodes
            result = make[node.value](*(build(a, src) for a in argument))  # type: ignore[index]
        else:
            result = make[node.value](build(argument, src))  # type: ignore[index]
        return result if power is None else make["pow"](result, make["integer"](power))
    if kind == "pi":
        return make["pi"]()
    raise AssertionError(f"unknown node kind {kind!r}")


def _factor(node: Node, src: Source) -> sp.Expr:
    if node.kind == "inv":
        return _power(build(node.value, src), sp.S.NegativeOne, node, src)  # type: ignore[arg-type]
    return build(node, src)


def _power(base: sp.Expr, exponent: sp.Expr, node: Node, src: Source) -> sp.Expr:
    """base^exponent, refusing what would cost too much to compute or to multiply out (limits
    by cost: an exact number's size, a sum's expanded size), and roots of negative numbers."""
    if exponent.is_Rational:
        if abs(exponent) > MAX_EXPONENT:
            src.fail(
                f"Exponent too large: at most {MAX_EXPONENT:,} in absolute value.",
                node.start,
                node.end,
            )
        if exponent.is_Integer and _expanded_terms(base, abs(int(exponent))) > MAX_EXPANDED_TERMS:
            src.fail(
                "This power of a sum is too large to work with (multiplied out it would have "
                f"more than {MAX_EXPANDED_TERMS:,} terms).",
                node.start,
                node.end,
            )
        if base.is_Rational:
            if exponent.is_Integer:
                bits = max(abs(base.p).bit_length(), base.q.bit_length()) * abs(int(exponent))
                if bits > MAX_NUMBER_BITS:
                    src.fail(
                        "This power gives a number too large to work with.", node.start, node.end
                    )
            elif base.is_negative:
                src.fail(NOT_FINITE, node.start, node.end)
    return SYMPY_CONSTRUCTORS["pow"](base, exponent)


def _expanded_terms(base: sp.Expr, n: int) -> int:
    """How many terms base^n has multiplied out: C(n + k - 1, k - 1) for a sum of k terms."""
    k = len(sp.Add.make_args(base))
    if k == 1 or n <= 1:
        return 1
    return math.comb(n + k - 1, k - 1) if k <= 64 else MAX_EXPANDED_TERMS + 1


def check_finite(side: sp.Expr, node: Node | None, src: Source, imaginary: bool = False) -> None:
    """Refuse a side that evaluated to infinity, NaN or, in a question that does not declare
    the imaginary unit, an imaginary number (1/0, ln(0))."""
    if side.has(*(_BAD_VALUES[:-1] if imaginary else _BAD_VALUES)):
        start, end = (node.start, node.end) if node is not None else (0, len(src.text))
        src.fail(NOT_FINITE, start, end)
