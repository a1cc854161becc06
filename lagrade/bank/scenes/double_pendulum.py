"""The double pendulum: two bobs on two rods, each angle from the downward vertical; chaotic at
large amplitude, two normal modes at small amplitude."""

from sympy import cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bodies(s):
    x1, y1 = s.l_1 * sin(s.theta_1), -s.l_1 * cos(s.theta_1)
    return (
        PointMass("bob1", s.m_1, (x1, y1)),
        PointMass("bob2", s.m_2, (x1 + s.l_2 * sin(s.theta_2), y1 - s.l_2 * cos(s.theta_2))),
    )


def _mode(s, sign):
    """ω² = g [(m₁+m₂)(l₁+l₂) ± √((m₁+m₂)((m₁+m₂)(l₁+l₂)² − 4 m₁ l₁ l₂))] / (2 m₁ l₁ l₂)."""
    M, L = s.m_1 + s.m_2, s.l_1 + s.l_2
    root = sqrt(M * (M * L**2 - 4 * s.m_1 * s.l_1 * s.l_2))
    return sqrt(s.g * (M * L + sign * root) / (2 * s.m_1 * s.l_1 * s.l_2))


SCENE = Scene(
    id="double_pendulum",
    title="Double pendulum",
    statement=(
        "A bob of mass m_1 hangs from a fixed point on a massless rod of length l_1; from it "
        "hangs a second bob of mass m_2 on a rod of length l_2. Both swing in one vertical "
        "plane. Use the angles {theta_1} and {theta_2} of the rods from the downward vertical."
    ),
    coordinates=("theta_1", "theta_2"),
    parameters=(
        param("m_1", "positive", "kg", (0.5, 1.0, 2.0), "mass of the upper bob"),
        param("m_2", "positive", "kg", (0.5, 1.0, 2.0), "mass of the lower bob"),
        param("l_1", "positive", "m", (0.5, 1.0), "length of the upper rod"),
        param("l_2", "positive", "m", (0.5, 1.0), "length of the lower rod"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (
        c.bob1.x**2 + c.bob1.y**2 - s.l_1**2,
        (c.bob2.x - c.bob1.x) ** 2 + (c.bob2.y - c.bob1.y) ** 2 - s.l_2**2,
    ),
    quantities=(
        Quantity(
            "slow_mode_frequency",
            "the lower normal-mode angular frequency",
            lambda s: _mode(s, -1),
            "rad/s",
        ),
        Quantity(
            "fast_mode_frequency",
            "the higher normal-mode angular frequency",
            lambda s: _mode(s, 1),
            "rad/s",
        ),
    ),
    tags=("chaotic",),
)
