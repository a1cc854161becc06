"""A momentum that is ∂L/∂q̇ short of (or with an extra) factor of its terms names the factor
(issue 38: "p_θ is not ∂L/∂θ̇" where a missing factor r could be named). The factor is found
by the correction it implies, so each case is checked independently: the answer corrected by
the named factor is the momentum sympy.physics.mechanics derives for the same system (the
spherical pendulum's p_φ = m l² sin²θ φ̇)."""

from __future__ import annotations

import pytest
import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

from lagrade.judge.check import check

SPHERICAL = {"scene": "spherical_pendulum"}
KEPLER = {"scene": "kepler"}
m, l, theta, phi_dot = sp.symbols("m l theta phi_dot")
S = sp.sin(theta)


def _spherical_p_phi() -> sp.Expr:
    """p_φ = ∂L/∂φ̇ of a spherical pendulum of length l, from sympy.physics.mechanics."""
    q_theta, q_phi = dynamicsymbols("theta phi")
    g = sp.Symbol("g")
    N, O = ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    radial = sp.sin(q_theta) * (sp.cos(q_phi) * N.x + sp.sin(q_phi) * N.y)
    bob = O.locatenew("bob", l * (radial - sp.cos(q_theta) * N.z))
    bob.set_vel(N, bob.pos_from(O).dt(N))
    particle = Particle("bob", bob, m)
    particle.potential_energy = m * g * bob.pos_from(O).dot(N.z)
    p_phi = sp.diff(Lagrangian(N, particle), q_phi.diff())
    return p_phi.subs(q_phi.diff(), phi_dot).subs(q_theta, theta)


@pytest.mark.parametrize(
    ("typed", "answer", "factor", "said"),
    [
        ("m l^2 phi_dot", m * l**2 * phi_dot, S**2, "without its factor sin(theta)^2"),
        ("m l^2 sin(theta) phi_dot", m * l**2 * S * phi_dot, S, "without its factor sin(theta)"),
        ("m l^2 sin(theta)^2", m * l**2 * S**2, phi_dot, "without its factor phi_dot"),
    ],
)  # fmt: skip
def test_the_missing_factor_of_a_spherical_pendulum_is_named(typed, answer, factor, said):
    verdict = check(SPHERICAL, "momenta", f"p_theta = m l^2 theta_dot; p_phi = {typed}")
    assert verdict.status == "incorrect" and verdict.score == 0.5
    (sentence,) = verdict.feedback
    assert sentence.startswith(f"p_phi is ∂L/∂phi_dot {said} ("), sentence
    assert "at θ = " in sentence  # the situation names what the difference depends on
    assert sp.simplify(answer * factor - _spherical_p_phi()) == 0  # the correction it implies


def test_an_extra_factor_is_named():
    verdict = check(KEPLER, "momenta", "p_r = m r_dot; p_theta = m r^3 theta_dot")
    assert verdict.feedback[0].startswith("p_theta is ∂L/∂theta_dot with an extra factor r ")


def test_no_factor_is_named_where_none_corrects_it():
    verdict = check(KEPLER, "momenta", "p_r = m r_dot; p_theta = m r^2 theta_dot + r")
    assert verdict.feedback[0].startswith("p_theta is not ∂L/∂theta_dot"), verdict.feedback


def test_the_catalogue_still_names_a_missing_parameter():
    verdict = check(KEPLER, "momenta", "p_r = m r_dot; p_theta = r^2 theta_dot")
    assert verdict.feedback[0] == "The term m*r^2*theta_dot in your p_theta lacks the factor m."
