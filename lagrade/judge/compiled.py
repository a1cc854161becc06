"""Expressions compiled once by top-level terms for evaluation at the sample points, so that every
value comes with the size of the terms it is made of (the scale a residual is measured against)."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.judge.evaluate import (
    COMPLEX,
    FLOAT,
    MP,
    MP_COMPLEX,
    Program,
    compile_program,
    finite_in_mp,
    run,
    run_hyperdual,
    top_terms,
)


class Compiled:
    """An expression compiled by top-level terms: its value is their sum, its size the sum of
    their absolute values. `expr`, the sympy form, is given or built on first use (an answer
    compiled from the parser's tree needs it only for a diagnosis)."""

    __slots__ = ("program", "_expr", "_whole")

    def __init__(self, expr: sp.Expr | Callable[[], sp.Expr], program: Program):
        self.program = program
        self._expr = expr
        self._whole: Program | None = None

    @classmethod
    def of(cls, expr: sp.Expr) -> Compiled:
        return cls(expr, compile_program(top_terms(sp.S(expr))))

    @property
    def expr(self) -> sp.Expr:
        if callable(self._expr) and not isinstance(self._expr, sp.Basic):
            self._expr = self._expr()
        return self._expr  # type: ignore[return-value]

    @property
    def symbols(self) -> frozenset[sp.Symbol]:
        return self.program.symbols

    @property
    def whole(self) -> Program:
        """The expression as one output: the sum of the terms."""
        if self._whole is None:
            code, outputs = self.program.code, self.program.outputs
            if len(outputs) == 1:
                self._whole = self.program
            else:
                self._whole = Program((*code, ("add", outputs)), (len(code),), self.program.symbols)
        return self._whole

    def values(self, env: Mapping, backend=FLOAT) -> tuple[np.ndarray, np.ndarray]:
        """(value, size) at the points of env."""
        terms = run(self.program, env, backend)
        return total(terms), total(abs(x) for x in terms)

    def hyperdual(self, env: Mapping, backend=FLOAT) -> list:
        return run_hyperdual(self.program, env, backend)


@dataclass(frozen=True)
class Combination:
    """Σ c·part over compiled parts: a mutant of the mistake catalogue, the reference plus a few
    scaled terms. Every evaluation here is linear in the expression, so its values are its
    parts' values combined, and a part shared by many mutants (the reference above all) is
    compiled once, not once per mutant. The size is Σ |c|·size(part): a bound on the terms'."""

    parts: tuple[tuple[sp.Rational, Compiled], ...]

    @property
    def expr(self) -> sp.Expr:
        return sp.Add(*(c * part.expr for c, part in self.parts))

    @property
    def symbols(self) -> frozenset[sp.Symbol]:
        return frozenset().union(*(part.symbols for _, part in self.parts))

    @property
    def weights(self) -> tuple[float, ...]:
        """The coefficients as floats (the catalogue's are ±1, ±2 and ½: exact in binary)."""
        return tuple(float(c) for c, _ in self.parts)

    def combine(self, pairs: Sequence[tuple]) -> tuple:
        """(value, size) of the combination from its parts' (value, size) pairs, in order:
        (Σ c·value, Σ |c|·size)."""
        weights = self.weights
        return (
            weighted(weights, [v for v, _ in pairs]),
            weighted([abs(c) for c in weights], [s for _, s in pairs]),
        )

    def values(self, env: Mapping, backend=FLOAT) -> tuple[np.ndarray, np.ndarray]:
        return self.combine([part.values(env, backend) for _, part in self.parts])

    def hyperdual(self, env: Mapping, backend=FLOAT) -> list:
        return [
            tuple(c * x for x in term)
            for c, (_, part) in zip(self.weights, self.parts, strict=True)
            for term in part.hyperdual(env, backend)
        ]


def weighted(weights: Sequence[float], arrays: Sequence):
    """Σ c·array."""
    with np.errstate(all="ignore"):
        return total(c * a for c, a in zip(weights, arrays, strict=True))


def total(items: Iterable):
    total = 0
    for x in items:
        total = total + x
    return total


def to_length(x, n: int, backend=FLOAT):
    """x as an array of length n (constants come out of the evaluator as scalars)."""
    if np.ndim(x) == 0:
        in_floats = backend is FLOAT or backend is COMPLEX
        kind = (complex if np.iscomplexobj(x) else float) if in_floats else object
        return np.full(n, x, dtype=kind)
    return x


def tiled(x, copies: int) -> np.ndarray:
    """np.tile(x, copies): a value per point repeated `copies` times end to end (the seeds of a
    hyper-dual pass, the blocks of rows). For a 1-D array, by concatenation: the same array for
    a third of np.tile's dispatch, which dominates on the few short arrays here."""
    if np.ndim(x) != 1 or copies < 1:
        return np.tile(x, copies)
    return np.concatenate((x,) * copies)


def finite_mask(
    compiled: Sequence[Compiled], complex_values: bool = False
) -> Callable[[dict], np.ndarray]:
    """A validity test for sampling: every compiled reference has a value at the point.

    A value beyond float range (SI quantities to a power: (M r)^10 with M = 2e30 kg, r = 1.5e11
    m; a ratio M^20/m^19 whose float is inf/inf) is a value all the same when high precision,
    whose exponents are unbounded, says so: judging must not depend on float range. With
    `complex_values` (an expression question), a complex value on principal branches is a value
    too (log of a negative number); undefined means no value at all: a pole, log 0. Points
    where float64 has none are tried in complex128 first (cheap, vectorised), and only those
    without a value there either (an overflow, or a true pole) in high precision."""

    def valid(env: dict) -> np.ndarray:
        n = len(next(iter(env.values())))
        ok = np.ones(n, dtype=bool)
        with np.errstate(all="ignore"):
            for c in compiled:
                ok &= _has_values(c, env, n, complex_values)
        return ok

    return valid


def _has_values(c: Compiled, env: dict, n: int, complex_values: bool) -> np.ndarray:
    value, size = c.values(env)
    finite = np.isfinite(to_length(value, n)) & np.isfinite(to_length(size, n))
    if finite.all():
        return finite
    value, size = c.values(env, COMPLEX)
    in_complex = np.isfinite(to_length(value, n)) & np.isfinite(to_length(size, n))
    if complex_values:
        finite |= in_complex
    beyond = ~finite & ~in_complex  # no value even in complex128: past float range, or a pole
    if beyond.any():
        backend = MP_COMPLEX if complex_values else MP
        finite |= beyond & finite_in_mp(lambda p: c.values(p, backend), env, beyond)
    return finite
