"""The scene families of the bank, one small module each; `SCENES` lists them in lecture order:
the lecture's eight systems first, then the other standard systems of the course."""

from types import ModuleType

from lagrade.bank.scenes import (
    atwood,
    charged_particle,
    cone_particle,
    coupled_oscillators,
    double_pendulum,
    driven_pendulum,
    free_particle,
    harmonic_oscillator,
    hoop,
    incline_pendulum,
    kepler,
    pendulum_on_cart,
    projectile,
    rolling_cylinder,
    rotating_frame,
    rotating_rod_bead,
    simple_pendulum,
    sliding_ladder,
    spherical_pendulum,
    spring_pendulum,
    two_body_spring,
    wedge,
    wheel,
)
from lagrade.mechanics.scene import Scene

_MODULES: tuple[ModuleType, ...] = (
    # The lecture's eight systems, in the order the lecture works them.
    free_particle,
    wedge,
    hoop,
    projectile,
    kepler,
    wheel,
    charged_particle,
    incline_pendulum,
    # The other standard systems.
    harmonic_oscillator,
    simple_pendulum,
    double_pendulum,
    spherical_pendulum,
    spring_pendulum,
    pendulum_on_cart,
    driven_pendulum,
    atwood,
    coupled_oscillators,
    two_body_spring,
    rotating_rod_bead,
    rotating_frame,
    cone_particle,
    rolling_cylinder,
    sliding_ladder,
)


def _scenes_of(module: ModuleType) -> tuple[Scene, ...]:
    """A module's `SCENE`, or its `SCENES` when it holds two closely related ones."""
    return tuple(getattr(module, "SCENES", None) or (module.SCENE,))


# A stable sort keeps the module order but moves a module's extra, non-lecture scenes (the
# plane projectile) behind the lecture's eight.
SCENES: tuple[Scene, ...] = tuple(
    sorted(
        (scene for module in _MODULES for scene in _scenes_of(module)),
        key=lambda scene: "lecture" not in scene.tags,
    )
)
