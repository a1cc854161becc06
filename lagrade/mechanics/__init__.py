"""Layer 0: Lagrangian mechanics on jets (q, q̇, q̈ as plain symbols), parameter domains, and the
Scene type that the bank's systems are declared with. Imports nothing else of lagrade's but
its errors."""

from lagrade.mechanics.domains import Domain
from lagrade.mechanics.lagrange import Jet, LagrangianSystem, jet, total_derivative
from lagrade.mechanics.scene import PointMass, Quantity, RigidBody, Scene, SceneVariant
from lagrade.mechanics.vanishing import identically_zero

__all__ = [
    "Domain",
    "Jet",
    "LagrangianSystem",
    "PointMass",
    "Quantity",
    "RigidBody",
    "Scene",
    "SceneVariant",
    "identically_zero",
    "jet",
    "total_derivative",
]
