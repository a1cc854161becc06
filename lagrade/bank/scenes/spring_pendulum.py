"""The elastic (spring) pendulum in plane polar coordinates: a bob on a spring swinging in a
vertical plane."""

from sympy import Rational, cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bob(s):
    if s.opt["angle_from"] == "vertical":
        return (s.r * sin(s.theta), -s.r * cos(s.theta))
    return (s.r * cos(s.theta), -s.r * sin(s.theta))


SCENE = Scene(
    id="spring_pendulum",
    title="Spring pendulum",
    statement=(
        "A bob of mass m hangs from a fixed point on a massless spring of spring constant k and "
        "natural length l_0, and moves in a vertical plane. Use the length {r} of the spring "
        "and the angle {theta} between the spring and the {angle_from}."
    ),
    coordinates=("r", "theta"),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.2, 0.5), "mass of the bob"),
        param("k", "positive", "N/m", (10.0, 20.0, 50.0), "spring constant"),
        param("l_0", "positive", "m", (0.2, 0.3, 0.5), "natural length of the spring"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=lambda s: (PointMass("bob", s.m, _bob(s)),),
    potential=lambda s, bodies: gravity(s.g, bodies) + Rational(1, 2) * s.k * (s.r - s.l_0) ** 2,
    renames={"r": ("r", "rho"), "theta": ("theta", "phi")},
    options={"angle_from": ("vertical", "horizontal")},
    quantities=(
        Quantity(
            "equilibrium_length",
            "length of the spring with the bob at rest",
            lambda s: s.l_0 + s.m * s.g / s.k,
            "m",
        ),
        Quantity(
            "radial_frequency",
            "angular frequency of small bouncing oscillations",
            lambda s: sqrt(s.k / s.m),
            "rad/s",
        ),
        Quantity(
            "swing_frequency",
            "angular frequency of small swinging oscillations",
            lambda s: sqrt(s.g / (s.l_0 + s.m * s.g / s.k)),
            "rad/s",
        ),
    ),
)
