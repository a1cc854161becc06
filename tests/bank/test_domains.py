"""Parameter domains as instructors and request files write them."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.errors import LagradeError
from lagrade.mechanics.domains import Domain, _exact_number, exact_number


@pytest.mark.parametrize(
    ("text", "lower", "upper", "lower_open", "upper_open"),
    [
        ("positive", 0, sp.oo, True, True),
        ("nonnegative", 0, sp.oo, False, True),
        ("real", -sp.oo, sp.oo, True, True),
        ("(0, pi/2)", 0, sp.pi / 2, True, True),
        ("[0, 1]", 0, 1, False, False),
        ("(-2pi, 2*pi]", -2 * sp.pi, 2 * sp.pi, True, False),
        ("(-1.5, inf)", sp.Rational(-3, 2), sp.oo, True, True),
        # SI values (an electron's charge, a planet's mass), read exactly
        ("(1.5e-19, 1.7E-19)", sp.Rational(15, 10**20), sp.Rational(17, 10**20), True, True),
        ("[1e24, 2e30]", sp.Integer(10) ** 24, 2 * sp.Integer(10) ** 30, False, False),
    ],
)
def test_domains_are_read_exactly(text, lower, upper, lower_open, upper_open) -> None:
    d = Domain.parse(text)
    assert (d.lower, d.upper, d.lower_open, d.upper_open) == (lower, upper, lower_open, upper_open)
    lo, hi = d.sample_range()
    assert d.contains(lo) and d.contains(hi) and lo < hi


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("(1, 0)", "empty interval"),
        ("(0, 1e999)", "too large"),
        ("(0, 1e5000)", "cannot read the interval bound"),  # at most three exponent digits
        ("(0, sqrt(2))", "unknown domain"),
        ("between 0 and 1", "unknown domain"),
    ],
)
def test_bad_domains_say_what_is_wrong(text, message) -> None:
    with pytest.raises(LagradeError, match=message):
        Domain.parse(text)


@pytest.mark.parametrize("value", [9.81, 6.674e-11, 5.97e24, 0.1, 2, 1.5, -3.25, 1e-36, 2 / 3])
def test_a_value_is_the_exact_number_sympy_reads_it_as(value) -> None:
    """`exact_number` is sympy's nsimplify(rational=True), once per value: the same number
    however often it is asked for, and an int and the float equal to it each as itself."""
    assert exact_number(value) == sp.nsimplify(value, rational=True)
    kept = _exact_number.cache_info().hits
    assert exact_number(value) is exact_number(value)
    assert _exact_number.cache_info().hits > kept  # converted once, found again
    assert exact_number(2) == exact_number(2.0) == 2


def test_a_value_that_cannot_be_kept_is_converted_as_sympy_converts_it() -> None:
    """An unhashable value (no scene's) is not kept: it meets nsimplify itself, error and all."""

    def outcome(convert):
        try:
            return convert([0.5])
        except Exception as error:  # noqa: BLE001 - the comparison is the point
            return type(error)

    assert outcome(exact_number) == outcome(lambda v: sp.nsimplify(v, rational=True))
