"""Sentences about a quantity wrongly offered as conserved that rest on facts of the system, each
fact decided by values at the part's points before it is said: why T + V is not conserved (the
constraint moves, V depends on the velocities, L depends on t) and whether the Jacobi integral h
is; and a quantity that lacks a factor (m l² φ̇ where m l² sin²θ φ̇ is conserved), said only when
the answer times that factor passes the part's own conservation test."""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.matching import full, vanish_rows
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points
from lagrade.mechanics import t
from lagrade.notation import plain

#: Is a quantity conserved (D_t Q = 0 on-shell, Q not a constant): the part's own test.
Conserved = Callable[[Compiled], bool]

_JACOBI = "the Jacobi integral h = Σ q̇ ∂L/∂q̇ − L"


def energy_sentence(problem: Problem, points: Points, conserved: Conserved) -> str:
    """Why the offered T + V (found not conserved by the verdict) is not, as far as values
    show: the constraint moves (T ≠ 0 with every velocity zero, so the positions depend on t),
    V depends on the velocities (a generalized potential: T + V is then not h), L depends on t
    (so h is not conserved either); and h is named conserved only when it passes the test."""
    split = problem.catalogue.split
    env = points.env
    T = problem.compiled_reference("split T", lambda: split.T)
    V = problem.compiled_reference("split V", lambda: split.V)
    L = problem.L
    at_rest = {**env, **{j.dot: np.zeros(points.n) for j in problem.jets}}
    reasons = []
    if _differs(T, {**at_rest}, None, points):  # T(q, 0, t) ≠ 0: the positions move by themselves
        reasons.append("the constraint moves, so energy flows in and out")
    h_conserved = conserved(problem.compiled_reference("h", lambda: problem.system.energy_function))
    if h_conserved:
        if not reasons and _differs(V, env, at_rest, points):
            reasons.append("V depends on the velocities, so T + V is not the energy function")
        why = f": {'; '.join(reasons)}" if reasons else ""
        return f"T + V is not conserved here{why}; {_JACOBI} is."
    shifted = {**env, t: np.asarray(env[t], float) + 0.5} if t in env else None
    if shifted is not None and _differs(L, env, shifted, points):
        reasons.append(
            "L depends on t explicitly, so the Jacobi integral h is not conserved either"
        )
    else:
        reasons.append("the Jacobi integral h is not conserved either")
    return f"T + V is not conserved here: {'; '.join(reasons)}."


def _differs(Q: Compiled, env: dict, other: dict | None, points: Points) -> bool:
    """Q's values at env differ from those at `other` (from zero, without it) at some point,
    beyond rounding of their terms."""
    with np.errstate(all="ignore"):
        a, sa = full(Q.values(env), points.n)
        b, sb = full(Q.values(other), points.n) if other is not None else (0.0 * a, 0.0 * a)
        d, s = np.asarray(a - b, float), np.asarray(sa + sb, float)
    finite = np.isfinite(d) & np.isfinite(s)
    return bool(finite.any()) and not vanish_rows(d[finite][None], s[finite][None])[0]


def missing_factor(problem: Problem, answer: Compiled, conserved: Conserved) -> str | None:
    """ "Q is missing a factor f" for a factor f of a key conserved quantity that depends on the
    coordinates alone (sin²θ of p_φ = m l² sin²θ φ̇), when f·Q is conserved by the part's own
    test; None when no such factor makes it so."""
    for f in _coordinate_factors(problem):
        if conserved(Compiled.of(f * answer.expr)):
            return f"is missing a factor {plain(f)}: {plain(f)} times it is conserved"
    return None


def _coordinate_factors(problem: Problem) -> Iterator[sp.Expr]:
    """The factors of the key's conserved quantities that hold a coordinate and no velocity,
    each power of them down to the first (sin(θ)^2, then sin(θ)), once each."""
    coordinates = {j.q for j in problem.jets}
    velocities = {j.dot for j in problem.jets}
    seen: set = set()
    for q in problem.system.conserved_quantities.values():
        for f in sp.Mul.make_args(sp.factor_terms(sp.expand(q))):
            symbols = f.free_symbols
            if not symbols & coordinates or symbols & velocities:
                continue
            base, exp = f.as_base_exp()
            powers = range(int(exp), 0, -1) if exp.is_Integer and exp > 0 else (1,)
            for k in powers:
                g = base**k if exp.is_Integer else f
                if g not in seen:
                    seen.add(g)
                    yield g
