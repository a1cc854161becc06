"""Hamiltonian mechanics on phase space: the Legendre transform of a Lagrangian system.

Glossary (q = (q_1 … q_n), p = (p_1 … p_n); matrices and vectors in the velocities):

- L quadratic in the velocities   L = ½ q̇ᵀ A q̇ + cᵀ q̇ − U, with A(q, t) = ∂²L/∂q̇∂q̇ (the
                                   mass matrix), c(q, t) = ∂L/∂q̇ at q̇ = 0 (e A for a charge),
                                   U(q, t) = −L at q̇ = 0
- canonical momenta                p = ∂L/∂q̇ = A q̇ + c, so q̇ = A⁻¹ (p − c)
- hamiltonian                      H(q, p, t) = Σ p_j q̇_j − L = ½ (p − c)ᵀ A⁻¹ (p − c) + U
                                   (the energy function h written in the momenta)
- hamilton_equations               q̇_j = ∂H/∂p_j,  ṗ_j = −∂H/∂q_j

A momentum is the symbol `p_<coordinate>` (p_theta), its rate `p_<coordinate>_dot`: the jet
of the name p_theta (`momentum_jet`), so the parser and the judge meet the same symbols.

Example, a simple pendulum: L = ½ m l² θ̇² + m g l cos θ, p_θ = m l² θ̇,
H = p_θ²/(2 m l²) − m g l cos θ, θ̇ = p_θ/(m l²), ṗ_θ = −m g l sin θ.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import sympy as sp

from lagrade.mechanics.lagrange import Jet, LagrangianSystem, jet, t

#: The prefix of a momentum's name: p_theta is the momentum conjugate to theta.
MOMENTUM_PREFIX = "p_"


def momentum_name(coordinate: str) -> str:
    """`p_<coordinate>`: how students and keys name the momentum conjugate to a coordinate."""
    return MOMENTUM_PREFIX + coordinate


def momentum_jet(coordinate: str) -> Jet:
    """The momentum conjugate to `coordinate` with its rate: symbols p_q and p_q_dot (real)."""
    return jet(momentum_name(coordinate))


class NotQuadratic(ValueError):
    """L is not quadratic in the velocities (A depends on q̇), or A is singular: the Legendre
    transform has no closed form here."""


class HamiltonianSystem:
    """H(q, p, t) and Hamilton's equations of a Lagrangian system, each derived on first use.

    A question that asks only for H never forms Hamilton's equations; a question about the
    equations never simplifies H."""

    def __init__(self, system: LagrangianSystem):
        self.system = system
        self.jets = system.jets
        self.momentum_jets = tuple(momentum_jet(j.name) for j in self.jets)

    @property
    def momenta(self) -> tuple[sp.Symbol, ...]:
        """The momentum symbols p_q, in the order of the coordinates."""
        return tuple(m.q for m in self.momentum_jets)

    @property
    def rates(self) -> tuple[sp.Symbol, ...]:
        """The symbols of ṗ_q (p_q_dot)."""
        return tuple(m.dot for m in self.momentum_jets)

    @cached_property
    def velocity_matrix(self) -> sp.Matrix:
        """A = ∂p/∂q̇ (the mass matrix of the kinetic term); NotQuadratic when it depends on q̇
        or is singular."""
        A = sp.Matrix(
            [[sp.diff(p, j.dot) for j in self.jets] for p in self.system.generalized_momenta]
        )
        velocities = {j.dot for j in self.jets}
        if A.free_symbols & velocities:
            raise NotQuadratic("L is not quadratic in the velocities; H has no closed form here")
        if A.det() == 0:
            raise NotQuadratic("the velocities cannot be solved from the momenta (A is singular)")
        return A

    @cached_property
    def momentum_offset(self) -> sp.Matrix:
        """c = p at q̇ = 0: the part of the momenta a velocity-dependent potential gives (e A)."""
        rest = {j.dot: 0 for j in self.jets}
        return sp.Matrix([sp.expand(p.xreplace(rest)) for p in self.system.generalized_momenta])

    @cached_property
    def effective_potential(self) -> sp.Expr:
        """U = −L at q̇ = 0 (V, plus the centrifugal term of a turning constraint)."""
        return sp.expand(-self.system.L.xreplace({j.dot: 0 for j in self.jets}))

    @cached_property
    def inverse_matrix(self) -> sp.Matrix:
        """A⁻¹, entry by entry in lowest terms."""
        A = self.velocity_matrix
        if A.is_diagonal():
            inverse = sp.diag(*[1 / A[k, k] for k in range(A.rows)])
        else:
            inverse = A.adjugate() / sp.factor(A.det())
        return inverse.applyfunc(lambda e: sp.factor(sp.cancel(e)))

    @cached_property
    def velocities(self) -> tuple[sp.Expr, ...]:
        """q̇ = A⁻¹ (p − c), in the momenta."""
        shifted = sp.Matrix(self.momenta) - self.momentum_offset
        return tuple(sp.expand(e) for e in self.inverse_matrix * shifted)

    @cached_property
    def hamiltonian(self) -> sp.Expr:
        """H = ½ (p − c)ᵀ A⁻¹ (p − c) + U."""
        shifted = sp.Matrix(self.momenta) - self.momentum_offset
        inverse, n = self.inverse_matrix, len(self.jets)
        # term by term, each coefficient in lowest terms: p_θ²/(2 m l²), (p_y − e B x)²/(2 m)
        kinetic = [inverse[i, i] * shifted[i] ** 2 / 2 for i in range(n)]
        kinetic += [
            inverse[i, k] * shifted[i] * shifted[k] for i in range(n) for k in range(i + 1, n)
        ]
        return sp.Add(*kinetic) + self.effective_potential

    @cached_property
    def hamilton_equations(self) -> tuple[sp.Equality, ...]:
        """q̇_j = ∂H/∂p_j for every j, then ṗ_j = −∂H/∂q_j, each collected by the monomials in
        the momenta with factored coefficients (as a textbook writes them)."""
        H = self.hamiltonian
        forward = [
            sp.Eq(j.dot, self._neat(sp.diff(H, p)))
            for j, p in zip(self.jets, self.momenta, strict=True)
        ]
        back = [
            sp.Eq(r, self._neat(-sp.diff(H, j.q)))
            for j, r in zip(self.jets, self.rates, strict=True)
        ]
        return (*forward, *back)

    def _neat(self, expr: sp.Expr) -> sp.Expr:
        expr = sp.expand(expr)
        try:
            monomials = sp.Poly(expr, *self.momenta).monoms()
        except sp.PolynomialError:
            return expr
        powers = [
            sp.Mul(*[p**k for p, k in zip(self.momenta, m, strict=True)])
            for m in sorted(set(monomials))
            if sum(m) > 0
        ]
        return sp.collect(expr, powers, sp.factor)

    @cached_property
    def is_time_independent(self) -> bool:
        """∂H/∂t = 0, so H is conserved."""
        return not self.system.L.has(t)


def legendre_map(system: LagrangianSystem) -> dict[sp.Symbol, sp.Expr]:
    """p_j in terms of (q, q̇, t), keyed by the momentum symbols: how a point of velocity space
    is carried to phase space."""
    hs = HamiltonianSystem(system)
    return dict(zip(hs.momenta, system.generalized_momenta, strict=True))


def momentum_symbols(coordinates: Sequence[str]) -> tuple[sp.Symbol, ...]:
    """The momentum symbols of `coordinates`."""
    return tuple(momentum_jet(c).q for c in coordinates)


def phase_space(system: LagrangianSystem) -> HamiltonianSystem:
    """H(q, p, t) and Hamilton's equations of `system`, derived once per system (a function
    here, not a method of LagrangianSystem, so that lagrange.py never imports this module,
    which builds on it)."""
    cache = system.__dict__
    if "_phase_space" not in cache:
        cache["_phase_space"] = HamiltonianSystem(system)
    return cache["_phase_space"]
