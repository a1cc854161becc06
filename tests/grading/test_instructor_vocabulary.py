"""Issue 12: the vocabulary instructors and sympy write in, where a case needs more than an
expression pair (those, with their sources and independently checked labels, are in
benchmarks/corpus/external.jsonl and tests/stability/test_external_corpus.py): atan2 inside a
Lagrangian (the evaluator's derivatives) and the messages of functions of two arguments."""

from __future__ import annotations

from lagrade.judge.check import check


def test_atan2_in_a_lagrangian_gives_the_right_equations():
    """The evaluator's derivatives of atan2 (hyper-dual numbers): L = T − k·atan2(y, x)."""
    problem = {
        "lagrangian": "1/2 m (x_dot^2 + y_dot^2) - k atan2(y, x)",
        "coordinates": ["x", "y"],
        "parameters": {"m": "positive", "k": "positive"},
    }
    right = ["m x_ddot = k y/(x^2 + y^2)", "m y_ddot = -k x/(x^2 + y^2)"]
    wrong = ["m x_ddot = -k y/(x^2 + y^2)", "m y_ddot = k x/(x^2 + y^2)"]
    assert check(problem, "eom", right, time_limit=None).status == "correct"
    assert check(problem, "eom", wrong, time_limit=None).status == "incorrect"


def test_functions_of_two_arguments_say_how_to_write_them():
    problem = {"expression": "x", "parameters": {"x": "real", "y": "real"}}
    for answer, message in (
        ("atan2(y)", "atan2 takes two arguments"),
        ("atan2 y", "Write atan2(y, x) with brackets"),
    ):
        verdict = check(problem, "expression", answer, time_limit=None)
        assert verdict.status == "invalid" and message in verdict.feedback[0]
