"""Feedback names a point only as a situation a student can picture: coordinates (in rad when
they are angles) and motion, three significant figures, no sampled parameter values unless
the answer has nothing else; and no conserved quantity under a parameter's name."""

from __future__ import annotations

import re

import pytest

from lagrade.judge.check import check
from lagrade.judge.problem import build_problem
from lagrade.judge.situation import rounded, situation

#: More than three significant figures: the old "M = 0.839378".
LONG_NUMBER = re.compile(r"\d\.\d{4,}|\d{5,}")


@pytest.mark.parametrize(
    ("value", "text"),
    [(0.839378, "0.839"), (0.3, "0.3"), (24.5667, "24.6"), (1234.5, "1230"), (-1.5, "−1.5"),
     (2.5e-7, "2.5×10⁻⁷"), (0.0, "0")],
)  # fmt: skip
def test_rounded_to_three_significant_figures(value, text):
    assert rounded(value) == text


def test_a_state_at_rest():
    hoop = build_problem({"scene": "hoop"})
    text = situation({"theta": 0.3, "theta_dot": 0.0, "m": 0.839378, "g": 1.1}, hoop)
    assert text == "at θ = 0.3 rad with the system at rest"


def test_a_moving_state_without_parameters():
    hoop = build_problem({"scene": "hoop"})
    text = situation({"theta": -2.21601, "theta_dot": 1.56433, "R": 1.59507}, hoop)
    assert text == "at θ = −2.22 rad, moving with θ̇ = 1.56 rad/s"


def test_parameters_only_when_nothing_else():
    wedge = build_problem({"scene": "wedge"})
    text = situation({"g": 0.960123, "alpha": 1.1234}, wedge)
    assert text == "with g = 0.96 m/s² and α = 1.12 rad"


@pytest.mark.parametrize(
    ("spec", "part", "answer"),
    [
        ({"scene": "hoop"}, "lagrangian", "1/2 m R^2 theta_dot^2 - m g R cos(theta)"),
        ({"scene": "hoop"}, "eom", ["theta_ddot = 0"]),
        ({"scene": "hoop"}, "T", "1/2 m R^2 theta_dot^2"),
        ({"scene": "wedge"}, "momenta", ["p_x_M = M x_M_dot", "p_q = m q_dot"]),
        ({"scene": "wedge"}, "conserved", ["x_M"]),
    ],
)
def test_wrong_answers_quote_situations(spec, part, answer):
    verdict = check(spec, part, answer, time_limit=10)
    assert verdict.status == "incorrect"
    text = " ".join(verdict.feedback)
    assert "(for example" in text, text
    assert not LONG_NUMBER.search(text), text
    assert not re.search(r"\b(m|M|g|R) = ", text), text  # sampled parameters stay out


def test_conserved_quantity_does_not_borrow_a_parameters_name():
    verdict = check({"scene": "wedge"}, "conserved", ["0"], time_limit=10, given={"all": True})
    text = " ".join(verdict.feedback)
    assert "the energy function" in text
    assert not re.search(r"\bh\b", text), text  # h is the wedge's height


def test_energy_function_keeps_its_name_without_a_clash():
    verdict = check({"scene": "hoop"}, "conserved", ["0"], time_limit=10, given={"all": True})
    assert "the energy function h" in " ".join(verdict.feedback)


def test_a_wrong_T_quotes_both_values_at_the_witness():
    verdict = check({"scene": "simple_pendulum", "seed": 3}, "T", "m l phi_dot^2", time_limit=10)
    text = " ".join(verdict.feedback)
    # m l φ̇² is no energy: the reference's unit is not put after the student's value
    match = re.search(r"where your T is (\S+) and the reference's is (\S+) J\)", text)
    assert match, text
    assert match.group(1) != match.group(2)
    for number in match.groups():  # three significant figures
        assert len(number.replace("−", "").replace(".", "").lstrip("0")) <= 3, number


def test_a_wrong_equation_of_one_coordinate_quotes_both_accelerations():
    verdict = check(
        {"scene": "simple_pendulum", "seed": 3}, "eom", ["phi_ddot + (g/l) phi = 0"], time_limit=10
    )
    assert verdict.status == "incorrect"
    text = " ".join(verdict.feedback)
    assert re.search(r"your equation gives φ̈ = \S+ rad/s² and the reference φ̈ = \S+ rad/s²", text)
    assert "accelerating with" not in text, text


def test_no_values_without_handout_numbers_to_reproduce_them():
    verdict = check({"scene": "simple_pendulum"}, "T", "m l theta_dot^2", time_limit=10)
    text = " ".join(verdict.feedback)
    assert "(for example" in text and "reference's is" not in text, text


def test_a_questions_units_are_found_once(monkeypatch):
    """Every wrong answer's witness is told in the question's units: found once per question
    (the reference walked once), the same as found afresh, a copy for each caller."""
    from lagrade.judge import situation as module

    found = []
    real = module._angles
    monkeypatch.setattr(module, "_angles", lambda p: found.append(p) or real(p))
    problem = build_problem({"scene": "pendulum_on_cart"})
    first = situation({"theta": 0.3, "x": 1.0}, problem)
    again = situation({"theta": 0.3, "x": 1.0}, problem)
    assert first == again and "rad" in first
    assert found == [problem]
    units = module.coordinate_units(problem)
    assert units == module._coordinate_units(problem)
    assert units is not module.coordinate_units(problem)
    assert module.angles(problem) == real(problem)
