"""A block sliding down a fixed frictionless incline with a pendulum hanging from it; sliding
freely, the pendulum can hang steadily perpendicular to the incline."""

from sympy import cos, pi, sin, tan

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bob_offset(s):
    """Bob relative to the block; the angle from the downward vertical or from the horizontal."""
    if s.opt["angle_from"] == "vertical":
        return (s.l * sin(s.phi), -s.l * cos(s.phi))
    return (s.l * cos(s.phi), -s.l * sin(s.phi))


def _bodies(s):
    # The incline descends towards −x, so a positive angle leans the pendulum uphill (+x), where
    # it hangs while the block slides; s is measured down the incline from the origin.
    block = (-s.s * cos(s.alpha), -s.s * sin(s.alpha))
    dx, dy = _bob_offset(s)
    return (
        PointMass("block", s.M, block),
        PointMass("bob", s.m, (block[0] + dx, block[1] + dy)),
    )


SCENE = Scene(
    id="incline_pendulum",
    title="Pendulum hanging from a block on an incline",
    statement=(
        "A block of mass M slides without friction down a fixed incline of angle alpha. From the "
        "block hangs a pendulum of length l with a bob of mass m, swinging in the vertical plane "
        "of the incline's slope. Use the distance {s} the block has slid down the incline and "
        "the pendulum's angle {phi}, measured {angle_from}."
    ),
    coordinates=("s", "phi"),
    parameters=(
        param("M", "positive", "kg", (1.0, 2.0, 3.0), "mass of the block"),
        param("m", "positive", "kg", (0.2, 0.5, 1.0), "mass of the bob"),
        param("l", "positive", "m", (0.3, 0.5, 1.0), "length of the pendulum"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("alpha", "(0, pi/2)", "rad", (0.5236, 0.6109, 0.7854), "angle of the incline"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (
        c.block.y - c.block.x * tan(s.alpha),
        (c.bob.x - c.block.x) ** 2 + (c.bob.y - c.block.y) ** 2 - s.l**2,
    ),
    renames={"s": ("s", "q", "x"), "phi": ("phi", "theta", "psi")},
    options={"angle_from": ("vertical", "horizontal")},
    wording={
        "angle_from": {
            "vertical": "from the downward vertical, positive towards the top of the incline",
            "horizontal": "downwards from the horizontal that points to the top of the incline",
        }
    },
    quantities=(
        Quantity(
            "steady_angle",
            "the angle at which the pendulum hangs steadily while the block slides",
            lambda s: s.alpha if s.opt["angle_from"] == "vertical" else pi / 2 - s.alpha,
            "rad",
        ),
        Quantity(
            "steady_acceleration",
            "the acceleration of the block along the incline while the pendulum hangs steadily",
            lambda s: s.g * sin(s.alpha),
            "m/s^2",
        ),
    ),
    tags=("lecture",),
)
