"""The `eom` part: each equation must lie in the span of the Euler–Lagrange rows, and the set must
yield the same accelerations (any row operations, solved forms, multiplied through)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import decide
from lagrade.judge.dimensions import hint_for, tells
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.parts.common import (
    acceleration_text,
    equations_needed,
    method_name,
    too_few_independent,
    where_text,
    witness_point,
)
from lagrade.judge.parts.eom_claims import negated_rhs, own_lagrangian_sentence
from lagrade.judge.parts.items import list_items
from lagrade.judge.parts.reading import Lines, Read, own_lagrangian, read, read_lines
from lagrade.judge.problem import Problem
from lagrade.judge.rows import (
    equation_rows,
    in_span,
    lagrangian_rows,
    outside_span,
    row_rank,
    span_basis,
)
from lagrade.judge.tolerances import ZERO_ROW
from lagrade.judge.verdict import Verdict, invalid


def read_eom(problem: Problem, answer: Any) -> Lines:
    """The equations of an `eom` answer, one per item (a bare expression is `= 0`)."""

    def read_line(item: Any) -> Read:
        return read(problem, item, (), "equation" if isinstance(item, str) else "answer")

    return read_lines(list_items(answer, "eom"), read_line)


def check_eom(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    lines = read_eom(problem, answer)
    if not lines.reads:
        return invalid("eom", "Give one equation of motion per coordinate.")
    return _judge(problem, lines, [r.compiled for r in lines.reads], given)


def _judge(problem: Problem, lines, compiled: list[Compiled], given: Mapping | None) -> Verdict:
    """The verdict on the equations read (`lines`), compiled from their trees: decided once, and
    a wrong one's feedback read from the same programs."""
    reads = lines.reads
    echoes = lines.echoes
    entry = [k for k, e in enumerate(lines.entries) if isinstance(e, Read)]  # read → position
    total = len(lines.entries)
    unreadable = bool(lines.unreadable)
    jets = problem.jets
    n = len(jets)
    points = problem.points("eom")
    ref_rows = problem.reference_rows(points)
    with np.errstate(all="ignore"):
        rows = equation_rows(compiled, jets, points.env)
    right, outcomes, feedback, mistakes = [], [], lines.feedback(), []

    def right_row(equation: Compiled) -> bool:
        """The part's own test of one equation: in the span of the reference rows."""
        return decide(lambda b: _span_residual(problem, [equation], ref_rows, 0, points, b)).equal

    wrong: list[int] = []
    witness = None
    for k in range(len(reads)):
        label = f"Equation {entry[k] + 1} ({reads[k].echo})" if total > 1 else "Your equation"
        nonlinear = decide(lambda b, k=k: _nonlinear_residual(compiled, k, jets, points, b))
        if not nonlinear.equal:
            feedback.append(
                f"{label} is not linear in the accelerations, so it cannot be an "
                "Euler–Lagrange equation."
            )
            wrong.append(k)
            outcomes.append(nonlinear)
            continue
        size = rows.size[:, k]
        norm = np.linalg.norm(rows.coef[:, k, :].astype(float), axis=1)
        if np.all(norm <= ZERO_ROW * np.maximum(size, 1e-300)):
            feedback.append(f"{label} says nothing (it reduces to 0 = 0).")
            mistakes.append("trivial_equation")
            wrong.append(k)
            continue
        out = decide(lambda b, k=k: _span_residual(problem, compiled, ref_rows, k, points, b))
        outcomes.append(out)
        if out.equal:
            right.append(k)
            continue
        wrong.append(k)
        # The witness is one state, the first wrong equation's, whole (coordinates and
        # velocities): a later sentence quotes its own state only when it is that one, so that
        # every number quoted is in the witness.
        point = witness_point(points, out)
        witness = witness or point
        mutant = problem.catalogue.match_row(compiled[k], points)
        negated = None if mutant is not None else negated_rhs(problem, reads[k], right_row)
        if mutant is not None:
            feedback.append(f"{label}: {mutant.message}.")
            mistakes.append(mutant.kind)
        elif negated is not None:
            feedback.append(f"{label}: {negated}.")
            mistakes.append("negated_rhs")
        else:
            quoted = point == witness
            feedback.append(
                f"{label} does not follow from the Euler–Lagrange equations of this "
                "system"
                + (
                    where_text(
                        point,
                        problem,
                        acceleration_text(
                            problem, points, out, compiled[k], entry[k] if total == n else None
                        ),
                    )
                    if quoted
                    else ""
                )
                + "."
            )
        told = tells(mutant) and negated is None  # a negated side keeps every term's units
        dimensions = hint_for(problem, reads[k], "equation") if told else ""
        if dimensions:
            feedback.append(f"{label}: {dimensions[0].lower()}{dimensions[1:]}")
    rank = row_rank(rows.coef.astype(float), right)
    follows = False
    own = own_lagrangian(problem, given)
    if wrong and own is not None:
        follows = _follows_from_own(problem, own, compiled, wrong, points)
        if follows:
            mistake = problem.catalogue.match_lagrangian(own, problem.points("lagrangian"))
            message = None if mistake is None else mistake.message
            feedback.append(own_lagrangian_sentence(message, not right))
    if not wrong and not unreadable and rank == n:
        notes = ()
        if len(reads) > n:
            notes = (f"You gave {len(reads)} equations; {n} of them are independent.",)
        return Verdict("eom", "correct", 1.0, notes, echoes, method_name(*outcomes))
    if not wrong and not unreadable and rank < n:
        feedback.append(too_few_independent(rank, n, n, len(reads)))
        mistakes.append("too_few_equations")
        score = rank / n
    else:
        score = len(right) / max(total, n)  # an unreadable line counts as a wrong one
        if total < n and not wrong:
            feedback.append(f"{equations_needed(n, n)}.")
    return Verdict(
        "eom",
        "incorrect",
        float(min(score, 1.0)),
        tuple(feedback),
        echoes,
        method_name(*outcomes),
        witness=witness,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _nonlinear_residual(compiled, k, jets, points, backend):
    env = points.arrays(backend)
    rows = equation_rows([compiled[k]], jets, env, backend)
    return rows.nonlinear[:, 0], rows.size[:, 0]


def _span_residual(problem, compiled, ref_rows, k, points, backend):
    if backend is FLOAT:  # the reference rows' basis is made once per set of points
        student = equation_rows([compiled[k]], problem.jets, points.env)
        basis = problem.cached("row-basis", points, lambda: span_basis(ref_rows))
        x, size = student.coef[:, 0, :].astype(float), student.size[:, 0].astype(float)
        return outside_span(x, size, basis)
    env = points.arrays(backend)
    student = equation_rows([compiled[k]], problem.jets, env, backend)
    ref = problem.rows_at(points, backend)
    return in_span(student, ref, 0, backend)


def _follows_from_own(problem: Problem, own_c: Compiled, compiled, wrong, points) -> bool:
    jets = problem.jets
    try:
        with np.errstate(all="ignore"):
            own_rows = lagrangian_rows(own_c, jets, points.env)
        if not np.all(np.isfinite(own_rows.coef.astype(float))):
            return False
        for k in wrong:

            def residual(backend, k=k):
                env = points.arrays(backend)
                s = equation_rows([compiled[k]], jets, env, backend)
                r = own_rows if backend is FLOAT else lagrangian_rows(own_c, jets, env, backend)
                return in_span(s, r, 0, backend)

            if not decide(residual).equal:
                return False
    except (UnsupportedExpression, ValueError, np.linalg.LinAlgError):
        return False
    return True
