"""Equilibria at rest and small oscillations about a stable one (normal modes).

Glossary (L = ½ q̇ᵀ A q̇ + cᵀ q̇ − U, as in `hamilton`):

- equilibrium at rest   q₀ with q̇ = 0 and q̈ = 0 for all time: ∂U/∂q = 0 at q₀ (L without t)
- mass matrix           M = A(q₀)
- stiffness matrix      K = ∂²U/∂q∂q at q₀
- small oscillations    M δq̈ + K δq = 0, so δq = a cos(ω t + φ) with K a = ω² M a:
                        the generalized symmetric eigenproblem, ω_k = √λ_k
- stable                every λ_k ≥ 0, a zero λ only for a direction U does not change along
                        (a cyclic coordinate, a free translation: a zero mode, ω = 0)

There are no normal modes of K and M alone when L depends on time (a driven support), when
a velocity-dependent potential couples the coordinates (the gyroscopic matrix
G = ∂c/∂q − (∂c/∂q)ᵀ ≠ 0: a charge in a magnetic field, a rotating frame), when U has no
stationary point (gravity on a free body, Kepler's −k/r), or when no stationary point is
stable at the variant's values. `SmallOscillations.why_not` says which.

Example, a pendulum on a cart (x, θ): U = −m g l cos θ, equilibria θ = 0 and θ = π, x free;
θ = 0 is stable, with ω = 0 (x) and ω² = (M + m) g / (M l).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp

from lagrade.mechanics.hamilton import HamiltonianSystem, NotQuadratic
from lagrade.mechanics.lagrange import LagrangianSystem, t

#: Eigenvalues below this fraction of the largest are zero (a zero mode, ω = 0).
ZERO_MODE = 1e-9
#: Matrices up to this size get closed-form frequencies from sympy (diagonal ones always).
CLOSED_FORM_SIZE = 2


@dataclass(frozen=True)
class Equilibrium:
    """A configuration at rest that stays at rest: the coordinates fixed there (symbol → value
    in the parameters), those left free (any value: a zero mode), and M, K there."""

    at: Mapping[sp.Symbol, sp.Expr]
    free: tuple[str, ...]
    mass: sp.Matrix
    stiffness: sp.Matrix


def deciding_values(values: Mapping[sp.Symbol, float], domains: Mapping) -> dict[sp.Symbol, float]:
    """The parameter values that single out the stable equilibrium: a variant's handout values,
    the middle of its sample range for a parameter without one (the declared form, an ad-hoc
    Lagrangian). One rule for the key and the judge, so they choose the same equilibrium."""
    out = {s: float(v) for s, v in values.items()}
    for s, domain in domains.items():
        if s not in out:
            lo, hi = domain.sample_range()
            out[s] = (lo + hi) / 2
    return out


def variant_oscillations(variant) -> SmallOscillations:
    """A scene variant's equilibria and normal modes, at its `deciding_values`."""
    symbols = variant.parameter_symbols
    values = {symbols[n]: v for n, v in variant.values.items()}
    domains = {symbols[n]: d for n, d in variant.domains.items()}
    return small_oscillations(variant.system, deciding_values(values, domains))


def _number(expr: sp.Expr, values: Mapping) -> float | None:
    """A real finite value of expr at `values`, or None."""
    try:
        value = complex(sp.N(expr.xreplace(dict(values)), 20))
    except (TypeError, ValueError):
        return None
    if not np.isfinite(value) or abs(value.imag) > 1e-12 * (1 + abs(value.real)):
        return None
    return value.real


def generalized_eigenvalues(K: np.ndarray, M: np.ndarray) -> np.ndarray:
    """λ with K a = λ M a, ascending (scipy's symmetric-definite solver; M must be positive
    definite, as every kinetic energy's matrix is)."""
    from scipy.linalg import eigh  # scipy on first use: most questions never ask

    return eigh(K, M, eigvals_only=True)


def generalized_modes(K: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """λ ascending and the mode vectors a_k (the columns, M-normalised) of K a = λ M a."""
    from scipy.linalg import eigh

    return eigh(K, M)


def frequencies_from(K: np.ndarray, M: np.ndarray) -> np.ndarray:
    """The angular frequencies √λ, ascending, zero modes as 0 (NaN for an unstable λ < 0)."""
    lam = generalized_eigenvalues(K, M)
    top = max(float(np.abs(lam).max()), 1e-300)
    lam = np.where(np.abs(lam) <= ZERO_MODE * top, 0.0, lam)
    with np.errstate(invalid="ignore"):
        return np.sqrt(lam)


class SmallOscillations:
    """The equilibria of a Lagrangian system at rest and its normal modes about the stable one
    that the given parameter values (a variant's) single out, each derived on first use."""

    def __init__(self, system: LagrangianSystem, values: Mapping[sp.Symbol, float]):
        self.system = system
        self.jets = system.jets
        self.values = dict(values)

    @cached_property
    def _phase(self) -> HamiltonianSystem:
        return HamiltonianSystem(self.system)

    @cached_property
    def obstacle(self) -> str | None:
        """Why the system has no equilibrium at rest with normal modes of K and M alone, before
        any equation is solved; None when it may have one."""
        if self.system.L.has(t):
            return "L depends explicitly on time, so nothing stays at rest"
        try:
            _ = self._phase.velocity_matrix  # raises NotQuadratic
        except NotQuadratic as error:
            return str(error)
        c = self._phase.momentum_offset
        G = sp.Matrix(
            [[sp.diff(c[i], j.q) - sp.diff(c[k], i_j.q) for k, j in enumerate(self.jets)]
             for i, i_j in enumerate(self.jets)]
        )  # fmt: skip
        if sp.simplify(G) != sp.zeros(*G.shape):
            return (
                "a velocity-dependent force (magnetic or Coriolis) couples the coordinates, so "
                "small oscillations are not the normal modes of K and M alone"
            )
        return None

    @cached_property
    def equilibria(self) -> tuple[Equilibrium, ...]:
        """Every stationary point of U that sympy finds in closed form, real at the values."""
        if self.obstacle is not None:
            return ()
        U = self._phase.effective_potential
        moving = [j for j in self.jets if U.has(j.q)]
        if not moving:
            return (self._equilibrium({}),)
        gradient = [sp.diff(U, j.q) for j in moving]
        try:
            found = sp.solve(
                gradient, [j.q for j in moving], dict=True, check=False, simplify=False
            )
        except (NotImplementedError, ValueError):
            return ()
        out = []
        for solution in found:
            # a family (x_1 = x_3, x_2 = x_3: a molecule free to translate): its member with
            # the coordinates left free at 0; those stay free (zero modes)
            unsolved = {j.q: sp.S.Zero for j in self.jets if j.q not in solution}
            solution = {q: sp.S(v).xreplace(unsolved) for q, v in solution.items()}
            if any(sp.simplify(g.xreplace(solution | unsolved)) != 0 for g in gradient):
                continue  # sympy's solver drops an equation it cannot meet (a constant slope)
            if all(_number(v, self.values) is not None for v in solution.values()):
                out.append(self._equilibrium(solution))
        return tuple(out)

    def _equilibrium(self, solution: Mapping[sp.Symbol, sp.Expr]) -> Equilibrium:
        U = self._phase.effective_potential
        fixed = {j.q: self._tidy(solution[j.q]) for j in self.jets if j.q in solution}
        free = tuple(j.name for j in self.jets if j.q not in solution)
        at = {j.q: fixed.get(j.q, sp.S.Zero) for j in self.jets}
        hessian = sp.hessian(U, [j.q for j in self.jets])
        K = hessian.xreplace(at).applyfunc(sp.simplify)
        M = self._phase.velocity_matrix.xreplace(at).applyfunc(sp.simplify)
        return Equilibrium(fixed, free, M, K)

    def _tidy(self, value: sp.Expr) -> sp.Expr:
        """An equilibrium value as a textbook writes it: ±acos(…) for the half-angle form sympy's
        solver gives an angle (−2 atan(√(Rω² − g)/√(Rω² + g)) is −acos(g/(Rω²)))."""
        value = sp.simplify(value)
        if not value.has(sp.atan):
            return value
        cosine = sp.simplify(sp.expand_trig(sp.cos(value)))
        number = _number(value, self.values)
        if number is None or sp.count_ops(cosine) >= sp.count_ops(value):
            return value
        tidy = sp.acos(cosine) if number >= 0 else -sp.acos(cosine)
        again = _number(tidy, self.values)
        return (
            tidy if again is not None and abs(again - number) <= 1e-9 * (1 + abs(number)) else value
        )

    def numeric(
        self, eq: Equilibrium, values: Mapping | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """(K, M) of `eq` as float arrays at `values` (default: the variant's)."""
        values = self.values if values is None else values
        K = np.array(sp.N(eq.stiffness.xreplace(dict(values)), 20).tolist(), dtype=float)
        M = np.array(sp.N(eq.mass.xreplace(dict(values)), 20).tolist(), dtype=float)
        return K, M

    def is_stable(self, eq: Equilibrium) -> bool:
        """Every λ ≥ 0 at the values, and exactly as many zero modes as free directions."""
        K, M = self.numeric(eq)
        if not self.regular(M):
            return False
        lam = generalized_eigenvalues(K, M)
        top = max(float(np.abs(lam).max()), 1e-300)
        zero = int(np.sum(np.abs(lam) <= ZERO_MODE * top))
        return bool(np.all(lam > -ZERO_MODE * top)) and zero == len(eq.free)

    @staticmethod
    def regular(M: np.ndarray) -> bool:
        """M positive definite: the coordinates are not singular there (a spherical pendulum's
        φ at the pole is)."""
        return bool(np.all(np.isfinite(M)) and np.all(np.linalg.eigvalsh(M) > 0))

    @cached_property
    def stable(self) -> Equilibrium | None:
        """The stable equilibrium with the lowest U at the values, or None."""
        U = self._phase.effective_potential
        ranked = []
        for eq in self.equilibria:
            if self.is_stable(eq):
                at = {j.q: eq.at.get(j.q, sp.S.Zero) for j in self.jets}
                ranked.append((_number(U.xreplace(at), self.values) or 0.0, eq))
        ranked.sort(key=lambda pair: pair[0])
        return ranked[0][1] if ranked else None

    @cached_property
    def why_not(self) -> str | None:
        """Why there are no normal modes (None: `stable` has them)."""
        if self.obstacle is not None:
            return self.obstacle
        if not self.equilibria:
            return "U has no stationary point that sympy finds, so there is no equilibrium at rest"
        if self.stable is None:
            if not any(self.regular(self.numeric(eq)[1]) for eq in self.equilibria):
                return (
                    "the coordinates are singular at every equilibrium (the mass matrix is not "
                    "invertible there), so small oscillations need other coordinates"
                )
            return "no equilibrium at rest is stable at these values"
        return None

    @cached_property
    def frequencies(self) -> tuple[sp.Expr, ...] | None:
        """The angular frequencies about `stable` in closed form (zero modes as 0), when sympy
        gives them (a diagonal problem, or at most CLOSED_FORM_SIZE coordinates); else None."""
        eq = self.stable
        if eq is None:
            return None
        M, K = eq.mass, eq.stiffness
        if not (M.is_diagonal() and K.is_diagonal()) and M.rows > CLOSED_FORM_SIZE:
            return None
        if M.is_diagonal() and K.is_diagonal():
            squares = [K[k, k] / M[k, k] for k in range(M.rows)]
        else:
            squares = []
            for value, times in (M.inv() * K).eigenvals().items():
                squares += [value] * times
        out = [sp.sqrt(sp.factor(sp.simplify(s))) for s in squares]
        return tuple(sorted(out, key=lambda w: _number(w, self.values) or 0.0))

    @cached_property
    def mode_shapes(self) -> tuple[tuple[sp.Expr, tuple[sp.Expr, ...]], ...] | None:
        """(ω, a) of each oscillating mode about `stable` in closed form, a solving
        (K − ω² M) a = 0 scaled so that its first nonzero entry is 1 (a degenerate ω once per
        vector of a basis of its plane); None when the frequencies have no closed form."""
        eq, closed = self.stable, self.frequencies
        if eq is None or closed is None:
            return None
        out = []
        for w in dict.fromkeys(closed):
            if w == 0:
                continue
            basis = (eq.stiffness - w**2 * eq.mass).applyfunc(sp.simplify).nullspace(simplify=True)
            for vector in basis:
                a = list(vector)
                first = next(x for x in a if sp.simplify(x) != 0)
                out.append((w, tuple(sp.factor(sp.simplify(x / first)) for x in a)))
        return tuple(out)

    def numeric_mode_shapes(self) -> list[tuple[float, np.ndarray]]:
        """(ω, a) of each oscillating mode about `stable` at the variant's values, by scipy's
        `eigh(K, M)`, each a scaled so that its largest entry is 1 (for a key when `mode_shapes`
        has no closed form)."""
        if self.stable is None:
            return []
        lam, vectors = generalized_modes(*self.numeric(self.stable))
        top = max(float(np.abs(lam).max()), 1e-300)
        return [
            (float(np.sqrt(value)), vectors[:, k] / vectors[np.abs(vectors[:, k]).argmax(), k])
            for k, value in enumerate(lam)
            if value > ZERO_MODE * top
        ]

    def numeric_frequencies(self, values: Mapping | None = None) -> np.ndarray | None:
        """The angular frequencies about `stable` at `values` (default: the variant's), by
        scipy's generalized symmetric eigensolver; None without a stable equilibrium."""
        if self.stable is None:
            return None
        return frequencies_from(*self.numeric(self.stable, values))


def small_oscillations(system: LagrangianSystem, values) -> SmallOscillations:
    """Equilibria and normal modes of `system` at the parameter `values` (symbol → number),
    computed once per values."""
    cache = system.__dict__.setdefault("_oscillations", {})
    key = tuple(sorted((s.name, float(v)) for s, v in values.items()))
    if key not in cache:
        cache[key] = SmallOscillations(system, values)
    return cache[key]
