"""Tree → sympy, through one whitelist: `SYMPY_CONSTRUCTORS` maps the tree's node kinds and the
function names a student may write to sympy constructors, and nothing else in the parser builds
sympy objects."""

from __future__ import annotations

import math
from collections.abc import Callable

import sympy as sp

from lagrade.mechanics import total_derivative
from lagrade.notation.lexer import Source
from lagrade.notation.limits import (
    MAX_DERIVATIVE_NODES,
    MAX_EXPANDED_TERMS,
    MAX_EXPONENT,
    MAX_NUMBER_BITS,
)
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
    # Max(a, b, …), Min(a, b, …): left unevaluated, since sympy compares every pair of arguments
    # when it builds them (40 ms for two, seconds for a dozen); the judge evaluates them itself
    "Max": lambda *args: sp.Max(*args, evaluate=False),
    "Min": lambda *args: sp.Min(*args, evaluate=False),
    "max": lambda *args: sp.Max(*args, evaluate=False),
    "min": lambda *args: sp.Min(*args, evaluate=False),
}
FUNCTIONS = frozenset(SYMPY_CONSTRUCTORS) - {"add", "mul", "pow", "integer", "rational", "pi"}
#: Functions of two arguments, written f(a, b).
TWO_ARGUMENTS = frozenset({"atan2", "arctan2"})
#: Functions of two or more arguments, written f(a, b, …); every other function takes one.
SEVERAL_ARGUMENTS = frozenset({"Max", "Min", "max", "min"})
#: Functions whose node holds a tuple of arguments.
TUPLE_ARGUMENTS = TWO_ARGUMENTS | SEVERAL_ARGUMENTS

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
        if node.value in TUPLE_ARGUMENTS:  # atan2(y, x), Max(a, b, c): a tuple of nodes
            result = make[node.value](*(build(a, src) for a in argument))  # type: ignore[index]
        else:
            result = make[node.value](build(argument, src))  # type: ignore[index]
        return result if power is None else make["pow"](result, make["integer"](power))
    if kind == "pi":
        return make["pi"]()
    if kind == "ddt":
        return _time_derivative(node, src)
    raise AssertionError(f"unknown node kind {kind!r}")


#: What a time derivative must not contain to be evaluated: sign's derivative (the derivative of
#: |x| is sign(x) ẋ, which is fine), Max's and Min's are distributions sympy leaves as such.
_NOT_DIFFERENTIABLE = (sp.Derivative, sp.Subs, sp.DiracDelta, sp.Heaviside)


def _time_derivative(node: Node, src: Source) -> sp.Expr:
    """d/dt(expr), d^2/dt^2(expr), diff(expr, t): D_t on the jets (design.md),
    D_t = ∂_t + Σ q̇ ∂_q + Σ q̈ ∂_q̇, as often as the order says. A third derivative has no
    symbol (d/dt of an acceleration is refused), and what the product rule would write out is
    bounded before it is written (MAX_DERIVATIVE_NODES)."""
    order, time, jets = node.extra  # type: ignore[misc]
    expr = build(node.value, src)  # type: ignore[arg-type]
    for _ in range(order):
        accelerations = [j.ddot.name for j in jets if expr.has(j.ddot)]
        if accelerations:
            src.fail(
                f"This time derivative would be a third derivative: what it differentiates "
                f"holds an acceleration ({', '.join(accelerations)}), and only velocities and "
                "accelerations exist here.",
                node.start,
                node.end,
            )
        if derivative_size(expr) > MAX_DERIVATIVE_NODES:
            src.fail(
                "This time derivative is too large to work out (the product rule would write "
                f"more than {MAX_DERIVATIVE_NODES:,} terms and factors); differentiate it by "
                "hand, or a smaller expression.",
                node.start,
                node.end,
            )
        expr = total_derivative(expr, jets, time)
    if expr.has(*_NOT_DIFFERENTIABLE):
        src.fail(
            "This time derivative cannot be worked out: sign, Max and Min have no derivative "
            "where they jump or bend; write the derivative itself.",
            node.start,
            node.end,
        )
    return expr


def derivative_size(expr: sp.Expr) -> int:
    """An upper estimate of the nodes D_t(expr) writes out, from the product and chain rules:
    d(a·b·c) = da·b·c + a·db·c + a·b·dc repeats every other factor; f(a)' = f'(a)·da copies
    the function. Computed in one pass over the tree, before any differentiating."""
    return _sizes(expr)[1]


def _sizes(expr: sp.Basic) -> tuple[int, int]:
    """(nodes of expr, estimated nodes of its derivative)."""
    if not expr.args:
        return 1, 1
    parts = [_sizes(a) for a in expr.args]
    size = 1 + sum(p[0] for p in parts)
    if isinstance(expr, sp.Add):
        return size, 1 + sum(p[1] for p in parts)
    if isinstance(expr, sp.Mul):
        return size, 1 + sum(d + size - s for s, d in parts)
    return size, size + 2 + sum(p[1] for p in parts)  # f'(a)·da: a copy of f, and da


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
