"""Two equal masses on a line, held by three springs (wall–mass–mass–wall): the textbook pair of
normal modes, in phase and out of phase."""

from sympy import Rational, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, param

_HALF = Rational(1, 2)

SCENE = Scene(
    id="coupled_oscillators",
    title="Coupled oscillators",
    statement=(
        "Two blocks of mass m slide without friction on a horizontal line between two walls. "
        "Each is tied to its wall by a spring of constant k, and to each other by a spring of "
        "constant k_c; at rest all springs are relaxed and the blocks are a distance {a} apart. "
        "Use the displacements {x_1} and {x_2} of the blocks from their rest positions."
    ),
    coordinates=("x_1", "x_2"),
    parameters=(
        param("m", "positive", "kg", (0.5, 1.0, 2.0), "mass of each block"),
        param("k", "positive", "N/m", (10.0, 20.0, 50.0), "constant of the outer springs"),
        param("k_c", "positive", "N/m", (2.0, 5.0, 10.0), "constant of the coupling spring"),
        param("a", "positive", "m", (0.2, 0.3), "distance between the blocks at rest"),
    ),
    bodies=lambda s: (
        PointMass("block1", s.m, (s.x_1, 0)),
        PointMass("block2", s.m, (s.a + s.x_2, 0)),
    ),
    potential=lambda s, bodies: (
        _HALF * s.k * s.x_1**2 + _HALF * s.k_c * (s.x_2 - s.x_1) ** 2 + _HALF * s.k * s.x_2**2
    ),
    constraints=lambda s, c: (c.block1.y, c.block2.y),
    quantities=(
        Quantity(
            "in_phase_frequency",
            "angular frequency of the mode x_1 = x_2",
            lambda s: sqrt(s.k / s.m),
            "rad/s",
        ),
        Quantity(
            "out_of_phase_frequency",
            "angular frequency of the mode x_1 = -x_2",
            lambda s: sqrt((s.k + 2 * s.k_c) / s.m),
            "rad/s",
        ),
    ),
)
