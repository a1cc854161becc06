"""More mistakes named (issue 36), each sentence said only when the correction it implies makes
the answer right: a solved equation with its right-hand side negated, equations derived
correctly from the student's own wrong L (with that L's mistake), E = T + V where only h or
nothing is conserved, a conserved quantity without its factor sin²θ."""

from __future__ import annotations

import pytest

from lagrade.judge.parts.eom_claims import NEGATED_RHS

from .conftest import judge

OSCILLATOR = {"scene": "harmonic_oscillator", "seed": 1}
KEPLER = {"scene": "kepler", "seed": 1}


# --- a negated right-hand side -------------------------------------------------------------------


def test_a_negated_right_hand_side_is_named_and_its_correction_is_right():
    verdict = judge(OSCILLATOR, "eom", ["q_ddot = -(g*m - k*q)/m"])
    assert verdict.feedback == (f"Your equation: {NEGATED_RHS}.",)
    assert verdict.mistakes == ("negated_rhs",)
    assert judge(OSCILLATOR, "eom", ["q_ddot = (g*m - k*q)/m"]).status == "correct"


def test_a_negated_right_hand_side_in_a_system_names_its_row():
    answer = ["rho_ddot = -(rho*theta_dot^2 - G*M/rho^2)", "theta_ddot = -2*rho_dot*theta_dot/rho"]
    verdict = judge(KEPLER, "eom", answer)
    assert len(verdict.feedback) == 1, verdict.feedback
    assert verdict.feedback[0].startswith("Equation 1 (")
    assert verdict.feedback[0].endswith(f": {NEGATED_RHS}.")
    fixed = ["rho_ddot = rho*theta_dot^2 - G*M/rho^2", answer[1]]
    assert judge(KEPLER, "eom", fixed).status == "correct"


@pytest.mark.parametrize(
    "answer",
    [
        "q_ddot = -(g*m + k*q)/m",  # negating does not make it right
        "m*q_ddot + k*q - g*m = -(0)",  # no right-hand side to speak of
    ],
)
def test_no_negated_right_hand_side_where_negating_it_is_not_the_fix(answer):
    verdict = judge(OSCILLATOR, "eom", [answer])
    assert not any(NEGATED_RHS in s for s in verdict.feedback), verdict.feedback


# --- equations of the student's own L ------------------------------------------------------------

KEPLER_OWN_L = "m*rho_dot^2 + m*rho^2*theta_dot^2/2 + G*M*m/rho"
KEPLER_OWN_EOM = [
    "2*m*rho_ddot - m*rho*theta_dot^2 + G*M*m/rho^2 = 0",
    "m*rho^2*theta_ddot + 2*m*rho*rho_dot*theta_dot = 0",
]


def test_equations_of_the_own_wrong_L_say_so_and_name_its_mistake():
    verdict = judge(KEPLER, "eom", KEPLER_OWN_EOM, given={"lagrangian": KEPLER_OWN_L})
    assert verdict.follows_from_own_answer
    last = verdict.feedback[-1]
    # the θ equation is right: only the wrong one was tested against the own L
    assert last.startswith(
        "Your wrong equations follow correctly from your own Lagrangian, which is not the "
        "right one: "
    ), last
    named = last.split("which is not the right one: ", 1)[1]
    own = judge(KEPLER, "lagrangian", KEPLER_OWN_L)
    assert own.feedback[0].lower().startswith(named.rstrip(".").lower()), (named, own.feedback)
    fixed_L = "m*rho_dot^2/2 + m*rho^2*theta_dot^2/2 + G*M*m/rho"  # what the sentence names
    assert judge(KEPLER, "lagrangian", fixed_L).status == "correct"


def test_every_equation_of_the_own_L_wrong_says_these_equations():
    own_L = (
        "1/2 m (x_M_dot^2 + q_dot^2 + x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"
        " - m g (h - q sin(alpha))"
    )
    eom = [
        "M*x_M_ddot + m*q_ddot*cos(alpha)/2 + m*x_M_ddot = 0",
        "-g*m*sin(alpha) + m*q_ddot + m*x_M_ddot*cos(alpha)/2 = 0",
    ]
    verdict = judge({"scene": "wedge", "seed": 1}, "eom", eom, given={"lagrangian": own_L})
    assert verdict.follows_from_own_answer
    assert verdict.feedback[-1] == (
        "These equations follow correctly from your own Lagrangian, which is not the right "
        "one: the term m*q_dot*x_M_dot*cos(alpha) in your L is half what it should be."
    ), verdict.feedback


def test_equations_that_do_not_follow_from_the_own_L_say_nothing_of_it():
    eom = ["3*m*rho_ddot - m*rho*theta_dot^2 + G*M*m/rho^2 = 0", KEPLER_OWN_EOM[1]]
    verdict = judge(KEPLER, "eom", eom, given={"lagrangian": KEPLER_OWN_L})
    assert not verdict.follows_from_own_answer
    assert not any("your own Lagrangian" in s for s in verdict.feedback)


# --- E = T + V where only h, or nothing, is conserved ---------------------------------------------

JACOBI_IS = "the Jacobi integral h = Σ q̇ ∂L/∂q̇ − L is."


def test_energy_on_a_rotating_hoop_names_the_moving_constraint_and_h():
    answer = ["R^2*m*omega^2*sin(theta)^2/2 + R^2*m*theta_dot^2/2 - R*g*m*cos(theta)"]
    verdict = judge({"scene": "hoop", "seed": 1}, "conserved", answer)
    assert verdict.feedback == (
        "T + V is not conserved here: the constraint moves, so energy flows in and out; "
        + JACOBI_IS,
    )


def test_energy_with_a_vector_potential_names_no_moving_constraint():
    """Nothing moves in the charged particle's scene: T + V is not h because V = −e v·A."""
    answer = ["B*e*x_dot*y + m*x_dot^2/2 + m*y_dot^2/2 + m*z_dot^2/2"]
    verdict = judge({"scene": "charged_particle", "seed": 1}, "conserved", answer)
    (sentence,) = verdict.feedback
    assert "constraint moves" not in sentence
    assert "V depends on the velocities" in sentence and sentence.endswith(JACOBI_IS)


def test_energy_of_a_driven_pendulum_says_h_is_not_conserved_either():
    answer = [
        "a^2*m*omega^2*sin(omega*t)^2/2 + a*g*m*cos(omega*t) - "
        "a*l*m*omega*theta_dot*sin(theta)*sin(omega*t) - g*l*m*cos(theta) + l^2*m*theta_dot^2/2"
    ]
    verdict = judge({"scene": "driven_pendulum", "seed": 1}, "conserved", answer)
    assert verdict.feedback == (
        "T + V is not conserved here: the constraint moves, so energy flows in and out; "
        "L depends on t explicitly, so the Jacobi integral h is not conserved either.",
    )


FORCED = {
    "lagrangian": "m*x_dot^2/2 - k*x^2/2 + F*x*cos(w*t)",
    "coordinates": ["x"],
    "parameters": {"m": "positive", "k": "positive", "F": "positive", "w": "positive"},
}


def test_energy_of_a_forced_oscillator_is_named_though_it_equals_h():
    """T + V = h here, and neither is conserved: L depends on t, and nothing moves."""
    verdict = judge(FORCED, "conserved", ["m*x_dot^2/2 + k*x^2/2 - F*x*cos(w*t)"])
    assert verdict.feedback == (
        "T + V is not conserved here: L depends on t explicitly, so the Jacobi integral h is "
        "not conserved either.",
    ), verdict.feedback


# --- a conserved quantity without its factor ------------------------------------------------------

SPHERICAL = {"scene": "spherical_pendulum", "seed": 1}


@pytest.mark.parametrize(
    ("answer", "factor"),
    [("l^2*m*psi_dot", "sin(vartheta)^2"), ("l^2*m*psi_dot*sin(vartheta)", "sin(vartheta)")],
)
def test_a_dropped_factor_is_named_and_the_answer_times_it_is_conserved(answer, factor):
    verdict = judge(SPHERICAL, "conserved", [answer])
    assert verdict.feedback == (
        f"{answer} is missing a factor {factor}: {factor} times it is conserved.",
    )
    assert judge(SPHERICAL, "conserved", [f"({answer})*{factor}"]).status == "correct"


def test_no_missing_factor_where_no_factor_makes_it_conserved():
    verdict = judge(SPHERICAL, "conserved", ["l^2*m*psi_dot*cos(vartheta)"])
    assert not any("missing a factor" in s for s in verdict.feedback), verdict.feedback


def test_a_sin_or_cos_dropped_from_one_term_of_a_momentum_is_named():
    wedge = {"scene": "wedge", "seed": 1}
    answer = ["p_x_M = M*x_M_dot + m*q_dot + m*x_M_dot", "p_q = m*q_dot + m*x_M_dot*cos(alpha)"]
    verdict = judge(wedge, "momenta", answer)
    assert verdict.feedback == (
        "The term m*q_dot*cos(alpha) in your p_x_M lacks the factor cos(alpha).",
    ), verdict.feedback
    fixed = ["p_x_M = M*x_M_dot + m*q_dot*cos(alpha) + m*x_M_dot", answer[1]]
    assert judge(wedge, "momenta", fixed).status == "correct"
