"""A planet around a fixed sun in polar coordinates: θ is cyclic and p_θ = m r² θ̇ (the angular
momentum) is conserved."""

from sympy import cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, param

SCENE = Scene(
    id="kepler",
    title="Kepler problem",
    statement=(
        "A planet of mass m moves in the gravitational field of a sun of mass M, which stays at "
        "rest at the origin; the potential is V = -G M m/{r}. Use the polar coordinates {r} and "
        "{theta} of the planet in its orbital plane. Follow-up: with what angular velocity does "
        "the planet go round a circular orbit of radius a?"
    ),
    coordinates=("r", "theta"),
    parameters=(
        param("m", "positive", "kg", (3.30e23, 5.97e24, 6.42e23), "mass of the planet"),
        param("M", "positive", "kg", (1.989e30,), "mass of the sun"),
        param("G", "positive", "m^3/(kg s^2)", (6.674e-11,), "gravitational constant"),
        param("a", "positive", "m", (5.79e10, 1.496e11, 2.279e11), "radius of a circular orbit"),
    ),
    bodies=lambda s: (PointMass("planet", s.m, (s.r * cos(s.theta), s.r * sin(s.theta))),),
    potential=lambda s, bodies: -s.G * s.M * s.m / s.r,
    renames={"r": ("r", "rho"), "theta": ("theta", "phi")},
    quantities=(
        Quantity(
            "circular_angular_velocity",
            "angular velocity of the circular orbit of radius a (Kepler's third law)",
            lambda s: sqrt(s.G * s.M / s.a**3),
            "rad/s",
        ),
    ),
    tags=("lecture",),
)
