"""Issue 12: implicit products after a division, as textbooks print them (`k/m (x - x0)`,
`3 g/(2 (L-d)) cos(phi)`), are read left to right — the implicit product binds like '*', as
mainstream computer algebra reads it (SymPy's implicit_multiplication, Mathematica, Maxima) —
instead of refusing the answer (which in batch grading zeroes a right answer with no chance to
fix it). Issue 30: a warning says so only where the other reading, a/(b c), is plausible — the
factor written against the divisor (`g/2l`, `k/m(x - x0)`), never `m/2 (…)` or a bracket after
a number — and never on a correct verdict, whose reading was the right one."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.cli.parse import preview_command
from lagrade.judge.check import check
from lagrade.notation.parse import Vocabulary, parse_answer

VOCAB = Vocabulary.from_names(["x", "phi"], {n: "positive" for n in "k m x0 g L d l R".split()})
k, m, x, x0, g, L, d, l, phi, R = sp.symbols("k m x x0 g L d l phi R")


@pytest.mark.parametrize(
    ("text", "meaning", "warns"),
    [
        ("k/m (x - x0)", lambda s: s["k"] / s["m"] * (s["x"] - s["x0"]), False),
        ("k/m(x - x0)", lambda s: s["k"] / s["m"] * (s["x"] - s["x0"]), True),
        (
            "3 g/(2 (L-d)) cos(phi)",
            lambda s: 3 * s["g"] / (2 * (s["L"] - s["d"])) * sp.cos(s["phi"]),
            False,
        ),
        ("g/2 l", lambda s: s["g"] / 2 * s["l"], False),
        ("g/2l", lambda s: s["g"] / 2 * s["l"], True),
        ("3g/2l", lambda s: 3 * s["g"] / 2 * s["l"], True),
        ("m g/2 R", lambda s: s["m"] * s["g"] / 2 * s["R"], False),
        ("k/m x x0", lambda s: s["k"] / s["m"] * s["x"] * s["x0"], False),
        (
            "m/2 (x^2 + R^2 phi^2)",
            lambda s: s["m"] / 2 * (s["x"] ** 2 + s["R"] ** 2 * s["phi"] ** 2),
            False,
        ),
        (
            "m/2(x^2 + R^2 phi^2)",
            lambda s: s["m"] / 2 * (s["x"] ** 2 + s["R"] ** 2 * s["phi"] ** 2),
            False,
        ),
    ],
)
def test_read_left_to_right_warned_where_the_other_reading_is_plausible(text, meaning, warns):
    parsed = parse_answer(text, VOCAB)
    names = {str(s): s for s in parsed.expr.free_symbols}
    expected = meaning({n: names.get(n, sp.Symbol(n)) for n in "k m x x0 g L d l phi R".split()})
    assert sp.simplify(parsed.expr - expected) == 0
    warnings = [w for w in parsed.warnings if "fraction bar" in w]
    assert len(warnings) == warns, warnings
    if warns:
        assert warnings[0].startswith(f"{text} is read as (")


def test_a_plain_fraction_gets_no_warning():
    for text in ("1/2 m x^2", "k x/m", "(k/m) x", "k/(m x)", "m g l cos(phi)"):
        assert not parse_answer(text, VOCAB).warnings, text


def test_preview_says_how_it_was_read():
    status, text = preview_command("k/m(x - x0)", ["x"], ["k", "m", "x0"], None)
    assert status == 0
    assert "Warning: k/m(x - x0) is read as (k/m)*(x - x0)" in text
    status, text = preview_command("k/m (x - x0)", ["x"], ["k", "m", "x0"], None)
    assert status == 0 and "Warning" not in text and "Interpreted as: k/m*(x - x0)" in text


PROBLEM = {
    "expression": "k*(x - x0)/m",
    "parameters": {"k": "positive", "m": "positive", "x": "real", "x0": "real"},
}


def test_a_right_answer_stays_right_and_unwarned():
    for text in ("k/m (x - x0)", "k/m(x - x0)"):
        verdict = check(PROBLEM, "expression", text, time_limit=None)
        assert verdict.status == "correct" and verdict.feedback == (), verdict.feedback
    hoop = check(
        {"scene": "hoop"},
        "eom",
        "theta_ddot = omega^2 sin(theta) cos(theta) - g/R sin(theta)",
        time_limit=None,
    )
    assert hoop.status == "correct" and hoop.feedback == (), hoop.feedback
    kepler_T = "m/2 (r_dot^2 + r^2 theta_dot^2)"  # the issue's own right answer
    assert check({"scene": "kepler"}, "T", kepler_T, time_limit=None).feedback == ()


def test_a_wrong_answer_says_how_it_was_read():
    """k/(m (x − x0)) meant, k/m(x − x0) typed: wrong, and the note shows why."""
    verdict = check({**PROBLEM, "expression": "k/(m*(x - x0))"}, "expression", "k/m(x - x0)")
    assert verdict.status == "incorrect"
    assert any("is read as (k/m)*(x - x0)" in f for f in verdict.feedback), verdict.feedback


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


def test_no_warning_on_a_right_answer_of_the_corpora():
    """benchmarks/reading_warnings.py measures every corpus; here the two labelled pair files,
    whose right answers include textbook-typed divisions (14 of 107 external ones warned)."""
    import json
    from pathlib import Path

    corpus = Path(__file__).resolve().parents[2] / "benchmarks" / "corpus"
    warned = []
    for name in ("external.jsonl", "pairs.jsonl"):
        for line in (corpus / name).read_text(encoding="utf-8").splitlines():
            row = json.loads(line)
            if not row["label"]:
                continue
            vocabulary = Vocabulary.from_names(
                row["coordinates"], row["parameters"], imaginary_unit=row.get("imaginary_unit")
            )
            parsed = parse_answer(row["answer"], vocabulary)
            warned += [row["id"] for w in parsed.warnings if "fraction bar" in w]
    assert warned == []
