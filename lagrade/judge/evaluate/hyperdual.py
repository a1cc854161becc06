"""Forward-mode differentiation of a program with hyper-dual numbers f = a + b ε₁ + c ε₂ + d ε₁ε₂
(ε₁² = ε₂² = 0): seeding ε₁ with the direction of the motion (∂t = 1, ∂q = q̇, ∂q̇ = q̈) and ε₂
with ∂/∂q̇_j makes d = D_t(∂L/∂q̇_j) exactly — the Euler–Lagrange expressions of any L, at every
sample point, without differentiating symbolically (`lagrade.judge.derivatives`)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from lagrade.errors import UnsupportedExpression
from lagrade.judge.evaluate.backends import FLOAT, apply, extreme
from lagrade.judge.evaluate.program import Program

HyperDual = tuple  # (a, b, c, d): a + b ε₁ + c ε₂ + d ε₁ε₂


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


def run_hyperdual(program: Program, env: Mapping[Any, HyperDual], backend=FLOAT) -> list:
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
            f = apply(backend, name, x[0])
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
