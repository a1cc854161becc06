"""A pendulum whose support is driven up and down as a cos ωt: L depends explicitly on t, so h is
not conserved."""

from sympy import cos, sin

from lagrade.mechanics.scene import PointMass, Scene, gravity, param


def _bob(s):
    support = s.a * cos(s.omega * s.t)
    if s.opt["angle_from"] == "vertical":
        return (s.l * sin(s.theta), support - s.l * cos(s.theta))
    return (s.l * cos(s.theta), support - s.l * sin(s.theta))


SCENE = Scene(
    id="driven_pendulum",
    title="Pendulum with an oscillating support",
    statement=(
        "The support of a simple pendulum (bob of mass m, massless rod of length l) is driven "
        "up and down so that its height is {a} cos(omega t). Use the angle {theta} between the "
        "rod and the {angle_from}. Is h conserved?"
    ),
    coordinates=("theta",),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.2, 0.5), "mass of the bob"),
        param("l", "positive", "m", (0.2, 0.5, 1.0), "length of the pendulum"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("a", "positive", "m", (0.01, 0.02, 0.05), "amplitude of the support's motion"),
        param("omega", "positive", "rad/s", (50.0, 100.0, 200.0), "angular frequency of the drive"),
    ),
    bodies=lambda s: (PointMass("bob", s.m, _bob(s)),),
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (c.bob.x**2 + (c.bob.y - s.a * cos(s.omega * s.t)) ** 2 - s.l**2,),
    renames={"theta": ("theta", "phi", "psi")},
    options={"angle_from": ("vertical", "horizontal")},
    tags=("time_dependent",),
)
