"""Expressions judged where they are defined (issue 25): a complex value on principal branches is
a value, "undefined" means no value at all (a pole, log 0); sampling finds the part of the box
where a reference is defined, however small; a ratio of two quantities past float range is
evaluated in high precision. Each of these questions was refused before ("the reference answer
is undefined at every point drawn from the declared domains"), or, with the imaginary unit
declared, judged on the real part of the domain only (a false accept).

Labels: by hand from the principal branches (sympy's and mpmath's: sqrt(−a) = i√a,
log(−a) = log a + iπ, asin x = π/2 − i acosh x for x > 1), each checked below at 50 digits."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import lagrade.judge.evaluate as ev

from .conftest import judge

POSITIVE = {"x": "positive"}
SI_MASSES = {"G": "(6e-11, 7e-11)", "M": "(1e30, 2e30)", "m": "(5e24, 7e24)"}
BOX = {name: "(-1, 1)" for name in "abcd"}


def _expression(reference: str, parameters: dict, unit: str | None = None) -> dict:
    problem = {"expression": reference, "parameters": parameters}
    return problem | ({"imaginary_unit": unit} if unit else {})


# (reference, parameters, imaginary unit, right answers, wrong answers)
COMPLEX_EVERYWHERE = [
    ("log(-x)", POSITIVE, None, ["log(-x)", "log(-2*x) - log(2)"], ["log(x)", "-log(-x)"]),
    ("log(-x)", POSITIVE, "I", ["log(x) + I*pi", "log(-x)"], ["log(x) - I*pi", "log(x)"]),
    ("sqrt(x - 5)", {"x": "(0, 1)"}, None, ["sqrt(x - 5)", "(x - 5)^(1/2)"], ["sqrt(5 - x)"]),
    ("sqrt(x - 5)", {"x": "(0, 1)"}, "I", ["I*sqrt(5 - x)"], ["-I*sqrt(5 - x)", "sqrt(5 - x)"]),
    ("asin(x)", {"x": "(2, 3)"}, "I", ["pi/2 - I*acosh(x)"], ["pi/2 + I*acosh(x)"]),
    ("log(-x-1)", POSITIVE, None, ["log(-2*x - 2) - log(2)"], ["log(x + 1)"]),
    ("sqrt(-x^2 - 1)", {"x": "real"}, "I", ["I*sqrt(x^2 + 1)"], ["sqrt(x^2 + 1)"]),
]


@pytest.mark.parametrize("reference, parameters, unit, right, wrong", COMPLEX_EVERYWHERE)
def test_a_reference_complex_on_its_whole_domain_is_judged(
    reference, parameters, unit, right, wrong
):
    problem = _expression(reference, parameters, unit)
    for answer in right:
        verdict = judge(problem, "expression", answer)
        assert verdict.status == "correct", (answer, verdict.feedback)
    for answer in wrong:
        verdict = judge(problem, "expression", answer)
        assert verdict.status == "incorrect", (answer, verdict.feedback)


def test_with_the_imaginary_unit_the_negative_half_of_the_domain_counts():
    # I sqrt(x) is −sqrt|x| for x < 0: I sqrt(|x|) and sqrt(−x) agree only on the positive half
    problem = _expression("I*sqrt(x)", {"x": "real"}, "I")
    assert judge(problem, "expression", "I*sqrt(abs(x))").status == "incorrect"
    assert judge(problem, "expression", "sqrt(-x)").status == "incorrect"
    assert judge(problem, "expression", "I*x/sqrt(x)").status == "correct"


# (reference, parameters, right, wrong): references real (or with any value) on a part of the box
PART_OF_THE_BOX = [
    ("sqrt(a)*sqrt(b)*sqrt(c)*sqrt(d)", BOX, "sqrt(a)*sqrt(b)*sqrt(c)*sqrt(d)", "sqrt(a*b*c*d)"),
    (
        "atan2(sqrt(a), sqrt(b))*atan2(sqrt(c), sqrt(d))",
        BOX,
        "atan(sqrt(a)/sqrt(b))*atan2(sqrt(c), sqrt(d))",
        "atan2(sqrt(b), sqrt(a))*atan2(sqrt(c), sqrt(d))",
    ),
]


@pytest.mark.parametrize("reference, parameters, right, wrong", PART_OF_THE_BOX)
def test_an_expression_defined_on_part_of_the_box_is_judged_there(
    reference, parameters, right, wrong
):
    problem = _expression(reference, parameters)
    assert judge(problem, "expression", right).status == "correct"
    assert judge(problem, "expression", wrong).status == "incorrect"


# Lagrangians real on a small part of the box: the pendulum in Cartesian x with |x| < l ≤ 0.2
# (coordinates are drawn in ±(0.2, 2.5)), and products of square roots of signed quantities
PENDULUM_X = {
    "lagrangian": "1/2*m*x_dot^2 + m*g*sqrt(l^2 - x^2)",
    "coordinates": ["x"],
    "parameters": {"m": "positive", "g": "positive", "l": "(0, 0.2)"},
}
ROOTS = {
    "lagrangian": "1/2*m*x_dot^2 - sqrt(a)*sqrt(b)*sqrt(c)*sqrt(d)*x^2",
    "coordinates": ["x"],
    "parameters": {"m": "positive"} | BOX,
}
ROOT_COORDINATES = {
    "lagrangian": "m (x_dot^2 + y_dot^2 + z_dot^2 + w_dot^2)/2 - k sqrt(x) sqrt(y) sqrt(z) sqrt(w)",
    "coordinates": ["x", "y", "z", "w"],
    "parameters": {"m": "positive", "k": "positive"},
}


@pytest.mark.parametrize(
    "problem, part, right, wrong",
    [
        (PENDULUM_X, "lagrangian", "1/2 m x_dot^2 + m g sqrt(l^2 - x^2) + 7",
         "1/2 m x_dot^2 - m g sqrt(l^2 - x^2)"),
        (PENDULUM_X, "eom", ["m x_ddot + m g x/sqrt(l^2 - x^2) = 0"],
         ["m x_ddot + m g x/sqrt(l^2 + x^2) = 0"]),
        (PENDULUM_X, "momenta", ["p_x = m x_dot"], ["p_x = m x_dot/2"]),
        (PENDULUM_X, "conserved", ["1/2 m x_dot^2 - m g sqrt(l^2 - x^2)"],
         ["1/2 m x_dot^2 + m g sqrt(l^2 - x^2)"]),
        (ROOTS, "lagrangian", "1/2 m x_dot^2 - sqrt(a b c d) x^2",
         "1/2 m x_dot^2 + sqrt(a b c d) x^2"),
        (ROOTS, "eom", ["m x_ddot + 2 sqrt(a) sqrt(b) sqrt(c) sqrt(d) x = 0"],
         ["m x_ddot + 2 sqrt(a) sqrt(b) sqrt(c) x = 0"]),
        (ROOT_COORDINATES, "lagrangian",
         "1/2 m (x_dot^2 + y_dot^2 + z_dot^2 + w_dot^2) - k sqrt(x y) sqrt(z w)",
         "1/2 m (x_dot^2 + y_dot^2 + z_dot^2 + w_dot^2) - k sqrt(x y z)"),
    ],
)  # fmt: skip
def test_mechanics_real_on_a_small_part_of_the_box_is_judged_there(problem, part, right, wrong):
    assert judge(problem, part, right).status == "correct"
    assert judge(problem, part, wrong).status == "incorrect"


@pytest.mark.parametrize(
    "reference, right, wrong",
    [
        ("G*M^20/m^19", ["G*(M/m)^19*M", "(G*M)^20/(G*m)^19"], ["2*G*M^20/m^19", "G*M^19/m^19"]),
        ("M^30/m^29", ["(M/m)^30*m"], ["(M/m)^29*m"]),
        ("(M/m)^20", ["m^-20*M^20"], ["m^-20*M^21"]),
    ],
)
def test_a_ratio_of_quantities_past_float_range_is_judged_in_high_precision(
    reference, right, wrong
):
    problem = _expression(reference, SI_MASSES)
    for answer in right:
        assert judge(problem, "expression", answer).status == "correct", answer
    for answer in wrong:
        verdict = judge(problem, "expression", answer)
        assert verdict.status == "incorrect", answer


def test_the_values_of_a_wrong_answer_past_float_range_are_quoted():
    verdict = judge(_expression("G*M^20/m^19", SI_MASSES), "expression", "2*G*M^20/m^19")
    assert "where your answer is" in verdict.feedback[0], verdict.feedback


def test_undefined_still_means_no_value_at_all():
    # log(x) − log(x) + 1/0-like poles: an answer without a value where the reference has one
    problem = _expression("log(-x)", POSITIVE)
    assert judge(problem, "expression", "log(-x) + 1/(x - x + 0*x)").status != "correct"


# --- the complex backend's branches are mpmath's (and sympy's) --------------------------------

_BRANCHED = ["sqrt", "log", "asin", "acos", "acosh", "atanh", "asinh", "atan"]


@settings(max_examples=200, deadline=None)
@given(
    name=st.sampled_from(_BRANCHED),
    x=st.floats(-50, 50, allow_nan=False).filter(lambda v: abs(v) not in (0.0, 1.0)),
)
def test_complex_backend_takes_mpmaths_principal_branch_for_real_arguments(name, x):
    ours = complex(getattr(ev.COMPLEX, name)(np.array([x]))[0])
    with mpmath.workdps(30):
        theirs = complex(getattr(mpmath, name)(mpmath.mpf(x)))
    assert abs(ours - theirs) <= 1e-12 * max(1.0, abs(theirs))


def test_a_negative_zero_does_not_flip_a_root_across_its_cut():
    z = np.array([complex(-2.0, -0.0)])
    assert complex(ev.COMPLEX.sqrt(z)[0]) == pytest.approx(1j * 2**0.5)
    assert complex(sp.sqrt(-2).evalf()) == pytest.approx(1j * 2**0.5)
