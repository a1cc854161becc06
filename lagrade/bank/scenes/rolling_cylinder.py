"""A cylinder rolling without slipping down an incline: a rigid body with a rolling constraint,
whose acceleration g sin α / (1 + I/(m R²)) is slower than sliding."""

from sympy import Rational, cos, sin

from lagrade.mechanics.scene import Quantity, RigidBody, Scene, gravity, param

# I / (m R²) about the axis of the cylinder.
_INERTIA_RATIO = {"solid": Rational(1, 2), "hollow": 1}


def _bodies(s):
    # The incline descends towards +x; the centre sits a distance R above the surface, and
    # rolling down (clockwise) turns the cylinder by −s/R.
    centre = (
        s.s * cos(s.alpha) + s.R * sin(s.alpha),
        -s.s * sin(s.alpha) + s.R * cos(s.alpha),
    )
    inertia = _INERTIA_RATIO[s.opt["shape"]] * s.m * s.R**2
    return (RigidBody("cylinder", s.m, centre, inertia, -s.s / s.R),)


SCENE = Scene(
    id="rolling_cylinder",
    title="Cylinder rolling down an incline",
    statement=(
        "A {shape} cylinder of mass m and radius R rolls without slipping down a fixed incline of "
        "angle alpha. Use the distance {s} its centre has moved along the incline. Count the "
        "constraints (one of them is the rolling condition) and find the acceleration."
    ),
    coordinates=("s",),
    parameters=(
        param("m", "positive", "kg", (0.5, 1.0, 2.0), "mass of the cylinder"),
        param("R", "positive", "m", (0.05, 0.1, 0.2), "radius of the cylinder"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("alpha", "(0, pi/2)", "rad", (0.5236, 0.6109, 0.7854), "angle of the incline"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (
        # The centre stays a distance R above the incline (normal coordinate) …
        c.cylinder.x * sin(s.alpha) + c.cylinder.y * cos(s.alpha) - s.R,
        # … and the distance along the incline equals the arc rolled off: x_along + R φ = 0.
        c.cylinder.x * cos(s.alpha) - c.cylinder.y * sin(s.alpha) + s.R * c.cylinder.phi,
    ),
    renames={"s": ("s", "x", "q")},
    options={"shape": tuple(_INERTIA_RATIO)},
    quantities=(
        Quantity(
            "acceleration",
            "acceleration of the centre along the incline",
            lambda s: s.g * sin(s.alpha) / (1 + _INERTIA_RATIO[s.opt["shape"]]),
            "m/s^2",
        ),
    ),
    tags=("rigid_body",),
)
