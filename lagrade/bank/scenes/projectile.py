"""A projectile under uniform gravity, in space (x and y cyclic) and in a vertical plane (x
cyclic): the lecture's first example of cyclic coordinates and conserved momenta."""

from lagrade.mechanics.scene import PointMass, Scene, param

_MASS = param("m", "positive", "kg", (0.1, 0.5, 1.0, 2.0), "mass of the projectile")
_G = param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration")

PROJECTILE = Scene(
    id="projectile",
    title="Projectile in space",
    statement=(
        "A projectile of mass m moves in uniform gravity g (no air resistance). Use the "
        "Cartesian coordinates {x}, {y} (horizontal) and {z} (vertical, up). Which coordinates "
        "are cyclic, and which momenta are conserved?"
    ),
    coordinates=("x", "y", "z"),
    parameters=(_MASS, _G),
    bodies=lambda s: (PointMass("ball", s.m, (s.x, s.y, s.z)),),
    potential=lambda s, bodies: s.m * s.g * s.z,
    tags=("lecture",),
)

PROJECTILE_PLANE = Scene(
    id="projectile_plane",
    title="Projectile in a vertical plane",
    statement=(
        "A projectile of mass m is thrown in a vertical plane in uniform gravity g (no air "
        "resistance). Use the horizontal coordinate {x} and the height {y}. Which coordinate is "
        "cyclic, and which momentum is conserved?"
    ),
    coordinates=("x", "y"),
    parameters=(_MASS, _G),
    bodies=lambda s: (PointMass("ball", s.m, (s.x, s.y)),),
    potential=lambda s, bodies: s.m * s.g * s.y,
    renames={"y": ("y", "h")},
)

SCENES = (PROJECTILE, PROJECTILE_PLANE)
