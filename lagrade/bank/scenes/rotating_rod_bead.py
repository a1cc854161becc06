"""A bead on a rod that is driven round at constant angular velocity in a horizontal plane: a
time-dependent constraint, yet ∂L/∂t = 0, so h is conserved although T is not."""

from sympy import cos, sin

from lagrade.mechanics.scene import PointMass, Quantity, Scene, param

SCENE = Scene(
    id="rotating_rod_bead",
    title="Bead on a rotating rod",
    statement=(
        "A bead of mass m slides without friction on a straight rod that is driven round at the "
        "constant angular velocity omega about a vertical axis through one end, in a horizontal "
        "plane. Use the bead's distance {r} from the axis. Is the energy conserved? Is h?"
    ),
    coordinates=("r",),
    parameters=(
        param("m", "positive", "kg", (0.05, 0.1, 0.2), "mass of the bead"),
        param("omega", "positive", "rad/s", (2.0, 3.0, 5.0), "angular velocity of the rod"),
    ),
    bodies=lambda s: (
        PointMass("bead", s.m, (s.r * cos(s.omega * s.t), s.r * sin(s.omega * s.t))),
    ),
    potential=lambda s, bodies: 0,
    constraints=lambda s, c: (c.bead.x * sin(s.omega * s.t) - c.bead.y * cos(s.omega * s.t),),
    renames={"r": ("r", "x", "q")},
    quantities=(
        Quantity(
            "growth_rate",
            "the rate lambda in r = A exp(lambda t) + B exp(-lambda t)",
            lambda s: s.omega,
            "1/s",
        ),
    ),
    tags=("time_dependent",),
)
