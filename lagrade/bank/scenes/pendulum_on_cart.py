"""A pendulum hanging from a cart that rolls freely on a horizontal track: the cart's position is
cyclic and the total horizontal momentum is conserved."""

from sympy import cos, sin, sqrt

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param


def _bodies(s):
    if s.opt["angle_from"] == "vertical":
        dx, dy = s.l * sin(s.theta), -s.l * cos(s.theta)
    else:
        dx, dy = s.l * cos(s.theta), -s.l * sin(s.theta)
    return (PointMass("cart", s.M, (s.x, 0)), PointMass("bob", s.m, (s.x + dx, dy)))


SCENE = Scene(
    id="pendulum_on_cart",
    title="Pendulum on a cart",
    statement=(
        "A cart of mass M rolls without friction on a horizontal track. From it hangs a "
        "pendulum: a bob of mass m on a massless rod of length l, swinging in the vertical "
        "plane of the track. Use the cart's position {x} and the angle {theta} between the rod "
        "and the {angle_from}."
    ),
    coordinates=("x", "theta"),
    parameters=(
        param("M", "positive", "kg", (1.0, 2.0, 5.0), "mass of the cart"),
        param("m", "positive", "kg", (0.2, 0.5, 1.0), "mass of the bob"),
        param("l", "positive", "m", (0.3, 0.5, 1.0), "length of the pendulum"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (
        c.cart.y,
        (c.bob.x - c.cart.x) ** 2 + (c.bob.y - c.cart.y) ** 2 - s.l**2,
    ),
    renames={"x": ("x", "X", "s"), "theta": ("theta", "phi", "psi")},
    options={"angle_from": ("vertical", "horizontal")},
    quantities=(
        Quantity(
            "small_oscillation_frequency",
            "angular frequency of small oscillations of the pendulum",
            lambda s: sqrt(s.g * (s.M + s.m) / (s.M * s.l)),
            "rad/s",
        ),
    ),
)
