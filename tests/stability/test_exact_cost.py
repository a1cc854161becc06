"""Exactness never costs a right answer (issue 25): the exact stage of the default method is
bounded by its cost before it starts — the multiple of a trig argument (sin(n y) expands into a
polynomial of degree n) and the estimated size of its exact numbers — and leaves a costly pair
to the high-precision stage, whose verdict is as sure. Each right answer here ran for seconds or
minutes in the exact stage before (a `timeout` under a time limit, depending on machine load);
each wrong one beside it must still be told apart.

The checks run in a killable worker with a limit far above what they take now (tens of
milliseconds), so that the old behaviour fails as `timeout` instead of hanging the suite."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import benchmarks.exact_rational as exact
import lagrade.judge.evaluate as ev
from lagrade.judge.check import check

#: Far above what these pairs take now; far below what the unbounded exact stage took.
GENEROUS = 20.0

REAL_T = {"t": "real"}
REAL_X = {"x": "real"}

# (answer, reference, parameters): equal pairs the exact stage could not finish quickly
RIGHT = [
    ("sin(10^6*t)^2", "1 - cos(10^6*t)^2", REAL_T),
    ("sin(1000000*t)*cos(1000000*t)", "sin(2000000*t)/2", REAL_T),
    ("sin(12345*t)^2 + cos(12345*t)^2", "1", REAL_T),
    ("tan(1000*t)", "sin(1000*t)/cos(1000*t)", REAL_T),
    ("cos(10^6*t)", "1 - 2*sin(5*10^5*t)^2", REAL_T),
    ("sin(x/1000 + x/999)^2", "1 - cos(1999*x/999000)^2", REAL_X),  # units lcm 999000
    ("sin(6.02e23*t)^2 + cos(6.02e23*t)^2", "1", REAL_T),
    ("sin(1000*x)", "sin(1000*x)", REAL_X),
    ("cos(100*x)^2", "(1 + cos(200*x))/2", REAL_X),
    ("1/(x+1/7)^100 + 1/(x+2/7)^100 + 1/(x+3/7)^100 + 1/(x+4/7)^100 + 1/(x+5/7)^100",
     "1/(x+5/7)^100 + 1/(x+4/7)^100 + 1/(x+3/7)^100 + 1/(x+2/7)^100 + 1/(x+1/7)^100",
     {"x": "positive"}),
]  # fmt: skip

# near misses of the same kinds: the high-precision stage must still see the difference
WRONG = [
    ("sin(10^6*t)^2", "1 - cos(10^6*t)^2 + 10^-12", REAL_T),
    ("sin(1000000*t)*cos(1000000*t)", "sin(2000001*t)/2", REAL_T),
    ("cos(10^6*t)", "1 - 2*sin(5*10^5*t + 10^-9)^2", REAL_T),
    ("sin(1000*x) + 1/1000", "sin(1000*x)", REAL_X),
    ("cos(100*x)^2", "(1 + cos(201*x))/2", REAL_X),
    ("1/(x+1/7)^100 + 1/(x+2/7)^100", "1/(x+1/7)^100 + 1/(x+2/7)^99", {"x": "positive"}),
]


def _checked(answer: str, reference: str, parameters: dict):
    problem = {"expression": reference, "parameters": parameters}
    return check(problem, "expression", answer, time_limit=GENEROUS)


@pytest.mark.parametrize("answer, reference, parameters", RIGHT)
def test_a_right_answer_costly_to_decide_exactly_is_correct_not_timeout(
    answer, reference, parameters
):
    verdict = _checked(answer, reference, parameters)
    assert verdict.status == "correct", verdict.feedback


@pytest.mark.parametrize("answer, reference, parameters", WRONG)
def test_a_near_miss_of_the_same_kind_is_still_incorrect(answer, reference, parameters):
    verdict = _checked(answer, reference, parameters)
    assert verdict.status == "incorrect", verdict.feedback


x, t = sp.symbols("x t", real=True)


@pytest.mark.parametrize(
    "answer, reference",
    [
        (sp.sin(1000 * x), sp.sin(1000 * x)),
        (sp.sin(10**6 * t) ** 2, 1 - sp.cos(10**6 * t) ** 2),
        (sp.sin(x / 1000 + x / 999), sp.sin(1999 * x / 999000)),
    ],
)
def test_the_exact_stage_declines_a_large_multiple_before_expanding_it(
    monkeypatch, answer, reference
):
    def refuse(*args):
        raise AssertionError("expand_trig was called on a costly multiple")

    monkeypatch.setattr(sp, "expand_trig", refuse)
    assert exact.ExactRational().decide(answer, reference, {}) is None


def test_the_exact_stage_declines_numbers_too_large_before_computing_them(monkeypatch):
    def refuse(*args):
        raise AssertionError("the exact values were computed")

    monkeypatch.setattr(exact, "_exact_values", refuse)
    many = sum(1 / (x + sp.Rational(k, 7)) ** 100 for k in range(1, 31))
    assert exact.ExactRational().decide(many, many, {}) is None


def test_a_small_identity_is_still_decided_exactly():
    assert exact.ExactRational().decide(sp.sin(2 * x), 2 * sp.sin(x) * sp.cos(x), {}) is True
    assert exact.ExactRational().decide(sp.sin(40 * x) ** 2, 1 - sp.cos(40 * x) ** 2, {}) is True


def test_the_work_estimate_grows_with_powers_and_distinct_denominators():
    bits = {x: (53, 52)}

    def work(expr):
        return exact.exact_work(ev.compile_program([expr]), bits)

    assert work((x + 1) ** 2000) > 100 * work((x + 1) ** 100)
    # one common denominator: the terms of a polynomial; distinct ones multiply out
    common = work(sum(x**k for k in range(1, 20)))
    distinct = work(sum(1 / (x + k) ** 20 for k in range(1, 20)))
    assert distinct > 100 * common
    assert np.isfinite(work(sp.Integer(10) ** 40 * x))
