"""Figures of systems with massless helper bodies and moving pulleys (a double Atwood machine,
Taylor's problem 7.32): the moving pulley hangs from its rope, without the ceiling a fixed
pulley's strut is drawn from, and the massless body that carries it is a small ring without a
mass label (no "0" beside it)."""

from __future__ import annotations

from matplotlib.text import Text

from lagrade.assign.figures import compose
from lagrade.bank.scenefile import scene_from_text

DOUBLE_ATWOOD = """\
title = "Double Atwood machine"
statement = "Use {x} and {y}."
coordinates = ["x", "y"]
potential = "gravity"
constraints = ["x_m1 + R", "x_axle - R", "x_m2 - 2 R", "x_m3", "y_m1 + y_axle",
               "2 y_axle - y_m2 - y_m3"]

[parameters]
m_1 = { domain = "positive", unit = "kg", values = [3.0] }
m_2 = { domain = "positive", unit = "kg", values = [1.0] }
m_3 = { domain = "positive", unit = "kg", values = [1.5] }
R = { domain = "positive", unit = "m", values = [0.1] }
g = { domain = "positive", unit = "m/s^2", values = [9.81] }

[bodies.m1]
mass = "m_1"
position = ["-R", "-x"]

[bodies.axle]                 # the moving pulley's axle: a massless helper
mass = "0"
position = ["R", "x"]

[bodies.m2]
mass = "m_2"
position = ["2 R", "x - y"]

[bodies.m3]
mass = "m_3"
position = ["0", "x + y"]

[figure]
sweeps = { x = "none", y = "none" }
offsets = { m1 = [0, "-6 R"], axle = [0, "-6 R"], m2 = [0, "-9 R"], m3 = [0, "-9 R"] }
fixtures = [
    { kind = "pulley", points = [[0, 0]], radius = "R" },
    { kind = "pulley", points = ["axle"], radius = "R" },
    { kind = "rope", points = [["R", 0], "axle"] },
]
"""


def test_a_moving_pulley_hangs_from_its_rope_and_a_helper_has_no_mass_label():
    variant = scene_from_text(DOUBLE_ATWOOD, "double_atwood").default
    assert variant.dof == 2
    figure = compose(variant)
    try:
        elements = {e.name: e for e in figure.elements}
        fixed, moving = elements["pulley1"], elements["pulley2"]
        # the fixed pulley: strut, ceiling (line and hatches), wheel, axle; the moving one:
        # wheel and axle only
        assert len(moving.artists) == 2 < len(fixed.artists)
        helper = elements["axle"]
        assert helper.artists and not any(isinstance(a, Text) for a in helper.artists)
        shown = [t.get_text() for t in figure.axes.texts]
        assert "$0$" not in shown
    finally:
        figure.figure.clear()
