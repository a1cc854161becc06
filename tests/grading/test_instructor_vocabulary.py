"""Issue 12: a reference written the way instructors and sympy write it — Abs, sign, atan2,
asinh/acosh/atanh, cbrt, t as an ordinary variable of an expression problem — is read (it was
refused), and judged right. The identities come from sympy's own tests (sympy/sympy, file and
test named per case); each label is checked here independently with mpmath at 50 digits at
random points of the declared domain, where the reference is real and finite."""

from __future__ import annotations

import random

import mpmath
import pytest

from lagrade.judge.check import check

SYMPY = "sympy/sympy: sympy/functions/elementary/tests/"

# (id, source, reference, answer, parameters, label, mpmath reference, mpmath answer)
CASES = [
    (
        "abs_sqrt_square",
        SYMPY + "test_complexes.py::test_Abs_rewrite",
        "Abs(x)",
        "sqrt(x^2)",
        {"x": "real"},
        True,
        lambda v: abs(v["x"]),
        lambda v: mpmath.sqrt(v["x"] ** 2),
    ),
    (
        "abs_not_x",
        SYMPY + "test_complexes.py::test_Abs_rewrite",
        "Abs(x)",
        "x",
        {"x": "real"},
        False,
        lambda v: abs(v["x"]),
        lambda v: v["x"],
    ),
    (
        "sign_times_x",
        SYMPY + "test_complexes.py::test_sign",
        "sign(x) x",
        "abs(x)",
        {"x": "real"},
        True,
        lambda v: mpmath.sign(v["x"]) * v["x"],
        lambda v: abs(v["x"]),
    ),
    (
        "sgn_alias",
        SYMPY + "test_complexes.py::test_sign",
        "sgn(x)",
        "x/abs(x)",
        {"x": "real"},
        True,
        lambda v: mpmath.sign(v["x"]),
        lambda v: v["x"] / abs(v["x"]),
    ),
    (
        "atan2_is_atan_right_half",
        SYMPY + "test_trigonometric.py::test_atan2",
        "atan2(y, x)",
        "atan(y/x)",
        {"x": "positive", "y": "real"},
        True,
        lambda v: mpmath.atan2(v["y"], v["x"]),
        lambda v: mpmath.atan(v["y"] / v["x"]),
    ),
    (
        "atan2_not_atan_everywhere",
        SYMPY + "test_trigonometric.py::test_atan2",
        "atan2(y, x)",
        "atan(y/x)",
        {"x": "real", "y": "real"},
        False,
        lambda v: mpmath.atan2(v["y"], v["x"]),
        lambda v: mpmath.atan(v["y"] / v["x"]),
    ),
    (
        "atan2_half_angle",
        SYMPY + "test_trigonometric.py::test_atan2",
        "atan2(y, x)",
        "2 atan(y/(sqrt(x^2 + y^2) + x))",
        {"x": "real", "y": "real"},
        True,
        lambda v: mpmath.atan2(v["y"], v["x"]),
        lambda v: 2 * mpmath.atan(v["y"] / (mpmath.sqrt(v["x"] ** 2 + v["y"] ** 2) + v["x"])),
    ),
    (
        "atan2_arguments_swapped",
        SYMPY + "test_trigonometric.py::test_atan2",
        "atan2(y, x)",
        "atan2(x, y)",
        {"x": "real", "y": "real"},
        False,
        lambda v: mpmath.atan2(v["y"], v["x"]),
        lambda v: mpmath.atan2(v["x"], v["y"]),
    ),
    (
        "cbrt_is_third_root",
        SYMPY + "test_miscellaneous.py::test_root",
        "cbrt(x)",
        "x^(1/3)",
        {"x": "positive"},
        True,
        lambda v: mpmath.cbrt(v["x"]),
        lambda v: v["x"] ** (mpmath.mpf(1) / 3),
    ),
    (
        "cbrt_not_square_root",
        SYMPY + "test_miscellaneous.py::test_root",
        "cbrt(x)",
        "sqrt(x)",
        {"x": "positive"},
        False,
        lambda v: mpmath.cbrt(v["x"]),
        lambda v: mpmath.sqrt(v["x"]),
    ),
    (
        "asinh_log",
        SYMPY + "test_hyperbolic.py::test_asinh_rewrite",
        "asinh(x)",
        "log(x + sqrt(x^2 + 1))",
        {"x": "real"},
        True,
        lambda v: mpmath.asinh(v["x"]),
        lambda v: mpmath.log(v["x"] + mpmath.sqrt(v["x"] ** 2 + 1)),
    ),
    (
        "asinh_atanh",
        SYMPY + "test_hyperbolic.py::test_asinh_rewrite",
        "asinh(x)",
        "atanh(x/sqrt(1 + x^2))",
        {"x": "real"},
        True,
        lambda v: mpmath.asinh(v["x"]),
        lambda v: mpmath.atanh(v["x"] / mpmath.sqrt(1 + v["x"] ** 2)),
    ),
    (
        "asinh_sign_slip",
        SYMPY + "test_hyperbolic.py::test_asinh_rewrite",
        "asinh(x)",
        "log(x - sqrt(x^2 + 1))",
        {"x": "real"},
        False,
        lambda v: mpmath.asinh(v["x"]),
        lambda v: mpmath.log(v["x"] - mpmath.sqrt(v["x"] ** 2 + 1)),
    ),
    (
        "acosh_log",
        SYMPY + "test_hyperbolic.py::test_acosh_rewrite",
        "acosh(x)",
        "log(x + sqrt(x - 1) sqrt(x + 1))",
        {"x": "(1, 20)"},
        True,
        lambda v: mpmath.acosh(v["x"]),
        lambda v: mpmath.log(v["x"] + mpmath.sqrt(v["x"] - 1) * mpmath.sqrt(v["x"] + 1)),
    ),
    (
        "arccosh_alias",
        SYMPY + "test_hyperbolic.py::test_acosh_rewrite",
        "arccosh(x)",
        "log(x + sqrt(x^2 - 1))",
        {"x": "(1, 20)"},
        True,
        lambda v: mpmath.acosh(v["x"]),
        lambda v: mpmath.log(v["x"] + mpmath.sqrt(v["x"] ** 2 - 1)),
    ),
    (
        "atanh_log",
        SYMPY + "test_hyperbolic.py::test_atanh_rewrite",
        "atanh(x)",
        "(log(1 + x) - log(1 - x))/2",
        {"x": "(-1, 1)"},
        True,
        lambda v: mpmath.atanh(v["x"]),
        lambda v: (mpmath.log(1 + v["x"]) - mpmath.log(1 - v["x"])) / 2,
    ),
    (
        "atanh_half_missing",
        SYMPY + "test_hyperbolic.py::test_atanh_rewrite",
        "atanh(x)",
        "log(1 + x) - log(1 - x)",
        {"x": "(-1, 1)"},
        False,
        lambda v: mpmath.atanh(v["x"]),
        lambda v: mpmath.log(1 + v["x"]) - mpmath.log(1 - v["x"]),
    ),
    (
        "t_as_a_variable",
        "issue 12: t as an ordinary variable of an expression problem",
        "t^2 - a t",
        "t (t - a)",
        {"t": "(0, 10)", "a": "real"},
        True,
        lambda v: v["t"] ** 2 - v["a"] * v["t"],
        lambda v: v["t"] * (v["t"] - v["a"]),
    ),
    (
        "t_as_a_variable_wrong",
        "issue 12: t as an ordinary variable of an expression problem",
        "t^2 - a t",
        "t (t + a)",
        {"t": "(0, 10)", "a": "real"},
        False,
        lambda v: v["t"] ** 2 - v["a"] * v["t"],
        lambda v: v["t"] * (v["t"] + v["a"]),
    ),
]


def _draw(domain: str, rng: random.Random) -> mpmath.mpf:
    if domain == "real":
        return mpmath.mpf(rng.uniform(-5, 5))
    if domain == "positive":
        return mpmath.mpf(rng.uniform(0.01, 5))
    lo, hi = (float(x) for x in domain.strip("()").split(","))
    return mpmath.mpf(rng.uniform(lo, hi))


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_label_holds_at_50_digits(case):
    """The label, checked without lagrade: equal at every point, or different at some."""
    _, _, _, _, params, label, ref, ans = case
    rng = random.Random(12)
    differs = 0
    with mpmath.workdps(50):
        for _ in range(40):
            v = {name: _draw(dom, rng) for name, dom in params.items()}
            r, a = ref(v), ans(v)
            if isinstance(r, mpmath.mpc) or not mpmath.isfinite(r):
                continue
            if isinstance(a, mpmath.mpc) or abs(a - r) > mpmath.mpf(10) ** -40 * (1 + abs(r)):
                differs += 1
    assert (differs == 0) == label


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_lagrade_agrees(case):
    _, _, reference, answer, params, label, _, _ = case
    problem = {"expression": reference, "parameters": params}
    verdict = check(problem, "expression", answer, time_limit=None)
    assert verdict.status == ("correct" if label else "incorrect"), verdict.feedback


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
