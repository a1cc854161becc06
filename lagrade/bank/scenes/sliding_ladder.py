"""A ladder sliding down a smooth wall on a smooth floor: a rigid body held by two contact
constraints, one degree of freedom."""

from sympy import Rational, cos, pi, sin

from lagrade.mechanics.scene import RigidBody, Scene, gravity, param


def _bodies(s):
    # θ from the wall; the body's own angle φ is the ladder's tilt from the vertical.
    tilt = s.theta if s.opt["angle_from"] == "wall" else pi / 2 - s.theta
    centre = (s.l / 2 * sin(tilt), s.l / 2 * cos(tilt))
    return (RigidBody("ladder", s.m, centre, Rational(1, 12) * s.m * s.l**2, tilt),)


SCENE = Scene(
    id="sliding_ladder",
    title="Ladder sliding down a wall",
    statement=(
        "A uniform ladder of mass m and length l leans against a smooth vertical wall and stands "
        "on a smooth horizontal floor; it slides down, staying in the vertical plane normal to "
        "the wall. Use the angle {theta} between the ladder and the {angle_from}."
    ),
    coordinates=("theta",),
    parameters=(
        param("m", "positive", "kg", (5.0, 10.0, 20.0), "mass of the ladder"),
        param("l", "positive", "m", (2.0, 3.0, 4.0), "length of the ladder"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=_bodies,
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (
        # Foot on the floor (y = 0) and top against the wall (x = 0).
        c.ladder.y - s.l / 2 * cos(c.ladder.phi),
        c.ladder.x - s.l / 2 * sin(c.ladder.phi),
    ),
    renames={"theta": ("theta", "phi", "alpha")},
    options={"angle_from": ("wall", "floor")},
    tags=("rigid_body",),
)
