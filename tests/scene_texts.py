"""Scene file texts more than one test folder writes from: the smallest whole scene, a pendulum,
which tests vary by a line (hostile files) or draw (figure labels)."""

PENDULUM = """\
title = "Pendulum"
statement = "A bob of mass m on a rod of length l. Use {theta}."
coordinates = ["theta"]
potential = "gravity"
constraints = ["x_bob^2 + y_bob^2 - l^2"]

[parameters]
m = { domain = "positive", unit = "kg", values = [1.0] }
l = { domain = "positive", unit = "m", values = [1.0] }
g = { domain = "positive", unit = "m/s^2", values = [9.81] }

[bodies.bob]
mass = "m"
position = ["l sin(theta)", "-l cos(theta)"]
"""
