"""The Atwood machine: two masses on a string over a pulley, massless or (as an option) a
uniform disc whose rotation the string drives without slipping."""

from sympy import Rational

from lagrade.mechanics.scene import PointMass, Quantity, RigidBody, Scene, gravity, param


def _bodies(s):
    # x: how far m_1 has descended from the level where the two masses hang side by side.
    masses = (
        PointMass("mass1", s.m_1, (-s.R, -s.x)),
        PointMass("mass2", s.m_2, (s.R, s.x)),
    )
    if s.opt["pulley"] == "massless":
        return masses
    return masses + (RigidBody("pulley", s.M, (0, 0), Rational(1, 2) * s.M * s.R**2, s.x / s.R),)


def _constraints(s, c):
    string = (c.mass1.x + s.R, c.mass2.x - s.R, c.mass1.y + c.mass2.y)
    if s.opt["pulley"] == "massless":
        return string
    # The axle holds the pulley; the string turns it without slipping.
    return string + (c.pulley.x, c.pulley.y, s.R * c.pulley.phi + c.mass1.y)


def _acceleration(s):
    """a = (m₁ − m₂) g / (m₁ + m₂ + I/R²), with I/R² = M/2 for a uniform disc."""
    inertia = 0 if s.opt["pulley"] == "massless" else s.M / 2
    return (s.m_1 - s.m_2) * s.g / (s.m_1 + s.m_2 + inertia)


SCENE = Scene(
    id="atwood",
    title="Atwood machine",
    statement=(
        "Two masses m_1 and m_2 hang on an inextensible string over a pulley of radius R, whose "
        "axle is fixed; the pulley is {pulley}. Use the distance {x} that m_1 has descended from "
        "the level where the two masses hang side by side."
    ),
    coordinates=("x",),
    parameters=(
        param("m_1", "positive", "kg", (1.0, 1.5, 2.0, 3.0), "mass on the left"),
        param("m_2", "positive", "kg", (0.5, 0.8, 1.2), "mass on the right"),
        param("M", "positive", "kg", (0.2, 0.5, 1.0), "mass of the pulley"),
        param("R", "positive", "m", (0.05, 0.1, 0.2), "radius of the pulley"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=_constraints,
    renames={"x": ("x", "q", "s")},
    options={"pulley": ("massless", "massive")},
    wording={
        "pulley": {
            "massless": "massless",
            "massive": "a uniform disc of mass M, turned by the string without slipping",
        }
    },
    quantities=(
        Quantity("acceleration", "acceleration of m_1 (downwards)", _acceleration, "m/s^2"),
    ),
)
