"""One checker per answer part, registered by part name in `PARTS`; each returns a frozen Verdict
and never raises over a student's mistake (text that does not parse is `invalid`, with the
parser's message; in a part of several lines an unreadable line is named and counts as a
wrong one, and the part is `invalid` only when no line reads). Every command that judges a
part (`check`, `check --batch`, `grade`, key verification, the answer page, PrairieLearn, the
demo) comes through `run_checker` with the raw answer — a string, or the list of strings a sheet
or request holds — and the checker splits and reads it (`items`, `reading`): the one door.

    dof             an integer: 3N − k
    coordinates     the generalized coordinates, by name
    transformation  Cartesian coordinates that satisfy the constraints identically, full rank
    lagrangian      E(L′) = c E(L): c > 0 right (constant, dF/dt, factor named), c < 0 V − T
    T, V            T equal; V equal up to a constant (another zero level)
    eom             each equation in the span of the EL rows; the set yields the same q̈
    momenta         p_j = ∂L/∂q̇_j, each
    cyclic          the set of coordinates absent from L
    conserved       each Q non-constant with D_t Q = 0 on the reference motion
    expression      a number at the handout's values, or equal to the reference expression
    hamiltonian     H(q, p, t) = Σ p q̇ − L in the momenta, by its values on phase space
    hamilton_equations  q̇ = ∂H/∂p, ṗ = −∂H/∂q as a system in the rates (like eom)
    equilibrium     coordinate values where ∂U/∂q = 0 and K is positive on M (any stable one)
    normal_modes    the angular frequencies √λ of K a = λ M a there, in any order

`given` carries what the student brings besides the answer: their own L for follow-through on
later parts ("lagrangian"), their transformation equations ("transformation": when valid and
not the statement's, L, T, V, eom, momenta, cyclic and conserved are judged in the student's
own coordinates, `own_coordinates`), and for a numeric answer the handout's values and the
tolerance ("values", "tolerance").
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import replace
from typing import Any

from lagrade.errors import ParseError, RequestError, UnsupportedExpression
from lagrade.judge.parts.ambiguity import ambiguous_lines, best_reading
from lagrade.judge.parts.conserved import check_conserved
from lagrade.judge.parts.coordinates import check_coordinates
from lagrade.judge.parts.cyclic import check_cyclic
from lagrade.judge.parts.dof import check_dof
from lagrade.judge.parts.energy import check_kinetic, check_lagrangian, check_potential
from lagrade.judge.parts.eom import check_eom
from lagrade.judge.parts.expression import check_expression
from lagrade.judge.parts.hamilton_equations import check_hamilton_equations
from lagrade.judge.parts.hamiltonian import check_hamiltonian
from lagrade.judge.parts.mode_shapes import check_mode_shapes
from lagrade.judge.parts.momenta import check_momenta
from lagrade.judge.parts.oscillation import check_equilibrium, check_normal_modes
from lagrade.judge.parts.own_coordinates import (
    FOLLOWING,
    judged_in_chosen_coordinates,
    transformation_remark,
)
from lagrade.judge.parts.reading import reading_notes
from lagrade.judge.parts.transformation import check_transformation
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict, invalid

Checker = Callable[[Problem, Any, Mapping | None], Verdict]

PARTS: dict[str, Checker] = {
    "dof": check_dof,
    "coordinates": check_coordinates,
    "transformation": check_transformation,
    "lagrangian": check_lagrangian,
    "T": check_kinetic,
    "V": check_potential,
    "eom": check_eom,
    "momenta": check_momenta,
    "cyclic": check_cyclic,
    "conserved": check_conserved,
    "expression": check_expression,
    "hamiltonian": check_hamiltonian,
    "hamilton_equations": check_hamilton_equations,
    "equilibrium": check_equilibrium,
    "normal_modes": check_normal_modes,
    "mode_shapes": check_mode_shapes,
}

#: Parts that need a Lagrangian (a bank scene or an ad-hoc L), not only an expression.
NEEDS_LAGRANGIAN = frozenset(PARTS) - {"expression"}


def missing_reference(problem: Problem, part: str) -> str | None:
    """Why `problem` cannot be asked `part` (it has no Lagrangian, or no reference expression),
    or None: the request is refused, whatever the answer."""
    if part in NEEDS_LAGRANGIAN and problem.lagrangian is None:
        return (
            f"part {part!r} needs a scene or a Lagrangian, and this problem gives "
            "only an expression"
        )
    if part == "expression" and problem.expression is None:
        return (
            'part "expression" needs a reference expression (an "expression" '
            'problem, or a scene with "quantity")'
        )
    return None


def run_checker(problem: Problem, part: str, answer: Any, given: Mapping | None = None) -> Verdict:
    """Judge `answer` to `part` of `problem`. A student's mistake never raises: text that does
    not parse, or that names something the evaluator cannot compute, is `invalid` with a message.
    A malformed request (unknown part, wrong answer shape) raises RequestError."""
    checker = PARTS.get(part)
    if checker is None:
        raise RequestError(f"unknown part {part!r}; parts: {', '.join(PARTS)}")
    missing = missing_reference(problem, part)
    if missing is not None:
        raise RequestError(missing)

    def judged(answer: Any) -> tuple[Verdict, list[str]]:
        with reading_notes() as notes:
            if part in FOLLOWING and given and given.get("transformation") is not None:
                verdict = judged_in_chosen_coordinates(problem, part, answer, given, checker)
            else:
                verdict = checker(problem, answer, given)
            if part == "transformation":
                verdict = transformation_remark(problem, answer, verdict)
        return verdict, notes

    try:
        with ambiguous_lines() as ambiguous:
            try:
                verdict, notes = judged(answer)
            except ParseError as error:  # no line reads: an ambiguity may be all it is
                if not ambiguous:
                    raise
                verdict, notes = invalid(part, str(error), error.source), []
        if ambiguous and verdict.status != "correct":  # lines only an ambiguity left unread
            with ambiguous_lines():
                better = best_reading(judged, answer, part, ambiguous, verdict)
            verdict, notes = better or (verdict, notes)
        return with_notes(verdict, notes)
    except ParseError as error:
        return invalid(part, str(error), getattr(error, "source", ""))
    except UnsupportedExpression as error:
        return invalid(part, f"Cannot evaluate your answer: {error}.")


def with_notes(verdict: Verdict, notes: list[str]) -> Verdict:
    """The verdict with the parser's notes on how the answer was read, after its feedback; not
    on a correct answer, whose reading was the right one (there a note is only noise)."""
    if verdict.status == "correct":
        return verdict
    new = [n for n in notes if n not in verdict.feedback]
    return replace(verdict, feedback=(*verdict.feedback, *new)) if new else verdict


__all__ = ["NEEDS_LAGRANGIAN", "PARTS", "missing_reference", "run_checker"]
