"""The `transformation` part: Cartesian coordinates of the bodies in the generalized coordinates,
right when they satisfy the constraints identically and have full rank."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import Decision, decide
from lagrade.judge.derivatives import gradient
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.parts.common import (
    method_name,
    where_text,
    witness_point,
)
from lagrade.judge.parts.items import list_items
from lagrade.judge.parts.reading import Lines, Read, read, read_lines
from lagrade.judge.parts.transformation_slips import transformation_slips
from lagrade.judge.problem import NEEDS_BODIES, Problem
from lagrade.judge.rows import row_rank
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import DIFFERENT_ABOVE
from lagrade.judge.verdict import Verdict, invalid
from lagrade.notation import plain


def check_transformation(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    return transformation_positions(problem, answer)[0]


def transformation_positions(problem: Problem, answer: Any) -> tuple[Verdict, dict[str, sp.Expr]]:
    """The verdict on a transformation answer, and the positions it gives when it is right
    (`x_bob` → its expression, a rigid body's `phi_wheel` too: the student's own coordinates;
    empty when the verdict is not `correct`)."""
    positions: dict[str, sp.Expr] = {}
    verdict = _judged(problem, answer, positions)
    return verdict, (positions if verdict.status == "correct" else {})


def _labels(problem: Problem) -> tuple[list[str], list[str]]:
    """The Cartesian coordinates a transformation answer gives: the required (each body's x, y
    and a rigid body's angle) and the optional (z of a planar body)."""
    v = problem.variant
    if v is None:
        raise RequestError(NEEDS_BODIES)
    required = list(v.transformation)
    optional = [f"z_{b.name}" for b in v.bodies if b.planar and f"z_{b.name}" not in required]
    return required, optional


def read_transformation(problem: Problem, answer: Any) -> Lines:
    """The lines of a transformation answer, each `x_body = expression`."""
    required, optional = _labels(problem)
    labels = required + optional

    def read_line(item: Any) -> Read:
        got = read(problem, item, labels, "answer")
        if got.rhs is None or not (isinstance(got.lhs, sp.Symbol) and str(got.lhs) in labels):
            text = item if isinstance(item, str) else str(item)
            raise ParseError(
                f"Write each line as a Cartesian coordinate = expression, with one of: "
                f"{', '.join(labels)}.",
                (0, len(text)),
                text,
            )
        return got

    return read_lines(list_items(answer, "transformation"), read_line)


def _judged(problem: Problem, answer: Any, given_pos: dict[str, sp.Expr]) -> Verdict:
    """The transformation check; fills `given_pos` with the positions the answer gives."""
    v = problem.variant
    required = list(v.transformation) if v is not None else []
    lines = read_transformation(problem, answer)
    echoes = lines.echoes
    unread = lines.feedback()  # an unreadable line counts as wrong: its coordinate is not given
    for got in lines.reads:
        name = str(got.lhs)
        if name in given_pos:
            return invalid("transformation", f"{name} is given twice.", echoes)
        given_pos[name] = got.rhs
    missing = [n for n in required if n not in given_pos]
    if missing:
        return Verdict(
            "transformation",
            "incorrect",
            0.0,
            (*unread, f"Give every Cartesian coordinate; missing: {', '.join(missing)}."),
            echoes,
            "exact",
            mistakes=("missing_coordinate",),
        )
    for name, expr in given_pos.items():
        if any(expr.has(j.dot) or expr.has(j.ddot) for j in problem.jets):
            return Verdict(
                "transformation",
                "incorrect",
                0.0,
                (*unread, f"{name} must depend on the coordinates (and t), not on velocities."),
                echoes,
                "exact",
            )
    points = problem.points("transformation")
    failures, outcomes = _violations(problem, given_pos, points)
    rank = _transformation_rank(problem, list(given_pos.values()), points)
    n = len(problem.jets)
    feedback, mistakes = unread, []
    # one point for every sentence, so that the verdict's witness reproduces each: the first
    # violation's, quoted again for a later constraint only where that one fails there too
    first = failures[0].where if failures else None
    witness = witness_point(points, failures[0].decision, *given_pos.values()) if failures else None
    for f in failures:
        here = where_text(witness, problem) if f.fails_at(first) else ""
        feedback.append(f"Your positions violate the constraint {f.shown}{here}.")
        mistakes.append("violates_constraint")
    if rank < n:
        feedback.append(
            f"Your positions depend on only {rank} independent combination(s) of the "
            f"{n} coordinates; the map must have full rank."
        )
        mistakes.append("rank_deficient")
    if failures or rank < n:
        for slip in transformation_slips(
            problem, given_pos, points, partial(valid_positions, problem)
        ):
            feedback.append(f"{slip.sentence}.")
            mistakes.append(slip.kind)
    if not feedback:
        return Verdict("transformation", "correct", 1.0, (), echoes, method_name(*outcomes))
    total = max(1, len(outcomes))
    score = 0.0 if rank < n else 0.5 * (total - len(failures)) / total
    return Verdict(
        "transformation",
        "incorrect",
        score,
        tuple(feedback),
        echoes,
        method_name(*outcomes),
        witness=witness,
        mistakes=tuple(mistakes),
    )


@dataclass(frozen=True)
class Violation:
    """A constraint the positions do not satisfy: how it is shown, the decision (its `where`
    is the point quoted) and the residual ratio at every point."""

    shown: str
    decision: Decision
    ratio: np.ndarray

    @property
    def where(self) -> int | None:
        return self.decision.where

    def fails_at(self, i: int | None) -> bool:
        """Whether the constraint clearly fails at point i (quoted there)."""
        return i is not None and (i == self.where or bool(self.ratio[i] > DIFFERENT_ABOVE))


def _violations(
    problem: Problem, positions: Mapping[str, sp.Expr], points: Points
) -> tuple[list[Violation], list[Decision]]:
    """The scene's constraints that `positions` (`x_bob` → expression) violate, and every
    constraint's decision."""
    v = problem.variant
    cart = {}
    for b in v.bodies:
        for axis, sym in vars(getattr(v.cartesian, b.name)).items():
            cart[sym] = positions.get(f"{axis}_{b.name}", sp.S.Zero)
    compiled_pos = {s: Compiled.of(e) for s, e in cart.items()}
    failures, outcomes = [], []
    for label, f in v.constraints:
        if f == 0:
            continue
        fc = Compiled.of(f)

        def residual(backend, fc=fc):
            env = dict(points.arrays(backend))
            n = points.n
            for s, c in compiled_pos.items():
                val = c.values(env, backend)[0]
                env[s] = (
                    np.full(n, val, dtype=float if backend is FLOAT else object)
                    if np.ndim(val) == 0
                    else val
                )
            value, size = fc.values(env, backend)
            return (
                np.broadcast_to(value, (n,)) if np.ndim(value) == 0 else value,
                np.broadcast_to(size, (n,)) if np.ndim(size) == 0 else size,
            )

        out = decide(residual)
        outcomes.append(out)
        if not out.equal:
            shown = "z = 0 (motion in the x-y plane)" if label != "declared" else f"{plain(f)} = 0"
            with np.errstate(all="ignore"):
                r, size = residual(FLOAT)
                ratio = np.abs(np.asarray(r, dtype=complex)) / np.asarray(size, dtype=float)
            failures.append(Violation(shown, out, np.nan_to_num(ratio, nan=np.inf)))
    return failures, outcomes


def valid_positions(problem: Problem, positions: Mapping[str, sp.Expr]) -> bool:
    """Whether `positions` satisfy every constraint identically and have full rank: what the
    checker accepts (for a correction of an answer, `transformation_slips`)."""
    points = problem.points("transformation")
    failures, _ = _violations(problem, positions, points)
    rank = _transformation_rank(problem, list(positions.values()), points)
    return not failures and rank == len(problem.jets)


def _transformation_rank(problem: Problem, exprs: list[sp.Expr], points: Points) -> int:
    coords = [j.q for j in problem.jets]
    with np.errstate(all="ignore"):
        rows = []
        for e in exprs:
            grads = gradient(Compiled.of(e), coords, points.env)
            rows.append(sum(grads) if grads else np.zeros((points.n, len(coords))))
        J = np.stack([np.broadcast_to(r, (points.n, len(coords))) for r in rows], axis=1)
    if not np.all(np.isfinite(J)):
        return 0
    return row_rank(np.transpose(J, (0, 2, 1)), list(range(len(coords))))
