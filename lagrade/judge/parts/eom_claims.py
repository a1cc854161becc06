"""Sentences about a wrong equation of motion that the catalogue of term mistakes cannot name,
each said only after the correction it implies has been judged right at the part's points: a
solved equation whose right-hand side has the wrong sign (q̈ = −f where q̈ = f), and equations
that follow from the student's own wrong Lagrangian, with that Lagrangian's mistake named."""

from __future__ import annotations

from collections.abc import Callable

from lagrade.judge.compiled import Compiled
from lagrade.judge.parts.reading import Read, has_acceleration
from lagrade.judge.problem import Problem

NEGATED_RHS = "the right-hand side has the wrong sign"


def negated_rhs(problem: Problem, read: Read, is_right: Callable[[Compiled], bool]) -> str | None:
    """NEGATED_RHS when the equation is solved for the accelerations (lhs holds them, rhs does
    not and is not zero) and lhs = −rhs is a right equation (`is_right`, the part's own span
    test): a student who wrote q̈ = −f for q̈ = f. None otherwise. Why a check of its own: in
    the solved form the reference's terms are divided by the mass matrix, so no single term of
    the catalogue has the wrong sign."""
    if not read.has_rhs:
        return None
    lhs, rhs = read.lhs, read.rhs
    if rhs is None or rhs == 0 or lhs == 0:
        return None
    if not has_acceleration(problem, lhs) or has_acceleration(problem, rhs):
        return None
    return NEGATED_RHS if is_right(Compiled.of(lhs + rhs)) else None


def own_lagrangian_sentence(lagrangian_mistake: str | None, every_equation: bool) -> str:
    """The follow-through sentence: the equations (all of them, or the wrong ones when some
    are right: only those were tested against the student's L) are the Euler–Lagrange
    equations of the student's own L, which is wrong — and how, when the Lagrangian part's
    diagnosis names it (a sentence whose own correction makes that L right)."""
    which = "These equations" if every_equation else "Your wrong equations"
    said = f"{which} follow correctly from your own Lagrangian, which is not the right one"
    if lagrangian_mistake is None:
        return said + "."
    return f"{said}: {lagrangian_mistake.rstrip('.')}."
