"""The `conserved` part: each quantity non-constant with D_t Q = 0 on the reference motion, the
set independent; any true conserved quantity earns credit, not only the key's."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.decision import Outcome, decide
from lagrade.judge.derivatives import time_derivative_on_shell
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.parts.common import (
    as_sentence,
    free_parameters,
    method_name,
    where_text,
    witness_point,
)
from lagrade.judge.parts.reading import (
    NONE_WORDS,
    has_acceleration,
    items_of,
    own_lagrangian,
    read_labelled,
    read_lines,
)
from lagrade.judge.problem import Problem
from lagrade.judge.rows import equation_rows, lagrangian_rows, row_rank, solve_accelerations
from lagrade.judge.sampling import Points
from lagrade.judge.verdict import Verdict


def _accelerations(problem: Problem, points: Points):
    rows = problem.cached(
        "rows", points, lambda: equation_rows(problem.euler_lagrange, problem.jets, points.env)
    )
    acc = problem.cached("acc", points, lambda: solve_accelerations(rows))

    def values(backend):
        if backend is FLOAT:
            return acc
        ref = equation_rows(problem.euler_lagrange, problem.jets, points.arrays(backend), backend)
        return solve_accelerations(ref, backend)

    return values


def _conservation(
    problem: Problem, Q: Compiled, points: Points
) -> tuple[Outcome, bool, np.ndarray]:
    """(is D_t Q = 0 on-shell, is Q constant, gradient of Q at the points)."""
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
    constant = bool(np.all(np.abs(grad).max(axis=1) <= 1e-10 * np.maximum(size, 1e-300)))
    return out, constant, grad


def check_conserved(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    items = (
        []
        if isinstance(answer, str) and answer.strip().lower() in NONE_WORDS
        else items_of(answer, "conserved")
    )
    items = [i for i in items if not (isinstance(i, str) and i.strip().lower() in NONE_WORDS)]
    lines = read_lines(items, lambda item: read_labelled(problem, item))
    reads = lines.reads
    echoes = lines.echoes or ["none"]
    key = problem.system.conserved_quantities
    free = free_parameters(problem, *(r.expr for r in reads))
    points = problem.points("conserved", free)
    key_rank = problem.cached(
        "key_rank",
        points,
        lambda: _gradient_rank(
            [_conservation(problem, Compiled.of(q), points)[2] for q in key.values()]
        ),
    )
    own = own_lagrangian(problem, given)
    feedback, mistakes, outcomes = lines.feedback(), [], []
    right_grads = []
    witness = None
    any_wrong = False
    follows_all = not lines.unreadable  # an unreadable line follows from nothing
    for r in reads:
        label = r.echo
        if has_acceleration(problem, r.expr):
            feedback.append(
                f"{label} contains an acceleration; a conserved quantity is a function "
                "of the coordinates, velocities and t."
            )
            mistakes.append("acceleration")
            continue
        Q = Compiled.of(r.expr)
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
            if mutant is not None:
                feedback.append(as_sentence(mutant.message))
                mistakes.append(mutant.kind)
            else:
                feedback.append(
                    f"{label} is not conserved: its time derivative along the motion "
                    f"is not zero{where_text(witness_point(points, out, Q), problem)}."
                )
    rank = _gradient_rank(right_grads)
    n_right = len(right_grads)
    listed = len(lines.entries)  # an unreadable line counts as a wrong one
    if key_rank == 0:
        score = 1.0 if n_right == listed else (n_right / listed if listed else 1.0)
    else:
        fraction = n_right / listed if listed else 0.0
        score = fraction * min(1.0, rank / key_rank)
        if rank < key_rank:
            names = ", ".join(_named(problem, name) for name in key)
            noun = "quantity" if key_rank == 1 else "quantities"
            feedback.append(
                f"This system has {key_rank} independent conserved {noun} "
                f"(for example {names}); you gave {rank}."
            )
            mistakes.append("missing_conserved")
    status = "correct" if score >= 1.0 - 1e-12 and not feedback else "incorrect"
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


def _conserved_by_own(problem: Problem, own: sp.Expr, Q: Compiled, points: Points) -> bool:
    """Follow-through: D_t Q = 0 along the motion of the student's own L (its accelerations
    from its own Euler–Lagrange equations), decided like the reference case."""
    own_c = Compiled.of(own)
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
