"""Lagrange's equations with dissipation and given generalized forces, and what they still
conserve.

A Rayleigh dissipation function F(q, q̇, t) (½ b ẋ² for a dashpot) and generalized forces Q_j
that no potential gives (a drive F₀ cos ωt) enter the equations of motion beside L:

    E_j + ∂F/∂q̇_j = Q_j,      E_j = D_t ∂L/∂q̇_j − ∂L/∂q_j,

so the rows this system calls its Euler–Lagrange expressions are E_j + R_j with
R_j = ∂F/∂q̇_j − Q_j, and everything built on them (mass matrix, forcing, accelerations, the
judge's rows and its on-shell time derivatives) follows the damped motion.

What is conserved is decided by these equations, not by L alone: a quantity C that L's own
motion conserves (p_j of a cyclic q_j, the energy function h) changes along the damped motion
at the rate −(∂C/∂q̇)ᵀ A⁻¹ R (A the mass matrix; the accelerations shift by −A⁻¹ R). For p_j
that is −R_j, for h it is −Σ q̇_j R_j: a damped oscillator conserves nothing.

Example, a damped oscillator: L = ½ m ẋ² − ½ k x², F = ½ b ẋ², E = m ẍ + k x + b ẋ, and h =
½ m ẋ² + ½ k x² is not conserved (D_t h = −b ẋ²).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import sympy as sp

from lagrade.mechanics.lagrange import Jet, LagrangianSystem, Ranges


class DissipativeSystem(LagrangianSystem):
    """L with a Rayleigh function `dissipation` and generalized `forces` (one per coordinate,
    in order): the momenta, cyclic coordinates and energy function are L's; the equations of
    motion and the conserved quantities are the damped, driven motion's."""

    def __init__(
        self,
        L: sp.Expr,
        jets: Sequence[Jet],
        dissipation: sp.Expr = sp.S.Zero,
        forces: Sequence[sp.Expr] = (),
        ranges: Ranges | None = None,
    ):
        super().__init__(L, jets, ranges)
        self.dissipation = sp.expand(dissipation)
        self.forces = tuple(sp.expand(q) for q in forces) or (sp.S.Zero,) * len(self.jets)
        if len(self.forces) != len(self.jets):
            raise ValueError("one generalized force per coordinate")
        #: The motion L alone gives (its equations, its conserved quantities).
        self.conservative = LagrangianSystem(L, jets)

    @cached_property
    def nonconservative(self) -> tuple[sp.Expr, ...]:
        """R_j = ∂F/∂q̇_j − Q_j, what the equations of motion add to E_j."""
        return tuple(
            sp.expand(sp.diff(self.dissipation, j.dot) - Q)
            for j, Q in zip(self.jets, self.forces, strict=True)
        )

    @cached_property
    def euler_lagrange(self) -> tuple[sp.Expr, ...]:  # type: ignore[override]
        """E_j + ∂F/∂q̇_j − Q_j, expanded; = 0 are the equations of motion."""
        return tuple(
            sp.expand(e + r)
            for e, r in zip(self.conservative.euler_lagrange, self.nonconservative, strict=True)
        )

    @cached_property
    def conserved_quantities(self) -> dict[str, sp.Expr]:  # type: ignore[override]
        """Those of L's conserved quantities that the damped, driven motion still conserves:
        their rate −(∂C/∂q̇)ᵀ A⁻¹ R vanishes identically."""
        found = self.conservative.conserved_quantities
        R = sp.Matrix(self.nonconservative)
        if R.is_zero_matrix:
            return dict(found)
        shift = self.conservative.mass_matrix.LUsolve(R)  # the accelerations move by −A⁻¹ R
        kept = {}
        for name, C in found.items():
            rate = sum(
                (sp.diff(C, j.dot) * s for j, s in zip(self.jets, shift, strict=True)), sp.S.Zero
            )
            if sp.simplify(rate) == 0:
                kept[name] = C
        return kept
