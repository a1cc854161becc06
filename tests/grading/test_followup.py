"""Numeric follow-ups of an assignment: the wedge's acceleration for a student's own numbers."""

import pytest
import sympy as sp

from lagrade.bank import get_scene
from lagrade.judge.parts import run_checker
from lagrade.judge.problem import build_problem

SEED = 3


@pytest.fixture(scope="module")
def wedge():
    variant = get_scene("wedge").variant(SEED)
    problem = build_problem({"scene": "wedge", "seed": SEED, "quantity": "block_acceleration"})
    value = float(sp.N(variant.quantities["block_acceleration"].xreplace(variant.numeric_values)))
    return variant, problem, value


def judge(wedge, text, tolerance=0.01):
    variant, problem, _ = wedge
    return run_checker(
        problem, "expression", text, {"values": variant.values, "tolerance": tolerance}
    )


def test_the_value_with_or_without_its_unit_is_right(wedge):
    value = wedge[2]
    for text in (
        f"{value:.3f}",
        f"{value:.3g} m/s^2",
        f"{value:.4g} m/s**2",
        f"{value:.3g} [m/s^2]",
    ):
        assert judge(wedge, text).status == "correct", text


def test_a_value_outside_the_tolerance_is_wrong_and_says_by_how_much(wedge):
    verdict = judge(wedge, f"{1.05 * wedge[2]:.4g}")
    assert verdict.status == "incorrect" and "off by 5" in verdict.feedback[0]


def test_a_flipped_sign_is_named(wedge):
    verdict = judge(wedge, f"{-wedge[2]:.4g}")
    assert verdict.mistakes == ("numeric_sign",) and "Check the sign" in verdict.feedback[0]


def test_the_closed_form_in_the_parameters_is_right(wedge):
    assert judge(wedge, "g sin(alpha) (m+M)/(M + m sin(alpha)^2)").status == "correct"
    assert judge(wedge, "g sin(alpha)").status == "incorrect"


def test_text_that_does_not_parse_is_invalid(wedge):
    assert judge(wedge, "5.4 furlongs").status == "invalid"
