"""Numeric follow-ups of an assignment (the wedge's acceleration for this student's m, M, α):
a number within the rubric's relative tolerance of the key, with or without its unit, or a
formula in the parameters that is equivalent to the closed form."""

from __future__ import annotations

import re

import sympy as sp

from lagrade.errors import ParseError
from lagrade.judge.checks import Verdict, run_checker
from lagrade.judge.problem import Problem
from lagrade.mechanics.scene import SceneVariant
from lagrade.notation.parse import Vocabulary, parse_expression


def _strip_unit(text: str, unit: str) -> str:
    """'5.39 m/s^2' → '5.39' when the quantity's unit is m/s^2 (spaces and ** tolerated)."""
    if not unit:
        return text
    pattern = re.escape(unit).replace(r"\^", r"(?:\^|\*\*)").replace(r"\ ", r"\s*")
    return re.sub(rf"\s*(?:\[\s*)?{pattern}(?:\s*\])?\s*$", "", text.strip())


def check_numeric_followup(
    variant: SceneVariant, problem: Problem, quantity: str, answer: str, tolerance: float
) -> Verdict:
    """Judge a follow-up answer: numbers against the key's value at this variant's parameter
    values (relative `tolerance`), formulas by symbolic equivalence with the closed form."""
    unit = next((q.unit for q in variant.scene.quantities if q.name == quantity), "")
    text = _strip_unit(answer, unit)
    vocabulary = Vocabulary(coordinates=(), parameters=dict(variant.parameter_symbols))
    try:
        parsed = parse_expression(text, vocabulary)
    except ParseError as error:
        return Verdict("expression", "invalid", 0.0, (str(error),), text, "parse")
    if parsed.expr.free_symbols:
        return run_checker(problem, "expression", text)
    reference = variant.quantities[quantity].xreplace(variant.numeric_values)
    expected = complex(sp.N(reference, 30))
    got = complex(sp.N(parsed.expr, 30))
    echo = f"{got.real:.6g}"  # a number reads better as a decimal than as 6887/1000
    if abs(expected.imag) > 1e-12 * max(1.0, abs(expected)):
        return Verdict(
            "expression",
            "incorrect",
            0.0,
            ("For these values the quantity is not real; the key says so.",),
            echo,
            "numeric",
        )
    error = abs(got - expected.real) / max(abs(expected.real), 1e-300)
    if error <= tolerance:
        return Verdict("expression", "correct", 1.0, (), echo, "numeric")
    sign_flipped = abs(got.real + expected.real) <= tolerance * abs(expected.real)
    return Verdict(
        "expression",
        "incorrect",
        0.0,
        (
            f"Your value {got.real:.4g} is off by {100 * error:.3g} % (the tolerance is "
            f"{100 * tolerance:g} %)." + (" Check the sign." if sign_flipped else ""),
        ),
        echo,
        "numeric",
        mistakes=("numeric_sign",) if sign_flipped else ("numeric_value",),
    )
