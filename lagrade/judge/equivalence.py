"""Equivalence of expressions, equations and Lagrangians, decided numerically at seeded sample
points and confirmed at 50 digits when the numbers are close to the tolerance.

Every test is a residual that vanishes identically exactly when the answer is right
(a − b; E(L′) − c E(L); the part of a student's equation outside the span of the reference
rows, in `rows`; D_t Q on-shell, from `derivatives`), measured against the size of the terms
it is made of, never against its own value, so that cancellation cannot fool it (`decision`):

    ratio = |residual| / Σ |terms|      equal below 1e-10, different above 1e-6,
                                         in between: recomputed in mpmath at 50 digits.

q, q̇, q̈ and t are independent variables at the sample points; parameters are drawn inside
their declared domains in a few groups of points that share parameter values (`sampling`), so
that a factor that depends only on the parameters (a global scale of L) can be told from one
that depends on the motion. This module holds the tests of expressions, of values, of a
difference by a constant, and of Lagrangians.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from lagrade.judge.compiled import Compiled, to_length, total
from lagrade.judge.decision import EQUAL_BELOW, Decision, decide
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.sampling import Points, memo_inputs
from lagrade.judge.tolerances import ROUNDING, SAME_FACTOR, SAME_VALUE
from lagrade.mechanics import Jet


def reference_values(reference: Compiled, points: Points, backend=FLOAT) -> tuple:
    """A reference's (value, size) at the points; in float64 computed once per points."""
    env = points.arrays(backend)
    if backend is not FLOAT:
        return reference.values(env, backend)
    return memo_inputs(
        f"values:{id(reference)}", env, (), lambda: (reference, reference.values(env))
    )[1]


def expressions_equal(answer: Compiled, reference: Compiled, points: Points) -> Decision:
    """answer ≡ reference on the domain: a − b vanishes at every point, relative to the terms;
    in complex arithmetic where the reference is complex (`Points.complex_values`)."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = reference_values(reference, points, backend)
        return to_length(a - b, points.n, backend), to_length(sa + sb, points.n, backend)

    return decide(residual, points.backends)


def differ_by_constant(answer: Compiled, reference: Compiled, points: Points) -> Decision:
    """answer − reference is the same number at all points of a parameter group (another zero
    level of a potential): the residual is the spread of the difference within each group."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = reference_values(reference, points, backend)
        d = to_length(a - b, points.n, backend)
        rest, first = offset_removed(d, points.group)
        return rest, to_length(sa + sb, points.n, backend) + first

    return decide(residual)


def group_starts(group: np.ndarray) -> np.ndarray:
    """For each point, the index of the first point of its parameter group (the points of a
    group are consecutive and share their parameters' values)."""
    return np.searchsorted(group, group)


def offset_removed(values, group: np.ndarray):
    """(values less the first value of their parameter group, the size of that first value):
    the one definition of "equal up to a constant per parameter group" — an answer that differs
    from the reference by such a constant (the zero of V, a dropped m g h) leaves 0 here, and
    its residual is measured against the terms' size plus the constant's. `values` may hold
    one row per point or one row per candidate (points on the last axis)."""
    first = values[..., group_starts(group)]
    return values - first, abs(first)


def values_equal(answer: Compiled, values: Callable[[object], tuple], points: Points) -> Decision:
    """answer ≡ a reference given only by its values at the points (`values(backend)` returns
    (value, size)), e.g. the momenta of a student's own Lagrangian."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = values(backend)
        return to_length(a - b, points.n, backend), to_length(sa, points.n, backend) + abs(sb)

    return decide(residual)


def common_factor(factors: Sequence[float]) -> float | None:
    """The factor shared by every parameter group (within 1e-8), or None when they differ
    (a factor that depends on the parameters) or there are none."""
    if not factors:
        return None
    c0 = factors[0]
    return c0 if all(abs(c - c0) <= SAME_FACTOR * max(1.0, abs(c0)) for c in factors) else None


@dataclass(frozen=True)
class LagrangianMatch:
    """How a Lagrangian relates to a reference: E(L′) = c E(L) with c per parameter group."""

    outcome: Decision
    factors: tuple[float, ...] = ()  # c per parameter group
    answer_el: tuple[np.ndarray, np.ndarray] | None = None  # E(answer) and its size, float64

    @property
    def factor(self) -> float | None:
        """The common factor c when all groups agree, else None."""
        return common_factor(self.factors)


@dataclass(frozen=True)
class AffineMatch:
    """answer = c·reference + k identically, with c and k per parameter group."""

    factors: tuple[float, ...]
    shifted: bool  # k ≠ 0 somewhere: the answer differs by a constant
    worst: float  # the largest ratio of residual to term size

    @property
    def factor(self) -> float | None:
        """The common factor c when all groups agree, else None."""
        return common_factor(self.factors)


def affine_match(
    answer: tuple[np.ndarray, np.ndarray],
    reference: tuple[np.ndarray, np.ndarray],
    points: Points,
) -> AffineMatch | None:
    """Is answer = c·reference + k, with c > 0 and k constant in each parameter group? Given
    (value, size) of both at the points. Only a clear yes is returned (residual below
    EQUAL_BELOW of the terms everywhere); anything else is None, for the full test to decide.

    Why: a Lagrangian that is a positive multiple of T − V plus a constant has the same motion,
    and comparing values costs a fraction of evaluating Euler–Lagrange expressions — most right
    answers (expanded, factored, rewritten with identities, m g h dropped) are settled here."""
    n = points.n
    with np.errstate(all="ignore"):
        a, sa = (np.broadcast_to(np.asarray(x, float), (n,)) for x in answer)
        b, sb = (np.broadcast_to(np.asarray(x, float), (n,)) for x in reference)
        group = points.group
        count = np.bincount(group)
        mean_a = (np.bincount(group, a) / count)[group]
        mean_b = (np.bincount(group, b) / count)[group]
        da, db = a - mean_a, b - mean_b
        spread = np.bincount(group, db * db)
        c = np.bincount(group, da * db) / spread
        if not (np.all(np.isfinite(c)) and np.all(c > 0)):
            return None
        k = mean_a - c[group] * mean_b
        residual = da - c[group] * db
        size = sa + c[group] * sb + np.abs(k)
        ratio = np.abs(residual) / size
        # both must vary with the motion well above rounding, or c means nothing (a constant L)
        varies = (spread > ROUNDING * np.bincount(group, sb * sb)) & (
            np.bincount(group, da * da) > ROUNDING * np.bincount(group, sa * sa)
        )
    if not (np.all(ratio < EQUAL_BELOW) and np.all(varies)):
        return None
    shifted = bool(np.any(np.abs(k) > SAME_VALUE * size))
    return AffineMatch(tuple(float(x) for x in c), shifted, float(ratio.max()))


def lagrangians_match(
    answer: Compiled,
    reference: Compiled | Callable,
    jets: Sequence[Jet],
    points: Points,
    answer_el: tuple[np.ndarray, np.ndarray] | None = None,
) -> LagrangianMatch:
    """Is E(answer) = c E(reference) for a c constant in (q, q̇, q̈, t)? c is fitted by least
    squares in each parameter group, then the residual E(L′) − c E(L) is decided. `answer_el`:
    E(answer) and its size in float64 at the points, when the caller has them already."""
    found: dict[str, list] = {}

    def residual(backend):
        env = points.arrays(backend)
        if backend is FLOAT and answer_el is not None:
            Ea, Sa = answer_el
        else:
            Ea, Sa = euler_lagrange_values(answer, jets, env, backend)
        Eb, Sb = (
            reference(backend)
            if callable(reference)
            else euler_lagrange_values(reference, jets, env, backend)
        )
        if backend is FLOAT:  # every group at once
            found["el"] = (Ea, Sa)
            group = points.group
            num = np.bincount(group, np.sum(Ea * Eb, axis=1))
            den = np.bincount(group, np.sum(Eb * Eb, axis=1))
            c = np.where(den != 0, num / np.where(den != 0, den, 1.0), 0.0)
            found["c"] = list(c)
            per_point = c[group][:, None]
            return Ea - per_point * Eb, Sa + np.abs(per_point) * Sb
        r = np.empty_like(Ea)
        s = np.empty_like(Ea)
        factors = []
        for g in np.unique(points.group):
            rows = points.group == g
            num = total((Ea[rows] * Eb[rows]).ravel())
            den = total((Eb[rows] * Eb[rows]).ravel())
            c = num / den if den != 0 else 0 * num
            factors.append(c)
            r[rows] = Ea[rows] - c * Eb[rows]
            s[rows] = Sa[rows] + abs(c) * Sb[rows]
        found["c"] = factors
        return r, s

    outcome = decide(residual)
    return LagrangianMatch(outcome, tuple(float(c) for c in found.get("c", ())), found.get("el"))
