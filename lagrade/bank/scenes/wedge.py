"""Block on a wedge that slides on a frictionless floor (the lecture's first worked example)."""

from sympy import cos, sin, tan

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param

SCENE = Scene(
    id="wedge",
    title="Block on a sliding wedge",
    statement=(
        "A block of mass m slides without friction down the face of a wedge of mass M, height h "
        "and angle alpha; the wedge itself slides without friction on a horizontal floor. Use the "
        "wedge's position {x_M} and the distance {q} the block has slid down the face."
    ),
    coordinates=("x_M", "q"),
    parameters=(
        param("m", "positive", "kg", (0.5, 1.0, 1.5, 2.0), "mass of the block"),
        param("M", "positive", "kg", (3.0, 4.0, 5.0, 8.0), "mass of the wedge"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("h", "positive", "m", (1.0, 1.5, 2.0), "height of the wedge"),
        param("alpha", "(0, pi/2)", "rad", (0.5236, 0.6109, 0.7854), "angle of the wedge"),
    ),
    bodies=lambda s: (
        PointMass("wedge", s.M, (s.x_M, 0)),
        PointMass("block", s.m, (s.x_M + s.q * cos(s.alpha), s.h - s.q * sin(s.alpha))),
    ),
    potential=lambda s, bodies: gravity(s.g, bodies[1:]),
    constraints=lambda s, c: (
        c.wedge.y,
        c.block.y - s.h + (c.block.x - c.wedge.x) * tan(s.alpha),
    ),
    renames={"x_M": ("x_M", "X"), "q": ("q", "s")},
    quantities=(
        Quantity(
            "block_acceleration",
            "acceleration of the block along the face of the wedge, relative to the wedge",
            lambda s: s.g * sin(s.alpha) * (s.M + s.m) / (s.M + s.m * sin(s.alpha) ** 2),
            "m/s^2",
        ),
    ),
    tags=("lecture",),
)
