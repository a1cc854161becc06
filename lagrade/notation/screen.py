"""Which trees need sympy before they can be trusted, and which do not.

A parsed answer is built into a sympy expression only when a step needs one (display, a
diagnosis, algebra); the judge compiles the tree itself. But sympy also has the last word on
what an answer *is*: its automatic evaluation finds 1/(x − x), log(0), sqrt(−1) and powers too
large to compute, which `build` refuses. So an answer is left unbuilt only when this screen is
sure sympy would refuse nothing; otherwise it is built at once and checked as before — the same
errors for the same answers, whichever way the answer went.

The screen evaluates the tree at two generic points (every symbol a different positive number,
as no symbol may be negative by its assumptions) and asks for sympy when anything could
evaluate to something sympy refuses: a value that is not finite (or not real, in a question
without the imaginary unit), a sum that cancels, a product that is exactly 0, a function of a
constant (sin(pi), where sympy knows exact values), a power past the cheap range, a time
derivative (`build` works it out in sympy)."""

from __future__ import annotations

import cmath
import math
import zlib
from fractions import Fraction
from functools import lru_cache

from lagrade.notation.limits import MAX_EXPANDED_TERMS, MAX_NUMBER_BITS
from lagrade.notation.nodes import Node

#: Powers a tree may hold and still be screened (a larger one is sympy's to judge).
SMALL_EXPONENT = 64
#: A sum this small against its terms has cancelled (x − x, 2x − x − x): sympy would make it 0.
CANCELLED = 1e-8


class _Sympy(Exception):
    """This tree goes to sympy."""


def needs_sympy(sides: tuple[Node | None, ...], imaginary: bool = False) -> bool:
    """Whether the tree of an answer (its sides) must be built and checked by sympy now."""
    try:
        for side in sides:
            if side is not None:
                _structure(side)
                _values(side, imaginary)
    except (_Sympy, ValueError, ZeroDivisionError, OverflowError, TypeError, RecursionError):
        return True
    return False


def _generic(name: str, point: int) -> float:
    """A positive value of the symbol `name` at generic point 0 or 1, the same every run."""
    h = zlib.crc32(f"{point}:{name}".encode())
    return 0.55 + (h % 100_003) / 100_003  # in (0.55, 1.55)


@lru_cache(maxsize=4_096)  # a question has a few dozen names: each is hashed once
def _generic_pair(name: str) -> tuple[float, float]:
    """The symbol's values at both generic points."""
    return _generic(name, 0), _generic(name, 1)


# --- structure ------------------------------------------------------------------------------------


def _structure(node: Node) -> None:
    kind = node.kind
    if kind == "ddt":
        raise _Sympy
    if kind in ("add", "mul"):
        for child in node.value:  # type: ignore[union-attr]
            _structure(child)
    elif kind in ("neg", "inv"):
        _structure(node.value)  # type: ignore[arg-type]
    elif kind == "pow":
        _structure(node.value)  # type: ignore[arg-type]
        _structure(node.extra)  # type: ignore[arg-type]
        _power(node)
    elif kind == "call":
        argument = node.extra[0]  # type: ignore[index]
        arguments = (argument,) if hasattr(argument, "kind") else argument
        for a in arguments:
            _structure(a)
        if all(constant(a) for a in arguments):
            _constant_call(node.value, arguments)  # type: ignore[arg-type]


def _power(node: Node) -> None:
    """A power whose cost `build._power` would weigh: small exponents of screened bases only."""
    extra: Node = node.extra  # type: ignore[assignment]
    if extra.kind == "num" and extra.value[1] == 1 and not constant(node.value):  # type: ignore
        _integer_power_of_symbols(node.value, extra.value[0])  # type: ignore
        return  # the usual x^2, as below without making Fractions
    exponent = fold(extra)  # type: ignore[arg-type]
    if exponent is None:
        if constant(node.extra):  # 2^sqrt(2): a constant sympy may make rational
            raise _Sympy
        return
    if abs(exponent) > SMALL_EXPONENT:
        raise _Sympy
    base = node.value
    if constant(base):  # type: ignore[arg-type]
        if base.kind == "pi":  # type: ignore[union-attr]
            return
        value = fold(base)  # type: ignore[arg-type]
        if value is None or value < 0 and exponent.denominator != 1:
            raise _Sympy
        if value == 0 and exponent < 0:
            raise _Sympy
        bits = max(abs(value.numerator).bit_length(), value.denominator.bit_length())
        if bits * abs(exponent) > MAX_NUMBER_BITS:
            raise _Sympy
        return
    if exponent.denominator == 1:
        _integer_power_of_symbols(base, int(exponent))  # type: ignore[arg-type]


def _integer_power_of_symbols(base: Node, n: int) -> None:
    """A power of a base with a symbol in it to the integer n: one whose expansion would
    hold more than MAX_EXPANDED_TERMS terms is sympy's to weigh."""
    if abs(n) > SMALL_EXPONENT:
        raise _Sympy
    if abs(n) > 1:
        k = _terms(base)
        if k > 1 and math.comb(abs(n) + k - 1, k - 1) > MAX_EXPANDED_TERMS:
            raise _Sympy


def _terms(node: Node) -> int:
    """At least as many top-level terms as sympy's form of the node has (sums flattened, a
    number times a sum distributed)."""
    if node.kind == "add":
        return sum(_terms(t) for t in node.value)  # type: ignore[union-attr]
    if node.kind == "neg":
        return _terms(node.value)  # type: ignore[arg-type]
    if node.kind == "mul":
        rest = [f for f in node.value if not constant(f)]  # type: ignore[union-attr]
        if len(rest) == 1 and rest[0].kind in ("add", "neg"):
            return _terms(rest[0])
    return 1


#: Functions of a constant whose sympy value is that function of it, nothing sympy refuses.
_SAFE_OF_RATIONAL = {
    "sqrt": lambda v: v > 0,
    "cbrt": lambda v: v > 0,
    "exp": lambda v: True,
    "ln": lambda v: v > 0 and v != 1,
    "log": lambda v: v > 0 and v != 1,
}


def _constant_call(name: str, arguments: tuple) -> None:
    test = _SAFE_OF_RATIONAL.get(name)
    value = fold(arguments[0]) if test is not None and len(arguments) == 1 else None
    if value is None or not test(value):  # type: ignore[misc]
        raise _Sympy


def constant(node: Node) -> bool:
    """Whether the node holds no symbol (the declared imaginary unit is a number)."""
    kind = node.kind
    if kind in ("num", "pi"):
        return True
    if kind == "sym":
        return not getattr(node.value, "is_Symbol", False)
    if kind in ("add", "mul"):
        return all(constant(n) for n in node.value)  # type: ignore[union-attr]
    if kind in ("neg", "inv"):
        return constant(node.value)  # type: ignore[arg-type]
    if kind == "pow":
        return constant(node.value) and constant(node.extra)  # type: ignore[arg-type]
    if kind == "call":
        argument = node.extra[0]  # type: ignore[index]
        return all(constant(a) for a in ((argument,) if hasattr(argument, "kind") else argument))
    return False


def fold(node: Node) -> Fraction | None:
    """The exact rational value of a node of numbers, +, −, ×, / and integer powers up to
    SMALL_EXPONENT, or None."""
    kind = node.kind
    if kind == "num":
        p, q = node.value  # type: ignore[misc]
        return Fraction(p, q)
    if kind == "neg":
        inner = fold(node.value)  # type: ignore[arg-type]
        return None if inner is None else -inner
    if kind == "add":
        values = [fold(t) for t in node.value]  # type: ignore[union-attr]
        return None if None in values else sum(values, Fraction(0))  # type: ignore[arg-type]
    if kind == "mul":
        total = Fraction(1)
        for factor in node.value:  # type: ignore[union-attr]
            value = fold(factor.value if factor.kind == "inv" else factor)
            if value is None or (factor.kind == "inv" and value == 0):
                return None
            total *= 1 / value if factor.kind == "inv" else value
        return total
    if kind == "pow":
        base, exponent = fold(node.value), fold(node.extra)  # type: ignore[arg-type]
        if base is None or exponent is None or exponent.denominator != 1:
            return None
        n = int(exponent)
        if abs(n) > SMALL_EXPONENT or (base == 0 and n < 0):
            return None
        return base**n
    return None


# --- values at generic points ---------------------------------------------------------------------

_REAL = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "sinh": math.sinh, "cosh": math.cosh,
    "tanh": math.tanh, "asin": math.asin, "acos": math.acos, "atan": math.atan,
    "arcsin": math.asin, "arccos": math.acos, "arctan": math.atan, "exp": math.exp,
    "ln": math.log, "log": math.log, "sqrt": math.sqrt, "asinh": math.asinh,
    "acosh": math.acosh, "atanh": math.atanh, "arcsinh": math.asinh, "arccosh": math.acosh,
    "arctanh": math.atanh, "arsinh": math.asinh, "arcosh": math.acosh, "artanh": math.atanh,
    "abs": abs, "Abs": abs,
    "sec": lambda x: 1 / math.cos(x), "csc": lambda x: 1 / math.sin(x),
    "cot": lambda x: 1 / math.tan(x),
    "sign": lambda x: math.copysign(1.0, x) if x else 0.0,
    "cbrt": lambda x: x ** (1 / 3) if x > 0 else _refuse(),
}  # fmt: skip
_SGN = {"sgn": "sign"}
_COMPLEX = {
    "sin": cmath.sin, "cos": cmath.cos, "tan": cmath.tan, "sinh": cmath.sinh,
    "cosh": cmath.cosh, "tanh": cmath.tanh, "exp": cmath.exp, "ln": cmath.log,
    "log": cmath.log, "sqrt": cmath.sqrt, "abs": abs, "Abs": abs,
}  # fmt: skip


def _refuse():
    raise _Sympy


def _values(node: Node, imaginary: bool) -> tuple:
    """The node's values at both generic points, in one walk (each point's arithmetic as if
    alone: the same operations in the same order); raises where sympy could see what the
    screen cannot (see the module)."""
    kind = node.kind
    if kind == "num":
        p, q = node.value  # type: ignore[misc]
        v = p / q
        return v, v
    if kind == "pi":
        return _PI
    if kind == "sym":
        symbol = node.value
        if not getattr(symbol, "is_Symbol", False):
            return _I  # the declared imaginary unit
        return _generic_pair(symbol.name)  # type: ignore[union-attr]
    if kind == "neg":
        a, b = _values(node.value, imaginary)  # type: ignore[arg-type]
        return -a, -b
    if kind == "add":
        return _sum([_values(t, imaginary) for t in node.value], imaginary)  # type: ignore[union-attr]
    if kind == "mul":
        a = b = 1.0
        for factor in node.value:  # type: ignore[union-attr]
            if factor.kind == "inv":
                x, y = _values(factor.value, imaginary)
                a /= x
                b /= y
            else:
                x, y = _values(factor, imaginary)
                a *= x
                b *= y
        return _nonzero(_checked(a, imaginary)), _nonzero(_checked(b, imaginary))
    if kind == "pow":
        a, b = _values(node.value, imaginary)  # type: ignore[arg-type]
        x, y = _values(node.extra, imaginary)  # type: ignore[arg-type]
        return _nonzero(_checked(a**x, imaginary)), _nonzero(_checked(b**y, imaginary))
    if kind == "call":
        name = _SGN.get(node.value, node.value)  # type: ignore[arg-type]
        argument, power = node.extra  # type: ignore[misc]
        if not hasattr(argument, "kind"):  # atan2, Max, Min: a tuple of arguments
            pairs = [_values(a, imaginary) for a in argument]
            return tuple(
                _call_of_several(name, [pair[k] for pair in pairs], power, imaginary)
                for k in (0, 1)
            )
        a, b = _values(argument, imaginary)
        return _call(name, a, power, imaginary), _call(name, b, power, imaginary)
    raise _Sympy  # ddt, or a kind the screen does not know


def _sum(pairs: list[tuple], imaginary: bool) -> tuple:
    """A sum at both points; one that cancels (x − x) is sympy's (it makes it 0)."""
    out = []
    for k in (0, 1):
        values = [pair[k] for pair in pairs]
        total = sum(values)
        if abs(total) <= CANCELLED * sum(abs(v) for v in values):
            raise _Sympy
        out.append(_checked(total, imaginary))
    return out[0], out[1]


def _call(name: str, x, power: int | None, imaginary: bool):
    """A function of one argument at one point."""
    if isinstance(x, complex):
        f = _COMPLEX.get(name)
        if f is None:
            raise _Sympy
        result = f(x)
    else:
        result = _REAL[name](x)
    if power is not None:
        result = result**power
    return _nonzero(_checked(result, imaginary))


def _call_of_several(name: str, values: list, power: int | None, imaginary: bool):
    """atan2, Max or Min at one point."""
    if any(isinstance(v, complex) for v in values):
        raise _Sympy
    if name in ("atan2", "arctan2"):
        result = math.atan2(values[0], values[1])
    else:
        result = max(values) if name.lower() == "max" else min(values)
    if power is not None:
        result = result**power
    return _nonzero(_checked(result, imaginary))


_PI = (math.pi, math.pi)
_I = (1j, 1j)


def _checked(value, imaginary: bool):
    if isinstance(value, complex):
        if not imaginary or not cmath.isfinite(value):
            raise _Sympy
        return value
    if not math.isfinite(value):
        raise _Sympy
    return value


def _nonzero(value):
    """A computed value that is exactly 0 (0·x, 0^2): sympy makes it the number 0, and a
    division by it, or a function of it, is sympy's to judge."""
    if value == 0:
        raise _Sympy
    return value
