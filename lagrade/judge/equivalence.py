"""Equivalence of expressions, equations and Lagrangians, decided numerically at seeded sample
points and confirmed at 50 digits when the numbers are close to the tolerance.

Every test here is a residual that vanishes identically exactly when the answer is right
(a − b; E(L′) − c E(L); the part of a student's equation outside the span of the reference
rows; D_t Q on-shell), measured against the size of the terms it is made of, never against its
own value, so that cancellation cannot fool it:

    ratio = |residual| / Σ |terms|      equal below 1e-10, different above 1e-6,
                                         in between: recomputed in mpmath at 50 digits.

q, q̇, q̈ and t are independent variables at the sample points; parameters are drawn inside
their declared domains in a few groups of points that share parameter values, so that a factor
that depends only on the parameters (a global scale of L) can be told from one that depends on
the motion.
"""

from __future__ import annotations

import math
import re
import zlib
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

import mpmath
import numpy as np
import sympy as sp

from lagrade.errors import ReferenceUndefined
from lagrade.judge.evaluate import (
    FLOAT,
    MP,
    MP_DIGITS,
    Program,
    compile_program,
    run,
    run_hyperdual,
    top_terms,
)
from lagrade.mechanics.domains import Domain
from lagrade.mechanics.lagrange import Jet, t

#: Below this ratio of residual to term size the answers agree in float64.
EQUAL_BELOW = 1e-10
#: Above it they differ; in between, 50-digit arithmetic decides.
DIFFERENT_ABOVE = 1e-6
#: The 50-digit decision: equal below this ratio.
MP_EQUAL_BELOW = 1e-30

GROUPS = 4
PER_GROUP = 6

_RADIAL = re.compile(r"^(r|rho|ρ|ell|l)(_?\w*)?$")


def seed_for(*parts: object) -> int:
    """A stable seed from a request's identity (same points for every student of a problem)."""
    return zlib.crc32("|".join(map(str, parts)).encode())


def coordinate_range(name: str) -> tuple[float, float]:
    """Where a coordinate is drawn when the problem says nothing: a radius-like name in
    (0.3, 2.5), any other coordinate in ±(0.2, 2.5) — both signs of sin and cos of an angle,
    away from 0 where many expressions are special."""
    return (0.3, 2.5) if _RADIAL.match(name) else (-2.5, 2.5)


# --- the sample space and its points ------------------------------------------------------------


@dataclass(frozen=True)
class Space:
    """The independent variables of a problem: coordinates with their jets, t, and parameters
    with domains (and, for a numeric variant, the values on its handout)."""

    jets: tuple[Jet, ...]
    parameters: Mapping[sp.Symbol, Domain]
    values: Mapping[sp.Symbol, float] = field(default_factory=dict)
    coordinate_domains: Mapping[str, tuple[float, float]] = field(default_factory=dict)

    @cached_property
    def jet_symbols(self) -> frozenset[sp.Symbol]:
        return frozenset(s for j in self.jets for s in (j.q, j.dot, j.ddot))

    def draw(
        self,
        seed: int,
        free: Iterable[sp.Symbol] | None = None,
        valid: Callable[[dict], np.ndarray] | None = None,
        groups: int = GROUPS,
        per_group: int = PER_GROUP,
    ) -> Points:
        """Sample points: `groups` parameter draws, each with `per_group` draws of (q, q̇, q̈, t).

        Parameters in `free` (default: all) are drawn from their domains; the others keep the
        variant's values when it has them. Points where `valid` (the reference is finite) says
        no are redrawn; a group whose parameters leave the reference undefined is redrawn whole.
        """
        rng = np.random.default_rng(seed)
        free_set = set(self.parameters) if free is None else set(free)
        chosen: list[dict[sp.Symbol, np.ndarray]] = []
        for _ in range(groups):
            for _attempt in range(6):
                block = self._group(rng, free_set, per_group)
                if valid is None:
                    chosen.append(block)
                    break
                ok = valid(block)
                for _redraw in range(4):
                    if ok.all():
                        break
                    fresh = self._group(rng, free_set, per_group, params_from=block)
                    ok_fresh = valid(fresh)
                    for s in block:
                        block[s] = np.where(ok, block[s], fresh[s])
                    ok = ok | ok_fresh
                if ok.all():
                    chosen.append(block)
                    break
        if len(chosen) < max(1, groups // 2):
            raise ReferenceUndefined(
                "the reference answer is undefined at every point drawn from the declared domains"
            )
        env = {s: np.concatenate([b[s] for b in chosen]) for s in chosen[0]}
        group = np.repeat(np.arange(len(chosen)), per_group)
        return Points(env, group)

    def _group(self, rng, free: set, k: int, params_from: dict | None = None) -> dict:
        block: dict[sp.Symbol, np.ndarray] = {}
        for s, dom in self.parameters.items():
            if params_from is not None:
                block[s] = params_from[s]
            elif s not in free and s in self.values:
                block[s] = np.full(k, float(self.values[s]))
            else:
                block[s] = np.full(k, rng.uniform(*dom.sample_range()))
        for j in self.jets:
            lo, hi = self.coordinate_domains.get(j.name) or coordinate_range(j.name)
            block[j.q] = _away_from_zero(rng, lo, hi, k)
            block[j.dot] = _away_from_zero(rng, -2.0, 2.0, k)
            block[j.ddot] = _away_from_zero(rng, -2.0, 2.0, k)
        block[t] = rng.uniform(0.1, 3.0, k)
        return block


def _away_from_zero(rng, lo: float, hi: float, k: int) -> np.ndarray:
    """Uniform in (lo, hi) but with |x| ≥ 0.2 when the range straddles 0."""
    x = rng.uniform(lo, hi, k)
    if lo < 0 < hi:
        near = np.abs(x) < 0.2
        x = np.where(near, np.sign(x + 1e-300) * (0.2 + rng.uniform(0, 0.3, k)), x)
    return x


@dataclass
class Points:
    """Sample points as arrays, one entry per point, and the parameter group of each point."""

    env: dict[sp.Symbol, np.ndarray]
    group: np.ndarray
    _mp_env: dict | None = None

    @property
    def n(self) -> int:
        return len(self.group)

    def arrays(self, backend=FLOAT) -> dict:
        if backend is FLOAT:
            return self.env
        if self._mp_env is None:
            self._mp_env = {s: MP.array(v) for s, v in self.env.items()}
        return self._mp_env

    def point(self, i: int, symbols: Iterable[sp.Symbol] | None = None) -> dict[str, float]:
        """Point i as {name: value} (the witness of a difference), for the named symbols."""
        keep = self.env if symbols is None else [s for s in symbols if s in self.env]
        names = {s: s.name for s in keep}  # not str(s): sympy's printer is slow
        return {
            names[s]: float(f"{float(self.env[s][i]):.6g}") for s in sorted(keep, key=names.get)
        }


# --- the decision -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Outcome:
    """A decision: equal or not, which method decided, the worst ratio of residual to term size,
    and when different the index of a point where the answers differ (and why)."""

    equal: bool
    method: str
    worst: float
    where: int | None = None
    reason: str = ""


Residual = Callable[[object], tuple[np.ndarray, np.ndarray]]


def decide(residual: Residual) -> Outcome:
    """Decide whether `residual` vanishes identically. `residual(backend)` returns arrays
    (r, s) of the residual and the size of the terms it is made of, per point (a second axis
    is allowed: several components per point). nan in r means the answer is undefined there."""
    with np.errstate(all="ignore"):
        r, s = residual(FLOAT)
        r, s = np.asarray(r, dtype=float), np.asarray(s, dtype=float)
        ratio = _ratio(r, s)
    per_point = ratio.reshape(ratio.shape[0], -1).max(axis=1) if ratio.ndim > 1 else ratio
    if not np.all(np.isfinite(per_point)):
        where = int(np.flatnonzero(~np.isfinite(per_point))[0])
        return Outcome(False, "numeric", math.inf, where, "undefined")
    worst = float(per_point.max()) if per_point.size else 0.0
    if worst < EQUAL_BELOW:
        return Outcome(True, "numeric", worst)
    if worst > DIFFERENT_ABOVE:
        return Outcome(False, "numeric", worst, int(per_point.argmax()))
    with mpmath.workdps(MP_DIGITS), np.errstate(all="ignore"):
        r_mp, s_mp = residual(MP)
        ratio_mp = np.array(
            [_mp_ratio(a, b) for a, b in zip(np.ravel(r_mp), np.ravel(s_mp), strict=True)]
        ).reshape(np.shape(r_mp))
    per_point = (
        ratio_mp.reshape(ratio_mp.shape[0], -1).max(axis=1) if ratio_mp.ndim > 1 else ratio_mp
    )
    worst_mp = float(per_point.max())
    if worst_mp < MP_EQUAL_BELOW:
        return Outcome(True, "numeric+mpmath50", worst_mp)
    return Outcome(False, "numeric+mpmath50", worst_mp, int(per_point.argmax()))


def _ratio(r: np.ndarray, s: np.ndarray) -> np.ndarray:
    """|r| / s, with 0/0 = 0 (an answer and reference that are both exactly zero agree) and
    r/0 = inf for r ≠ 0; nan where r is nan (undefined). Call under np.errstate."""
    ratio = np.abs(r) / s
    both_zero = (s == 0) & (r == 0)
    if both_zero.any():
        ratio = np.where(both_zero, 0.0, ratio)
    return ratio


def _mp_ratio(r, s) -> float:
    if not (mpmath.isfinite(r) and mpmath.isfinite(s)):
        return math.inf
    if s == 0:
        return 0.0 if r == 0 else math.inf
    return float(abs(r) / s)


# --- compiled expressions ---------------------------------------------------------------------


@dataclass(frozen=True)
class Compiled:
    """An expression compiled by top-level terms: its value is their sum, its size the sum of
    their absolute values."""

    expr: sp.Expr
    program: Program

    @classmethod
    def of(cls, expr: sp.Expr) -> Compiled:
        return cls(expr, compile_program(top_terms(sp.S(expr))))

    @property
    def symbols(self) -> frozenset[sp.Symbol]:
        return self.program.symbols

    def values(self, env: Mapping, backend=FLOAT) -> tuple[np.ndarray, np.ndarray]:
        """(value, size) at the points of env."""
        terms = run(self.program, env, backend)
        return _sum(terms), _sum(abs(x) for x in terms)

    def hyperdual(self, env: Mapping, backend=FLOAT) -> list:
        return run_hyperdual(self.program, env, backend)


def _sum(items: Iterable):
    total = 0
    for x in items:
        total = total + x
    return total


def to_length(x, n: int, backend=FLOAT):
    """x as an array of length n (constants come out of the evaluator as scalars)."""
    if np.ndim(x) == 0:
        return np.full(n, x, dtype=float if backend is FLOAT else object)
    return x


def finite_mask(compiled: Sequence[Compiled]) -> Callable[[dict], np.ndarray]:
    """A validity test for sampling: every compiled reference is finite at the point."""

    def valid(env: dict) -> np.ndarray:
        n = len(next(iter(env.values())))
        ok = np.ones(n, dtype=bool)
        with np.errstate(all="ignore"):
            for c in compiled:
                value, size = c.values(env)
                ok &= np.isfinite(to_length(value, n)) & np.isfinite(to_length(size, n))
        return ok

    return valid


# --- expressions -------------------------------------------------------------------------------


def reference_values(reference: Compiled, points: Points, backend=FLOAT) -> tuple:
    """A reference's (value, size) at the points; in float64 computed once per points."""
    env = points.arrays(backend)
    if backend is not FLOAT:
        return reference.values(env, backend)
    return _memo_inputs(
        f"values:{id(reference)}", env, (), lambda: (reference, reference.values(env))
    )[1]


def expressions_equal(answer: Compiled, reference: Compiled, points: Points) -> Outcome:
    """answer ≡ reference on the domain: a − b vanishes at every point, relative to the terms."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = reference_values(reference, points, backend)
        return to_length(a - b, points.n, backend), to_length(sa + sb, points.n, backend)

    return decide(residual)


def differ_by_constant(answer: Compiled, reference: Compiled, points: Points) -> Outcome:
    """answer − reference is the same number at all points of a parameter group (another zero
    level of a potential): the residual is the spread of the difference within each group."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = reference_values(reference, points, backend)
        d = to_length(a - b, points.n, backend)
        first = d[_group_starts(points)]
        return d - first, to_length(sa + sb, points.n, backend) + abs(first)

    return decide(residual)


def _group_starts(points: Points) -> np.ndarray:
    """For each point, the index of the first point of its group."""
    starts = np.searchsorted(points.group, points.group)
    return starts


def values_equal(answer: Compiled, values: Callable[[object], tuple], points: Points) -> Outcome:
    """answer ≡ a reference given only by its values at the points (`values(backend)` returns
    (value, size)), e.g. the momenta of a student's own Lagrangian."""

    def residual(backend):
        env = points.arrays(backend)
        a, sa = answer.values(env, backend)
        b, sb = values(backend)
        return to_length(a - b, points.n, backend), to_length(sa, points.n, backend) + abs(sb)

    return decide(residual)


# --- Euler–Lagrange expressions, numerically ------------------------------------------------------


_MEMO: dict = {}
_MEMO_SIZE = 256


def _memo_inputs(kind: str, env: Mapping, jets: Sequence[Jet], make: Callable[[], dict]) -> dict:
    """Inputs derived from the sample points alone (tiled copies, hyper-dual seeds), built once
    per points instead of once per answer. float64 only; the entry holds `env` itself, so an
    id is never mistaken for another's. Sample points never change once drawn; an env that
    did would be served stale inputs. Callers must not modify what they get."""
    key = (kind, id(env), tuple(jets))
    hit = _MEMO.get(key)
    if hit is not None and hit[0] is env:
        return hit[1]
    value = make()
    if len(_MEMO) >= _MEMO_SIZE:
        _MEMO.clear()
    _MEMO[key] = (env, value)
    return value


def _tile(x, copies: int, n: int, backend):
    return np.tile(to_length(x, n, backend), copies)


def _unit_blocks(copies: int, n: int, hot: int, backend):
    """An array of `copies` blocks of n entries: ones in block `hot`, zeros elsewhere."""
    arr = np.zeros(copies * n)
    arr[hot * n : (hot + 1) * n] = 1.0
    return backend.array(arr) if backend is not FLOAT else arr


def euler_lagrange_values(L: Compiled, jets: Sequence[Jet], env: Mapping, backend=FLOAT):
    """E_j = D_t(∂L/∂q̇_j) − ∂L/∂q_j at the points of env, and the size of its terms; both of
    shape (points, coordinates).

    Hyper-dual evaluation: ε₁ is the direction of the motion (∂t = 1, ∂q = q̇, ∂q̇ = q̈), ε₂ is
    ∂/∂q̇_j in copy j and ∂/∂q_j in copy n + j; then D_t ∂L/∂q̇_j is the ε₁ε₂ part of copy j and
    ∂L/∂q_j the ε₂ part of copy n + j.
    """
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = 2 * n
    for j in jets:
        if j.ddot in L.symbols:
            raise ValueError("a Lagrangian must not contain accelerations")
    if backend is FLOAT:
        seeds = _memo_inputs("el", env, jets, lambda: _el_seeds(jets, env, env, backend))
    else:
        seeds = _el_seeds(jets, env, L.symbols, backend)
    terms = L.hyperdual({s: seeds[s] for s in L.symbols if s in seeds}, backend)
    dtype = float if backend is FLOAT else object
    E = np.zeros((n_pts, n), dtype=dtype)
    S = np.zeros((n_pts, n), dtype=dtype)
    for term in terms:
        d = to_length(term[3], copies * n_pts, backend)
        c = to_length(term[2], copies * n_pts, backend)
        for k in range(n):
            dk = d[k * n_pts : (k + 1) * n_pts]
            ck = c[(n + k) * n_pts : (n + k + 1) * n_pts]
            E[:, k] = E[:, k] + dk - ck
            S[:, k] = S[:, k] + abs(dk) + abs(ck)
    return E, S


def _el_seeds(jets: Sequence[Jet], env: Mapping, wanted, backend) -> dict:
    """Hyper-dual inputs of the symbols in `wanted` for `euler_lagrange_values`."""
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = 2 * n
    seeds: dict = {}
    for s in wanted:
        if s in env:
            seeds[s] = (_tile(env[s], copies, n_pts, backend), 0, 0, 0)
    for k, j in enumerate(jets):
        if j.q in wanted:
            seeds[j.q] = (
                _tile(env[j.q], copies, n_pts, backend),
                _tile(env[j.dot], copies, n_pts, backend),
                _unit_blocks(copies, n_pts, n + k, backend),
                0,
            )
        if j.dot in wanted:
            seeds[j.dot] = (
                _tile(env[j.dot], copies, n_pts, backend),
                _tile(env[j.ddot], copies, n_pts, backend),
                _unit_blocks(copies, n_pts, k, backend),
                0,
            )
    if t in wanted:
        seeds[t] = (_tile(env[t], copies, n_pts, backend), 1, 0, 0)
    return seeds


def common_factor(factors: Sequence[float]) -> float | None:
    """The factor shared by every parameter group (within 1e-8), or None when they differ
    (a factor that depends on the parameters) or there are none."""
    if not factors:
        return None
    c0 = factors[0]
    return c0 if all(abs(c - c0) <= 1e-8 * max(1.0, abs(c0)) for c in factors) else None


@dataclass(frozen=True)
class LagrangianMatch:
    """How a Lagrangian relates to a reference: E(L′) = c E(L) with c per parameter group."""

    outcome: Outcome
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
        varies = (spread > 1e-12 * np.bincount(group, sb * sb)) & (
            np.bincount(group, da * da) > 1e-12 * np.bincount(group, sa * sa)
        )
    if not (np.all(ratio < EQUAL_BELOW) and np.all(varies)):
        return None
    shifted = bool(np.any(np.abs(k) > 1e-9 * size))
    return AffineMatch(tuple(float(x) for x in c), shifted, float(ratio.max()))


def lagrangians_match(
    answer: Compiled, reference: Compiled | Callable, jets: Sequence[Jet], points: Points
) -> LagrangianMatch:
    """Is E(answer) = c E(reference) for a c constant in (q, q̇, q̈, t)? c is fitted by least
    squares in each parameter group, then the residual E(L′) − c E(L) is decided."""
    found: dict[str, list] = {}

    def residual(backend):
        env = points.arrays(backend)
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
            num = _sum((Ea[rows] * Eb[rows]).ravel())
            den = _sum((Eb[rows] * Eb[rows]).ravel())
            c = num / den if den != 0 else 0 * num
            factors.append(c)
            r[rows] = Ea[rows] - c * Eb[rows]
            s[rows] = Sa[rows] + abs(c) * Sb[rows]
        found["c"] = factors
        return r, s

    outcome = decide(residual)
    return LagrangianMatch(outcome, tuple(float(c) for c in found.get("c", ())), found.get("el"))


# --- equations linear in q̈: rows [A | c] at the points -------------------------------------------


@dataclass
class Rows:
    """Equations E = A q̈ + c at each point: `coef` (points, equations, n + 1) holds [A | c],
    `size` (points, equations) the size of their terms, `nonlinear` (points, equations) the
    part that is not linear in q̈ (zero for a proper equation of motion)."""

    coef: np.ndarray
    size: np.ndarray
    nonlinear: np.ndarray


def acceleration_blocks(jets: Sequence[Jet], env: Mapping, backend=FLOAT) -> dict:
    """env repeated n + 2 times with q̈ = 0, e_1, …, e_n, and the drawn q̈."""
    if backend is FLOAT:
        return _memo_inputs("blocks", env, jets, lambda: _acceleration_blocks(jets, env, FLOAT))
    return _acceleration_blocks(jets, env, backend)


def _acceleration_blocks(jets: Sequence[Jet], env: Mapping, backend) -> dict:
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = n + 2
    stacked = {s: np.tile(v, copies) for s, v in env.items()}
    for k, j in enumerate(jets):
        q_dd = np.zeros(copies * n_pts)
        q_dd[(k + 1) * n_pts : (k + 2) * n_pts] = 1.0
        arr = backend.array(q_dd) if backend is not FLOAT else q_dd
        arr[(n + 1) * n_pts :] = env[j.ddot]
        stacked[j.ddot] = arr
    return stacked


def rows_from_values(
    values: np.ndarray, sizes: np.ndarray, jets: Sequence[Jet], env: Mapping
) -> Rows:
    """Rows from equation values at the acceleration blocks: values (blocks·points, equations)."""
    n = len(jets)
    n_pts = len(next(iter(env.values())))
    blocks = values.reshape(n + 2, n_pts, -1)
    size_blocks = sizes.reshape(n + 2, n_pts, -1)
    c = blocks[0]
    A = [blocks[k + 1] - c for k in range(n)]
    coef = np.stack(A + [c], axis=-1)  # (points, equations, n + 1)
    predicted = c + _sum(A[k] * env[j.ddot][:, None] for k, j in enumerate(jets))
    nonlinear = blocks[n + 1] - predicted
    size = size_blocks.max(axis=0) if blocks.dtype != object else _mp_max(size_blocks)
    return Rows(coef, size, nonlinear)


def _mp_max(arr: np.ndarray) -> np.ndarray:
    out = arr[0].copy()
    for k in range(1, arr.shape[0]):
        out = np.where(arr[k] > out, arr[k], out)
    return out


def equation_rows(
    equations: Sequence[Compiled], jets: Sequence[Jet], env: Mapping, backend=FLOAT
) -> Rows:
    """Rows [A | c] of equations given as expressions (lhs − rhs)."""
    stacked = acceleration_blocks(jets, env, backend)
    n_all = len(next(iter(stacked.values())))
    vals, sizes = [], []
    for eq in equations:
        v, s = eq.values(stacked, backend)
        vals.append(to_length(v, n_all, backend))
        sizes.append(to_length(s, n_all, backend))
    return rows_from_values(np.stack(vals, axis=-1), np.stack(sizes, axis=-1), jets, env)


def lagrangian_rows(L: Compiled, jets: Sequence[Jet], env: Mapping, backend=FLOAT) -> Rows:
    """Rows [A | c] of the Euler–Lagrange equations of L (from hyper-dual values)."""
    stacked = acceleration_blocks(jets, env, backend)
    E, S = euler_lagrange_values(L, jets, stacked, backend)
    return rows_from_values(E, S, jets, env)


def in_span(student: Rows, reference: Rows, k: int, backend=FLOAT) -> tuple[np.ndarray, np.ndarray]:
    """Residual of student row k outside the span of the reference rows, and its size, per
    point. The size counts the student's terms and the rounding the reference rows carry."""
    if backend is FLOAT:
        return _in_span_float(
            student.coef[:, k, :].astype(float),
            student.size[:, k].astype(float),
            reference.coef.astype(float),
            reference.size.astype(float),
        )
    n_pts = student.coef.shape[0]
    dtype = object
    r = np.zeros(n_pts, dtype=dtype)
    s = np.zeros(n_pts, dtype=dtype)
    for p in range(n_pts):
        R = reference.coef[p]  # (m, n + 1)
        x = student.coef[p, k]
        res = _project_out(R, x, backend)
        ref_norms = [_norm(row) for row in R]
        rel_ref = max(
            (sz / nr if nr != 0 else 0) for sz, nr in zip(reference.size[p], ref_norms, strict=True)
        )
        r[p] = _norm(res)
        s[p] = student.size[p, k] + _norm(x) * rel_ref
    return r, s


def _in_span_float(x: np.ndarray, size: np.ndarray, R: np.ndarray, R_size: np.ndarray):
    """in_span for all points at once: x (points, n+1), R (points, m, n+1)."""
    with np.errstate(all="ignore"):
        Q, _ = np.linalg.qr(np.transpose(R, (0, 2, 1)))  # (points, n+1, m): basis of the rows
        res = x - np.einsum("pij,pj->pi", Q, np.einsum("pji,pj->pi", Q, x))
        ref_norm = np.linalg.norm(R, axis=2)
        rel_ref = np.max(
            np.where(ref_norm > 0, R_size / np.where(ref_norm > 0, ref_norm, 1), 0), axis=1
        )
        return np.linalg.norm(res, axis=1), size + np.linalg.norm(x, axis=1) * rel_ref


def _norm(v):
    return _sum(abs(x) ** 2 for x in v) ** 0.5 if len(v) else 0


def _project_out(R: np.ndarray, x: np.ndarray, backend):
    """x minus its least-squares projection on the row space of R."""
    if backend is FLOAT:
        coeffs, *_ = np.linalg.lstsq(R.T.astype(float), x.astype(float), rcond=None)
        return x - R.T @ coeffs
    Rm = mpmath.matrix(R.tolist())
    xm = mpmath.matrix(list(x))
    G = Rm * Rm.T
    try:
        y = mpmath.lu_solve(G, Rm * xm)
    except ZeroDivisionError:
        return np.array(list(x), dtype=object)
    res = xm - Rm.T * y
    return np.array([res[i] for i in range(res.rows)], dtype=object)


def row_rank(coef: np.ndarray, rows: Sequence[int]) -> int:
    """The rank of the chosen rows at a typical point (the most common rank over the points)."""
    if not rows:
        return 0
    ranks = []
    for p in range(coef.shape[0]):
        M = np.array(coef[p, list(rows)], dtype=float)
        norms = np.linalg.norm(M, axis=1)
        M = M[norms > 0] / norms[norms > 0, None]
        if M.size == 0:
            ranks.append(0)
            continue
        sv = np.linalg.svd(M, compute_uv=False)
        ranks.append(int((sv > 1e-8 * sv[0]).sum()))
    return int(np.bincount(ranks).argmax())


def solve_accelerations(reference: Rows, backend=FLOAT) -> np.ndarray:
    """q̈ with A q̈ = −c at every point (the motion of the reference): shape (points, n)."""
    n_pts, m, cols = reference.coef.shape
    n = cols - 1
    if backend is FLOAT:
        A = reference.coef[:, :, :n].astype(float)
        b = -reference.coef[:, :, n].astype(float)
        if m == n:
            return np.linalg.solve(A, b[..., None])[..., 0]
        return np.stack([np.linalg.lstsq(A[p], b[p], rcond=None)[0] for p in range(n_pts)])
    out = np.empty((n_pts, n), dtype=object)
    for p in range(n_pts):
        A = mpmath.matrix(reference.coef[p, :, :n].tolist())
        b = mpmath.matrix([-x for x in reference.coef[p, :, n]])
        x = mpmath.lu_solve(A, b)
        for k in range(n):
            out[p, k] = x[k]
    return out


# --- derivatives of an expression along the coordinates -------------------------------------------


def gradient(expr: Compiled, variables: Sequence[sp.Symbol], env: Mapping, backend=FLOAT):
    """∂expr/∂v for each v in `variables`, per term: a list over terms of arrays
    (points, variables), from one dual evaluation with one copy per variable."""
    n_pts = len(next(iter(env.values())))
    copies = max(1, len(variables))
    hd: dict = {}
    for s in expr.symbols:
        if s in env:
            hd[s] = (_tile(env[s], copies, n_pts, backend), 0, 0, 0)
    for k, v in enumerate(variables):
        if v in expr.symbols:
            hd[v] = (hd[v][0], _unit_blocks(copies, n_pts, k, backend), 0, 0)
    per_term = []
    for term in expr.hyperdual(hd, backend):
        d = to_length(term[1], copies * n_pts, backend)
        per_term.append(d.reshape(copies, n_pts).T)
    return per_term


def directions(jets: Sequence[Jet]) -> list[sp.Symbol]:
    """The variables of a function on the jet space without accelerations: t, q, q̇."""
    return [t] + [j.q for j in jets] + [j.dot for j in jets]


def time_derivative_on_shell(
    Q: Compiled, jets: Sequence[Jet], env: Mapping, accelerations: np.ndarray, backend=FLOAT
):
    """D_t Q = ∂Q/∂t + Σ q̇ ∂Q/∂q + Σ q̈ ∂Q/∂q̇ with q̈ the reference accelerations, and the
    size of its contributions; plus the gradient (for the "is it a constant" test)."""
    variables = directions(jets)
    grads = gradient(Q, variables, env, backend)
    n = len(jets)
    speed = [1] + [env[j.dot] for j in jets] + [accelerations[:, k] for k in range(n)]
    total, size = 0, 0
    grad_total = 0
    for g in grads:
        for k, v in enumerate(speed):
            contribution = g[:, k] * v
            total = total + contribution
            size = size + abs(contribution)
        grad_total = grad_total + g
    return total, size, grad_total
