"""Matching one wrong answer against many mutants at once: the mutants' values at a set of points
are stacked into arrays once, and a few array operations per answer find the first mutant that
the answer matches, by the same tests as judging one mutant at a time."""

from __future__ import annotations

import operator
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from lagrade.judge.equivalence import offset_removed
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.rows import Rows, outside_span
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import SAME_FACTOR, SAME_VALUE

# What a mutant may raise when it is compiled or evaluated: such a mutant is never matched.
SKIPPED = (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError)


@dataclass(frozen=True)
class Stack:
    """Arrays of the candidates that evaluate at one set of points, one leading row each
    (`index`: the row's position among the candidates), to test all candidates at once."""

    candidates: tuple  # held, so that the id in the cache key stays theirs
    index: np.ndarray
    arrays: tuple

    def of(self, candidates: Sequence) -> bool:
        return len(candidates) == len(self.candidates) and all(
            map(operator.is_, candidates, self.candidates)
        )

    def first(self, ok: np.ndarray):
        """The first candidate whose row passed, in the candidates' order."""
        hits = np.flatnonzero(ok)
        return self.candidates[self.index[hits[0]]] if hits.size else None


def stacked(
    cached: Callable,
    name: str,
    candidates: Sequence,
    points: Points,
    evaluate: Callable[[Any], tuple[np.ndarray, ...]],
    finish: Callable[..., tuple],
) -> Stack | None:
    """`finish(evaluate(c) for each candidate c, stacked)`, built once per candidates and
    points and kept by `cached` (the question's `Problem.cached`); None when no candidate
    evaluates. Candidates that fail to compile or evaluate are left out, as the one-at-a-time
    loop skipped them."""

    def build() -> Stack:
        index, rows = [], []
        with np.errstate(all="ignore"):
            for k, c in enumerate(candidates):
                try:
                    rows.append(evaluate(c))
                except SKIPPED:
                    continue
                index.append(k)
            arrays = finish(*(np.stack(a) for a in zip(*rows, strict=True))) if rows else ()
        return Stack(tuple(candidates), np.array(index, dtype=int), arrays)

    stack = cached(f"{name}:{id(candidates)}", points, build)
    if not stack.of(candidates):
        stack = build()  # the sequence changed in place since the stack was built
    return stack if len(stack.index) else None


# --- Lagrangians: E(answer) = c E(mutant), c ≠ 0 per parameter group ------------------------------


def lagrangian_arrays(Eb: np.ndarray, Sb: np.ndarray, group: np.ndarray) -> tuple:
    """The mutants' E and its size (mutants, points, coordinates), Σ E² per parameter group
    (the denominator of c), and the point-to-group map."""
    groups, group_of = np.unique(group, return_inverse=True)
    in_group = (group_of[:, None] == np.arange(len(groups))).astype(float)
    return Eb, Sb, np.sum(Eb**2, axis=2) @ in_group, in_group, group_of


def first_lagrangian(stack: Stack, answer_el: tuple[np.ndarray, np.ndarray]):
    """The first mutant with E(answer) = c E(mutant), c ≠ 0 per parameter group, given E(answer)
    and its size at the points."""
    return stack.first(_lagrangians_ok(stack, answer_el))


def every_lagrangian(stack: Stack, answer_el: tuple[np.ndarray, np.ndarray]) -> list[tuple]:
    """Every mutant `first_lagrangian` would accept, in catalogue order, each with its E and
    the size of its terms at the points: (mutant, E, size)."""
    Eb, Sb = stack.arrays[:2]
    hits = np.flatnonzero(_lagrangians_ok(stack, answer_el))
    return [(stack.candidates[stack.index[h]], Eb[h], Sb[h]) for h in hits]


def _lagrangians_ok(stack: Stack, answer_el: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    Ea, Sa = answer_el
    Eb, Sb, den, in_group, group_of = stack.arrays
    with np.errstate(all="ignore"):
        # least-squares c per mutant and group; a non-finite value leaves c or r non-finite
        # for that mutant only (rows are independent), so it does not match, as before
        c = np.einsum("mpk,pk->mp", Eb, Ea) @ in_group / den  # (mutants, groups)
        ok = np.all((den != 0) & (np.abs(c) >= SAME_VALUE), axis=1)
        c = c[:, group_of, None]  # per point: (mutants, points, 1)
        return ok & vanish_rows(Ea - c * Eb, Sa + np.abs(c) * Sb)


def lagrangian_fix_is_right(
    answer_el: tuple[np.ndarray, np.ndarray],
    mutant_el: tuple[np.ndarray, np.ndarray],
    reference_el: tuple[np.ndarray, np.ndarray],
    group: np.ndarray,
) -> bool:
    """Whether undoing the mistake in the student's L as written — removing what the mistake
    changed, L_mut − L, at the scale its message prints it, not after rescaling the student's
    L to the mutant — leaves a right L: E(L′) − E(L_mut − L) = c E(L), c > 0 per group. (For
    ½ m ẋ² − k x², "−k x²/2 is twice too large" is true; "m ẋ²/2 is half what it should be"
    is true only of the student's L doubled.)"""
    (Ea, Sa), (Eb, Sb), (Er, Sr) = answer_el, mutant_el, reference_el
    with np.errstate(all="ignore"):
        fixed = Ea - (Eb - Er)
        size = Sa + Sb + Sr
        num = np.bincount(group, np.sum(fixed * Er, axis=1))
        den = np.bincount(group, np.sum(Er * Er, axis=1))
        c = num / den
        if not (np.all(np.isfinite(c)) and np.all(c > 0)):
            return False
        return bool(vanish_rows((fixed - c[group][:, None] * Er)[None], size[None])[0])


# --- values: equal, or equal up to a constant per parameter group ---------------------------------


def first_plain(stack: Stack, answer: tuple[np.ndarray, np.ndarray]):
    """The first mutant with the answer's values at the points, given the answer's (value,
    size) and a stack of the mutants' (value, size)."""
    a, sa = answer
    b, sb = stack.arrays
    with np.errstate(all="ignore"):
        return stack.first(vanish_rows(a - b, sa + sb))


def first_offset(stack: Stack, answer: tuple[np.ndarray, np.ndarray], points: Points):
    """The first mutant the answer equals up to a constant per parameter group."""
    a, sa = answer
    b, sb = stack.arrays
    with np.errstate(all="ignore"):
        rest, first = offset_removed(a - b, points.group)
        return stack.first(vanish_rows(rest, sa + sb + first))


# --- equations: the student's row in the span of a mutated system's rows --------------------------


def span_arrays(R: np.ndarray, Rs: np.ndarray) -> tuple:
    """What the span test of `rows.in_span` needs of mutated systems of rows R (mutants,
    points, rows, n + 1) with sizes Rs that does not depend on the answer: an orthonormal basis
    Q (mutants, points, n + 1, rows) of the rows (the QR is the costly part) and the relative
    size of their terms (mutants, points); and R itself, to tell which row an answer is for."""
    Q, _ = np.linalg.qr(np.swapaxes(R, -1, -2))
    norm = np.linalg.norm(R, axis=-1)
    rel_ref = np.max(np.where(norm > 0, Rs / np.where(norm > 0, norm, 1), 0), axis=-1)
    return Q, rel_ref, R


def first_row(stack: Stack, student: Rows, group: np.ndarray | None = None):
    """The first mutated system whose rows span the student's equation (row 0 of `student`)
    and whose mutated row is the one the student's equation is for (`is_for_row`): a Kepler θ
    equation without 2 m r ṙ θ̇ lies in the span of {r equation without m r̈, θ equation},
    but naming the r equation would be false."""
    found = every_row(stack, student, group, first_only=True)
    return found[0][0] if found else None


def every_row(
    stack: Stack, student: Rows, group: np.ndarray | None = None, first_only: bool = False
) -> list[tuple]:
    """Every (row, mutant) `first_row` would accept, in catalogue order, each with its mutated
    row at the points: ((row, mutant), row coefficients (points, n + 1))."""
    Q, rel_ref, R = stack.arrays
    x, xs = student.coef[:, 0, :].astype(float), student.size[:, 0].astype(float)
    with np.errstate(all="ignore"):
        # in_span's test, its answer-independent part precomputed per mutant:
        # x minus its projection on the mutated system's rows
        res = x - np.einsum("mpij,mpj->mpi", Q, np.einsum("mpji,pj->mpi", Q, x))
        r = np.linalg.norm(res, axis=2)
        size = xs + np.linalg.norm(x, axis=1) * rel_ref
        ok = vanish_rows(r, size)
    found = []
    for hit in np.flatnonzero(ok):
        candidate = stack.candidates[stack.index[hit]]
        if is_for_row(x, R[hit], candidate[0], group):
            found.append((candidate, R[hit][:, candidate[0], :]))
            if first_only:
                break
    return found


def row_fix_is_right(
    student: Rows, mutated_row: np.ndarray, i: int, reference: Rows, basis: tuple
) -> bool:
    """Whether undoing the mistake in the student's equation as written — removing what the
    mistake changed in row i, Δ = mutated row − reference row, at the scale its message prints
    it (either side of the student's `=` may hold the terms), not after rescaling the student's
    row to the mutated one — leaves a right equation (in the span of the reference rows). For
    m r² θ̈ + m r ṙ θ̇ = 0, "2 m r ṙ θ̇ is half what it should be" is true; "m r² θ̈ is twice
    too large" is true only of the student's equation doubled. `basis`: the reference rows'
    `span_basis`."""
    x, xs = student.coef[:, 0, :].astype(float), student.size[:, 0].astype(float)
    with np.errstate(all="ignore"):
        delta = mutated_row - reference.coef[:, i, :].astype(float)
        scale = xs + np.linalg.norm(delta, axis=1) + reference.size[:, i].astype(float)
        for sign in (1.0, -1.0):
            r, s = outside_span(x - sign * delta, scale, basis)
            if vanish_rows(r[None], s[None])[0]:
                return True
    return False


def is_for_row(x: np.ndarray, R: np.ndarray, i: int, group: np.ndarray | None) -> bool:
    """Whether the student's equation x (points, n + 1), in the span of the mutated system R
    (points, rows, n + 1) whose row i is the mutant, is that row itself, so that a mistake
    named in row i points at it. With accelerations: x is a multiple of row i at each point
    (a combination with other rows leaves unsure which equation is wrong: say less). Without:
    any two such rows are multiples at each point, so the factor must be one per parameter
    group (the student's r equation without m r̈, not a θ equation without its θ̈ term)."""
    n = x.shape[1] - 1
    row = R[:, i, :]
    scale = np.linalg.norm(x, axis=1)
    with np.errstate(all="ignore"):
        if np.any(np.linalg.norm(x[:, :n], axis=1) > SAME_VALUE * scale):
            unit = row / np.linalg.norm(row, axis=1)[:, None]
            res = x - unit * np.sum(unit * x, axis=1)[:, None]
            return bool(np.all(np.linalg.norm(res, axis=1) <= SAME_FACTOR * scale))
        if np.any(np.linalg.norm(row[:, :n], axis=1) > SAME_VALUE * np.linalg.norm(row, axis=1)):
            return False
        ratio = x[:, n] / row[:, n]
        if not np.all(np.isfinite(ratio)):
            return False
        if group is None:
            group = np.zeros(len(ratio), dtype=int)
        rest, first = offset_removed(ratio, group)
        return bool(np.all(np.abs(rest) <= SAME_FACTOR * first))


# --- helpers --------------------------------------------------------------------------------------


def full(pair, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(value, size) as float arrays of length n (constants come out of the evaluator as
    scalars)."""
    value, size = pair
    return (
        np.broadcast_to(np.asarray(value, float), (n,)),
        np.broadcast_to(np.asarray(size, float), (n,)),
    )


def vanish_rows(r: np.ndarray, size: np.ndarray) -> np.ndarray:
    """Per leading row (one per mutant): finite and within rounding of its terms everywhere."""
    r, size = r.reshape(len(r), -1), size.reshape(len(size), -1)
    return np.all(np.isfinite(r) & (np.abs(r) <= SAME_VALUE * size), axis=1)
