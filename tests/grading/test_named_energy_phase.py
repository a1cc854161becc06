"""Mistakes named in T, V, H, Hamilton's equations and a closed-form quantity (issue 36), each
sentence said only when the correction it implies makes the answer right: a wrong moment of
inertia, the ½ of H's kinetic part, V's sign in H, q̇ = p where q̇ = p/m, a dropped factor of a
closed form; and the numbers quoted are the ones a student reproduces from the quoted state."""

from __future__ import annotations

import math
import re

import pytest

from lagrade.bank.registry import get_scene
from lagrade.judge.situation import symbol_text

from .conftest import judge

CYLINDER = {"scene": "rolling_cylinder", "seed": 1}
LADDER = {"scene": "sliding_ladder", "seed": 1}
PENDULUM = {"scene": "simple_pendulum", "seed": 1}
HOOP = {"scene": "hoop", "seed": 1}
WEDGE_ACCELERATION = {"scene": "wedge", "seed": 1, "quantity": "block_acceleration"}
DRIVEN = {"scene": "driven_pendulum", "seed": 1}


# --- T: a wrong moment of inertia ----------------------------------------------------------------


def test_a_disc_with_m_r_squared_names_its_moment_of_inertia_and_the_fix_is_right():
    verdict = judge(CYLINDER, "T", "m*q_dot^2")  # I = m R² for ½ m R²: 3/4 → 1
    assert verdict.mistakes == ("wrong_inertia",)
    assert verdict.feedback[0].startswith(
        "The moment of inertia of the cylinder in your T is twice the right one"
    )
    assert judge(CYLINDER, "T", "3*m*q_dot^2/4").status == "correct"


def test_a_rod_about_its_end_names_the_factor_four():
    # a ladder's I = 1/12 m l² taken as 1/3 m l²: T = m l² θ̇²/8 + m l² θ̇²/6
    verdict = judge(LADDER, "T", "7*l^2*m*theta_dot^2/24")
    assert verdict.mistakes == ("wrong_inertia",)
    assert "is four times the right one" in verdict.feedback[0]


def test_a_t_wrong_otherwise_names_no_moment_of_inertia():
    verdict = judge(CYLINDER, "T", "m*q_dot^2/3")  # no common ratio of inertias gives 1/3
    assert "wrong_inertia" not in verdict.mistakes
    assert not any("moment of inertia" in f for f in verdict.feedback)


# --- H -------------------------------------------------------------------------------------------


def test_h_without_its_half_is_named():
    verdict = judge(PENDULUM, "hamiltonian", "p_phi^2/(l^2*m) - g*l*m*sin(phi)")
    assert verdict.mistakes == ("dropped_half",)
    assert verdict.feedback[0].startswith("The ½ is missing in the kinetic part of your H")
    assert judge(PENDULUM, "hamiltonian", "p_phi^2/(2*l^2*m) - g*l*m*sin(phi)").status == "correct"


def test_v_with_the_wrong_sign_in_h_is_named_where_h_is_not_l():
    # on a turning hoop U = V − ½ m R² ω² sin²θ: flipping V alone is not L in the momenta
    answer = "-R^2*m*omega^2*sin(theta)^2/2 + R*g*m*cos(theta) + p_theta^2/(2*R^2*m)"
    verdict = judge(HOOP, "hamiltonian", answer)
    assert verdict.mistakes == ("sign_of_V",)
    said = "V has the wrong sign in your H: H = Σ p q̇ − L adds V (for example at θ = "
    assert verdict.feedback[0].startswith(said) and len(verdict.feedback) == 1, verdict.feedback
    fixed = "-R^2*m*omega^2*sin(theta)^2/2 - R*g*m*cos(theta) + p_theta^2/(2*R^2*m)"
    assert judge(HOOP, "hamiltonian", fixed).status == "correct"


def test_the_offset_sentence_of_a_driven_support_speaks_of_no_vector_potential():
    answer = (
        "-a^2*m*omega^2*sin(omega*t)^2/2 + a*g*m*cos(omega*t) - g*l*m*cos(theta)"
        " + p_theta^2/(2*l^2*m)"
    )
    verdict = judge(DRIVEN, "hamiltonian", answer)
    assert verdict.mistakes == ("missing_offset",)
    assert "velocity-dependent potential" not in verdict.feedback[0]
    assert "p − c" in verdict.feedback[0]


def test_a_point_of_phase_space_is_quoted_with_its_momenta_not_sampled_parameters():
    verdict = judge({"scene": "charged_particle", "seed": 1}, "hamiltonian",
                    "p_x^2/(2*m) + p_y^2/(2*m) + p_z^2/(2*m)")  # fmt: skip
    last = verdict.feedback[-1]
    assert "p_x = " in last and " kg" not in last, last
    assert set(verdict.witness) >= {"p_x"}


# --- Hamilton's equations: q̇ = p for q̇ = p/m ----------------------------------------------


def test_q_dot_equal_to_p_names_the_mass_not_divided_out():
    verdict = judge(
        PENDULUM, "hamilton_equations", ["phi_dot = p_phi", "p_phi_dot = g*l*m*cos(phi)"]
    )
    assert verdict.mistakes == ("mass_not_divided",)
    assert verdict.feedback[0] == (
        "Equation 1 (phi_dot = p_phi) gives φ̇ as l^2*m times what it is: the mass (l^2*m) is "
        "not divided out (q̇ = p/m, not p)."
    )
    fixed = ["phi_dot = p_phi/(l^2*m)", "p_phi_dot = g*l*m*cos(phi)"]
    assert judge(PENDULUM, "hamilton_equations", fixed).status == "correct"


def test_a_wrong_velocity_equation_of_another_kind_names_no_mass():
    verdict = judge(
        PENDULUM, "hamilton_equations", ["phi_dot = 2*p_phi", "p_phi_dot = g*l*m*cos(phi)"]
    )
    assert "mass_not_divided" not in verdict.mistakes


# --- a closed form: a dropped factor ------------------------------------------------------


@pytest.mark.parametrize(
    ("answer", "sentence", "fixed"),
    [
        ("g*sin(alpha)/(M + m*sin(alpha)^2)", "lacks the factor M + m", "*(M + m)"),
        ("g*(M + m)*sin(alpha)", "lacks the division by M + m*sin(alpha)^2",
         "/(M + m*sin(alpha)^2)"),
    ],
)  # fmt: skip
def test_a_dropped_factor_of_a_closed_form_is_named_and_putting_it_back_is_right(
    answer, sentence, fixed
):
    verdict = judge(WEDGE_ACCELERATION, "expression", answer)
    assert verdict.mistakes == ("missing_factor",)
    assert sentence in verdict.feedback[0]
    assert judge(WEDGE_ACCELERATION, "expression", f"({answer}){fixed}").status == "correct"


# --- numbers quoted ------------------------------------------------------------------------


def test_t_quotes_every_velocity_its_values_need():
    # the ż term left out: the reference's T needs ż, so the point quotes it and the witness has it
    verdict = judge({"scene": "free_particle", "seed": 1}, "T", "m*x_dot^2/2 + m*y_dot^2/2")
    assert "z_dot" in verdict.witness
    assert f"{symbol_text('z', 1)} = " in verdict.feedback[0]


def test_values_quoted_at_a_driven_state_are_those_at_the_quoted_time():
    """ω = 200 rad/s: the values are computed at t as quoted (three figures), not at the sample
    point's t, so a student who computes T at the quoted state gets the quoted numbers."""
    answer = (
        "a^2*m*omega^2*cos(omega*t)^2/2 - a*l*m*omega*theta_dot*cos(theta)*cos(omega*t)"
        " + l^2*m*theta_dot^2/2"
    )
    verdict = judge(DRIVEN, "T", answer)
    sentence = verdict.feedback[0]
    t = float(re.search(r"t = ([\d.]+) s", sentence).group(1))
    theta = float(re.search(r"θ = (−?[\d.]+) rad", sentence).group(1).replace("−", "-"))
    theta_dot = float(re.search(r"θ̇ = (−?[\d.]+) rad/s", sentence).group(1).replace("−", "-"))
    quoted = float(re.search(r"your T is (−?[\d.]+) J", sentence).group(1).replace("−", "-"))
    values = get_scene("driven_pendulum").variant(1).values  # the student's own variant
    m, l, a, omega = (float(values[n]) for n in ("m", "l", "a", "omega"))
    mine = (
        a**2 * m * omega**2 * math.cos(omega * t) ** 2 / 2
        - a * l * m * omega * theta_dot * math.cos(theta) * math.cos(omega * t)
        + l**2 * m * theta_dot**2 / 2
    )
    assert abs(mine - quoted) <= 5e-3 * abs(mine), (mine, sentence)
