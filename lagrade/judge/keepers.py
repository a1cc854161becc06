"""Which of a question's mutants the catalogue keeps: those the part's test can tell from the
right answer and from every mutant kept before them (the first, most specific, wins), decided by
fingerprint at the part's sample points. A filter sees the mutants in catalogue order and
remembers what it kept, so a lazily built catalogue keeps exactly what a whole one keeps.

Two mutants that differ by a factor are both kept (a Lagrangian's E, an equation's row, not
normalised): the part's test cannot tell them apart, but which one is true of what the student
wrote depends on the student's own scale (`matching.row_fix_is_right`) — for m r² θ̈ + m r ṙ θ̇,
"2 m r ṙ θ̇ is half what it should be", not "m r² θ̈ is twice too large"."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from lagrade.judge.compiled import Compiled
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.equivalence import lagrangians_match, offset_removed
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.mutations import Mutant
from lagrade.judge.rows import Rows, in_span
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import SAME_FACTOR, SAME_VALUE


class CatalogueView(Protocol):
    """What the filters use of their catalogue (`lagrade.judge.catalogue.Catalogue`)."""

    problem: Any

    def compiled(self, m: Mutant) -> Compiled: ...

    def el_values(self, mut: Compiled, points: Points) -> tuple[np.ndarray, np.ndarray]: ...

    def values(self, mut: Compiled, points: Points) -> tuple[np.ndarray, np.ndarray]: ...

    def mutant_rows(self, m: Mutant, points: Points) -> Rows: ...


def fingerprint(
    catalogue: CatalogueView, compiled: Compiled, mode: str, points: Points
) -> np.ndarray | None:
    """What the part's test sees of an answer: E(L) (at the scale written: a multiple of a
    mutant is another explanation), plain values, or values up to a constant per parameter
    group (V)."""
    if mode == "el":
        v = catalogue.el_values(compiled, points)[0].ravel()
        return None if not np.any(v) else np.asarray(v, float)
    v = np.asarray(catalogue.values(compiled, points)[0], float)
    if mode == "offset":
        v = offset_removed(v, points.group)[0]
    return v


def keeper(
    catalogue: CatalogueView, mode: str, reference_of: Callable[[], Compiled]
) -> Callable[[Mutant], bool]:
    """The filter that drops mutants that change nothing the part's test sees, and
    duplicates (the first, most specific, wins), by fingerprint at the part's points; it
    sees the mutants in catalogue order and remembers the ones it kept."""
    part = {"el": "lagrangian", "plain": "momenta", "offset": "V"}[mode]
    seen: list[np.ndarray] = []  # the reference's fingerprint (when it has one), then the kept
    began = False

    def keep(m: Mutant) -> bool:
        nonlocal began
        points = catalogue.problem.points(part)
        reference = reference_of()
        with np.errstate(all="ignore"):
            if not began:
                began = True
                own = fingerprint(catalogue, reference, mode, points)
                if own is not None:
                    seen.append(own)
            try:
                fp = fingerprint(catalogue, catalogue.compiled(m), mode, points)
            except (UnsupportedExpression, ValueError, ZeroDivisionError):
                return False
            if fp is None or not np.all(np.isfinite(fp)):
                return False
            if mode == "el" and same_dynamics(catalogue, m, reference, points):
                return False  # e.g. ½θ̇² for ½Iθ̇²: a parameter factor, the same motion
            if _close_to_any(fp, seen):
                return False
            seen.append(fp)
            return True

    return keep


def same_dynamics(catalogue: CatalogueView, m: Mutant, reference: Compiled, points: Points) -> bool:
    """A 'mistake' whose Euler–Lagrange equations are a multiple of the reference's is no
    mistake: the Lagrangian check accepts it (or, negative, names the convention), so the
    catalogue must not name it. The float64
    values of both are the ones the fingerprints were made from (computed once, not again per
    mutant); only a test that float64 cannot settle evaluates anew at high precision."""
    jets = catalogue.problem.jets
    mutant = catalogue.compiled(m)

    def reference_values(backend):
        if backend is FLOAT:
            return catalogue.el_values(reference, points)
        return euler_lagrange_values(reference, jets, points.arrays(backend), backend)

    answer_el = catalogue.el_values(mutant, points)
    match = lagrangians_match(mutant, reference_values, jets, points, answer_el=answer_el)
    # c < 0 too: V − T has the right motion in the wrong convention, which the L check names
    factors = match.factors
    same_sign = all(c > 0 for c in factors) or all(c < 0 for c in factors)
    return bool(match.outcome.equal) and bool(factors) and same_sign


def row_keeper(catalogue: CatalogueView) -> Callable[[tuple[int, Mutant]], bool]:
    """`keeper` for row mutants: a mutated row that still follows from the right equations
    changes nothing, and equal rows are duplicates (rows that differ by a factor are not: see
    the module's docstring)."""
    p = catalogue.problem
    seen: list[np.ndarray] = []

    def keep(pair: tuple[int, Mutant]) -> bool:
        _, m = pair
        points = p.points("eom")
        try:
            rows = catalogue.mutant_rows(m, points)
        except (UnsupportedExpression, ValueError, ZeroDivisionError):
            return False
        r, s = in_span(rows, p.reference_rows(points), 0)
        if np.all(np.abs(r) <= SAME_FACTOR * s):
            return False  # the mutated row is still a consequence of the right equations
        fp = rows.coef[:, 0, :].ravel().astype(float)
        norm = np.linalg.norm(fp)
        if not np.isfinite(norm) or norm == 0:
            return False
        if seen:
            kept = np.asarray(seen)
            if np.any(np.linalg.norm(kept - fp, axis=1) < SAME_FACTOR * norm):
                return False
        seen.append(fp)
        return True

    return keep


def _close_to_any(fp: np.ndarray, seen: list[np.ndarray]) -> bool:
    """fp equals one of `seen` to 1e-9 of the larger of the two (all compared at once)."""
    same = [o for o in seen if o.shape == fp.shape]
    if not same:
        return False
    kept = np.asarray(same)
    scale = np.maximum(np.max(np.abs(kept), axis=1), max(float(np.max(np.abs(fp))), 1e-300))
    return bool(np.any(np.max(np.abs(kept - fp), axis=1) <= SAME_VALUE * scale))
