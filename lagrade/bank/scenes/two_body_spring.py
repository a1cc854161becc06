"""Two masses joined by a spring, free on a horizontal table, in centre-of-mass and relative
polar coordinates: X, Y and the relative angle are cyclic."""

from sympy import Rational, cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, param


def _bodies(s):
    total = s.m_1 + s.m_2
    rx, ry = s.r * cos(s.theta), s.r * sin(s.theta)
    return (
        PointMass("mass1", s.m_1, (s.X - s.m_2 / total * rx, s.Y - s.m_2 / total * ry)),
        PointMass("mass2", s.m_2, (s.X + s.m_1 / total * rx, s.Y + s.m_1 / total * ry)),
    )


SCENE = Scene(
    id="two_body_spring",
    title="Two bodies joined by a spring",
    statement=(
        "Two pucks of masses m_1 and m_2 slide without friction on a horizontal table, joined by "
        "a spring of constant k and natural length l_0. Use the centre of mass ({X}, {Y}), the "
        "distance {r} between the pucks and the angle {theta} of the line from m_1 to m_2."
    ),
    coordinates=("X", "Y", "r", "theta"),
    parameters=(
        param("m_1", "positive", "kg", (0.1, 0.2, 0.3), "mass of the first puck"),
        param("m_2", "positive", "kg", (0.1, 0.2, 0.4), "mass of the second puck"),
        param("k", "positive", "N/m", (5.0, 10.0, 20.0), "spring constant"),
        param("l_0", "positive", "m", (0.1, 0.2), "natural length of the spring"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: Rational(1, 2) * s.k * (s.r - s.l_0) ** 2,
    renames={"r": ("r", "rho"), "theta": ("theta", "phi")},
    quantities=(
        Quantity(
            "radial_frequency",
            "angular frequency of small stretching oscillations without rotation",
            lambda s: sqrt(s.k * (s.m_1 + s.m_2) / (s.m_1 * s.m_2)),
            "rad/s",
        ),
    ),
)
