"""Layer 0: Lagrangian mechanics on jets (q, q̇, q̈ as plain symbols), parameter domains, and the
Scene type that the bank's systems are declared with. Imports nothing else of lagrade's but
the foundation under every layer (its errors, the lazy exports, the bounded memo `recent`).

The small-oscillation names (`Equilibrium`, `SmallOscillations`, `frequencies_from`,
`variant_oscillations`) are loaded on first use: they need numpy and scipy, which reading an
answer (`lagrade parse`) never does."""

from __future__ import annotations

from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "Anchor": "lagrade.mechanics.figure",
    "as_expr": "lagrade.mechanics.bodies",
    "cartesian_symbols": "lagrade.mechanics.reparametrize",
    "coordinates_through_positions": "lagrade.mechanics.reparametrize",
    "coordinates_to_carry": "lagrade.mechanics.reparametrize",
    "DDOT": "lagrade.mechanics.lagrange",
    "deciding_values": "lagrade.mechanics.oscillations",
    "Domain": "lagrade.mechanics.domains",
    "DOT": "lagrade.mechanics.lagrange",
    "Equilibrium": "lagrade.mechanics.oscillations",
    "exact_number": "lagrade.mechanics.domains",
    "FigureHint": "lagrade.mechanics.figure",
    "Fixture": "lagrade.mechanics.figure",
    "FIXTURE_KINDS": "lagrade.mechanics.figure",
    "frequencies_from": "lagrade.mechanics.oscillations",
    "generalized_eigenvalues": "lagrade.mechanics.oscillations",
    "generalized_modes": "lagrade.mechanics.oscillations",
    "HamiltonianSystem": "lagrade.mechanics.hamilton",
    "identically_zero": "lagrade.mechanics.vanishing",
    "Jet": "lagrade.mechanics.lagrange",
    "jet": "lagrade.mechanics.lagrange",
    "lagrange": "lagrade.mechanics.lagrange",  # the module
    "LABEL_PLACES": "lagrade.mechanics.figure",
    "LAGRANGIAN_PARTS": "lagrade.mechanics.scene",
    "LagrangianSystem": "lagrade.mechanics.lagrange",
    "momentum_jet": "lagrade.mechanics.hamilton",
    "momentum_name": "lagrade.mechanics.hamilton",
    "phase_space": "lagrade.mechanics.hamilton",
    "small_oscillations": "lagrade.mechanics.oscillations",
    "NotQuadratic": "lagrade.mechanics.hamilton",
    "Parameter": "lagrade.mechanics.domains",
    "PointMass": "lagrade.mechanics.bodies",
    "Quantity": "lagrade.mechanics.scene",
    "REAL": "lagrade.mechanics.domains",
    "Reparametrized": "lagrade.mechanics.reparametrize",
    "RigidBody": "lagrade.mechanics.bodies",
    "Scene": "lagrade.mechanics.scene",
    "SceneVariant": "lagrade.mechanics.scene",
    "SmallOscillations": "lagrade.mechanics.oscillations",
    "SpatialRigidBody": "lagrade.mechanics.bodies",
    "t": "lagrade.mechanics.lagrange",
    "collapse_trig": "lagrade.mechanics.bodies",
    "total_derivative": "lagrade.mechanics.lagrange",
    "variant_oscillations": "lagrade.mechanics.oscillations",
    "ZERO_MODE": "lagrade.mechanics.oscillations",
}
#: The modules exported as a whole.
_MODULES = {"lagrange"}

__all__ = [
    "Anchor",
    "as_expr",
    "cartesian_symbols",
    "collapse_trig",
    "coordinates_through_positions",
    "coordinates_to_carry",
    "exact_number",
    "DDOT",
    "deciding_values",
    "Domain",
    "DOT",
    "Equilibrium",
    "FigureHint",
    "Fixture",
    "FIXTURE_KINDS",
    "frequencies_from",
    "generalized_eigenvalues",
    "generalized_modes",
    "HamiltonianSystem",
    "identically_zero",
    "Jet",
    "jet",
    "lagrange",
    "LABEL_PLACES",
    "LAGRANGIAN_PARTS",
    "LagrangianSystem",
    "momentum_jet",
    "momentum_name",
    "NotQuadratic",
    "Parameter",
    "phase_space",
    "PointMass",
    "Quantity",
    "REAL",
    "Reparametrized",
    "RigidBody",
    "Scene",
    "SceneVariant",
    "small_oscillations",
    "SmallOscillations",
    "SpatialRigidBody",
    "t",
    "total_derivative",
    "variant_oscillations",
    "ZERO_MODE",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
