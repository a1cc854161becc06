"""Issue 12: the imaginary unit, only where the question declares it
(`"imaginary_unit": "I"`, or "i", "j"): then it is a number for the reference and the answers
alike, and answers are compared in complex arithmetic without dropping an imaginary part.
Elsewhere `I` stays an unknown name. Labels checked here with mpmath at 50 digits."""

from __future__ import annotations

import random

import mpmath
import pytest

from lagrade.errors import RequestError
from lagrade.judge.check import check

CASES = [
    # Euler's formula and its slips (sympy/sympy: sympy/functions/elementary/tests/
    # test_exponential.py::test_exp_rewrite, exp(I*x).rewrite(cos) == cos(x) + I*sin(x))
    (
        "exp(I x)",
        "cos(x) + I sin(x)",
        True,
        lambda x: mpmath.exp(1j * x),
        lambda x: mpmath.cos(x) + 1j * mpmath.sin(x),
    ),
    (
        "exp(I x)",
        "cos(x) - I sin(x)",
        False,
        lambda x: mpmath.exp(1j * x),
        lambda x: mpmath.cos(x) - 1j * mpmath.sin(x),
    ),
    ("exp(I x)", "cos(x)", False, lambda x: mpmath.exp(1j * x), lambda x: mpmath.cos(x)),
    # a complex residual of 1j must not be taken for 0
    ("x + I", "x", False, lambda x: x + 1j, lambda x: x),
    # the real part of exp(I x) is cos(x) (test_exponential.py::test_exp_as_real_imag)
    (
        "(exp(I x) + exp(-I x))/2",
        "cos(x)",
        True,
        lambda x: (mpmath.exp(1j * x) + mpmath.exp(-1j * x)) / 2,
        lambda x: mpmath.cos(x),
    ),
    (
        "(exp(I x) - exp(-I x))/(2 I)",
        "sin(x)",
        True,
        lambda x: (mpmath.exp(1j * x) - mpmath.exp(-1j * x)) / 2j,
        lambda x: mpmath.sin(x),
    ),
]


@pytest.mark.parametrize(("reference", "answer", "label", "ref", "ans"), CASES)
def test_label_and_verdict(reference, answer, label, ref, ans):
    rng = random.Random(3)
    with mpmath.workdps(50):
        xs = [mpmath.mpf(rng.uniform(-3, 3)) for _ in range(20)]
        equal = all(abs(ref(x) - ans(x)) < mpmath.mpf(10) ** -40 for x in xs)
    assert equal == label
    problem = {"expression": reference, "parameters": {"x": "real"}, "imaginary_unit": "I"}
    verdict = check(problem, "expression", answer, time_limit=None)
    assert verdict.status == ("correct" if label else "incorrect"), verdict.feedback


def test_other_spellings_and_only_where_declared():
    declared = {"expression": "exp(i x)", "parameters": {"x": "real"}, "imaginary_unit": "i"}
    assert check(declared, "expression", "cos(x) + i sin(x)", time_limit=None).status == "correct"
    plain = {"expression": "x", "parameters": {"x": "real"}}
    verdict = check(plain, "expression", "x + 0*I", time_limit=None)
    assert verdict.status == "invalid" and "no imaginary unit is used here" in verdict.feedback[0]


@pytest.mark.parametrize(
    "problem, message",
    [
        ({"expression": "x", "parameters": {"x": "real"}, "imaginary_unit": "k"}, "imaginary_unit"),
        ({"expression": "I", "parameters": {"I": "real"}, "imaginary_unit": "I"}, "clashes"),
    ],
    ids=["unknown-spelling", "clashes-with-a-parameter"],
)
def test_a_bad_declaration_is_refused(problem, message):
    with pytest.raises(RequestError, match=message):
        check(problem, "expression", problem["expression"], time_limit=None)
