"""Bead on a hoop turning at constant angular velocity about its vertical diameter."""

from sympy import acos, cos, sin

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param

SCENE = Scene(
    id="hoop",
    title="Bead on a rotating hoop",
    statement=(
        "A bead of mass m slides without friction on a circular hoop of radius R. The hoop turns "
        "at constant angular velocity omega about its vertical diameter. Use the angle {theta} of "
        "the bead from the bottom of the hoop."
    ),
    coordinates=("theta",),
    parameters=(
        param("m", "positive", "kg", (0.05, 0.1, 0.2), "mass of the bead"),
        param("R", "positive", "m", (0.2, 0.3, 0.5), "radius of the hoop"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("omega", "positive", "rad/s", (8.0, 10.0, 12.0), "angular velocity of the hoop"),
    ),
    bodies=lambda s: (
        PointMass(
            "bead",
            s.m,
            (
                s.R * sin(s.theta) * cos(s.omega * s.t),
                s.R * sin(s.theta) * sin(s.omega * s.t),
                -s.R * cos(s.theta),
            ),
        ),
    ),
    potential=lambda s, bodies: gravity(s.g, bodies, axis="z"),
    constraints=lambda s, c: (
        c.bead.x**2 + c.bead.y**2 + c.bead.z**2 - s.R**2,
        c.bead.x * sin(s.omega * s.t) - c.bead.y * cos(s.omega * s.t),
    ),
    renames={"theta": ("theta", "phi")},
    quantities=(
        Quantity(
            "equilibrium_angle",
            "the off-axis equilibrium angle, which exists when omega^2 R > g",
            lambda s: acos(s.g / (s.omega**2 * s.R)),
            "rad",
        ),
    ),
    tags=("lecture",),
)
