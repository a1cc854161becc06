"""lagrade's problem bank: declarative scenes and the Lagrangian mechanics that solves them."""

from .assign import generate
from .bank import get_scene, scene_ids
from .domains import Domain
from .errors import LagradeError, SceneError, UnknownSceneError
from .mechanics import Jet, LagrangianSystem, jet, total_derivative
from .scene import Scene, SceneVariant

__all__ = [
    "Domain",
    "Jet",
    "LagradeError",
    "LagrangianSystem",
    "Scene",
    "SceneError",
    "SceneVariant",
    "UnknownSceneError",
    "generate",
    "get_scene",
    "jet",
    "scene_ids",
    "total_derivative",
]
