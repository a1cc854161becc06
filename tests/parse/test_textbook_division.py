"""Issue 12: implicit products after a division, as textbooks print them (`k/m (x - x0)`,
`3 g/(2 (L-d)) cos(phi)`), are read left to right — the implicit product binds like '*', as
mainstream computer algebra reads it (SymPy's implicit_multiplication, Mathematica, Maxima) —
and the reading is said in a warning, in the preview and in the verdict's feedback, instead of
refusing the answer (which in batch grading zeroes a right answer with no chance to fix it)."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.cli.parse import preview_command
from lagrade.judge.check import check
from lagrade.notation.parse import Vocabulary, parse_answer

VOCAB = Vocabulary.from_names(["x", "phi"], {n: "positive" for n in "k m x0 g L d l R".split()})
k, m, x, x0, g, L, d, l, phi, R = sp.symbols("k m x x0 g L d l phi R")


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("k/m (x - x0)", lambda s: s["k"] / s["m"] * (s["x"] - s["x0"])),
        (
            "3 g/(2 (L-d)) cos(phi)",
            lambda s: 3 * s["g"] / (2 * (s["L"] - s["d"])) * sp.cos(s["phi"]),
        ),
        ("g/2 l", lambda s: s["g"] / 2 * s["l"]),
        ("m g/2 R", lambda s: s["m"] * s["g"] / 2 * s["R"]),
        ("k/m x x0", lambda s: s["k"] / s["m"] * s["x"] * s["x0"]),
    ],
)
def test_read_left_to_right_with_a_warning(text, meaning):
    parsed = parse_answer(text, VOCAB)
    names = {str(s): s for s in parsed.expr.free_symbols}
    expected = meaning({n: names.get(n, sp.Symbol(n)) for n in "k m x x0 g L d l phi R".split()})
    assert sp.simplify(parsed.expr - expected) == 0
    (warning,) = [w for w in parsed.warnings if "fraction bar" in w]
    assert "is read as (" in warning


def test_a_plain_fraction_gets_no_warning():
    for text in ("1/2 m x^2", "k x/m", "(k/m) x", "k/(m x)", "m g l cos(phi)"):
        assert not parse_answer(text, VOCAB).warnings, text


def test_preview_says_how_it_was_read():
    status, text = preview_command("k/m (x - x0)", ["x"], ["k", "m", "x0"], None)
    assert status == 0
    assert "Warning: k/m (x - x0) is read as (k/m)*(x - x0)" in text


def test_the_verdict_says_it_and_a_right_answer_stays_right():
    problem = {
        "expression": "k*(x - x0)/m",
        "parameters": {"k": "positive", "m": "positive", "x": "real", "x0": "real"},
    }
    verdict = check(problem, "expression", "k/m (x - x0)", time_limit=None)
    assert verdict.status == "correct"
    assert any("is read as (k/m)*(x - x0)" in f for f in verdict.feedback)
    hoop = check(
        {"scene": "hoop"},
        "eom",
        "theta_ddot = omega^2 sin(theta) cos(theta) - g/R sin(theta)",
        time_limit=None,
    )
    assert hoop.status == "correct"
    assert any("(g/R)*sin(theta)" in f for f in hoop.feedback)


def test_a_note_from_the_students_own_lagrangian_stays_with_that_part():
    given = {
        "lagrangian": "1/2 m R^2 theta_dot^2 + m g R cos(theta) + m/2 R^2 omega^2 sin(theta)^2"
    }
    verdict = check(
        {"scene": "hoop"},
        "eom",
        "R theta_ddot = R omega^2 sin(theta) cos(theta) - g sin(theta)",
        time_limit=None,
        given=given,
    )
    assert not any("fraction bar" in f for f in verdict.feedback)
