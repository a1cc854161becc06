"""Layer 0: Lagrangian mechanics on jets (q, q̇, q̈ as plain symbols), parameter domains, and the
Scene type that the bank's systems are declared with. Imports nothing else of lagrade's but
its errors.

The small-oscillation names (`Equilibrium`, `SmallOscillations`, `frequencies_from`,
`variant_oscillations`) are loaded on first use: they need numpy and scipy, which reading an
answer (`lagrade parse`) never does."""

from typing import Any

from lagrade.mechanics.domains import Domain
from lagrade.mechanics.hamilton import HamiltonianSystem, NotQuadratic, momentum_jet, momentum_name
from lagrade.mechanics.lagrange import Jet, LagrangianSystem, jet, total_derivative
from lagrade.mechanics.scene import PointMass, Quantity, RigidBody, Scene, SceneVariant
from lagrade.mechanics.vanishing import identically_zero

__all__ = [
    "Domain",
    "Equilibrium",
    "HamiltonianSystem",
    "Jet",
    "LagrangianSystem",
    "NotQuadratic",
    "PointMass",
    "Quantity",
    "RigidBody",
    "Scene",
    "SceneVariant",
    "identically_zero",
    "SmallOscillations",
    "frequencies_from",
    "jet",
    "momentum_jet",
    "momentum_name",
    "total_derivative",
    "variant_oscillations",
]

_OSCILLATIONS = ("Equilibrium", "SmallOscillations", "frequencies_from", "variant_oscillations")


def __getattr__(name: str) -> Any:
    if name in _OSCILLATIONS:
        from lagrade.mechanics import oscillations

        return getattr(oscillations, name)
    raise AttributeError(f"module 'lagrade.mechanics' has no attribute {name!r}")
