"""The parts of the next lecture through the one door (`run_checker`): `hamiltonian`,
`hamilton_equations`, `equilibrium`, `normal_modes`. The key of every bank scene is accepted
(where the part exists), each named mistake is named, and what cannot be judged says why."""

from __future__ import annotations

import pytest

from lagrade.bank import get_scene, scene_ids
from lagrade.errors import RequestError
from lagrade.judge.key import key_answer
from lagrade.judge.parts import run_checker
from lagrade.judge.problem import build_problem

NEW_PARTS = ("hamiltonian", "hamilton_equations", "equilibrium", "normal_modes", "mode_shapes")


def _problem(scene: str, seed: int = 1):
    return build_problem({"scene": scene, "seed": seed})


def _verdict(scene: str, part: str, answer, seed: int = 1):
    return run_checker(_problem(scene, seed), part, answer)


@pytest.mark.parametrize("scene_id", scene_ids())
def test_every_key_is_accepted(scene_id):
    variant = get_scene(scene_id).variant(2)
    problem = _problem(scene_id, 2)
    for part in NEW_PARTS:
        try:
            key = key_answer(variant, part)
        except KeyError:  # no stable equilibrium: the part cannot be asked
            with pytest.raises(RequestError, match="needs a stable equilibrium"):
                run_checker(problem, part, "0")
            continue
        verdict = run_checker(problem, part, key)
        assert verdict.status == "correct", (part, key, verdict.feedback)


# --- hamiltonian (the simple pendulum of seed 1: angle phi from the horizontal) --------------

H = "p_phi^2/(2 m l^2) - m g l sin(phi)"


@pytest.mark.parametrize(
    "answer",
    [H, "H = " + H, r"H = \frac{p_\phi^2}{2ml^2} - mgl\sin\phi", H + " + 3 m g l"],
)
def test_a_right_hamiltonian(answer):
    assert _verdict("simple_pendulum", "hamiltonian", answer).status == "correct"


@pytest.mark.parametrize(
    ("scene", "answer", "mistake"),
    [
        ("simple_pendulum", "1/2 m l^2 phi_dot^2 - m g l sin(phi)", "velocities"),
        ("simple_pendulum", "p_phi^2/(2 m l^2) + m g l sin(phi)", "lagrangian"),
        ("simple_pendulum", "p_phi^2 m l^2/2 - m g l sin(phi)", "velocity_is_p"),
        ("simple_pendulum", "p_phi_dot^2", "rates"),
        ("charged_particle", "p_x^2/(2m) + p_y^2/(2m) + p_z^2/(2m)", "missing_offset"),
        (
            "hoop",
            "p_theta^2/(2 m R^2) - m g R cos(theta) + m R^2 omega^2 sin(theta)^2/2",
            "energy",
        ),
    ],
)
def test_named_hamiltonian_mistakes(scene, answer, mistake):
    verdict = _verdict(scene, "hamiltonian", answer)
    assert verdict.status == "incorrect" and mistake in verdict.mistakes, verdict


def test_the_charged_particle_needs_p_minus_e_a():
    """Goldstein §8.1 (the Hamiltonian of a charge): H = (p − eA)²/2m; with A = (−B y, 0, 0)
    (seed 1's gauge) p_x − e A_x = p_x + e B y."""
    problem = _problem("charged_particle")
    key = key_answer(get_scene("charged_particle").variant(1), "hamiltonian")
    assert run_checker(problem, "hamiltonian", key).status == "correct"


# --- Hamilton's equations ------------------------------------------------------------------


@pytest.mark.parametrize(
    "answer",
    [
        ["phi_dot = p_phi/(m l^2)", "p_phi_dot = m g l cos(phi)"],
        ["p_phi = m l^2 phi_dot", "p_phi_dot - m g l cos(phi) = 0"],
        [r"\dot{\phi} = \frac{p_\phi}{ml^2}", r"\dot{p}_\phi = mgl\cos\phi"],
        "phi_dot = p_phi/(m l^2); d/dt(p_phi) = m g l cos(phi)",
    ],
)
def test_right_hamilton_equations(answer):
    assert _verdict("simple_pendulum", "hamilton_equations", answer).status == "correct"


@pytest.mark.parametrize(
    ("answer", "mistake", "score"),
    [
        (["phi_dot = p_phi/(m l^2)", "p_phi_dot = -m g l cos(phi)"], "sign_p_dot", 0.5),
        (["phi_dot = -p_phi/(m l^2)", "p_phi_dot = m g l cos(phi)"], "sign_q_dot", 0.5),
        (["m l^2 phi_ddot = m g l cos(phi)"], "second_order", 0.0),
        (["phi_dot = p_phi/(m l^2)"], "too_few_equations", 0.5),
    ],
)
def test_named_hamilton_equation_mistakes(answer, mistake, score):
    verdict = _verdict("simple_pendulum", "hamilton_equations", answer)
    assert verdict.status == "incorrect" and mistake in verdict.mistakes
    assert verdict.score == pytest.approx(score)


def test_a_nonlinear_line_is_wrong_not_a_crash():
    verdict = _verdict(
        "simple_pendulum",
        "hamilton_equations",
        ["phi_dot^2 = p_phi/(m l^2)", "p_phi_dot = m g l cos(phi)"],
    )
    assert verdict.status == "incorrect" and "not linear" in verdict.feedback[0]


# --- equilibrium and normal modes ----------------------------------------------------------


@pytest.mark.parametrize(
    ("scene", "answer", "status", "mistake"),
    [
        ("simple_pendulum", "phi = pi/2", "correct", None),
        ("simple_pendulum", "pi/2", "correct", None),
        ("simple_pendulum", "phi = 5 pi/2", "correct", None),  # the same configuration
        ("simple_pendulum", "phi = -pi/2", "incorrect", "unstable"),
        ("simple_pendulum", "phi = 0", "incorrect", "not_equilibrium"),
        ("hoop", "theta = acos(g/(omega^2 R))", "correct", None),
        ("hoop", "theta = -acos(g/(omega^2 R))", "correct", None),  # any stable one
        ("hoop", "theta = 0", "incorrect", "unstable"),  # ω² R > g: the bottom is unstable
        ("pendulum_on_cart", "psi = 0", "correct", None),  # the cart's s is free
        ("pendulum_on_cart", "s = 0, psi = 0", "correct", None),
        ("spring_pendulum", "theta = 0", "incorrect", "missing_coordinate"),
    ],
)
def test_equilibrium(scene, answer, status, mistake):
    verdict = _verdict(scene, "equilibrium", answer)
    assert verdict.status == status, verdict.feedback
    if mistake:
        assert mistake in verdict.mistakes


@pytest.mark.parametrize(
    ("scene", "answer", "status", "mistake"),
    [
        ("simple_pendulum", "sqrt(g/l)", "correct", None),
        ("simple_pendulum", "omega = sqrt(g/l)", "correct", None),
        ("simple_pendulum", "g/l", "incorrect", "squared"),
        ("simple_pendulum", "sqrt(g/l)/(2 pi)", "incorrect", "cycles"),
        ("simple_pendulum", "2 pi sqrt(l/g)", "incorrect", "period"),
        ("simple_pendulum", "sqrt(g/l), 0", "incorrect", "zero_mode"),
        ("simple_pendulum", "sqrt(g/l), sqrt(g/l)", "incorrect", "repeated"),
        ("pendulum_on_cart", "0, sqrt((M+m) g/(M l))", "correct", None),
        ("pendulum_on_cart", "sqrt((M + m) g/(M l))", "correct", None),
        ("coupled_oscillators", "sqrt(k/m)", "incorrect", "missing_mode"),
        ("wheel", "none", "correct", None),
    ],
)
def test_normal_modes(scene, answer, status, mistake):
    verdict = _verdict(scene, "normal_modes", answer)
    assert verdict.status == status, verdict.feedback
    if mistake:
        assert mistake in verdict.mistakes


def test_frequencies_that_cross_between_parameter_draws():
    """A particle in an anisotropic trap (free_particle, seed 3): sqrt(k/m) twice and
    sqrt(k_z/m), whichever is larger in a draw."""
    variant = get_scene("free_particle").variant(3)
    key = key_answer(variant, "normal_modes")
    assert run_checker(_problem("free_particle", 3), "normal_modes", key).status == "correct"


@pytest.mark.parametrize("part", ["equilibrium", "normal_modes"])
def test_no_stable_equilibrium_is_a_request_error(part):
    with pytest.raises(RequestError, match="no stationary point"):
        _verdict("kepler", part, "0")


@pytest.mark.parametrize(
    ("part", "answer"),
    [
        ("hamiltonian", "p_theta^^2"),
        ("hamiltonian", "p_q^2"),
        ("hamilton_equations", "= ="),
        ("equilibrium", "phi = phi_dot"),
        ("normal_modes", "sqrt(g/l) phi"),
        ("equilibrium", "x = 1"),
    ],
)
def test_bad_text_is_invalid_with_a_message(part, answer):
    verdict = _verdict("simple_pendulum", part, answer)
    assert verdict.status in ("invalid", "incorrect") and verdict.feedback


def test_the_answer_page_preview_reads_momenta_and_their_rates():
    from lagrade.grading.answer_page.preview import preview

    entry = {"scene": "simple_pendulum", "seed": 1}
    part = {"part": "hamilton_equations", "key": "hamilton_equations", "points": 1}
    got = preview(entry, part | {"quantity": None}, "phi_dot = p_phi/(m l^2)\np_phi_dot = 0")
    assert got["status"] == "read" and len(got["lines"]) == 2
    assert all(line["mathml"] for line in got["lines"])  # typeset, with ṗ_φ dotted
    assert "&#729;" in got["lines"][1]["mathml"] or "\u02d9" in got["lines"][1]["mathml"]


def test_the_equilibria_are_derived_before_the_students_clock_starts():
    """sympy's solver takes a second or more for a turning hoop: that is the question's
    preparation (its own budget), never a student's time limit."""
    from lagrade.judge.check import check
    from lagrade.judge.driver import forget_problems

    forget_problems()
    spec = {"scene": "hoop", "seed": 4}
    (angle,) = get_scene("hoop").variant(4).coordinates
    verdict = check(spec, "equilibrium", f"{angle} = acos(g/(omega^2 R))", time_limit=0.5)
    assert verdict.status == "correct", verdict
    assert verdict.prepare_ms > verdict.ms
