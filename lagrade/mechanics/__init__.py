"""Layer 0: Lagrangian mechanics on jets (q, q̇, q̈ as plain symbols), parameter domains, and the
Scene type that the bank's systems are declared with. Imports nothing else of lagrade's but
its errors."""

from lagrade.mechanics.domains import Domain
from lagrade.mechanics.hamilton import HamiltonianSystem, NotQuadratic, momentum_jet, momentum_name
from lagrade.mechanics.lagrange import Jet, LagrangianSystem, jet, total_derivative
from lagrade.mechanics.oscillations import (
    Equilibrium,
    SmallOscillations,
    frequencies_from,
    variant_oscillations,
)
from lagrade.mechanics.scene import PointMass, Quantity, RigidBody, Scene, SceneVariant

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
    "SmallOscillations",
    "frequencies_from",
    "jet",
    "momentum_jet",
    "momentum_name",
    "total_derivative",
    "variant_oscillations",
]
