"""The simple pendulum, with its angle from the downward vertical or from the horizontal."""

from sympy import cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bob(s):
    if s.opt["angle_from"] == "vertical":
        return (s.l * sin(s.theta), -s.l * cos(s.theta))
    return (s.l * cos(s.theta), -s.l * sin(s.theta))


SCENE = Scene(
    id="simple_pendulum",
    title="Simple pendulum",
    statement=(
        "A bob of mass m hangs from a fixed point on a massless rod of length l and swings in a "
        "vertical plane. Use the angle {theta} between the rod and the {angle_from}."
    ),
    coordinates=("theta",),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.2, 0.5, 1.0), "mass of the bob"),
        param("l", "positive", "m", (0.25, 0.5, 1.0, 2.0), "length of the pendulum"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=lambda s: (PointMass("bob", s.m, _bob(s)),),
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (c.bob.x**2 + c.bob.y**2 - s.l**2,),
    renames={"theta": ("theta", "phi", "psi")},
    options={"angle_from": ("vertical", "horizontal")},
    quantities=(
        Quantity(
            "small_oscillation_frequency",
            "angular frequency of small oscillations about the lowest point",
            lambda s: sqrt(s.g / s.l),
            "rad/s",
        ),
    ),
)
