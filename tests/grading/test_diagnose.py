"""The mistake catalogue: each common mistake, made on purpose, is named in the feedback in the
student's own terms."""

from __future__ import annotations

import pytest
import sympy as sp

from grader.diagnose import plain, swap_sin_cos
from grader.problem import build_problem

from .conftest import HOOP, WEDGE, judge

W_T = "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"


@pytest.mark.parametrize(
    "problem, part, answer, kind, words",
    [
        (
            WEDGE,
            "lagrangian",
            "m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"
            " + m g q sin(alpha)",
            "dropped_half",
            "½",
        ),
        (WEDGE, "lagrangian", W_T + " - m g q sin(alpha)", "sign_of_V", "T − V"),
        (
            WEDGE,
            "lagrangian",
            "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha)",
            "missing_cross_term",
            "x_M_dot",
        ),
        (
            WEDGE,
            "lagrangian",
            "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot sin(alpha)) + 1/2 M x_M_dot^2"
            " + m g q cos(alpha)",
            "sin_cos_swapped",
            "sin and cos",
        ),
        (WEDGE, "lagrangian", W_T + " + g q sin(alpha)", "missing_factor", "factor m"),
        (
            HOOP,
            "lagrangian",
            "1/2 m R^2 theta_dot^2 + m g R cos(theta)",
            "missing_driven_term",
            "omega",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = m q_dot + m x_M_dot cos(alpha)", "p_q = m q_dot + m x_M_dot cos(alpha)"],
            "wrong_coordinate",
            "momentum of q",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = (M+m) x_M_dot", "p_q = m q_dot + m x_M_dot cos(alpha)"],
            "missing_cross_term",
            "lacks the term m*q_dot*cos(alpha)",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = (M+m) x_M_dot + m q_dot cos(alpha)", "p_q = m g sin(alpha)"],
            "force_not_momentum",
            "∂L/∂q",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot + m q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = -m g sin(alpha)",
            ],
            "el_sign",
            "minus sign",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot - m q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = m g sin(alpha)",
            ],
            "wrong_sign",
            "wrong sign",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot + q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = m g sin(alpha)",
            ],
            "missing_factor",
            "factor m",
        ),
        (
            WEDGE,
            "T",
            "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2",
            "missing_cross_term",
            "cross term",
        ),
        (WEDGE, "V", "-m g q cos(alpha)", "sin_cos_swapped", "sin and cos"),
        (
            HOOP,
            "conserved",
            ["1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"],
            "energy_not_conserved",
            "T + V",
        ),
    ],
)
def test_mistake_is_named(problem, part, answer, kind, words):
    v = judge(problem, part, answer)
    assert v.status == "incorrect"
    assert kind in v.mistakes, (v.mistakes, v.feedback)
    assert any(words.lower() in f.lower() for f in v.feedback), v.feedback


def test_cyclic_because_only_the_velocity_is_missing():
    """A coordinate whose velocity is absent from L is not cyclic for that reason."""
    problem = {
        "lagrangian": "m*r**2/2 + m*r*theta_dot**2/2 - k*r",
        "coordinates": ["r", "theta"],
        "parameters": {"m": "positive", "k": "positive"},
    }
    v = judge(problem, "cyclic", ["theta", "r"])
    assert v.mistakes == ("velocity_missing_not_cyclic",)
    assert "only its velocity r_dot is missing" in v.feedback[0]


def test_mutations_that_change_nothing_are_left_out():
    """Dropping the constant m g h from L changes no motion: not a mistake to name."""
    catalogue = build_problem(WEDGE).catalogue
    assert all("g*h*m" not in m.message for m in catalogue.lagrangian_mutants)
    assert any("g*m*q*sin(alpha)" in m.message for m in catalogue.lagrangian_mutants)


def test_catalogue_is_built_for_every_scene():
    from problem_bank.bank import scene_ids

    for sid in scene_ids():
        problem = build_problem({"scene": sid})
        cat = problem.catalogue
        if len(sp.Add.make_args(problem.lagrangian)) == 1:
            # The free wheel's ½Iθ̇²: every one-term mutation is a multiple with the same motion.
            assert cat.lagrangian_mutants == [], sid
            continue
        assert cat.lagrangian_mutants, sid
        assert all(m.message for m in cat.lagrangian_mutants)


def test_helpers():
    x = sp.Symbol("x")
    assert plain(x**2 / 2) == "x^2/2"
    assert swap_sin_cos(sp.sin(x) * sp.cos(2 * x)) == sp.cos(x) * sp.sin(2 * x)
