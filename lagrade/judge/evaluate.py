"""A small compiler from sympy trees to straight-line numeric code, evaluated on whole arrays of
sample points at once, in float64 (fast) or in mpmath at 50 digits (confirmation).

Why not `lambdify`: it prints the expression to Python source and executes it, which the project
forbids for anything derived from student text. Here a whitelist of sympy node types is walked
once into a list of instructions; anything else (an undefined function, a Derivative, the
imaginary unit) is rejected with a clear message.

Besides plain values the evaluator carries hyper-dual numbers f = a + b ε₁ + c ε₂ + d ε₁ε₂
(ε₁² = ε₂² = 0): seeding ε₁ with the direction of the motion (∂t = 1, ∂q = q̇, ∂q̇ = q̈) and ε₂
with ∂/∂q̇_j makes d = D_t(∂L/∂q̇_j) exactly — the Euler–Lagrange expressions of any L, at every
sample point, without differentiating symbolically.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from lagrade.errors import UnsupportedExpression

#: Digits of the confirming evaluation.
MP_DIGITS = 50


# --- compilation ------------------------------------------------------------------------------

_FUNCTIONS: dict[type, str] = {
    sp.sin: "sin",
    sp.cos: "cos",
    sp.tan: "tan",
    sp.cot: "cot",
    sp.sec: "sec",
    sp.csc: "csc",
    sp.asin: "asin",
    sp.acos: "acos",
    sp.atan: "atan",
    sp.sinh: "sinh",
    sp.cosh: "cosh",
    sp.tanh: "tanh",
    sp.asinh: "asinh",
    sp.acosh: "acosh",
    sp.atanh: "atanh",
    sp.exp: "exp",
    sp.log: "log",
    sp.Abs: "abs",
    sp.sign: "sign",
}


@dataclass(frozen=True)
class Program:
    """Straight-line code for several sympy expressions: instructions in dependency order, each
    shared subtree once. Instructions: ("in", symbol), ("const", number, its float), ("add", args),
    ("mul", args), ("powi", base, n), ("powc", base, exponent), ("powe", base, exponent),
    ("fn", name, arg), ("atan2", y, x)."""

    code: tuple[tuple, ...]
    outputs: tuple[int, ...]
    symbols: frozenset[sp.Symbol]


#: sympy's Max and Min → the instruction that takes the larger or smaller of its arguments.
EXTREMA: dict[type, str] = {sp.Max: "max", sp.Min: "min"}


def compile_program(exprs: Sequence[sp.Expr]) -> Program:
    """Compile `exprs` (each a sympy expression over the whitelist) into one Program whose
    outputs are the expressions in order."""
    code: list[tuple] = []
    index: dict[sp.Basic, int] = {}
    symbols: set[sp.Symbol] = set()

    def emit(node: sp.Basic) -> int:
        found = index.get(node)
        if found is not None:
            return found
        instr = _instruction(node, emit, symbols)
        code.append(instr)
        index[node] = len(code) - 1
        return len(code) - 1

    outputs = tuple(emit(sp.S(e) if isinstance(e, int | float) else e) for e in exprs)
    return Program(tuple(code), outputs, frozenset(symbols))


def _as_float(number: sp.Expr) -> np.float64:
    """A constant as a numpy float, so that float arithmetic on it follows IEEE rules (0 ** -1 is
    inf, not ZeroDivisionError) and a number beyond float range is ±inf, not OverflowError."""
    try:
        return np.float64(float(number))
    except OverflowError:
        return np.float64(np.inf if number > 0 else -np.inf)


def _instruction(node: sp.Basic, emit, symbols: set) -> tuple:
    if isinstance(node, sp.Symbol):
        symbols.add(node)
        return ("in", node)
    if isinstance(node, sp.Number):
        if not node.is_finite:
            raise UnsupportedExpression(f"the answer contains {node}, which is not a finite number")
        return ("const", node, _as_float(node))
    if node is sp.pi or node is sp.E:  # singletons: `is`, not sympy's slow ==
        return ("const", node, _as_float(node))
    if node is sp.I:  # only where a question declares the imaginary unit
        return ("const", node, np.complex128(1j))
    if isinstance(node, sp.Add):
        return ("add", tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Mul):
        return ("mul", tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Pow):
        base, exponent = node.args
        if isinstance(exponent, sp.Integer):
            return ("powi", emit(base), int(exponent))
        if isinstance(exponent, sp.Rational | sp.Float):
            return ("powc", emit(base), exponent)
        if base is sp.E:  # E**x is exp(x)
            return ("fn", "exp", emit(exponent))
        # b**e with a non-constant exponent: exp(e log b), defined for b > 0.
        return ("powe", emit(base), emit(exponent))
    if isinstance(node, sp.atan2):
        return ("atan2", emit(node.args[0]), emit(node.args[1]))
    if type(node) in EXTREMA:  # ("max", args): the largest of its arguments, elementwise
        return (EXTREMA[type(node)], tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Function):
        name = _FUNCTIONS.get(type(node))
        if name is None:
            raise UnsupportedExpression(f"the function {type(node).__name__} is not supported")
        if len(node.args) != 1:
            raise UnsupportedExpression(f"{type(node).__name__} with {len(node.args)} arguments")
        return ("fn", name, emit(node.args[0]))
    raise UnsupportedExpression(f"cannot evaluate {node} ({type(node).__name__})")


# --- backends: float64 arrays or mpmath object arrays -------------------------------------------


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
    def const(value: sp.Expr) -> float:
        return float(value)

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
    def const(value: sp.Expr):
        if value == sp.pi:
            return mpmath.mp.pi
        if value == sp.E:
            return mpmath.mp.e
        if value is sp.I:
            return mpmath.mpc(0, 1)
        if isinstance(value, sp.Rational):
            return mpmath.mpf(int(value.p)) / int(value.q)
        return mpmath.mpf(value._mpf_) if hasattr(value, "_mpf_") else mpmath.mpf(float(value))

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
    def const(value: sp.Expr) -> complex:
        return complex(value)

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


# First and second derivatives of each function, as functions of (x, f(x)), for the chain rule
# f(a + δ) = f(a) + f'(a) δ + ½ f''(a) δ² on hyper-dual numbers.


def _derivatives(B, name: str, x, f):
    if name == "sin":
        c = B.cos(x)
        return c, -f
    if name == "cos":
        s = B.sin(x)
        return -s, -f
    if name == "tan":
        d1 = 1 + f * f
        return d1, 2 * f * d1
    if name == "cot":
        d1 = -(1 + f * f)
        return d1, -2 * f * d1
    if name == "sec":
        t = B.tan(x)
        return f * t, f * (t * t + f * f)
    if name == "csc":
        c = 1 / B.tan(x)
        return -f * c, f * (c * c + f * f)
    if name == "exp":
        return f, f
    if name == "log":
        return 1 / x, -1 / (x * x)
    if name in ("asin", "acos"):
        r = 1 / B.sqrt(1 - x * x)
        sign = 1 if name == "asin" else -1
        return sign * r, sign * x * r * r * r
    if name == "atan":
        r = 1 / (1 + x * x)
        return r, -2 * x * r * r
    if name == "sinh":
        return B.cosh(x), f
    if name == "cosh":
        return B.sinh(x), f
    if name == "tanh":
        d1 = 1 - f * f
        return d1, -2 * f * d1
    if name == "asinh":
        r = 1 / B.sqrt(1 + x * x)
        return r, -x * r * r * r
    if name == "acosh":
        r = 1 / B.sqrt(x * x - 1)
        return r, -x * r * r * r
    if name == "atanh":
        r = 1 / (1 - x * x)
        return r, 2 * x * r * r
    if name == "abs":
        return B.sign(x), 0 * x
    if name == "sign":
        return 0 * x, 0 * x
    raise AssertionError(name)


def _apply(B, name: str, x):
    if name == "cot":
        return 1 / B.tan(x)
    if name == "sec":
        return 1 / B.cos(x)
    if name == "csc":
        return 1 / B.sin(x)
    return getattr(B, name)(x)


# --- evaluation -------------------------------------------------------------------------------


def run(program: Program, env: Mapping[sp.Symbol, Any], backend=FLOAT) -> list:
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
            vals.append(_apply(backend, instr[1], vals[instr[2]]))
    return [vals[k] for k in program.outputs]


HyperDual = tuple  # (a, b, c, d): a + b ε₁ + c ε₂ + d ε₁ε₂


def _vanishes(z) -> bool:
    """A component known to be zero: the exact integer 0 the seeds use (never an array)."""
    return isinstance(z, int) and z == 0


def _scaled(z, factor):
    return z if _vanishes(z) else z * factor


def _hd_mul(x: HyperDual, y: HyperDual) -> HyperDual:
    a0, a1, a2, a3 = x
    b0, b1, b2, b3 = y
    # A factor without infinitesimal parts (a parameter, a constant) only scales the other:
    # most products in a Lagrangian are of this kind, and skipping the zero terms halves them.
    if _vanishes(b1) and _vanishes(b2) and _vanishes(b3):
        return (a0 * b0, _scaled(a1, b0), _scaled(a2, b0), _scaled(a3, b0))
    if _vanishes(a1) and _vanishes(a2) and _vanishes(a3):
        return (a0 * b0, _scaled(b1, a0), _scaled(b2, a0), _scaled(b3, a0))
    return (a0 * b0, a0 * b1 + a1 * b0, a0 * b2 + a2 * b0, a0 * b3 + a1 * b2 + a2 * b1 + a3 * b0)


def _hd_chain(x: HyperDual, f, d1, d2) -> HyperDual:
    return (f, d1 * x[1], d1 * x[2], d1 * x[3] + d2 * x[1] * x[2])


def _hd_power(B, x: HyperDual, r) -> HyperDual:
    """x**r for a constant r."""
    a = x[0]
    if isinstance(r, int):
        if r == 1:
            return x
        if r == 2:
            return (a * a, 2 * a * x[1], 2 * a * x[2], 2 * (a * x[3] + x[1] * x[2]))
        f = a**r if r >= 0 else 1 / a ** (-r)
        d1 = r * (a ** (r - 1) if r >= 1 else 1 / a ** (1 - r))
        d2 = r * (r - 1) * (a ** (r - 2) if r >= 2 else 1 / a ** (2 - r))
        return _hd_chain(x, f, d1, d2)
    f = B.power(a, r)
    return _hd_chain(x, f, r * f / a, r * (r - 1) * f / (a * a))


def run_hyperdual(program: Program, env: Mapping[sp.Symbol, HyperDual], backend=FLOAT) -> list:
    """Hyper-dual values of the outputs; `env` maps each input symbol to (a, b, c, d)."""
    vals: list[HyperDual] = []
    for instr in program.code:
        op = instr[0]
        if op == "in":
            try:
                vals.append(env[instr[1]])
            except KeyError:
                raise UnsupportedExpression(f"the symbol {instr[1]} has no value here") from None
        elif op == "const":
            vals.append((instr[2] if backend is FLOAT else backend.const(instr[1]), 0, 0, 0))
        elif op == "add":
            parts = [vals[k] for k in instr[1]]
            vals.append(tuple(sum((p[i] for p in parts[1:]), parts[0][i]) for i in range(4)))
        elif op == "mul":
            acc = vals[instr[1][0]]
            for k in instr[1][1:]:
                acc = _hd_mul(acc, vals[k])
            vals.append(acc)
        elif op == "powi":
            vals.append(_hd_power(backend, vals[instr[1]], instr[2]))
        elif op == "powc":
            vals.append(_hd_power(backend, vals[instr[1]], backend.const(instr[2])))
        elif op == "powe":
            base, expo = vals[instr[1]], vals[instr[2]]
            a = base[0]
            log_b = _hd_chain(base, backend.log(a), 1 / a, -1 / (a * a))
            prod = _hd_mul(expo, log_b)
            f = backend.exp(prod[0])
            vals.append(_hd_chain(prod, f, f, f))
        elif op == "atan2":  # locally atan(y/x) plus a constant: atan's derivatives at y/x
            y, x = vals[instr[1]], vals[instr[2]]
            q = _hd_mul(y, _hd_power(backend, x, -1))
            r = 1 / (1 + q[0] * q[0])
            vals.append(_hd_chain(q, backend.atan2(y[0], x[0]), r, -2 * q[0] * r * r))
        elif op in ("max", "min"):
            vals.append(_hd_extreme(op, [vals[k] for k in instr[1]], backend))
        else:
            name, x = instr[1], vals[instr[2]]
            f = _apply(backend, name, x[0])
            d1, d2 = _derivatives(backend, name, x[0], f)
            vals.append(_hd_chain(x, f, d1, d2))
    return [vals[k] for k in program.outputs]


def _hd_extreme(op: str, xs: list[HyperDual], backend) -> HyperDual:
    """max or min of hyper-dual numbers: the derivatives of the argument that wins at each
    point (where two tie the function has a kink; either side's derivative is taken)."""
    best = xs[0]
    for x in xs[1:]:
        value = extreme(op, [best[0], x[0]], backend)
        if backend is FLOAT:
            take = np.asarray(x[0] > best[0] if op == "max" else x[0] < best[0])
        else:
            larger = np.frompyfunc(lambda a, b: bool(b > a) if op == "max" else bool(b < a), 2, 1)
            take = np.asarray(larger(best[0], x[0]), dtype=bool)
        best = (
            value,
            *(
                0 if _vanishes(a) and _vanishes(b) else np.where(take, b, a)
                for a, b in zip(best[1:], x[1:], strict=True)
            ),
        )
    return best


def top_terms(expr: sp.Expr) -> tuple[sp.Expr, ...]:
    """The top-level terms of expr, with a numeric factor distributed over a sum
    (½ (a + b) → ½ a, ½ b), so that the tolerance sees the size of each term, not of their sum."""
    terms: list[sp.Expr] = []
    for term in sp.Add.make_args(expr):
        coeff, rest = term.as_coeff_Mul()
        if isinstance(rest, sp.Add) and coeff != 1:
            terms.extend(coeff * t for t in rest.args)
        else:
            terms.append(term)
    return tuple(terms)
