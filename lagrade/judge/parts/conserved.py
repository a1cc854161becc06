"""The `conserved` part: each quantity non-constant with D_t Q = 0 on the reference motion, the
set independent; any true conserved quantity earns credit, not only the key's. Each quantity is
judged on its own; completeness (all the system's independent conserved quantities) is asked for
only by `given["all"] = True`, and then a missing one lowers the score, never the truth of what
was given."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.decision import Decision, decide
from lagrade.judge.derivatives import time_derivative_on_shell
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.parts.common import (
    as_sentence,
    method_name,
    where_text,
    witness_point,
)
from lagrade.judge.parts.conserved_claims import energy_sentence, missing_factor
from lagrade.judge.parts.items import list_items, without_none
from lagrade.judge.parts.reading import (
    Lines,
    has_acceleration,
    own_lagrangian,
    read_labelled,
    read_lines,
)
from lagrade.judge.problem import Problem
from lagrade.judge.rows import lagrangian_rows, row_rank, solve_accelerations
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import CONSTANT_GRADIENT, RANK, ROUNDING
from lagrade.judge.verdict import Verdict


def _accelerations(problem: Problem, points: Points):
    rows = problem.reference_rows(points)
    acc = problem.cached("acc", points, lambda: solve_accelerations(rows))

    def values(backend):
        if backend is FLOAT:
            return acc
        ref = problem.rows_at(points, backend)
        return solve_accelerations(ref, backend)

    return values


def _conservation(
    problem: Problem, Q: Compiled, points: Points
) -> tuple[Decision, bool, np.ndarray]:
    """(is D_t Q = 0 on-shell, is Q constant, gradient of Q on phase space at the points: with
    respect to the coordinates and velocities, parameters and t held fixed)."""
    jets = problem.jets
    acc = _accelerations(problem, points)

    def residual(backend):
        total, size, _grad = time_derivative_on_shell(
            Q, jets, points.arrays(backend), acc(backend), backend
        )
        return to_length(total, points.n, backend), to_length(size, points.n, backend)

    out = decide(residual)
    with np.errstate(all="ignore"):
        _t, _s, grad = time_derivative_on_shell(Q, jets, points.env, acc(FLOAT))
        grad = np.broadcast_to(np.asarray(grad, float), (points.n, 1 + 2 * len(jets)))
        value, size = Q.values(points.env)
        size = np.broadcast_to(size, (points.n,))
    constant = bool(
        np.all(np.abs(grad).max(axis=1) <= CONSTANT_GRADIENT * np.maximum(size, 1e-300))
    )
    return out, constant, grad[:, 1:]  # column 0 is ∂/∂t


def read_conserved(problem: Problem, answer: Any) -> Lines:
    """The quantities of a `conserved` answer, one per item, each `Q` or `name = Q`; `none`
    for none."""
    items = without_none(list_items(answer, "conserved"))
    return read_lines(items, lambda item: read_labelled(problem, item))


def check_conserved(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    lines = read_conserved(problem, answer)
    reads = lines.reads
    echoes = lines.echoes or ["none"]
    key = problem.system.conserved_quantities
    points = problem.points("conserved")
    key_rank = problem.cached(
        "key_rank",
        points,
        lambda: _gradient_rank(
            [_conservation(problem, Compiled.of(q), points)[2] for q in key.values()]
        ),
    )
    own = own_lagrangian(problem, given)
    feedback, mistakes, outcomes = lines.feedback(), [], []

    def conserved(Q: Compiled) -> bool:
        """The part's own test: D_t Q = 0 on the reference motion, Q not a constant."""
        out, constant, _grad = _conservation(problem, Q, points)
        return out.equal and not constant

    right_grads: list[np.ndarray] = []
    right_labels: list[str] = []
    complete = bool(given and given.get("all") is True)
    witness = None
    any_wrong = False
    follows_all = not lines.unreadable  # an unreadable line follows from nothing
    for r in reads:
        label = r.echo
        if has_acceleration(problem, r):
            feedback.append(
                f"{label} contains an acceleration; a conserved quantity is a function "
                "of the coordinates, velocities and t."
            )
            mistakes.append("acceleration")
            continue
        Q = r.compiled
        out, constant, grad = _conservation(problem, Q, points)
        outcomes.append(out)
        if constant:
            feedback.append(
                f"{label} is a constant; it is conserved trivially and says nothing "
                "about the motion."
            )
            mistakes.append("constant")
        elif out.equal:
            right_grads.append(grad)
            right_labels.append(label)
        elif own is not None and _conserved_by_own(problem, own, Q, points):
            feedback.append(
                f"{label} is conserved by the motion of your own Lagrangian, which is not "
                "the right one."
            )
            any_wrong = True
        else:
            any_wrong, follows_all = True, False
            witness = witness or witness_point(points, out, Q)
            mutant = problem.catalogue.match_offset(problem.catalogue.conserved_mutants, Q, points)
            factor = None if mutant is not None else missing_factor(problem, Q, conserved)
            if mutant is not None and mutant.kind == "energy_not_conserved":
                feedback.append(energy_sentence(problem, points, conserved))
                mistakes.append(mutant.kind)
            elif mutant is not None:
                feedback.append(as_sentence(mutant.message))
                mistakes.append(mutant.kind)
            elif factor is not None:
                feedback.append(f"{label} {factor}.")
                mistakes.append("missing_factor")
            else:
                feedback.append(
                    f"{label} is not conserved: its time derivative along the motion "
                    f"is not zero{where_text(witness_point(points, out, Q), problem)}."
                )
    counted, rank = _independent(right_grads, right_labels, points, feedback, mistakes)
    listed = len(lines.entries)  # an unreadable line counts as a wrong one
    if listed == 0:  # "none": right only when the system has no conserved quantity
        score = 1.0 if key_rank == 0 else 0.0
        if key_rank:
            feedback.append(_count_sentence(problem, key, key_rank, 0))
            mistakes.append("missing_conserved")
    else:
        score = counted / listed  # each true quantity counts once, a duplicate not
        if complete and rank < key_rank:
            score *= rank / key_rank
            feedback.append(_count_sentence(problem, key, key_rank, rank))
            mistakes.append("missing_conserved")
    status = "correct" if score >= 1.0 - ROUNDING and not feedback else "incorrect"
    if status == "correct":
        score = 1.0
    follows = status != "correct" and any_wrong and follows_all and own is not None
    return Verdict(
        "conserved",
        status,
        float(score),
        tuple(feedback),
        echoes,
        method_name(*outcomes),
        witness=witness,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _conserved_by_own(problem: Problem, own_c: Compiled, Q: Compiled, points: Points) -> bool:
    """Follow-through: D_t Q = 0 along the motion of the student's own L (its accelerations
    from its own Euler–Lagrange equations), decided like the reference case."""
    jets = problem.jets
    try:
        with np.errstate(all="ignore"):
            acc = solve_accelerations(lagrangian_rows(own_c, jets, points.env))
        if not np.all(np.isfinite(acc)):
            return False  # the own L has no motion here (a singular mass matrix)

        def residual(backend):
            env = points.arrays(backend)
            a = (
                acc
                if backend is FLOAT
                else solve_accelerations(lagrangian_rows(own_c, jets, env, backend), backend)
            )
            total, size, _grad = time_derivative_on_shell(Q, jets, env, a, backend)
            return to_length(total, points.n, backend), to_length(size, points.n, backend)

        return decide(residual).equal
    except (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError):
        return False


def _independent(
    grads: Sequence[np.ndarray],
    labels: Sequence[str],
    points: Points,
    feedback: list[str],
    mistakes: list[str],
) -> tuple[int, int]:
    """(How many true quantities count, how many independent ones they make: the rank of their
    gradients on phase space at a typical point). Quantities are functions on phase space: the
    parameters are fixed numbers, not variables. So one that is, with the parameters fixed, a
    fixed combination of those before it — a duplicate, 2Q, Q/m, Q + const, a Q1 + b Q2, with
    a, b any function of the parameters (its gradient the same combination of theirs at every
    point of each parameter group) — is named and not counted: m v and v are one quantity,
    whatever m is. A nonlinear function of another (E = p²/2I of a free wheel) is a named
    physical quantity of its own that adds nothing to the rank: the bank's keys list such
    pairs."""
    kept: list[np.ndarray] = []
    for grad, label in zip(grads, labels, strict=True):
        if not _fixed_combination(kept, grad, points.group):
            kept.append(grad)
            continue
        feedback.append(
            f"{label} is conserved, but it is a fixed combination of the quantities before it "
            "(a multiple, or with a constant added); it is not a new conserved quantity."
        )
        mistakes.append("dependent")
    return len(kept), _gradient_rank(kept)


def _fixed_combination(kept: Sequence[np.ndarray], grad: np.ndarray, group: np.ndarray) -> bool:
    """Whether grad is, in every parameter group, one combination of the kept gradients at all
    the group's points (coefficients that depend on the parameters alone)."""
    if not kept:
        return False
    return all(
        _stacked_rank([g[group == k] for g in (*kept, grad)]) <= len(kept) for k in np.unique(group)
    )


def _stacked_rank(grads: Sequence[np.ndarray]) -> int:
    """Rank of the gradients taken over all the given points at once: dependence with the same
    constant coefficients everywhere."""
    cols = [np.nan_to_num(np.asarray(g, float)).reshape(-1) for g in grads]
    coef = np.stack(cols, axis=1)
    scale = np.abs(coef).max(axis=0)
    coef = coef / np.where(scale > 0, scale, 1.0)
    sv = np.linalg.svd(coef, compute_uv=False)
    return int(np.sum(sv > RANK * max(sv[0], 1e-300)))


def _count_sentence(problem: Problem, key: Mapping, key_rank: int, rank: int) -> str:
    names = ", ".join(_named(problem, name) for name in key)
    noun = "quantity" if key_rank == 1 else "quantities"
    return (
        f"This system has {key_rank} independent conserved {noun} "
        f"(for example {names}); you gave {rank}."
    )


def _gradient_rank(grads: Sequence[np.ndarray]) -> int:
    """Functional independence: the rank of the gradients, at a typical point."""
    if not grads:
        return 0
    coef = np.stack([np.asarray(g, float) for g in grads], axis=1)
    if not np.all(np.isfinite(coef)):
        coef = np.nan_to_num(coef)
    return row_rank(coef, list(range(len(grads))))


def _named(problem: Problem, name: str) -> str:
    """A key quantity as the feedback names it: `h` is "the energy function h", or just "the
    energy function" when h is also a parameter (the wedge's height); a momentum whose name
    clashes with a parameter is called the momentum conjugate to its coordinate."""
    clash = name in problem.parameters
    if name == "h":
        return "the energy function" if clash else "the energy function h"
    if clash and name.startswith("p_"):
        return f"the momentum conjugate to {name[2:]}"
    return name
