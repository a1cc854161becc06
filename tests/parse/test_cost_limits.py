"""Issue 12: the limits that stop bombs are based on cost, not on a small constant. A high power
that numeric evaluation handles ((x - b)^5000: repeated squaring, mpmath's unbounded exponents)
is read and judged; what would cost too much — an exact number of millions of digits, a power
of a sum that multiplies out to billions of terms, an exponent past a million — is refused at
once with a message, and the judge never names a mistake from values that underflowed to 0."""

from __future__ import annotations

import pytest

from lagrade.errors import ParseError
from lagrade.judge.check import check
from lagrade.notation.parse import Vocabulary, parse_answer

VOCAB = Vocabulary.from_names(["x"], {"b": "positive", "a": "positive", "c": "positive"})
UNIT = {"expression": "(x - b)^5000", "parameters": {"x": "(0, 1)", "b": "(0, 1)"}}


def test_a_high_power_is_read_and_judged():
    assert parse_answer("(x - b)^5000", VOCAB).expr.exp == 5000
    assert check(UNIT, "expression", "(b - x)^5000", time_limit=None).status == "correct"
    wrong = check(UNIT, "expression", "(x - b)^5001", time_limit=None)
    assert wrong.status == "incorrect"
    odd = {"expression": "(x - b)^5001", "parameters": UNIT["parameters"]}
    assert check(odd, "expression", "(b - x)^5001", time_limit=None).status == "incorrect"


def test_no_mistake_is_named_from_values_that_underflowed():
    """(x − b)^5000 and (x − b)^5001 are both 0 in float64 at most points; a catalogue match
    there (it said "sin and cos are swapped" of an answer without sin or cos) would be false."""
    wrong = check(UNIT, "expression", "(x - b)^5001", time_limit=None)
    assert not wrong.mistakes
    assert not any("swapped" in f or "sign" in f for f in wrong.feedback)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("x^(10^9)", "Exponent too large"),
        ("9^9^9^9", "Exponent too large"),
        ("2^20000", "too large to work with"),
        ("(a + b + c + x + 1)^1000", "multiplied out it would have more than"),
        ("(a + b + c + x + 1)^(-1000)", "multiplied out it would have more than"),
    ],
)
def test_bombs_are_refused_at_once(text, message):
    with pytest.raises(ParseError, match=message):  # refused before anything is computed
        parse_answer(text, VOCAB)


def test_a_power_of_a_sum_below_the_limit_is_read():
    parsed = parse_answer("(a + b + c + x)^100", VOCAB)  # 176,851 terms if multiplied out
    assert parsed.expr.exp == 100
