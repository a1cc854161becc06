"""Velocities print with dots in LaTeX and MathML; students' notation for the plain form."""

from __future__ import annotations

import sympy as sp

from lagrade.mechanics.lagrange import jet
from lagrade.notation.printer import latex, mathml, plain, symbol_names


def test_dots_over_the_letter_not_the_subscript() -> None:
    names = symbol_names(["theta", "x_M"])
    assert names[jet("theta").dot] == r"\dot{\theta}"
    assert names[jet("x_M").ddot] == r"\ddot{x}_{M}"


def test_pendulum_lagrangian_in_every_notation() -> None:
    th = jet("theta")
    m, l, g = sp.symbols("m l g", positive=True)
    L = m * l**2 * th.dot**2 / 2 + m * g * l * sp.cos(th.q)
    assert (
        latex(L, ["theta"])
        == r"g l m \cos{\left(\theta \right)} + \frac{l^{2} m \dot{\theta}^{2}}{2}"
    )
    assert '<mover accent="true"><mi>&#952;</mi><mo>&#729;</mo></mover>' in mathml(L, ["theta"])
    assert plain(L) == "g*l*m*cos(theta) + l^2*m*theta_dot^2/2"
