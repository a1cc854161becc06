"""The spherical pendulum: polar angle and azimuth of a bob on a rod; the azimuth is cyclic and
the conical pendulum is its steady motion."""

from sympy import cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param

SCENE = Scene(
    id="spherical_pendulum",
    title="Spherical pendulum",
    statement=(
        "A bob of mass m hangs from a fixed point on a massless rod of length l that can swing "
        "in any direction. Use the angle {theta} of the rod from the downward vertical and its "
        "azimuth {phi} about the vertical. Follow-up: with what angular velocity must the bob go "
        "round so that the rod stays at the constant angle beta from the vertical (a conical "
        "pendulum)?"
    ),
    coordinates=("theta", "phi"),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.2, 0.5), "mass of the bob"),
        param("l", "positive", "m", (0.5, 1.0, 2.0), "length of the rod"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("beta", "(0, pi/2)", "rad", (0.5236, 0.7854, 1.0472), "angle of a conical motion"),
    ),
    bodies=lambda s: (
        PointMass(
            "bob",
            s.m,
            (
                s.l * sin(s.theta) * cos(s.phi),
                s.l * sin(s.theta) * sin(s.phi),
                -s.l * cos(s.theta),
            ),
        ),
    ),
    potential=lambda s, bodies: gravity(s.g, bodies, axis="z"),
    constraints=lambda s, c: (c.bob.x**2 + c.bob.y**2 + c.bob.z**2 - s.l**2,),
    renames={"theta": ("theta", "vartheta"), "phi": ("phi", "psi")},
    quantities=(
        Quantity(
            "conical_angular_velocity",
            "angular velocity of the conical pendulum at angle beta",
            lambda s: sqrt(s.g / (s.l * cos(s.beta))),
            "rad/s",
        ),
    ),
)
