"""The `lagrangian`, `T` and `V` parts. L′ is right when E(L′) = c E(L) with c > 0 (a dropped
constant, an added dF/dt, a factor are named); c < 0 is V − T. T must equal the reference;
V may differ by a constant (another zero level)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import Decision
from lagrade.judge.dimensions import hint_for
from lagrade.judge.equivalence import (
    affine_match,
    differ_by_constant,
    expressions_equal,
    lagrangians_match,
    offset_removed,
    reference_values,
)
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.parts.common import (
    handout_numbers,
    incorrect,
    method_name,
    named_finding,
    ratio_text,
    reference_el,
    values_text,
    where_text,
    witness_point,
)
from lagrade.judge.parts.reading import (
    Read,
    has_acceleration,
    read_single,
    without_additive_constant,
)
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import ROUNDING, SAME_VALUE
from lagrade.judge.verdict import Verdict


def judge_lagrangian(
    problem: Problem, expr: sp.Expr | Compiled
) -> tuple[str, float, list[str], Decision, dict[str, float] | None, tuple[str, ...]]:
    """(status, score, feedback, outcome, witness, mistakes) for a Lagrangian answer (a sympy
    expression, or compiled already); the witness is a point where the motion differs, when it
    does."""
    answer = expr if isinstance(expr, Compiled) else Compiled.of(expr)
    points = problem.points("lagrangian")
    if has_acceleration(problem, answer):  # before E(L), which needs an L(q, q̇, t)
        return (
            "incorrect",
            0.0,
            ["A Lagrangian depends on coordinates, velocities and t, not on accelerations."],
            Decision(False, "structure", math.inf),
            None,
            ("acceleration",),
        )
    fast = _affine_to_reference(problem, answer, points)
    if fast is not None:  # c (T − V) + k: the same motion, settled by values alone
        notes = _factor_notes(fast.factor) + ([_CONSTANT_NOTE] if fast.shifted else [])
        return ("correct", 1.0, notes, Decision(True, "numeric", fast.worst), None, ())
    match = lagrangians_match(answer, reference_el(problem, points), problem.jets, points)
    out = match.outcome
    factors = np.array(match.factors)
    if out.equal and np.all(np.abs(factors) < ROUNDING):
        return (
            "incorrect",
            0.0,
            [
                "Your L gives no equations of motion at all (it is a constant "
                "or a total time derivative)."
            ],
            out,
            None,
            ("trivial",),
        )
    if out.equal and np.all(factors > 0):
        return (
            "correct",
            1.0,
            _same_dynamics_notes(problem, answer, match, points),
            out,
            None,
            (),
        )
    if out.equal and np.all(factors < 0):
        return (
            "incorrect",
            0.5,
            [
                "Your L gives the right equations of motion but has the "
                "opposite sign: the convention is L = T − V, and you wrote "
                "V − T (or a negative multiple)."
            ],
            out,
            None,
            ("V_minus_T",),
        )
    mutant = problem.catalogue.match_lagrangian(answer, points, match.answer_el)
    mistakes: tuple[str, ...] = (mutant.kind,) if mutant is not None else ()
    witness = witness_point(points, out, answer)
    undefined = out.reason == "undefined" and _undefined_at(match.answer_el, out.where)
    where = where_text(witness, problem, ", where your L is undefined" if undefined else "")
    if mutant is not None:  # one sentence per finding
        feedback = [named_finding(mutant.message, where)]
    else:
        feedback = [f"Your L does not give the equations of motion of this system{where}."]
    return ("incorrect", 0.0, feedback, out, witness, mistakes)


def _undefined_at(answer_el: tuple[np.ndarray, np.ndarray] | None, where: int | None) -> bool:
    """Whether the answer's Euler–Lagrange values are not finite at point `where`."""
    if answer_el is None or where is None:
        return False
    return not np.all(np.isfinite(np.asarray(answer_el[0])[where]))


_CONSTANT_NOTE = (
    "Your L differs from T − V by a constant (for example m g h, another zero "
    "level of V); that does not change the motion."
)


def _affine_to_reference(problem: Problem, answer: Compiled, points: Points):
    """answer = c (T − V) + k at the points (see `affine_match`), or None."""
    try:
        with np.errstate(all="ignore"):
            values = answer.values(points.env)
    except (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError):
        return None
    return affine_match(values, reference_values(problem.L, points), points)


def _factor_notes(c: float | None) -> list[str]:
    if c is None:
        return [
            "Your L is T − V times a factor that depends on the parameters; that gives "
            "the same motion."
        ]
    if abs(c - 1) > SAME_VALUE:
        return [
            f"Your L is {ratio_text(c)} × (T − V); a constant factor gives the same "
            "equations of motion."
        ]
    return []


def _same_dynamics_notes(problem: Problem, answer: Compiled, match, points: Points) -> list[str]:
    """Name how a right L differs from T − V: a constant, dF/dt, a global factor."""
    notes = _factor_notes(match.factor)
    with np.errstate(all="ignore"):
        a, sa = answer.values(points.env)
        b, sb = reference_values(problem.L, points)
        factors = np.array(match.factors)[points.group]
        d = np.broadcast_to(a - factors * b, (points.n,))
        size = np.broadcast_to(sa + np.abs(factors) * sb, (points.n,))
    if np.all(np.abs(d) <= SAME_VALUE * size):
        return notes
    rest, first = offset_removed(d, points.group)
    if np.all(np.abs(rest) <= SAME_VALUE * (size + first)):
        notes.append(_CONSTANT_NOTE)
    else:
        notes.append(
            "Your L differs from T − V by a total time derivative dF/dt; that gives the "
            "same equations of motion."
        )
    return notes


def read_lagrangian(problem: Problem, answer: Any) -> Read:
    """A Lagrangian, `L = …` allowed, an arbitrary additive constant (`+ const`) dropped."""
    return without_additive_constant(problem, read_single(problem, answer, "lagrangian", "L"))


def read_kinetic(problem: Problem, answer: Any) -> Read:
    """A kinetic energy, `T = …` allowed."""
    return read_single(problem, answer, "T", "T")


def read_potential(problem: Problem, answer: Any) -> Read:
    """A potential energy, `V = …` allowed, an arbitrary additive constant dropped."""
    return without_additive_constant(problem, read_single(problem, answer, "V", "V"))


def check_lagrangian(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = read_lagrangian(problem, answer)
    status, score, feedback, out, witness, mistakes = judge_lagrangian(problem, got.compiled)
    if status != "correct":
        named = not mistakes or "missing_factor" in mistakes  # see dimensions.tells
        dimensions = hint_for(problem, got, "energy") if named else ""
        hints = [handout_numbers(problem, got, problem.L), dimensions]
        feedback += [hint for hint in hints if hint]
    return Verdict(
        "lagrangian",
        status,
        score,
        tuple(feedback),
        got.echo,
        method_name(out),
        witness=witness,
        mistakes=mistakes,
    )


def check_kinetic(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = read_kinetic(problem, answer)
    points = problem.points("T")
    answer_c = got.compiled
    out = expressions_equal(answer_c, problem.kinetic, points)
    if out.equal:
        return Verdict("T", "correct", 1.0, (), got.echo, method_name(out))
    mutant = problem.catalogue.match_plain(problem.catalogue.kinetic, answer_c, points)
    return incorrect(
        "T",
        got,
        mutant,
        "Your T is not the kinetic energy of this system",
        witness_point(points, out, answer_c, problem.kinetic),  # both sides' values are quoted
        method_name(out),
        problem,
        values_text(problem, points, out, answer_c, problem.kinetic, "T", "J"),
        reference=problem.kinetic,
    )


def check_potential(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = read_potential(problem, answer)
    reference = problem.potential
    points = problem.points("V")
    answer_c = got.compiled
    out = differ_by_constant(answer_c, reference, points)
    if out.equal:
        notes = ()
        if not expressions_equal(answer_c, reference, points).equal:
            notes = (
                "Your V differs from the reference by a constant (another zero level); "
                "that is fine.",
            )
        return Verdict("V", "correct", 1.0, notes, got.echo, method_name(out))
    mutant = problem.catalogue.match_offset(problem.catalogue.potential, answer_c, points)
    return incorrect(
        "V",
        got,
        mutant,
        "Your V is not the potential energy of this system (up to a constant)",
        witness_point(points, out, answer_c, reference),  # where the two differ
        method_name(out),
        problem,
        reference=reference,
    )
