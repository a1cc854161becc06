"""The commented template `lagrade scene new NAME` writes: a complete, valid scene (a pendulum
hanging from a sliding collar) whose comments name every key, so that an instructor edits a
working file instead of starting from a blank page. `docs/scenes.md` is the full reference."""

from __future__ import annotations

_TEMPLATE = '''\
# NAME: a scene file for lagrade (the format: docs/scenes.md; check it with
#   lagrade scene check NAME.toml
# which lists everything wrong at once, prints the derived solution, checks the quantities
# and draws the figure). This template is a working scene: a pendulum hanging from a collar
# that slides on a horizontal rod. Edit it into your own system.

title = "Pendulum on a sliding collar"

# The problem text. {x} and {theta} are where the coordinates' names go (a student's
# variant may rename them); {angle_from} is where an option's wording goes.
statement = """\\
A collar of mass M slides without friction on a horizontal rod. From it hangs a bob of mass m \\
on a massless rod of length l, swinging in the vertical plane of the rod. Use the collar's \\
position {x} and the angle {theta} between the pendulum and the {angle_from}."""

# The generalized coordinates, and other names a variant may give them (the first is the
# coordinate itself).
coordinates = ["x", "theta"]
renames = { x = ["x", "s"], theta = ["theta", "phi"] }
# Where a coordinate lives, when a constraint holds only there (a length under a square root:
# domains = { r = "positive" }); the others are real.

# Friction and drives, if any: Rayleigh's dissipation function and generalized forces enter the
# equations of motion as E_j + dF/dq_j_dot = Q_j:
# dissipation = "b x_dot^2/2"
# forces = { x = "F_0 cos(omega t)" }

# V: "gravity" is m g (height) for every body (y up in a plane, z up in space); or write an
# expression in the coordinates, velocities, parameters, t and the bodies' Cartesian
# coordinates (x_collar, y_bob, ...): "gravity + k (x_collar - x_bob)^2/2".
potential = "gravity"

# Holonomic constraints: expressions in the bodies' Cartesian coordinates that vanish.
# 3 N - (these + the planarity of 2-D positions) must equal the number of coordinates.
constraints = [
    "y_collar",                                       # the collar stays on the rod
    "(x_bob - x_collar)^2 + (y_bob - y_collar)^2 - l^2",   # the pendulum's rod
]

# Each parameter: its domain (positive, nonnegative, real or an interval such as "(0, pi/2)"),
# SI unit, the pool of values students draw from, and how the handout describes it.
[parameters]
M = { domain = "positive", unit = "kg", values = [1.0, 2.0], description = "mass of the collar" }
m = { domain = "positive", unit = "kg", values = [0.2, 0.5], description = "mass of the bob" }
l = { domain = "positive", unit = "m", values = [0.5, 1.0], description = "length of the pendulum" }
g = { domain = "positive", unit = "m/s^2", values = [9.81], description = "free-fall acceleration" }

# Bodies: a point mass has a mass and a position of 2 (x, y; y up) or 3 (x, y, z; z up)
# components in the coordinates, parameters and t. A rigid body adds inertia (about its centre
# of mass) and angle (how far it is turned); one turning in space gives 3 principal moments as
# inertia and its Z-X-Z Euler angles as angles = ["phi", "theta", "psi"].
[bodies.collar]
mass = "M"
position = ["x", 0]

[bodies.bob]
mass = "m"
position = ["x + bx", "by"]            # bx, by: bound by the option below

# A numeric follow-up an assignment can ask for; check says what the number is, so that
# `scene check` can verify it: the normal-mode frequencies about a state at rest (or
# accelerations = { q = "..." } in a state).
[quantities.small_oscillation_frequency]
description = "angular frequency of small oscillations of the pendulum"
value = "sqrt(g (M + m)/(M l))"
unit = "rad/s"
check = { at = { x = "0", theta = "bottom" }, frequencies = ["small_oscillation_frequency"] }

# A presentation option: each choice words itself in the statement and binds names (let);
# a choice may also add bodies, constraints and figure entries. The first is the default.
[options.angle_from.vertical]
wording = "downward vertical"
let = { bx = "l sin(theta)", by = "-l cos(theta)", bottom = "0" }

[options.angle_from.horizontal]
wording = "horizontal"
let = { bx = "l cos(theta)", by = "-l sin(theta)", bottom = "pi/2" }

# What the figure cannot tell from the geometry (fixtures such as springs, walls, surfaces,
# where a coordinate is drawn, ...): see docs/scenes.md. The rod the collar slides on:
[figure]
fixtures = [{ kind = "surface", points = [["-1.5 l", 0], ["1.5 l", 0]], side = 1 }]
'''


def template(name: str) -> str:
    """The template's text for a scene called `name`."""
    return _TEMPLATE.replace("NAME", name)
