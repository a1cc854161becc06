"""The student's own coordinates. When a problem's transformation equations are answered with a
valid map (it satisfies the scene's constraints identically, uses the scene's coordinate names
and has full rank: what the `transformation` checker accepts) that differs from the statement's,
the later parts — L, T, V, the equations of motion, momenta, cyclic coordinates, conserved
quantities — are judged against the reference in the student's coordinates, by the same
checkers, and the feedback says so ("Judged in your coordinates: your φ is measured the other
way from the statement's …").

The reference there is the scene's T and V evaluated on the student's own positions
(`lagrade.mechanics.reparametrize`): no inverse map. A potential the scene writes in its own
coordinates (a spring k (r − l_0)²/2 in r) is carried over by that coordinate's closed form in
the positions (r = √(x² + y²), x_2 = x_block2 − a), checked at the sample points, else by the
relation between the two sets of coordinates when it is known in closed form
(`lagrade.judge.coordinate_relation`: the statement's φ is −φ in yours); when neither exists
the student is not followed, the later parts are judged in the statement's coordinates, and the
feedback says so.

An invalid transformation, or none, is the statement's coordinates, as before. What is built
for a student's map is kept per question by the map's canonical form (a bounded number of
them), and built as question-side work on a budget of its own (`OWN_PREPARE_LIMIT`), so that
neither the student's clock nor the question's shared budget pays for it.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import LagradeError, ParseError, RequestError
from lagrade.judge.clocks import Budget, PreparationTimeout, set_aside
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.coordinate_relation import relate
from lagrade.judge.parts.reading import reading_notes
from lagrade.judge.parts.transformation import transformation_positions
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import coordinate_range
from lagrade.judge.situation import symbol_text
from lagrade.judge.tolerances import SAME_VALUE
from lagrade.judge.verdict import Verdict
from lagrade.mechanics import (
    Jet,
    Reparametrized,
    cartesian_symbols,
    collapse_trig,
    coordinates_through_positions,
    coordinates_to_carry,
)
from lagrade.recent import Recent

#: The parts judged in the student's coordinates when their transformation is valid.
FOLLOWING = frozenset({"lagrangian", "T", "V", "eom", "momenta", "cyclic", "conserved"})
#: Seconds of derivation one student's coordinates may take in a process (the bank's scenes
#: take well under one; see benchmarks/bench_own_coordinates.py).
OWN_PREPARE_LIMIT = 10.0
#: Students' maps kept per question (the least recently used dropped past it).
_KEPT = 32
#: The mistake-like tag of a valid transformation in other coordinates (the rubric's
#: `own_coordinates` deduction applies to it).
OWN_COORDINATES = "own_coordinates"


@dataclass(frozen=True)
class Choice:
    """The coordinates a problem's later parts are judged in: `statement` (the student's are
    the statement's, invalid, or not given), `own` (`problem` is then the reference in the
    student's coordinates) or `not_followed` (valid but different, and `reason` says why the
    reference cannot follow them). `description` says how the student's differ."""

    kind: str
    problem: Problem
    description: str = ""
    reason: str = ""


def chosen_coordinates(problem: Problem, transformation: Any) -> Choice:
    """The coordinates a student's transformation answer chooses, for `problem`."""
    statement = Choice("statement", problem)
    if not problem.has_bodies or transformation is None:
        return statement
    # two keys per map: its text and its canonical form
    memory: Recent = problem.__dict__.setdefault("_own_coordinates", Recent(2 * _KEPT))
    try:
        text = json.dumps(transformation, sort_keys=True)
    except (TypeError, ValueError):
        return statement
    if text in memory:
        return memory.recalled(text)
    try:
        with reading_notes():  # the notes belong to the transformation part, not to this one
            verdict, positions = transformation_positions(problem, transformation)
    except (ParseError, RequestError):
        return statement
    if verdict.status != "correct":
        choice = statement
    else:
        canonical = json.dumps(sorted((k, sp.srepr(v)) for k, v in positions.items()))
        choice = memory.get(canonical) or _choose(problem, positions, canonical)
        memory.keep(canonical, choice)
    memory.keep(text, choice)
    return choice


def _choose(problem: Problem, positions: Mapping[str, sp.Expr], canonical: str) -> Choice:
    """Relate the student's map to the statement's and, when it differs, build the reference
    in it (on a budget of its own)."""
    budget = Budget(OWN_PREPARE_LIMIT)
    description = "they are another choice than the statement's"  # until the relation is known
    try:
        with set_aside(budget):
            relation = relate(problem, positions)
            if relation.same:
                return Choice("statement", problem)
            description = relation.description
            if problem.variant.scene.nonconservative:
                # F and Q are written in the statement's coordinates and velocities; carrying
                # them over would need a pullback like a potential's, not built for them
                return Choice(
                    "not_followed",
                    problem,
                    description,
                    "this problem's dissipation and forces are written in the statement's "
                    "coordinates",
                )
            pullback, missing = _pullback(problem, relation.closed_form, positions)
            if pullback is None:
                names = ", ".join(symbol_text(j.name) for j in missing)
                return Choice(
                    "not_followed",
                    problem,
                    description,
                    f"this problem's potential is written in the statement's {names}, which "
                    "cannot be carried over to your coordinates",
                )
            variant = Reparametrized(problem.variant, positions, pullback)
            tag = hashlib.sha256(canonical.encode()).hexdigest()[:16]
            own = Problem(
                f"{problem.key}|own:{tag}",
                "scene",
                problem.jets,
                problem.parameters,
                problem.domains,
                problem.values,
                lagrangian=variant.lagrangian,
                variant=variant,
                relations=problem.relations,
                unit=problem.unit,
                budget=budget,
            )
            own.points("lagrangian")  # the reference must be defined somewhere
    except PreparationTimeout:
        return Choice("not_followed", problem, description, _took_too_long())
    except (LagradeError, ArithmeticError, ValueError, TypeError, RecursionError):
        return Choice(
            "not_followed",
            problem,
            description,
            "the reference cannot be derived in your coordinates",
        )
    return Choice("own", own, description)


def _took_too_long() -> str:
    return f"deriving the reference in your coordinates took longer than {OWN_PREPARE_LIMIT:g} s"


def _pullback(
    problem: Problem, closed_form: Mapping[sp.Symbol, sp.Expr] | None, positions: Mapping
) -> tuple[dict | None, tuple]:
    """The statement's coordinates that the potential names itself, each in the student's
    coordinates: by the coordinate's closed form in the positions (verified; what the potential
    means physically: a spring's r is the distance √(x² + y²) on any branch of the student's
    map), else by the closed-form relation between the two sets of coordinates. (None, the
    coordinates) when some cannot be carried over."""
    variant = problem.variant
    carry = coordinates_to_carry(variant)
    if not carry:
        return {}, ()
    inverses = _verified_inverses(problem, carry)
    if all(j.q in inverses for j in carry):
        symbols = cartesian_symbols(variant)
        put = {symbols[name]: positions[name] for name in symbols}
        return {j.q: _tidied(inverses[j.q].xreplace(put), problem) for j in carry}, ()
    if closed_form is not None:
        return {j.q: closed_form[j.q] for j in carry}, ()
    return None, tuple(j for j in carry if j.q not in inverses)


def _verified_inverses(problem: Problem, carry: Sequence[Jet]) -> dict[sp.Symbol, sp.Expr]:
    """The scene's coordinates in `carry` in its bodies' Cartesian coordinates (closed forms
    offered by `coordinates_through_positions`), each checked at the sample points: put the
    statement's positions in, and the coordinate comes out. Scene-side work, kept per
    question."""
    cached = problem.__dict__.get("_inverses")
    if cached is not None:
        return cached
    variant = problem.variant
    points = problem.points("transformation")
    symbols = cartesian_symbols(variant)
    put = {symbols[name]: e for name, e in variant.transformation.items()}
    found = {}
    for q, candidate in coordinates_through_positions(variant, [j.q for j in carry]).items():
        try:
            with np.errstate(all="ignore"):
                got = Compiled.of(candidate.xreplace(put)).values(points.env)[0]
        except LagradeError:
            continue
        got = np.asarray(to_length(got, points.n), dtype=complex)
        want = points.env[q]
        if np.all(np.abs(got - want) <= SAME_VALUE * (1 + np.abs(want))):
            found[q] = candidate
    problem.__dict__["_inverses"] = found
    return found


def _tidied(expr: sp.Expr, problem: Problem) -> sp.Expr:
    """A coordinate carried over through a square root, tidied: the radicand's sin² + cos²
    collapsed (√(r² cos²θ + r² sin²θ) = |r|), and |r| = r for a coordinate sampled positive
    (a radius: the reference is judged only there)."""
    rooted = expr.replace(
        lambda e: e.is_Pow and e.exp.is_Rational and e.exp.q == 2,
        lambda e: sp.Pow(collapse_trig(e.base), e.exp),
    )
    positive = {sp.Abs(j.q): j.q for j in problem.jets if coordinate_range(j.name)[0] > 0}
    return rooted.xreplace(positive) if positive else rooted


# --- judging a later part --------------------------------------------------------------------


def judged_in_chosen_coordinates(
    problem: Problem,
    part: str,
    answer: Any,
    given: Mapping,
    checker: Callable[[Problem, Any, Mapping | None], Verdict],
) -> Verdict:
    """A later part judged in the coordinates the student's transformation (`given`'s
    "transformation") chose, saying so; an answer that is wrong there but right in the
    statement's coordinates is told why."""
    choice = chosen_coordinates(problem, given.get("transformation"))
    if choice.kind == "own" and choice.problem.budget.exhausted:
        choice = Choice("not_followed", problem, choice.description, _took_too_long())
    if choice.kind == "statement":
        return checker(problem, answer, given)
    if choice.kind == "not_followed":
        verdict = checker(problem, answer, given)
        if verdict.status == "correct":
            return verdict
        note = (
            f"Your transformation equations use other coordinates than the statement's "
            f"({choice.description}), but {choice.reason}: this part is judged in the "
            "statement's coordinates."
        )
        return replace(verdict, feedback=(note, *verdict.feedback))
    own = choice.problem
    try:
        with set_aside(own.budget):
            _prepare(own, part)
        verdict = checker(own, answer, given)  # a wrong answer's diagnosis is on own.budget
    except PreparationTimeout:
        own.budget.charge(max(own.budget.left, 0.0))  # exhausted: every later part knows
        return judged_in_chosen_coordinates(problem, part, answer, given, checker)
    feedback = [f"Judged in your coordinates: {choice.description}."]
    if verdict.status == "incorrect" and checker(problem, answer, given).status == "correct":
        feedback.append(
            "This answer is right in the statement's coordinates, not in yours: it does not "
            "follow from your own transformation equations."
        )
    return replace(verdict, feedback=(*feedback, *verdict.feedback))


def _prepare(own: Problem, part: str) -> None:
    """What judging `part` needs of the reference in the student's coordinates (as
    `lagrade.judge.check.prepare` does for a question)."""
    if part in ("lagrangian", "momenta", "eom", "conserved", "T", "V"):
        own.points(part)
    if part == "conserved":
        _ = own.system.conserved_quantities


def transformation_remark(problem: Problem, answer: Any, verdict: Verdict) -> Verdict:
    """A valid transformation in other coordinates than the statement's: still correct, with a
    remark saying how they differ and in which coordinates the later parts are judged, and the
    tag `own_coordinates` (which the rubric may charge)."""
    if verdict.status != "correct" or not problem.has_bodies:
        return verdict
    choice = chosen_coordinates(problem, answer)
    if choice.kind == "statement":
        return verdict
    if choice.kind == "own":
        remark = (
            f"Your coordinates are not the statement's: {choice.description}. That is a valid "
            "choice: the later parts are judged in your coordinates."
        )
    else:
        remark = (
            f"Your coordinates are not the statement's: {choice.description}. That is a valid "
            f"choice, but {choice.reason}, so the later parts are judged in the statement's "
            "coordinates."
        )
    return replace(
        verdict,
        feedback=(*verdict.feedback, remark),
        mistakes=(*verdict.mistakes, OWN_COORDINATES),
    )
