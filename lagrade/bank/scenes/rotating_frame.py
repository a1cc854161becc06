"""A free particle described in a frame turning at constant angular velocity: L gains Coriolis
and centrifugal terms, and the Jacobi integral h is conserved while T is not."""

from sympy import cos, sin

from lagrade.mechanics.scene import PointMass, Scene, param


def _inertial(s):
    """The rotating-frame coordinates (x, y) seen from the inertial frame at time t."""
    c, n = cos(s.omega * s.t), sin(s.omega * s.t)
    return (s.x * c - s.y * n, s.x * n + s.y * c)


SCENE = Scene(
    id="rotating_frame",
    title="Free particle in a rotating frame",
    statement=(
        "A particle of mass m moves freely on a smooth horizontal table. Describe it in a frame "
        "that turns with the constant angular velocity omega about the vertical axis through the "
        "origin, by its coordinates {x} and {y} in that frame. Identify the Coriolis and "
        "centrifugal terms in L. Is T conserved? Is h?"
    ),
    coordinates=("x", "y"),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.5, 1.0), "mass of the particle"),
        param("omega", "positive", "rad/s", (0.5, 1.0, 2.0), "angular velocity of the frame"),
    ),
    bodies=lambda s: (PointMass("particle", s.m, _inertial(s)),),
    potential=lambda s, bodies: 0,
    renames={"x": ("x", "xi"), "y": ("y", "eta")},
    tags=("time_dependent",),
)
