"""A mass on a spring, lying on a table or hanging: gravity shifts the equilibrium but not the
frequency sqrt(k/m)."""

from sympy import Rational, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bodies(s):
    # x: the spring's extension beyond its natural length.
    position = (s.x, 0) if s.opt["orientation"] == "horizontal" else (0, -s.x)
    return (PointMass("mass", s.m, position),)


SCENE = Scene(
    id="harmonic_oscillator",
    title="Mass on a spring",
    statement=(
        "A body of mass m is attached to a spring of constant k whose other end is fixed; the "
        "spring {orientation}. Use the extension {x} of the spring beyond its natural length."
    ),
    coordinates=("x",),
    parameters=(
        param("m", "positive", "kg", (0.1, 0.2, 0.5, 1.0), "mass of the body"),
        param("k", "positive", "N/m", (5.0, 10.0, 20.0, 50.0), "spring constant"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies) + Rational(1, 2) * s.k * s.x**2,
    constraints=lambda s, c: (c.mass.y if s.opt["orientation"] == "horizontal" else c.mass.x,),
    renames={"x": ("x", "q", "u")},
    options={"orientation": ("horizontal", "vertical")},
    wording={
        "orientation": {
            "horizontal": "lies horizontally on a smooth table",
            "vertical": "hangs vertically from the ceiling, in gravity g",
        }
    },
    quantities=(
        Quantity(
            "angular_frequency",
            "angular frequency of the oscillation",
            lambda s: sqrt(s.k / s.m),
            "rad/s",
        ),
    ),
)
