"""Whether a derived expression is identically zero, decided by its values: the facts of a system
(a cyclic coordinate, ∂L/∂q_j ≡ 0; a Lagrangian without explicit time, ∂L/∂t ≡ 0) must not
depend on how sympy happened to print L. A potential written in the bodies' Cartesian coordinates
keeps sqrt(r² sin²θ + r² cos²θ), in which θ is printed but absent; `L.has(theta)` says "not
cyclic", the values say cyclic.

The rule. The expression is evaluated with mpmath at `POINTS` seeded points inside the ranges of
its symbols, at `LOW_DIGITS` and again at `HIGH_DIGITS` significant digits (the points are exact
binary numbers, so both evaluations see the same point; a low value of exactly 0 is taken again
at a middle precision). At a point the value is *rounding noise* when it shrinks with the
precision (|v_high| ≤ `SHRINK` · |v_low|) or is negligible against the size of its terms
(|v_high| ≤ `NEGLIGIBLE` · size, the size summing the sizes of the terms of every sum in it, so
that no cancellation hides it); a value that is not noise at any point is a proof, up to
evaluation error far below these tolerances, that the expression is not zero there. The
expression is identically zero when it is noise at every point that has a value (at least
`MIN_POINTS` of them), or structurally 0: a true nonzero value would have to lie some 38 digits
below the size of its terms at every random point to pass, while a true zero's rounding error
drops by 40 orders between the two precisions (20 under a square root). This is the
confirmation the facts need: a decision that is exact for the expressions scenes derive, in
milliseconds, where a symbolic simplification can take minutes.

What is evaluated here is only ever derived by lagrade (∂L/∂q of a scene's L, which the safe
reader built); it is walked node by node, never compiled or run as code.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Mapping
from functools import lru_cache

import mpmath
import sympy as sp

#: Seeded points per decision, and the fewest at which the expression must have a value.
POINTS = 6
MIN_POINTS = 3
#: Working precisions (significant decimal digits) of the two evaluations.
LOW_DIGITS = 30
HIGH_DIGITS = 70
#: A value that shrinks by this factor from the low to the high precision is rounding noise (a
#: true zero's shrinks by 10⁻⁴⁰, 10⁻²⁰ under a square root; a nonzero value's does not unless it
#: lies 38 digits below the size of its terms).
SHRINK = 1e-8
#: A value this small against the sum of its terms' sizes is rounding noise.
NEGLIGIBLE = 1e-45
#: Where a symbol without a given range is drawn: a positive one in (0.5, 3), any other in
#: ±(0.2, 2.5) (both signs of sin and cos of an angle, away from 0 where many expressions are
#: special).
POSITIVE_RANGE = (0.5, 3.0)
REAL_RANGE = (-2.5, 2.5)

Ranges = Mapping[sp.Symbol, tuple[float, float]]

_FUNCTIONS = {
    sp.sin: mpmath.sin,
    sp.cos: mpmath.cos,
    sp.tan: mpmath.tan,
    sp.sec: mpmath.sec,
    sp.csc: mpmath.csc,
    sp.cot: mpmath.cot,
    sp.asin: mpmath.asin,
    sp.acos: mpmath.acos,
    sp.atan: mpmath.atan,
    sp.sinh: mpmath.sinh,
    sp.cosh: mpmath.cosh,
    sp.tanh: mpmath.tanh,
    sp.asinh: mpmath.asinh,
    sp.acosh: mpmath.acosh,
    sp.atanh: mpmath.atanh,
    sp.exp: mpmath.exp,
    sp.log: mpmath.log,
    sp.Abs: abs,
    sp.sign: mpmath.sign,
}


class _Undefined(Exception):
    """The expression has no finite value at this point (a pole, 0/0)."""


def _value(expr: sp.Basic, point: Mapping[sp.Symbol, mpmath.mpf], memo: dict) -> object:
    """expr at `point` in mpmath's current precision (real or complex)."""
    found = memo.get(expr)
    if found is not None:
        return found
    if expr.is_Symbol:
        value = point[expr]
    elif expr.is_Integer:
        value = mpmath.mpf(int(expr))
    elif expr.is_Rational:
        value = mpmath.mpf(expr.p) / expr.q
    elif not expr.free_symbols:
        value = expr._to_mpmath(mpmath.mp.prec)  # decimals and constants (pi, sqrt(2))
    elif expr.is_Add:
        value = mpmath.fsum(_value(a, point, memo) for a in expr.args)
    elif expr.is_Mul:
        value = mpmath.fprod(_value(a, point, memo) for a in expr.args)
    elif expr.is_Pow:
        base, exponent = (_value(a, point, memo) for a in expr.args)
        value = mpmath.power(base, exponent)
    elif expr.func in _FUNCTIONS:
        value = _FUNCTIONS[expr.func](*(_value(a, point, memo) for a in expr.args))
    elif expr.func is sp.atan2:
        y, x = (_value(a, point, memo) for a in expr.args)
        value = mpmath.atan2(y, x)
    else:  # a function the table lacks: sympy's own evaluation at the point
        at = {s: sp.Float(point[s], mpmath.mp.dps) for s in expr.free_symbols}
        value = mpmath.mpmathify(complex(expr.xreplace(at).evalf(mpmath.mp.dps)))
    if not mpmath.isfinite(value):
        raise _Undefined
    memo[expr] = value
    return value


def sample_points(
    symbols: Iterable[sp.Symbol], ranges: Ranges | None = None, seed: int = 0, n: int = POINTS
) -> list[dict[sp.Symbol, float]]:
    """`n` seeded points: each symbol uniform in its range (given, else by its sign assumption;
    a range that straddles 0 keeps |x| ≥ 0.2)."""
    rng = random.Random(seed)
    ordered = sorted(set(symbols), key=str)
    points = []
    for _ in range(n):
        point = {}
        for s in ordered:
            lo, hi = (ranges or {}).get(s) or (POSITIVE_RANGE if s.is_positive else REAL_RANGE)
            x = rng.uniform(lo, hi)
            if lo < 0 < hi and abs(x) < 0.2:
                x = (0.2 + rng.uniform(0, 0.3)) * (1 if x >= 0 else -1)
            point[s] = x
        points.append(point)
    return points


def _size(expr: sp.Basic, point: Mapping, memo: dict) -> mpmath.mpf:
    """The size of expr's value without cancellation: sums of sizes for sums, products for
    products, |value| for anything else (what rounding errors are measured against)."""
    if expr.is_Add:
        return mpmath.fsum(_size(a, point, memo) for a in expr.args)
    if expr.is_Mul:
        return mpmath.fprod(_size(a, point, memo) for a in expr.args)
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
        return _size(expr.base, point, memo) ** int(expr.exp)
    return abs(_value(expr, point, memo))


def _at(expr: sp.Expr, point: Mapping[sp.Symbol, float], digits: int, memo: dict) -> object:
    with mpmath.workdps(digits):
        return _value(expr, {s: mpmath.mpf(x) for s, x in point.items()}, memo)


def _noise_at(expr: sp.Expr, point: Mapping[sp.Symbol, float]) -> bool:
    """Whether expr's value at `point` is rounding noise (see the module's rule); _Undefined
    when it has no value there. A low-precision value that is exactly 0 says nothing of how
    the noise shrinks: the middle precision stands in for it."""
    low = _at(expr, point, LOW_DIGITS, {})
    if low == 0:
        low = _at(expr, point, (LOW_DIGITS + HIGH_DIGITS) // 2, {})
    memo: dict = {}
    high = _at(expr, point, HIGH_DIGITS, memo)
    if high == 0:
        return True
    with mpmath.workdps(HIGH_DIGITS):
        size = _size(expr, {s: mpmath.mpf(x) for s, x in point.items()}, memo)
    return abs(high) <= SHRINK * abs(low) or abs(high) <= NEGLIGIBLE * size


def identically_zero(expr: sp.Expr, ranges: Ranges | None = None, seed: int = 0) -> bool:
    """Whether `expr` (derived by lagrade, never a student's text) is zero for every value of
    its symbols in their ranges, decided by its values at seeded points (the module's rule).

    >>> theta, r = sp.symbols("theta r", real=True)
    >>> identically_zero(sp.sin(2 * theta) - 2 * sp.sin(theta) * sp.cos(theta))
    True
    >>> identically_zero(sp.sin(2 * theta) - sp.sin(theta) * sp.cos(theta))
    False
    """
    expr = sp.Integer(expr) if isinstance(expr, int) else expr
    if expr == 0:
        return True
    if not expr.free_symbols:
        return False  # a nonzero constant
    # Only the ranges of expr's own symbols are read (`sample_points`): the key holds those.
    given = ranges or {}
    own = tuple((s, tuple(given[s])) for s in sorted(expr.free_symbols, key=str) if given.get(s))
    return _decided(expr, own, seed)


@lru_cache(maxsize=2_048)
def _decided(expr: sp.Expr, ranges: tuple, seed: int) -> bool:
    """`identically_zero`'s decision, once per process for an expression and its symbols'
    ranges: every variant of a scene asks it of the same derived expressions (measured: a
    tenth of grading a class's sheets before it was kept)."""
    counted = 0
    for point in sample_points(expr.free_symbols, dict(ranges), seed):
        try:
            if not _noise_at(expr, point):
                return False
        except (_Undefined, ZeroDivisionError, ValueError, OverflowError, TypeError):
            continue
        counted += 1
    return counted >= MIN_POINTS


def depends_on(expr: sp.Expr, symbol: sp.Symbol, ranges: Ranges | None = None) -> bool:
    """Whether `expr` depends on `symbol`: it contains it and ∂expr/∂symbol is not identically
    zero by values."""
    return expr.has(symbol) and not identically_zero(sp.diff(expr, symbol), ranges)


#: Values tried for a symbol that is printed but absent, simplest first.
_STAND_INS = (sp.S.Zero, sp.S.One, sp.Rational(1, 2), sp.S(2))


def without_absent(
    expr: sp.Expr, symbols: Iterable[sp.Symbol], ranges: Ranges | None = None
) -> sp.Expr:
    """expr written without each of `symbols` it contains but does not depend on (∂/∂s ≡ 0 by
    values): s replaced by a simple value at which expr is defined, kept only when the result
    equals expr by values (a sign(q), whose derivative vanishes wherever it has one, keeps q).
    So sqrt(r² sin²θ + r² cos²θ) becomes |r| and m g l (sin²φ + cos²φ) becomes m g l."""
    result = expr
    for s in symbols:
        if not result.has(s) or depends_on(result, s, ranges):
            continue
        for value in _STAND_INS:
            candidate = sp.expand(result.xreplace({s: value}))
            if candidate.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
                continue
            if identically_zero(result - candidate, ranges):
                result = candidate
                break
    return result
