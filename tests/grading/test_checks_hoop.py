"""The bead on a rotating hoop: a driven constraint, so T + V is not conserved but the Jacobi
integral h is; ad-hoc problems given by an instructor's L."""

from __future__ import annotations

import pytest

from .conftest import HOOP, HOOP_ADHOC, judge

JACOBI = "1/2 m R^2 theta_dot^2 - 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"
T_PLUS_V = "1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"


@pytest.mark.parametrize("problem", [HOOP, HOOP_ADHOC])
def test_jacobi_integral_is_conserved_and_t_plus_v_is_not(problem):
    assert judge(problem, "conserved", [JACOBI]).status == "correct"
    assert judge(problem, "conserved", ["h = 3 (" + JACOBI + ") + 7 m g R"]).status == "correct"
    v = judge(problem, "conserved", [T_PLUS_V])
    assert v.status == "incorrect" and v.witness


def test_t_plus_v_is_named_for_the_bank_hoop():
    v = judge(HOOP, "conserved", [T_PLUS_V])
    assert v.mistakes[0] == "energy_not_conserved" and "Jacobi" in v.feedback[0]


@pytest.mark.parametrize("problem", [HOOP, HOOP_ADHOC])
@pytest.mark.parametrize(
    "eq, status",
    [
        ("theta_ddot = omega^2 sin(theta) cos(theta) - (g/R) sin(theta)", "correct"),
        (
            "m R^2 theta_ddot - m R^2 omega^2 sin(theta) cos(theta) + m g R sin(theta) = 0",
            "correct",
        ),
        ("R theta_ddot = R omega^2 sin(theta) cos(theta) - g sin(theta)", "correct"),
        ("theta_ddot = omega^2 sin(theta) cos(theta) + (g/R) sin(theta)", "incorrect"),
        ("theta_ddot = -(g/R) sin(theta)", "incorrect"),
        ("theta_ddot^2 = omega^2 sin(theta) cos(theta) - (g/R) sin(theta)", "incorrect"),
    ],
)
def test_equation_of_motion(problem, eq, status):
    assert judge(problem, "eom", [eq]).status == status


def test_nonlinear_in_acceleration_is_said():
    v = judge(HOOP, "eom", ["theta_ddot^2 = g/R"])
    assert "not linear in the accelerations" in v.feedback[0]


def test_missing_centripetal_term_is_named():
    v = judge(HOOP, "lagrangian", "1/2 m R^2 theta_dot^2 + m g R cos(theta)")
    assert v.mistakes == ("missing_driven_term",) and "omega" in v.feedback[0]


def test_momentum_and_cyclic():
    assert judge(HOOP, "momenta", ["p_theta = m R^2 theta_dot"]).status == "correct"
    assert judge(HOOP, "cyclic", "none").status == "correct"
    v = judge(HOOP, "cyclic", ["theta"])
    assert v.status == "incorrect"


def test_equilibrium_angle_expression():
    problem = {**HOOP, "quantity": "equilibrium_angle"}
    assert judge(problem, "expression", "acos(g/(omega^2 R))").status == "correct"
    assert judge(problem, "expression", "arccos(g/(R omega^2))").status == "correct"
    assert judge(problem, "expression", "asin(g/(omega^2 R))").status == "incorrect"


def test_transformation_of_the_rotating_hoop():
    right = [
        "x_bead = R sin(theta) cos(omega t)",
        "y_bead = R sin(theta) sin(omega t)",
        "z_bead = -R cos(theta)",
    ]
    assert judge(HOOP, "transformation", right).status == "correct"
    frozen = ["x_bead = R sin(theta)", "y_bead = 0", "z_bead = -R cos(theta)"]
    assert judge(HOOP, "transformation", frozen).status == "incorrect"


def test_adhoc_problem_errors_are_request_errors():
    from lagrade.errors import RequestError

    with pytest.raises(RequestError, match="coordinates"):
        judge({"lagrangian": "theta_dot^2"}, "eom", ["theta_ddot = 0"])
    with pytest.raises(RequestError, match="unknown domain"):
        judge({**HOOP_ADHOC, "parameters": {"m": "big"}}, "eom", ["theta_ddot = 0"])
    with pytest.raises(RequestError, match="does not parse"):
        judge({**HOOP_ADHOC, "lagrangian": "m R^2 (theta_dot^2"}, "eom", ["theta_ddot = 0"])
    with pytest.raises(RequestError, match="unknown part"):
        judge(HOOP_ADHOC, "energy", "x")
    with pytest.raises(RequestError, match="T and V"):
        judge(HOOP_ADHOC, "T", "m R^2 theta_dot^2/2")


def test_expression_problem_with_domains():
    problem = {
        "expression": "g*sin(alpha)*(M+m)/(M+m*sin(alpha)**2)",
        "parameters": {"g": "positive", "M": "positive", "m": "positive", "alpha": "(0, pi/2)"},
    }
    assert (
        judge(problem, "expression", "g sin(alpha) (m+M)/(M + m sin(alpha)^2)").status == "correct"
    )
    # |cos α| = cos α on (0, π/2): equal on the declared domain
    problem2 = {"expression": "cos(alpha)", "parameters": {"alpha": "(0, pi/2)"}}
    assert judge(problem2, "expression", "sqrt(1 - sin(alpha)^2)").status == "correct"
    problem3 = {"expression": "cos(alpha)", "parameters": {"alpha": "real"}}
    assert judge(problem3, "expression", "sqrt(1 - sin(alpha)^2)").status == "incorrect"


def test_expression_problem_with_si_domains():
    """A cyclotron radius with an electron's charge and mass: bounds in scientific notation."""
    problem = {
        "expression": "m*v/(e*B)",
        "parameters": {
            "m": "[9.1e-31, 9.2e-31]",
            "e": "(1.5e-19, 1.7e-19)",
            "v": "(1e5, 1e7)",
            "B": "(1e-3, 1)",
        },
    }
    assert judge(problem, "expression", "(m v)/(B e)").status == "correct"
    assert judge(problem, "expression", "m v/(B e) + 1e-12").status == "incorrect"
    assert judge(problem, "expression", "e B/(m v)").mistakes == ("reciprocal",)
