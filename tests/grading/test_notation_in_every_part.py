"""The notation students actually write, judged in every part (issue 25): names in any spelling
the grammar reads (coordinates and cyclic coordinates included), the total time derivative of an
expression in an equation of motion, LaTeX's product of adjacent letters, angles in degrees,
mixed numbers, Max and Min. Each case was refused or misjudged before."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from lagrade.bank import get_scene
from lagrade.judge.check import check

#: Kepler's problem in the variant with coordinates r and theta (bank seed 3).
KEPLER = {"scene": "kepler", "seed": 3}
#: The spherical pendulum in the variant whose handout calls the polar angle ϑ (vartheta).
SPHERICAL = {"scene": "spherical_pendulum", "seed": 1}
DOUBLE = {"scene": "double_pendulum", "seed": 3}


def judge(problem, part, answer, given=None):
    return check(problem, part, answer, time_limit=None, given=given)


# --- names in any spelling, in every part ------------------------------------------------------


@pytest.mark.parametrize(
    ("problem", "answer"),
    [
        (KEPLER, "r, θ"),
        (KEPLER, r"r, \theta"),
        (KEPLER, r"$r$, $\theta$"),
        (KEPLER, "θ and r"),
        (SPHERICAL, "ϑ, ψ"),
        (SPHERICAL, r"\vartheta, \psi"),
        (SPHERICAL, "theta, psi"),
        (DOUBLE, "θ₁, θ₂"),
        (DOUBLE, "theta1, theta2"),
        (DOUBLE, r"\theta_1, \theta_2"),
    ],
)
def test_greek_coordinates_are_right_in_unicode_and_latex(problem, answer):
    verdict = judge(problem, "coordinates", answer)
    assert verdict.status == "correct", verdict.feedback


def test_a_wrong_coordinate_is_named_and_the_answer_is_not_handed_back():
    """The issue's case: "This problem uses 2 generalized coordinates (q, theta)" was said to a
    student who had written q, θ. Now a wrong list gets the right names, which differ from it."""
    verdict = judge(KEPLER, "coordinates", "r, φ")
    assert verdict.status == "incorrect"
    assert verdict.feedback == ("This problem uses 2 generalized coordinates (r, theta).",)
    assert verdict.interpreted == "r, phi"
    velocity = judge(KEPLER, "coordinates", "r, θ̇")
    assert velocity.status == "incorrect" and "theta_dot" in velocity.feedback[-1]


@pytest.mark.parametrize("answer", ["ψ", r"\psi", "psi"])
def test_cyclic_coordinates_in_any_spelling(answer):
    assert judge(SPHERICAL, "cyclic", answer).status == "correct"
    both = judge(SPHERICAL, "cyclic", f"ϑ and {answer}")
    plain = judge(SPHERICAL, "cyclic", "vartheta, psi")  # every coordinate: a blind guess, 0
    assert both.status == "incorrect" and (both.score, both.feedback) == (0.0, plain.feedback)


def test_every_part_reads_the_vartheta_coordinate_as_the_handout_prints_it():
    """The handout prints ϑ; θ, ϑ, \\vartheta and vartheta are one letter to the student."""
    variant = get_scene("spherical_pendulum").variant(1)
    assert variant.coordinates[0] == "vartheta"
    unicode_eom = [
        "l^2 m ϑ̈ + g l m sin(ϑ) - l^2 m ψ̇^2 sin(ϑ) cos(θ) = 0",
        "d/dt(l^2 m ψ̇ sin^2(ϑ)) = 0",
    ]
    assert judge(SPHERICAL, "eom", unicode_eom).status == "correct"
    latex_momenta = [
        r"p_{\vartheta} = m l^2 \dot\vartheta",
        r"p_{\psi} = m l^2 \dot\psi \sin^2\theta",
    ]
    assert judge(SPHERICAL, "momenta", latex_momenta).status == "correct"


# --- total time derivatives: d/dt(p) = 0 is an equation of motion ------------------------------


@pytest.mark.parametrize(
    "angular",
    [
        "d/dt(m r^2 theta_dot) = 0",
        "diff(m r^2 theta_dot, t) = 0",
        r"\frac{d}{dt}\left(m r^2 \dot\theta\right) = 0",
        r"\dot{\left(m r^2 \dot{\theta}\right)} = 0",
        "d/dt(m r^2 θ̇) = 0",
    ],
)
def test_the_textbook_form_of_a_conservation_law_is_an_equation_of_motion(angular):
    """The φ-equation of a central force as Taylor (Classical Mechanics, ch. 8) and Goldstein
    (ch. 3) write it: the time derivative of the angular momentum vanishes."""
    radial = "d/dt(m r_dot) = m r theta_dot^2 - G M m/r^2"
    verdict = judge(KEPLER, "eom", [radial, angular])
    assert verdict.status == "correct", verdict.feedback


def test_a_wrong_time_derivative_is_still_wrong_and_named():
    verdict = judge(
        KEPLER, "eom", ["d/dt(m r_dot) = m r theta_dot^2 - G M m/r^2", "d/dt(m r theta_dot) = 0"]
    )
    assert verdict.status == "incorrect" and verdict.score == pytest.approx(0.5)
    assert any("Equation 2" in f for f in verdict.feedback)


def test_a_third_derivative_is_refused_with_a_clear_message():
    verdict = judge(KEPLER, "eom", ["d/dt(m r_ddot) = 0", "d/dt(m r^2 theta_dot) = 0"])
    assert verdict.status == "incorrect"
    assert any("third derivative" in f and "r_ddot" in f for f in verdict.feedback)
    alone = judge(KEPLER, "eom", "d/dt(r_ddot) = 0")
    assert alone.status == "invalid" and "third derivative" in alone.feedback[0]


def test_a_conserved_quantity_written_with_d_dt_is_judged_as_its_value():
    """d/dt(m r^2 theta) is m r² θ̇ + 2 m r ṙ θ: not conserved, and judged as such (not refused)."""
    assert judge(KEPLER, "conserved", "d/dt(m r^2 theta)").status == "incorrect"
    assert judge(KEPLER, "conserved", "d/dt(m r^2 theta) - 2 m r r_dot theta").status == "correct"


# --- LaTeX's product of adjacent letters --------------------------------------------------------


def test_a_latex_fraction_with_a_run_of_parameters_is_their_product():
    L = r"\frac{1}{2} m \left(\dot r^2 + r^2 \dot\theta^2\right) + \frac{GMm}{r}"
    verdict = judge(KEPLER, "lagrangian", L)
    assert verdict.status == "correct"
    assert "(G*M*m)/r" in verdict.interpreted
    assert verdict.feedback == ()  # a right answer carries no notes on its reading (issue 30)
    wrong = judge(KEPLER, "lagrangian", L.replace("GMm", "2GMm"))
    assert "GMm is read as G*M*m: in LaTeX adjacent letters multiply." in wrong.feedback
    plain = judge(KEPLER, "lagrangian", "1/2 m (r_dot^2 + r^2 theta_dot^2) + GMm/r")
    assert plain.status == "correct"  # plain text reads the run too (issue 38)


# --- degrees for angles -------------------------------------------------------------------------

HOOP_ANGLE = {"scene": "hoop", "seed": 1, "quantity": "equilibrium_angle"}


def _hoop_angle() -> float:
    variant = get_scene("hoop").variant(1)
    return float(sp.N(variant.quantities["equilibrium_angle"].xreplace(variant.numeric_values)))


@pytest.mark.parametrize(
    "form", ["{:.4g}°", "{:.4g} deg", "{:.4g} degrees", r"{:.4g}^\circ", "{:.4g} º"]
)
def test_an_angle_in_degrees_is_converted_with_a_note(form):
    angle = _hoop_angle()
    verdict = judge(HOOP_ANGLE, "expression", form.format(math.degrees(angle)))
    assert verdict.status == "correct"
    assert (
        verdict.feedback and "is read as" in verdict.feedback[-1] and "rad" in verdict.feedback[-1]
    )


def test_degrees_stay_wrong_when_the_angle_is_wrong_and_a_bare_degree_value_is_told():
    angle = _hoop_angle()
    off = judge(HOOP_ANGLE, "expression", f"{1.1 * math.degrees(angle):.4g}°")
    assert off.status == "incorrect" and "off by" in off.feedback[0]
    bare = judge(HOOP_ANGLE, "expression", f"{math.degrees(angle):.4g}")
    assert bare.status == "incorrect" and bare.mistakes == ("degrees_for_radians",)
    assert "in degrees" in bare.feedback[0]


def test_degrees_for_a_quantity_that_is_no_angle_are_a_wrong_unit():
    spec = {"scene": "wedge", "seed": 3, "quantity": "block_acceleration"}
    verdict = judge(spec, "expression", "3.2°")
    assert verdict.status == "incorrect" and verdict.mistakes == ("wrong_unit",)


# --- mixed numbers, Max and Min -----------------------------------------------------------------


def test_a_mixed_number_is_read_as_a_sum_never_a_product():
    spec = {"expression": "11/4 g", "parameters": {"g": "positive"}}
    verdict = judge(spec, "expression", "2¾ g")
    assert verdict.status == "correct"
    assert verdict.feedback == ()  # a right answer carries no notes on its reading (issue 30)
    product = {"expression": "3/2 g", "parameters": {"g": "positive"}}
    wrong = judge(product, "expression", "2¾ g")
    assert wrong.status == "incorrect"  # not 2·¾
    assert "2¾ is read as the mixed number 2 + 3/4." in wrong.feedback
    ascii_mixed = judge(spec, "expression", "2 3/4 g")
    assert ascii_mixed.status == "invalid" and "mixed number" in ascii_mixed.feedback[0]


MAX = {"expression": "Max(a, b) - Min(a, b)", "parameters": {"a": "real", "b": "real"}}


@pytest.mark.parametrize(
    ("answer", "status"),
    [
        ("abs(a - b)", "correct"),
        ("max(b, a) - min(b, a)", "correct"),
        (r"\max(a, b) - \min(a, b)", "correct"),
        ("a - b", "incorrect"),
        ("Max(a, b) + Min(a, b)", "incorrect"),
        ("Max(a, b, 0) - Min(a, b)", "incorrect"),
    ],
)
def test_max_and_min_are_judged(answer, status):
    assert judge(MAX, "expression", answer).status == status


def test_max_and_min_have_one_value_in_every_evaluator():
    """float64, mpmath at 50 digits, exact Fractions and the hyper-dual numbers all evaluate
    Max and Min, and agree (sympy's own evaluation is the reference)."""
    from fractions import Fraction

    import mpmath

    import lagrade.judge.evaluate as ev
    from benchmarks.exact_rational import _FractionBackend

    a, b, c = sp.symbols("a b c", real=True)
    expr = sp.Max(a, b * c, evaluate=False) - 2 * sp.Min(a**2, c, evaluate=False)
    program = ev.compile_program([expr])
    points = [(0.3, -1.2, 2.0), (-2.0, 0.5, 0.25), (1.5, 1.5, 1.0)]
    for point in points:
        truth = float(expr.subs(dict(zip((a, b, c), point, strict=True))))
        env = {s: np.array([v]) for s, v in zip((a, b, c), point, strict=True)}
        assert ev.run(program, env)[0][0] == pytest.approx(truth)
        with mpmath.workdps(50):
            mp_env = {s: ev.MP.array([v]) for s, v in zip((a, b, c), point, strict=True)}
            assert float(ev.run(program, mp_env, ev.MP)[0][0]) == pytest.approx(truth)
        exact = {s: Fraction(v) for s, v in zip((a, b, c), point, strict=True)}
        assert ev.run(program, exact, _FractionBackend)[0] == sp.Rational(
            expr.subs({s: sp.Rational(v) for s, v in exact.items()})
        )
        hd = ev.run_hyperdual(program, {s: (env[s], 0, 0, 0) for s in env})
        assert float(np.ravel(hd[0][0])[0]) == pytest.approx(truth)


# --- textbook forms the systems corpus found (benchmarks/corpus/systems.jsonl) -------------------

PENDULUM_L = {
    "lagrangian": "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
    "coordinates": ["theta"],
    "parameters": {"m": "positive", "g": "positive", "l": "positive"},
}


@pytest.mark.parametrize(
    "answer",
    [
        "1/2 m l^2 theta_dot^2 + m g l cos(theta) + const",
        "L(theta, theta_dot) = 1/2 m l^2 theta_dot^2 + m g l cos(theta)",
        "L(θ, θ̇) = ½ m l² θ̇² + m g l cos θ + constant",
    ],
)
def test_a_lagrangian_with_an_additive_constant_or_its_arguments_is_read(answer):
    assert judge(PENDULUM_L, "lagrangian", answer).status == "correct"


def test_a_constant_that_is_not_added_is_not_dropped():
    verdict = judge(PENDULUM_L, "lagrangian", "1/2 m l^2 theta_dot^2 + const*m g l cos(theta)")
    assert verdict.status == "invalid" and "const" in verdict.feedback[0]
    kinetic = judge({"scene": "simple_pendulum", "seed": 1}, "T", "T = 1/2 m l^2 phi_dot^2 + const")
    assert kinetic.status != "correct"  # T has no arbitrary constant


@pytest.mark.parametrize(
    ("answer", "status"), [("2 π √(l/g)", "correct"), ("2π √(g/l)", "incorrect")]
)
def test_the_unicode_root_sign_is_sqrt(answer, status):
    period = {"expression": "2*pi*sqrt(l/g)", "parameters": {"l": "positive", "g": "positive"}}
    assert judge(period, "expression", answer).status == status


@pytest.mark.parametrize(
    ("answer", "status"), [("60°", "correct"), ("60 deg", "correct"), ("61°", "incorrect")]
)
def test_degrees_for_a_question_without_a_unit_are_pi_over_180(answer, status):
    """A degree is the number π/180; with no unit declared it is read so (with a unit declared,
    only an angle in rad takes degrees: the tests above)."""
    verdict = judge({"expression": "acos(1/2)", "parameters": {}}, "expression", answer)
    assert verdict.status == status
    if status == "incorrect":
        assert verdict.feedback[-1].endswith("is read as 61·π/180 rad.")
