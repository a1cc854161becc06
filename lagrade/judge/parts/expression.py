"""The `expression` part, and with it every numeric follow-up of an assignment, by one rule:

- a number (no symbols) is judged against the reference's value at the handout's parameter
  values, within a relative tolerance (`given["values"]`, `given["tolerance"]`; by default the
  question's own variant and `NUMERIC_TOLERANCE`), with or without the quantity's unit;
- anything else (a closed form) must equal the reference expression on the declared domains.

`lagrade check` and `lagrade grade` both come here, so one answer gets one verdict.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.judge.adaptive import ExactThenAdaptive
from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import Decision
from lagrade.judge.equivalence import expressions_equal
from lagrade.judge.parts.common import handout_witness, incorrect, method_name, values_text
from lagrade.judge.parts.items import single_text
from lagrade.judge.parts.reading import Read, read_single
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import coordinate_range
from lagrade.judge.situation import unit_text
from lagrade.judge.tolerances import NUMERIC_TOLERANCE, ROUNDING
from lagrade.judge.verdict import Verdict
from lagrade.mechanics import Domain, exact_number


def _domains_for(problem: Problem) -> dict:
    """Domains of every variable: parameters as declared, coordinates in their sample ranges.
    Made once per question structure (its domains and coordinates are the structure's: its
    shared points are drawn in them), not per answer: their sympy Floats were most of an exact
    verdict's cost outside the test itself. A copy, for the caller's own."""
    kept = problem.shared.get(_DOMAINS)
    if kept is None or not _same_symbols(kept, problem):
        kept = problem.shared[_DOMAINS] = _made_domains(problem)
    return dict(kept)


#: Where `_domains_for` keeps a structure's domains in `Problem.shared`.
_DOMAINS = "_expression_domains"


def _same_symbols(domains: dict, problem: Problem) -> bool:
    """Whether `domains` is keyed by the very symbols of `problem`, as if made for it (a variant
    of the structure whose symbols are equal but other objects gets its own)."""
    mine = (*problem.domains, *(j.q for j in problem.jets))
    return len(domains) == len(mine) and all(a is b for a, b in zip(domains, mine, strict=True))


def _made_domains(problem: Problem) -> dict:
    domains = dict(problem.domains)
    for j in problem.jets:
        lo, hi = (problem.coordinate_domains or {}).get(j.name) or coordinate_range(j.name)
        domains[j.q] = Domain(j.name, sp.Float(lo), sp.Float(hi))
    return domains


def strip_unit(text: str, unit: str) -> str:
    """'5.39 m/s^2' → '5.39' when the quantity's unit is m/s^2 (spaces and ** tolerated)."""
    if not unit:
        return text
    pattern = re.escape(unit).replace(r"\^", r"(?:\^|\*\*)").replace(r"\ ", r"\s*")
    return re.sub(rf"\s*(?:\[\s*)?{pattern}(?:\s*\])?\s*$", "", text.strip())


#: Units a value may carry: (scale to SI, dimensions as exponents of (m, kg, s)).
_UNITS = {
    "m": (1.0, (1, 0, 0)), "km": (1e3, (1, 0, 0)), "cm": (1e-2, (1, 0, 0)),  # not a tolerance
    "mm": (1e-3, (1, 0, 0)), "s": (1.0, (0, 0, 1)), "ms": (1e-3, (0, 0, 1)),  # not a tolerance
    "min": (60.0, (0, 0, 1)), "kg": (1.0, (0, 1, 0)), "N": (1.0, (1, 1, -2)),
    "J": (1.0, (2, 1, -2)), "W": (1.0, (2, 1, -3)), "Hz": (1.0, (0, 0, -1)),
    "rad": (1.0, (0, 0, 0)), "1": (1.0, (0, 0, 0)),
    "deg": (math.pi / 180, (0, 0, 0)), "degree": (math.pi / 180, (0, 0, 0)),
    "degrees": (math.pi / 180, (0, 0, 0)),
}  # fmt: skip
#: Units that measure an angle in degrees: accepted only for a quantity measured in rad.
_DEGREES = frozenset({"deg", "degree", "degrees"})
#: A degree sign after a number (78.7°, 78.7 º, LaTeX 78.7^\circ or 78.7\degree): the unit deg.
_DEGREE_SIGN = re.compile(r"(?<=[0-9.])\s*(?:°|º|\^\s*\{?\s*\\circ\s*\}?|\\degree)")
_UNIT_FACTOR = re.compile(
    r"\s*([/*·]?)\s*([A-Za-z]+|1)\s*(?:(?:\^|\*\*)\s*\(?\s*([-+]?\d+)\s*\)?)?"
)
_NUMBER_AND_UNIT = re.compile(
    r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?:\[\s*(.+?)\s*\]|([A-Za-z].*?))\s*$"
)


def read_unit(text: str) -> tuple[float, tuple[int, ...]] | None:
    """'m/s^2' → (1.0, (1, 0, −2)): a product of known units with integer powers, '/' dividing
    by the next factor. None when the text is not such a unit (it is never evaluated)."""
    scale, dims, pos, text = 1.0, [0, 0, 0], 0, text.strip()
    while pos < len(text):
        match = _UNIT_FACTOR.match(text, pos)
        if match is None or match.end() == pos or match[2] not in _UNITS:
            return None
        power = int(match[3] or 1) * (-1 if match[1] == "/" else 1)
        unit_scale, unit_dims = _UNITS[match[2]]
        scale *= unit_scale**power
        dims = [d + power * u for d, u in zip(dims, unit_dims, strict=True)]
        pos = match.end()
    return (scale, tuple(dims)) if text else None


def _with_unit(problem: Problem, answer: Any) -> tuple[str, str] | None:
    """(the number, its unit) of an answer written `5.39 m/s^2` for a quantity with a unit;
    a degree sign is the unit deg (`78.7°`)."""
    if not problem.unit or not isinstance(answer, str):
        return None
    match = _NUMBER_AND_UNIT.match(_DEGREE_SIGN.sub(" deg", answer))
    unit = (match[2] or match[3] or "").strip() if match else ""
    read, own = read_unit(unit), read_unit(problem.unit)
    if read is None or own is None:
        return None
    names = re.findall(r"[A-Za-z]+", unit)
    if all(n in problem.by_name for n in names) and read[1] != own[1]:
        return None  # `2 m` for a mass is twice the parameter m, not two metres
    return match[1], unit


def _angle_in_degrees(problem: Problem, answer: Any) -> tuple[str, str] | None:
    """(the number, what was written) of an angle typed in degrees (`60°`, `-45 deg`) for a
    question that declares no unit: a degree is the number π/180 in mathematics, so it is read
    as that (in rad), with a note; with a declared unit `_with_unit` decides instead."""
    if problem.unit or not isinstance(answer, str):
        return None
    match = _NUMBER_AND_UNIT.match(_DEGREE_SIGN.sub(" deg", answer))
    unit = (match[2] or match[3] or "").strip() if match else ""
    if not match or unit not in _DEGREES or unit in problem.by_name:
        return None
    return match[1], unit


def _in_degrees(unit: str) -> bool:
    return any(name in _DEGREES for name in re.findall(r"[A-Za-z]+", unit))


def _number_in_unit(problem: Problem, number: str, unit: str) -> str | Verdict:
    """The number in the quantity's own unit, or the verdict of a wrong unit. Degrees measure
    angles only: for a quantity in rad they are converted, for any other they are a wrong
    unit (a ratio has no degrees)."""
    theirs, mine = read_unit(problem.unit), read_unit(unit)
    if theirs is None or mine is None:
        return number
    wrong_angle = _in_degrees(unit) and not re.search(r"\brad\b", problem.unit)
    if mine[1] != theirs[1] or wrong_angle:
        return Verdict(
            "expression",
            "incorrect",
            0.0,
            (
                f"Your value is given in {unit}, which is not a unit of this quantity: "
                f"it is measured in {problem.unit}.",
            ),
            f"{number} {unit}",
            "units",
            mistakes=("wrong_unit",),
        )
    return repr(float(number) * mine[0] / theirs[0])


def _handout_values(problem: Problem, given: Mapping | None) -> dict[sp.Symbol, sp.Expr] | None:
    """The parameter values the student was given (exact numbers), or None without a handout."""
    values = (given or {}).get("values")
    if values is None and problem.variant is not None:
        values = problem.variant.values
    if not values or set(problem.parameters) - set(values):
        return None
    return {problem.parameters[n]: exact_number(v) for n, v in values.items()}


def _judge_number(
    problem: Problem, got: sp.Expr, values: Mapping, tolerance: float, bare: bool = True
) -> Verdict:
    """A number against the reference's value at the handout's values (relative tolerance).
    A `bare` number (no unit written) for an angle in rad that is the right angle in degrees
    is told so."""
    expected = complex(sp.N(problem.expression.xreplace(values), 30))
    value = complex(sp.N(got, 30))
    echo = f"{value.real:.6g}"  # a number reads better as a decimal than as 6887/1000
    if abs(expected.imag) > ROUNDING * max(1.0, abs(expected)):
        feedback = ("For these values the quantity is not real; the key says so.",)
        return Verdict("expression", "incorrect", 0.0, feedback, echo, "numeric")
    error = abs(value - expected.real) / max(abs(expected.real), 1e-300)
    if error <= tolerance:
        return Verdict("expression", "correct", 1.0, (), echo, "numeric")
    sign_flipped = abs(value.real + expected.real) <= tolerance * abs(expected.real)
    feedback = (
        f"Your value {value.real:.4g} is off by {100 * error:.3g} % (the tolerance is "
        f"{100 * tolerance:g} %)." + (" Check the sign." if sign_flipped else ""),
    )
    mistakes = ("numeric_sign",) if sign_flipped else ("numeric_value",)
    degrees = math.degrees(expected.real)
    if bare and problem.unit == "rad" and abs(value.real - degrees) <= tolerance * abs(degrees):
        feedback = (
            f"Your value {value.real:.4g} is the angle in degrees; a number alone is read in "
            f"rad. Give it in rad, or write {value.real:.4g}° (or deg).",
        )
        mistakes = ("degrees_for_radians",)
    return Verdict("expression", "incorrect", 0.0, feedback, echo, "numeric", mistakes=mistakes)


def judged_by_its_reading(problem: Problem, answer: Any) -> bool:
    """Whether the checker sees nothing of `answer` but its reading (`read_expression`'s one
    item): text with no `=` (a closed form and its value), no number with a unit (converted,
    or named as the wrong unit, beside the parser) and no angle in degrees (read with a note).
    The question's own unit after a closed form is dropped alike by the reader and the
    checker (`strip_unit`). Only such an answer may be given the verdict of another read the
    same (`same_reading`)."""
    return (
        isinstance(answer, str)
        and "=" not in answer
        and _with_unit(problem, answer) is None
        and _angle_in_degrees(problem, answer) is None
    )


def read_expression(problem: Problem, answer: Any) -> list[Read]:
    """What an `expression` answer gives: a closed form, a number (its unit or degree sign read
    as `_check_one` reads them), or both as `closed form = value`."""
    text = single_text(answer, "expression")
    if isinstance(text, str) and text.count("=") == 1:
        sides = [side.strip() for side in text.split("=")]
        try:
            return [read_single(problem, _bare(problem, side), "expression", "x") for side in sides]
        except (ParseError, RequestError):
            pass  # read as one answer (`x = …`), and its error is that reading's
    return [read_single(problem, _as_read(problem, text), "expression", "x")]


def _as_read(problem: Problem, answer: Any) -> Any:
    """The text `_check_one` reads of an answer: a number with its unit converted to the
    quantity's, an angle in degrees as a multiple of π/180, the quantity's own unit dropped."""
    with_unit = _with_unit(problem, answer)
    if with_unit is not None:
        converted = _number_in_unit(problem, *with_unit)
        return with_unit[0] if isinstance(converted, Verdict) else converted
    degrees = _angle_in_degrees(problem, answer)
    if degrees is not None:
        return f"({degrees[0]})*pi/180"
    return strip_unit(answer, problem.unit) if isinstance(answer, str) else answer


def check_expression(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    answer = single_text(answer, "expression")
    both = _closed_form_and_value(problem, answer, given)
    if both is not None:
        return both
    return _check_one(problem, answer, given)


def _closed_form_and_value(problem: Problem, answer: Any, given: Mapping | None) -> Verdict | None:
    """`acos(g/(R omega^2)) = 1.238`, as a prompt asking for "a closed form (or its value)"
    invites: both sides are judged, each by its own rule, and the answer is right when both are.
    None when the answer is not of that shape (`name = expression` is read as usual)."""
    if not isinstance(answer, str) or answer.count("=") != 1:
        return None
    left, right = (side.strip() for side in answer.split("="))
    try:
        one, two = (
            read_single(problem, _bare(problem, side), "expression", "x") for side in (left, right)
        )
    except (ParseError, RequestError):
        return None
    if not one.symbols and two.symbols:  # `1.238 = acos(…)`
        left, right, one, two = right, left, two, one
    if not one.symbols or two.symbols:
        return None
    closed, number = _check_one(problem, left, given), _check_one(problem, right, given)
    feedback = [f"Your closed form: {f}" for f in closed.feedback]
    feedback += [f"Your value: {f}" for f in number.feedback]
    right_ones = [v.status == "correct" for v in (closed, number)]
    return Verdict(
        "expression",
        "correct" if all(right_ones) else "incorrect",
        (closed.score + number.score) / 2,
        tuple(feedback),
        f"{closed.interpreted} = {number.interpreted}",
        closed.method,
        witness=closed.witness,
        mistakes=closed.mistakes + number.mistakes,
    )


def _bare(problem: Problem, side: str) -> str:
    """One side of `closed form = value` without the value's unit (any unit: a wrong one is
    judged, and named, by `_check_one`)."""
    with_unit = _with_unit(problem, side)
    return with_unit[0] if with_unit is not None else strip_unit(side, problem.unit)


#: Points of the float stage where Max or Min make the expressions piecewise: no exact test covers
#: them, and a region where two answers differ (both arguments negative: a quarter of the box)
#: is missed by 12 points one time in 30 but by 256 points never in practice ((3/4)^256).
PIECEWISE_POINTS = 256


def _piecewise(*compiled: Compiled) -> bool:
    return any(instr[0] in ("max", "min") for c in compiled for instr in c.program.code)


def _check_one(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    with_unit = _with_unit(problem, answer)
    note = ""
    if with_unit is not None:
        answer = _number_in_unit(problem, *with_unit)
        if isinstance(answer, Verdict):
            return answer
        if _in_degrees(with_unit[1]):
            note = f"{with_unit[0]} {with_unit[1]} is read as {float(answer):.6g} {problem.unit}."
    elif (degrees := _angle_in_degrees(problem, answer)) is not None:
        answer = f"({degrees[0]})*pi/180"
        note = f"{degrees[0]} {degrees[1]} is read as {degrees[0]}·π/180 rad."
    if isinstance(answer, str) and problem.unit:
        answer = strip_unit(answer, problem.unit)
    got = read_single(problem, answer, "expression", "x")
    values = _handout_values(problem, given) if not got.symbols else None
    if values is not None:
        tolerance = float((given or {}).get("tolerance", NUMERIC_TOLERANCE))
        verdict = _judge_number(problem, got.expr, values, tolerance, bare=not with_unit)
        return replace(verdict, feedback=(*verdict.feedback, note)) if note else verdict
    ref = problem.reference_expression
    ans = got.compiled
    # The default decision (docs/methods.csv): exact where possible, bounded floats otherwise;
    # the numeric hybrid decides only what that method cannot reach, and finds witnesses.
    method = (
        ExactThenAdaptive(points=PIECEWISE_POINTS) if _piecewise(ans, ref) else ExactThenAdaptive()
    )
    decided = method.decide_programs(ans.whole, ref.whole, _domains_for(problem))
    if decided:
        return Verdict("expression", "correct", 1.0, (), got.echo, "exact_then_adaptive")
    points = problem.points("expression")
    out = expressions_equal(ans, ref, points)
    if decided is not None:
        out = Decision(False, "exact_then_adaptive", out.worst, out.where)
    if out.equal:
        return Verdict("expression", "correct", 1.0, (), got.echo, method_name(out))
    # The catalogue's slips are real-valued tests: a complex question gets the plain sentence.
    mutant = (
        None
        if problem.imaginary_unit or points.complex_values
        else problem.catalogue.match_plain(problem.catalogue.expression_mutants, ans, points)
    )
    verdict = incorrect(
        "expression",
        got,
        mutant,
        "Your answer is not equal to the expected expression",
        handout_witness(problem, points, out, ans, ref),
        out.method if decided is not None else method_name(out),
        problem,
        values_text(problem, points, out, ans, ref, "answer", unit_text(problem.unit)),
        reference=ref,
    )
    return replace(verdict, feedback=(*verdict.feedback, note)) if note else verdict
