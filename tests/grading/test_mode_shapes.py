"""The `mode_shapes` part on the bank's coupled oscillators and double pendulum: each mode's
vector judged up to scale and matched to its frequency, in any order.

The labels are recomputed here without lagrade: the Lagrangians written out from the
textbooks, M and K as sympy Hessians at q = 0, and (K − ω² M) a = 0 checked at the variant's
own values with numpy (`_label`).

- Two equal masses and three springs, the middle one k_c (after Taylor, Classical Mechanics,
  ch. 11, which opens with this system; its section numbers were not checked here): the masses
  move together at ω = √(k/m), (1, 1), and oppositely at √((k + 2 k_c)/m), (1, −1).
- The double pendulum with equal masses and lengths (Kibble & Berkshire, Classical Mechanics,
  5th ed., ch. 11, example "Normal modes of the double pendulum", eqs. 11.20–11.21, read for
  this test: ω² = (2 ∓ √2) g/l, with shapes (1, ±√2) from the same 2×2 problem)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from lagrade.judge.parts import run_checker
from lagrade.judge.problem import build_problem
from lagrade.judge.read import read_answer

m, k, k_c, g, l = sp.symbols("m k k_c g l", positive=True)
x1, x2, v1, v2 = sp.symbols("x_1 x_2 x_1_dot x_2_dot", real=True)

#: Taylor §11.1's L with k₁ = k₃ = k, k₂ = k_c (the bank's coupled_oscillators).
CARTS_L = m * (v1**2 + v2**2) / 2 - k * (x1**2 + x2**2) / 2 - k_c * (x2 - x1) ** 2 / 2
#: The double pendulum with equal masses and lengths, as an ad-hoc Lagrangian.
DOUBLE = {
    "lagrangian": "m l^2 (theta_1_dot^2 + 1/2 theta_2_dot^2 + theta_1_dot theta_2_dot "
    "cos(theta_1 - theta_2)) + m g l (2 cos(theta_1) + cos(theta_2))",
    "coordinates": ["theta_1", "theta_2"],
    "parameters": {"m": "positive", "l": "positive", "g": "positive"},
}
t1, t2, w1, w2 = sp.symbols("theta_1 theta_2 theta_1_dot theta_2_dot", real=True)
DOUBLE_L = m * l**2 * (w1**2 + w2**2 / 2 + w1 * w2 * sp.cos(t1 - t2)) + m * g * l * (
    2 * sp.cos(t1) + sp.cos(t2)
)


def _label(L, q, v, values: dict, modes: list[tuple[sp.Expr, tuple]]) -> str:
    """Right when every (ω, a) solves (K − ω² M) a = 0 at q = 0 and the ω are the nonzero
    frequencies, each once: numpy at `values`."""
    at = {s: 0 for s in (*q, *v)}
    M = np.array(sp.hessian(L, v).subs(at).subs(values).tolist(), float)
    K = -np.array(sp.hessian(L, q).subs(at).subs(values).tolist(), float)
    want = sorted(np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real))
    got = []
    for w, a in modes:
        w = float(w.subs(values))
        a = np.array([float(sp.S(x).subs(values)) for x in a])
        if not np.allclose((K - w**2 * M) @ a, 0, atol=1e-9 * np.abs(K).max()):
            return "incorrect"
        got.append(w)
    return "correct" if np.allclose(sorted(got), want, rtol=1e-9) else "incorrect"


def _text(modes) -> str:
    lines = [f"omega = {sp.sstr(w)}: ({', '.join(sp.sstr(x) for x in a)})" for w, a in modes]
    return "\n".join(lines)


SLOW, FAST = sp.sqrt(k / m), sp.sqrt((k + 2 * k_c) / m)
CARTS = [
    ([(SLOW, (1, 1)), (FAST, (1, -1))], "correct", None),
    ([(FAST, (-3, 3)), (SLOW, (2, 2))], "correct", None),  # any order, any scale
    ([(SLOW, (1, -1)), (FAST, (1, 1))], "incorrect", "swapped"),
    ([(SLOW, (1, 1)), (FAST, (1, 0))], "incorrect", "wrong_shape"),
    ([(SLOW, (1, 1))], "incorrect", "missing_mode"),
]


@pytest.mark.parametrize(("modes", "label", "mistake"), CARTS)
def test_coupled_oscillators(modes, label, mistake):
    problem = build_problem({"scene": "coupled_oscillators", "seed": 2})
    values = {sp.Symbol(s.name, positive=True): v for s, v in problem.values.items()}
    assert _label(CARTS_L, (x1, x2), (v1, v2), values, modes) == label
    verdict = run_checker(problem, "mode_shapes", _text(modes))
    assert verdict.status == label, verdict.feedback
    if mistake:
        assert mistake in verdict.mistakes, verdict.mistakes


ROOT2 = sp.sqrt(2)
LOW, HIGH = sp.sqrt((2 - ROOT2) * g / l), sp.sqrt((2 + ROOT2) * g / l)
DOUBLES = [
    ([(LOW, (1, ROOT2)), (HIGH, (1, -ROOT2))], "correct", None),
    ([(HIGH, (-1, ROOT2)), (LOW, (ROOT2, 2))], "correct", None),
    ([(LOW, (1, 1)), (HIGH, (1, -1))], "incorrect", "wrong_shape"),
    ([(LOW, (1, 0)), (HIGH, (0, 1))], "incorrect", "mass_ignored"),  # K = m g l diag(2, 1)
    ([(LOW, (1, -ROOT2)), (HIGH, (1, ROOT2))], "incorrect", "swapped"),
]


@pytest.mark.parametrize(("modes", "label", "mistake"), DOUBLES)
def test_double_pendulum_with_equal_masses_and_lengths(modes, label, mistake):
    values = {m: 1.3, l: 0.7, g: 9.81}
    assert _label(DOUBLE_L, (t1, t2), (w1, w2), values, modes) == label
    verdict = run_checker(build_problem(DOUBLE), "mode_shapes", _text(modes))
    assert verdict.status == label, verdict.feedback
    if mistake:
        assert mistake in verdict.mistakes, verdict.mistakes


def test_the_bank_double_pendulums_key_and_a_swapped_key():
    """The bank's double pendulum (any masses and lengths): its key is accepted, and the key
    with the two vectors exchanged is named `swapped`."""
    from lagrade.bank import get_scene
    from lagrade.judge.key import key_answer

    key = key_answer(get_scene("double_pendulum").variant(4), "mode_shapes")
    problem = build_problem({"scene": "double_pendulum", "seed": 4})
    assert run_checker(problem, "mode_shapes", key).status == "correct"
    (f1, a1), (f2, a2) = (line.split(": ", 1) for line in key)
    swapped = [f"{f1}: {a2}", f"{f2}: {a1}"]
    verdict = run_checker(problem, "mode_shapes", swapped)
    assert verdict.status == "incorrect" and verdict.mistakes == ("swapped", "swapped")


@pytest.mark.parametrize(
    ("answer", "message"),
    [
        ("sqrt(k/m) (1, 1)", "Write each mode on its own line"),
        ("omega = sqrt(k/m): 1", "amplitudes in brackets"),
        ("omega = sqrt(k/m): (1, 1, 1)", "one amplitude per coordinate, in the order (x_1, x_2)"),
        ("omega = sqrt(k/m): (x_1, 1)", "holds no coordinate"),
        # the caret under the + in the whole line
        ("omega = sqrt(k/m): (1, 1 +)", "  omega = sqrt(k/m): (1, 1 +)\n" + " " * 27 + "^"),
    ],
)
def test_bad_text_is_invalid_with_a_message(answer, message):
    verdict = run_checker(
        build_problem({"scene": "coupled_oscillators", "seed": 2}), "mode_shapes", answer
    )
    assert verdict.status == "invalid" and message in " ".join(verdict.feedback), verdict


def test_the_preview_reads_each_mode_without_judging():
    problem = build_problem({"scene": "coupled_oscillators", "seed": 2})
    answer = "omega = sqrt(k/m): (1, 1)\nsqrt(3k/m): (1, -1 +)"
    reading = read_answer(problem, "mode_shapes", answer)
    assert reading.status == "read"
    assert reading.lines[0].plain == "omega = sqrt(k/m): (1, 1)"
    assert reading.lines[1].error.startswith("Line 2")


@pytest.mark.parametrize(
    ("answer", "status", "mistake"),
    [
        (
            ["omega = sqrt(k_z/m): (0, 0, 1)", "sqrt(k/m): (1, 1, 0)", "sqrt(k/m): (1, -1, 0)"],
            "correct",
            None,
        ),
        (
            ["omega = sqrt(k_z/m): (0, 0, 1)", "sqrt(k/m): (1, 0, 0)", "sqrt(k/m): (2, 0, 0)"],
            "incorrect",
            "repeated",
        ),
    ],
)
def test_a_repeated_frequency_takes_any_two_independent_vectors_of_its_plane(
    answer, status, mistake
):
    """A particle in a trap with k_x = k_y = k (free_particle, seed 3): the plane z = 0 is one
    frequency's modes, so (1, 1, 0) and (1, −1, 0) are right and one direction twice is not."""
    verdict = run_checker(
        build_problem({"scene": "free_particle", "seed": 3}), "mode_shapes", answer
    )
    assert verdict.status == status, verdict.feedback
    if mistake:
        assert mistake in verdict.mistakes
