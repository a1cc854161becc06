"""Issue 12: expressions are compared the way mathematics compares them — principal branches in
complex arithmetic over the declared domain, at points where the reference is finite — and
judging does not depend on float range. Each label is checked here independently: mpmath
complex arithmetic at 50 digits (its functions are the principal branches) at random points
of the declared domain; lagrade must agree.

Sources: sympy/sympy's own tests of when a rewrite holds (file and test named per case), and
SI-scale quantities from the Kepler problem and atomic physics (Taylor, Classical Mechanics,
ch. 8; Bohr radius a0 = 4 pi eps0 hbar^2/(m e^2))."""

from __future__ import annotations

import random

import mpmath
import pytest

from lagrade.judge.check import check

SYMPY = "sympy/sympy: sympy/"
m = mpmath

# (id, source, reference, answer, parameters, label, mpmath reference, mpmath answer)
CASES = [
    (
        "power_of_power_real_base",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "(a^b)^c",
        "a^(b c)",
        {"a": "real", "b": "real", "c": "real"},
        False,
        lambda v: m.power(m.power(v["a"], v["b"]), v["c"]),
        lambda v: m.power(v["a"], v["b"] * v["c"]),
    ),
    (
        "power_of_power_positive_base",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "(a^b)^c",
        "a^(b c)",
        {"a": "positive", "b": "real", "c": "real"},
        True,
        lambda v: m.power(m.power(v["a"], v["b"]), v["c"]),
        lambda v: m.power(v["a"], v["b"] * v["c"]),
    ),
    (
        "sqrt_of_abs",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "sqrt(x)",
        "sqrt(abs(x))",
        {"x": "real"},
        False,
        lambda v: m.sqrt(v["x"]),
        lambda v: m.sqrt(abs(v["x"])),
    ),
    (
        "sqrt_of_abs_positive",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "sqrt(x)",
        "sqrt(abs(x))",
        {"x": "positive"},
        True,
        lambda v: m.sqrt(v["x"]),
        lambda v: m.sqrt(abs(v["x"])),
    ),
    (
        "sqrt_of_square",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "sqrt(x^2)",
        "abs(x)",
        {"x": "real"},
        True,
        lambda v: m.sqrt(v["x"] ** 2),
        lambda v: abs(v["x"]),
    ),
    (
        "product_of_roots",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "sqrt(y - 2) sqrt(y - 6)",
        "sqrt((y - 2) (y - 6))",
        {"y": "real"},
        False,
        lambda v: m.sqrt(v["y"] - 2) * m.sqrt(v["y"] - 6),
        lambda v: m.sqrt((v["y"] - 2) * (v["y"] - 6)),
    ),
    (
        "product_of_roots_far_out",
        "issue 12: a reference defined only far out in the box",
        "sqrt(y - 2) sqrt(y - 6)",
        "sqrt((y - 2) (y - 6))",
        {"y": "(6, 40)"},
        True,
        lambda v: m.sqrt(v["y"] - 2) * m.sqrt(v["y"] - 6),
        lambda v: m.sqrt((v["y"] - 2) * (v["y"] - 6)),
    ),
    (
        "product_of_roots_right",
        "issue 12: a reference defined only far out in the box",
        "sqrt(y - 2) sqrt(y - 6)",
        "sqrt(y - 2) sqrt(y - 6)",
        {"y": "real"},
        True,
        lambda v: m.sqrt(v["y"] - 2) * m.sqrt(v["y"] - 6),
        lambda v: m.sqrt(v["y"] - 2) * m.sqrt(v["y"] - 6),
    ),
    (
        "root_of_product",
        SYMPY + "simplify/tests/test_powsimp.py::test_powdenest",
        "sqrt(x) sqrt(y)",
        "sqrt(x y)",
        {"x": "real", "y": "real"},
        False,
        lambda v: m.sqrt(v["x"]) * m.sqrt(v["y"]),
        lambda v: m.sqrt(v["x"] * v["y"]),
    ),
    (
        "log_of_square",
        SYMPY + "functions/elementary/tests/test_exponential.py::test_log_expand",
        "log(x^2)",
        "2 log(x)",
        {"x": "real"},
        False,
        lambda v: m.log(v["x"] ** 2),
        lambda v: 2 * m.log(v["x"]),
    ),
    (
        "log_of_square_positive",
        SYMPY + "functions/elementary/tests/test_exponential.py::test_log_expand",
        "log(x^2)",
        "2 log(x)",
        {"x": "positive"},
        True,
        lambda v: m.log(v["x"] ** 2),
        lambda v: 2 * m.log(v["x"]),
    ),
    (
        "acosh_log_one_root",
        SYMPY + "functions/elementary/tests/test_hyperbolic.py::test_acosh_rewrite",
        "acosh(x)",
        "log(x + sqrt(x^2 - 1))",
        {"x": "real"},
        False,
        lambda v: m.acosh(v["x"]),
        lambda v: m.log(v["x"] + m.sqrt(v["x"] ** 2 - 1)),
    ),
    (
        "acosh_log_two_roots",
        SYMPY + "functions/elementary/tests/test_hyperbolic.py::test_acosh_rewrite",
        "acosh(x)",
        "log(x + sqrt(x - 1) sqrt(x + 1))",
        {"x": "real"},
        True,
        lambda v: m.acosh(v["x"]),
        lambda v: m.log(v["x"] + m.sqrt(v["x"] - 1) * m.sqrt(v["x"] + 1)),
    ),
    (
        "exp_log",
        SYMPY + "functions/elementary/tests/test_exponential.py::test_exp_log",
        "exp(log(x))",
        "x",
        {"x": "real"},
        True,
        lambda v: m.exp(m.log(v["x"])),
        lambda v: v["x"],
    ),
    (
        "log_exp",
        SYMPY + "functions/elementary/tests/test_exponential.py::test_exp_log",
        "log(exp(x))",
        "x",
        {"x": "real"},
        True,
        lambda v: m.log(m.exp(v["x"])),
        lambda v: v["x"],
    ),
    (
        "kepler_force_si",
        "Taylor, Classical Mechanics, ch. 8 (Kepler problem, SI values)",
        "(G M m)^2/(r^4)",
        "G^2 M^2 m^2 r^(-4)",
        {"G": "(6.6e-11, 6.8e-11)", "M": "(1e30, 3e30)", "m": "(1e24, 1e25)", "r": "(1e11, 3e11)"},
        True,
        lambda v: (v["G"] * v["M"] * v["m"]) ** 2 / v["r"] ** 4,
        lambda v: v["G"] ** 2 * v["M"] ** 2 * v["m"] ** 2 * v["r"] ** -4,
    ),
    (
        "si_tenth_power",
        "Taylor, Classical Mechanics, ch. 8 (Kepler problem, SI values)",
        "(M r)^10",
        "M^10 r^10",
        {"M": "(1e30, 3e30)", "r": "(1e11, 2e11)"},
        True,
        lambda v: (v["M"] * v["r"]) ** 10,
        lambda v: v["M"] ** 10 * v["r"] ** 10,
    ),
    (
        "si_tenth_power_wrong",
        "Taylor, Classical Mechanics, ch. 8 (Kepler problem, SI values)",
        "(M r)^10",
        "M^10 r^11",
        {"M": "(1e30, 3e30)", "r": "(1e11, 2e11)"},
        False,
        lambda v: (v["M"] * v["r"]) ** 10,
        lambda v: v["M"] ** 10 * v["r"] ** 11,
    ),
    (
        "si_near_miss",
        "Taylor, Classical Mechanics, ch. 8 (Kepler problem, SI values)",
        "(M r)^10",
        "M^10 r^10 (1 + 1e-12)",
        {"M": "(1e30, 3e30)", "r": "(1e11, 2e11)"},
        False,
        lambda v: (v["M"] * v["r"]) ** 10,
        lambda v: v["M"] ** 10 * v["r"] ** 10 * (1 + m.mpf("1e-12")),
    ),
    (
        "bohr_radius_squared",
        "Bohr radius a0 = 4 pi eps0 hbar^2/(m e^2), squared twice",
        "(4 pi eps hbar^2/(me e^2))^4",
        "256 pi^4 eps^4 hbar^8/(me^4 e^8)",
        {
            "eps": "(8.8e-12, 8.9e-12)",
            "hbar": "(1.05e-34, 1.06e-34)",
            "me": "(9.1e-31, 9.2e-31)",
            "e": "(1.6e-19, 1.61e-19)",
        },
        True,
        lambda v: (4 * m.pi * v["eps"] * v["hbar"] ** 2 / (v["me"] * v["e"] ** 2)) ** 4,
        lambda v: 256 * m.pi**4 * v["eps"] ** 4 * v["hbar"] ** 8 / (v["me"] ** 4 * v["e"] ** 8),
    ),
]


def _draw(domain: str, rng: random.Random) -> mpmath.mpf:
    if domain == "real":
        return mpmath.mpf(rng.uniform(-40, 40))
    if domain == "positive":
        return mpmath.mpf(rng.uniform(0.01, 40))
    lo, hi = (float(x) for x in domain.strip("()").split(","))
    return mpmath.mpf(rng.uniform(lo, hi))


def _finite(z) -> bool:
    return not (mpmath.isnan(z) or mpmath.isinf(z))


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_label_holds_in_complex_arithmetic_at_50_digits(case):
    _, _, _, _, params, label, ref, ans = case
    rng = random.Random(7)
    differs = compared = 0
    with mpmath.workdps(50):
        for _ in range(60):
            v = {name: _draw(dom, rng) for name, dom in params.items()}
            try:
                r = ref(v)
            except (ValueError, ZeroDivisionError):
                continue
            if not _finite(r):
                continue
            compared += 1
            a = ans(v)
            if not _finite(a) or abs(a - r) > mpmath.mpf(10) ** -40 * (1 + abs(r)):
                differs += 1
    assert compared > 10
    assert (differs == 0) == label


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_lagrade_agrees(case):
    _, _, reference, answer, params, label, _, _ = case
    verdict = check(
        {"expression": reference, "parameters": params}, "expression", answer, time_limit=None
    )
    assert verdict.status == ("correct" if label else "incorrect"), verdict.feedback
