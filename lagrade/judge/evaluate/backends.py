"""The arithmetics a program runs in: float64 numpy arrays (fast), complex128 on principal
branches, and mpmath at 50 digits (confirmation), real or complex; and `run`, which evaluates a
program in any of them (or any object with the same functions: exact fractions, numbers modulo
a prime)."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from typing import Any

import mpmath
import numpy as np

from lagrade.errors import UnsupportedExpression
from lagrade.judge.evaluate.program import PI, Constant, E, I, Program, Real, as_float

#: Digits of the confirming evaluation.
MP_DIGITS = 50


def _mp_real(f, nargs: int = 1):
    """An mpmath function made elementwise, with complex results (log of a negative number,
    asin outside [-1, 1]) mapped to nan: outside the real domain, as in float64."""

    def real(*xs):
        try:
            y = f(*xs)
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            return mpmath.mpf("nan")
        if isinstance(y, mpmath.mpc) and not any(isinstance(x, mpmath.mpc) for x in xs):
            return mpmath.mpf("nan")  # complex from real arguments: outside the real domain
        return y  # a complex argument (a question with the imaginary unit): principal value

    return np.frompyfunc(real, nargs, 1)


class _Float:
    """float64 numpy."""

    name = "numeric"
    sin, cos, tan, exp, log = np.sin, np.cos, np.tan, np.exp, np.log
    asin, acos, atan = np.arcsin, np.arccos, np.arctan
    sinh, cosh, tanh, sqrt, abs, sign = np.sinh, np.cosh, np.tanh, np.sqrt, np.abs, np.sign
    asinh, acosh, atanh, atan2 = np.arcsinh, np.arccosh, np.arctanh, np.arctan2
    power = np.power

    @staticmethod
    def const(value: Constant):
        return as_float(value)

    @staticmethod
    def array(values: np.ndarray) -> np.ndarray:
        return np.asarray(values, dtype=float)

    @staticmethod
    def finite(values) -> np.ndarray:
        return np.isfinite(values)


class _Mp:
    """mpmath at MP_DIGITS digits, elementwise over object arrays (the caller sets mp.dps)."""

    name = "mpmath"
    sin, cos, tan = _mp_real(mpmath.sin), _mp_real(mpmath.cos), _mp_real(mpmath.tan)
    exp, log = _mp_real(mpmath.exp), _mp_real(mpmath.log)
    asin, acos, atan = _mp_real(mpmath.asin), _mp_real(mpmath.acos), _mp_real(mpmath.atan)
    sinh, cosh, tanh = _mp_real(mpmath.sinh), _mp_real(mpmath.cosh), _mp_real(mpmath.tanh)
    sqrt, abs, sign = _mp_real(mpmath.sqrt), np.frompyfunc(abs, 1, 1), _mp_real(mpmath.sign)
    asinh, acosh, atanh = _mp_real(mpmath.asinh), _mp_real(mpmath.acosh), _mp_real(mpmath.atanh)
    atan2 = _mp_real(mpmath.atan2, 2)
    power = _mp_real(mpmath.power, 2)

    @staticmethod
    def const(value: Constant):
        if isinstance(value, Fraction):
            return mpmath.mpf(value.numerator) / value.denominator
        if isinstance(value, Real):
            return mpmath.mpf(value.mpf)
        if value is PI:
            return mpmath.mp.pi
        if value is E:
            return mpmath.mp.e
        if value is I:
            return mpmath.mpc(0, 1)
        return mpmath.mpf(float(value))

    @staticmethod
    def array(values) -> np.ndarray:
        flat = np.asarray(values, dtype=float)
        out = np.empty(flat.shape, dtype=object)
        for i, v in np.ndenumerate(flat):
            out[i] = mpmath.mpf(float(v))
        return out

    @staticmethod
    def finite(values) -> np.ndarray:
        arr = np.asarray(values, dtype=object)
        return np.array([mpmath.isfinite(v) for v in arr.ravel()], dtype=bool).reshape(arr.shape)


def _as_complex(x) -> np.ndarray:
    """x as complex128, a zero imaginary part made +0: mpmath's zero has no sign, and −0 would
    flip sqrt and log across their cuts (−2 − 0j has sqrt −1.41j)."""
    return np.asarray(x, dtype=complex) + 0j


def _principal(f, lower_side_above_one: bool = False):
    """A numpy complex function on principal branches as mpmath and sympy take them: on a cut,
    a real argument lies on the side counter-clockwise continuity gives it; numpy's C99
    functions put +0j on the upper side, so asin, acos and atanh of a real x > 1 are taken at
    x − 0j (asin 2 = π/2 − 1.317i, as sympy's asin(2))."""

    def g(x):
        z = _as_complex(x)
        if lower_side_above_one:
            z = np.where((z.imag == 0) & (z.real > 1), np.conj(z), z)
        return f(z)

    return g


class _Complex:
    """complex128 numpy on principal branches: the values of a question whose reference is
    complex (a logarithm or root of a negative number, the declared imaginary unit) — complex
    values are values, as docs/formats.md promises."""

    name = "numeric"
    sin, cos, tan, exp = np.sin, np.cos, np.tan, np.exp
    sinh, cosh, tanh, asinh, atan = np.sinh, np.cosh, np.tanh, np.arcsinh, np.arctan
    log, sqrt, acosh = _principal(np.log), _principal(np.sqrt), _principal(np.arccosh)
    asin, acos = _principal(np.arcsin, True), _principal(np.arccos, True)
    atanh = _principal(np.arctanh, True)
    abs, sign = np.abs, np.sign  # |z| and z/|z|, as sympy's Abs and sign of a complex number

    @staticmethod
    def power(base, exponent):
        return np.power(_as_complex(base), exponent)

    @staticmethod
    def atan2(y, x):
        """A real function: no value where an argument is not real."""
        y, x = _as_complex(y), _as_complex(x)
        real = (y.imag == 0) & (x.imag == 0)
        return np.where(real, np.arctan2(y.real, x.real), np.nan)

    @staticmethod
    def const(value: Constant) -> complex:
        return complex(as_float(value))

    @staticmethod
    def array(values: np.ndarray) -> np.ndarray:
        return np.asarray(values, dtype=float)

    @staticmethod
    def finite(values) -> np.ndarray:
        return np.isfinite(values)


def _mp_complex(f, nargs: int = 1):
    """An mpmath function made elementwise on principal branches, complex results kept (a
    division by zero or a domain error has no value: nan)."""

    def value(*xs):
        try:
            return f(*xs)
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            return mpmath.mpf("nan")

    return np.frompyfunc(value, nargs, 1)


def _mp_atan2(y, x):
    if isinstance(y, mpmath.mpc) or isinstance(x, mpmath.mpc):
        return mpmath.mpf("nan")  # atan2 is a real function
    return mpmath.atan2(y, x)


class _MpComplex(_Mp):
    """mpmath at MP_DIGITS digits on principal branches, complex values kept: the confirming
    evaluation of a question judged in complex arithmetic."""

    name = "mpmath"
    sin, cos, tan = _mp_complex(mpmath.sin), _mp_complex(mpmath.cos), _mp_complex(mpmath.tan)
    exp, log = _mp_complex(mpmath.exp), _mp_complex(mpmath.log)
    asin, acos, atan = _mp_complex(mpmath.asin), _mp_complex(mpmath.acos), _mp_complex(mpmath.atan)
    sinh, cosh = _mp_complex(mpmath.sinh), _mp_complex(mpmath.cosh)
    tanh, sqrt = _mp_complex(mpmath.tanh), _mp_complex(mpmath.sqrt)
    asinh, acosh = _mp_complex(mpmath.asinh), _mp_complex(mpmath.acosh)
    atanh, sign = _mp_complex(mpmath.atanh), _mp_complex(mpmath.sign)
    atan2, power = _mp_complex(_mp_atan2, 2), _mp_complex(mpmath.power, 2)


FLOAT = _Float
MP = _Mp
#: The same, in complex arithmetic on principal branches (`Points.complex_values`).
COMPLEX = _Complex
MP_COMPLEX = _MpComplex


def extreme(op: str, values: Sequence, backend=FLOAT):
    """max or min ("max", "min") of `values`, elementwise, in any backend: float64 arrays, and
    otherwise (mpmath object arrays, scalars of mpmath or exact Fractions) value by value. It is
    undefined (nan) where any value is, or is not real: a complex number has no order."""
    if backend is FLOAT:
        if any(np.iscomplexobj(v) for v in values):
            real = [np.real(v) for v in values]
            imaginary = sum(np.abs(np.imag(v)) for v in values)
            return np.where(imaginary == 0, extreme(op, real), np.nan)
        pick = np.maximum if op == "max" else np.minimum
        out = values[0]
        for v in values[1:]:
            out = pick(out, v)
        return out
    choose = _larger if op == "max" else _smaller
    return np.frompyfunc(lambda *xs: _extreme_of(choose, xs), len(values), 1)(*values)


def _larger(a, b) -> bool:
    return b > a


def _smaller(a, b) -> bool:
    return b < a


def _extreme_of(choose, xs):
    """The value that `choose` prefers among xs; nan when one is nan or not real."""
    best = None
    for x in xs:
        if isinstance(x, mpmath.mpc):
            if x.imag != 0:
                return mpmath.mpf("nan")
            x = x.real
        if x != x:  # nan
            return x
        if best is None or choose(best, x):
            best = x
    return best


def finite_in_mp(
    values_at: Callable[[dict], Sequence], env: Mapping, where: np.ndarray
) -> np.ndarray:
    """Whether `values_at(point)` (arrays of one mpmath value each) are all finite at the
    points `where` of env, in mpmath, whose exponents are unbounded: a value past float range
    (SI quantities to a power) is finite all the same. Undefined there counts as not finite."""
    out = np.zeros(len(where), dtype=bool)
    with mpmath.workdps(MP_DIGITS):
        for i in np.nonzero(where)[0]:
            point = {s: MP.array(np.atleast_1d(v)[i : i + 1]) for s, v in env.items()}
            try:
                values = values_at(point)
            except (ZeroDivisionError, ValueError, OverflowError):
                continue
            out[i] = all(MP.finite(v).all() for v in values)
    return out


def apply(B, name: str, x):
    """The function `name` of x in arithmetic B (cot, sec, csc by their reciprocals)."""
    if name == "cot":
        return 1 / B.tan(x)
    if name == "sec":
        return 1 / B.cos(x)
    if name == "csc":
        return 1 / B.sin(x)
    return getattr(B, name)(x)


# --- evaluation -------------------------------------------------------------------------------


def run(program: Program, env: Mapping[Any, Any], backend=FLOAT) -> list:
    """Values of the program's outputs; `env` maps every input symbol to an array (or scalar)."""
    vals: list = []
    for instr in program.code:
        op = instr[0]
        if op == "in":
            try:
                vals.append(env[instr[1]])
            except KeyError:
                raise UnsupportedExpression(f"the symbol {instr[1]} has no value here") from None
        elif op == "const":
            vals.append(instr[2] if backend is FLOAT else backend.const(instr[1]))
        elif op == "add":
            acc = vals[instr[1][0]]
            for k in instr[1][1:]:
                acc = acc + vals[k]
            vals.append(acc)
        elif op == "mul":
            acc = vals[instr[1][0]]
            for k in instr[1][1:]:
                acc = acc * vals[k]
            vals.append(acc)
        elif op == "powi":
            n = instr[2]
            base = vals[instr[1]]
            vals.append(base**n if n >= 0 else 1 / base ** (-n))
        elif op == "powc":
            vals.append(backend.power(vals[instr[1]], backend.const(instr[2])))
        elif op == "powe":
            vals.append(backend.exp(vals[instr[2]] * backend.log(vals[instr[1]])))
        elif op == "atan2":
            vals.append(backend.atan2(vals[instr[1]], vals[instr[2]]))
        elif op in ("max", "min"):
            vals.append(extreme(op, [vals[k] for k in instr[1]], backend))
        else:  # fn
            vals.append(apply(backend, instr[1], vals[instr[2]]))
    return [vals[k] for k in program.outputs]
