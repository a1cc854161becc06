"""The exact test runs answer and reference as one program; where that program has no value at
a point, each side is evaluated alone to tell which one is undefined there: an answer undefined
where the reference has a value is wrong, a point where the reference has none is drawn again."""

from fractions import Fraction

import numpy as np
import sympy as sp

import benchmarks.exact_rational as exact

x, y = sp.symbols("x y", real=True)
ZERO_AT_MINUS_ONE = 2 * y * (2 * x + 2) / (x + 1)  # 4y, but undefined at x = −1


def _at_minus_one(monkeypatch):
    """Every drawn rational is −1 (so x + 1 vanishes at every point)."""
    monkeypatch.setattr(exact, "_fraction_in", lambda lo, hi, rng: Fraction(-1))


def _compare(answer, reference):
    return exact._exact_compare(answer, reference, {}, 3, np.random.default_rng(0), trig=False)


def test_an_answer_undefined_where_the_reference_is_defined_is_wrong(monkeypatch):
    _at_minus_one(monkeypatch)
    assert _compare(ZERO_AT_MINUS_ONE, 4 * y) is False


def test_points_where_the_reference_is_undefined_are_drawn_again(monkeypatch):
    _at_minus_one(monkeypatch)
    assert _compare(4 * y, ZERO_AT_MINUS_ONE) is None  # no point left to decide on


def test_where_both_are_defined_the_pair_decides():
    assert _compare(ZERO_AT_MINUS_ONE, 4 * y) is True
    assert _compare(ZERO_AT_MINUS_ONE, 4 * y + x) is False
