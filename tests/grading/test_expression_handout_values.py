"""A wrong closed form in the parameters alone is shown at the student's own handout values
(issue 38: "expression feedback quotes random parameter values instead of the student's
handout values"): every parameter value a sentence quotes is one the handout gave, so the
student can reproduce both numbers. Without a handout (an ad-hoc question) the sampled point
is all there is; where both sides agree at the handout's values, no point is quoted."""

from __future__ import annotations

import math
import re

from lagrade.judge.check import check
from lagrade.judge.problem import build_problem

PENDULUM = {"scene": "simple_pendulum", "seed": 3, "quantity": "small_oscillation_frequency"}
WEDGE = {"scene": "wedge", "seed": 3, "quantity": "block_acceleration"}


def _quoted(text: str) -> dict[str, float]:
    """The `name = number` pairs of a sentence (Greek names as the sentence writes them)."""
    return {n: float(v.replace("−", "-")) for n, v in re.findall(r"(\w+) = (−?[\d.]+)", text)}


def test_the_reciprocal_is_shown_at_the_handout_values():
    values = {s.name: float(v) for s, v in build_problem(PENDULUM).values.items()}
    verdict = check(PENDULUM, "expression", "sqrt(l/g)", time_limit=20)
    text = " ".join(verdict.feedback)
    assert verdict.status == "incorrect"
    quoted = _quoted(text)
    assert quoted == {"g": values["g"], "l": values["l"]}, text
    mine = math.sqrt(values["l"] / values["g"])  # what the student computes from the handout
    theirs = math.sqrt(values["g"] / values["l"])
    # sqrt(l/g) is a time, not an angular velocity: the unit is the reference's alone
    assert f"your answer is {mine:.3g} and the reference's is {theirs:.3g} rad/s)" in text, text
    assert verdict.witness == {"g": values["g"], "l": values["l"]}


def test_every_parameter_quoted_is_the_handouts():
    values = {s.name: float(v) for s, v in build_problem(WEDGE).values.items()}
    verdict = check(WEDGE, "expression", "g sin(alpha)", time_limit=20)
    text = " ".join(verdict.feedback)
    assert "(for example with" in text, text
    assert re.search(r"your answer is \S+ m/s² and the reference's is \S+ m/s²\)", text), text
    assert verdict.witness == {n: values[n] for n in ("M", "alpha", "g", "m")}
    for name, value in _quoted(text).items():
        key = {"α": "alpha"}.get(name, name)
        assert value == float(f"{values[key]:.3g}"), (name, value, text)  # three figures


def test_no_point_where_both_sides_agree_at_the_handout_values():
    # wrong in general, right for this student's M = 5 kg: no sampled M to quote instead
    answer = "g sin(alpha) (M + m)/(M + m sin(alpha)^2) + (M - 5) g"
    verdict = check(WEDGE, "expression", answer, time_limit=20)
    text = " ".join(verdict.feedback)
    assert verdict.status == "incorrect", text
    assert "for example" not in text and verdict.witness is None, text


def test_an_ad_hoc_question_keeps_its_sampled_point():
    spec = {"expression": "cos(alpha)", "parameters": {"alpha": "(0, pi/2)"}}
    verdict = check(spec, "expression", "sin(alpha)", time_limit=20)
    assert verdict.status == "incorrect"
    assert "(for example with α = " in " ".join(verdict.feedback), verdict.feedback
