"""The equation-of-motion mistakes of the catalogue as fingerprints: each mistaken row [A | c] at
the question's points, the reference's row plus a few scaled pieces — ∂L/∂q for the sign of
Lagrange's equation, E(piece) for a Lagrangian mistake carried into the equations (one hyper-dual
pass over all pieces), a term of the expanded row, its sin↔cos swap, the term without a parameter
factor. The rows are arrays made once per question; the keeping (`keepers.row_keeper`) and the
matching (`Catalogue.match_row`) are array operations on all of them at once, and sympy builds
the sentence of the mistake that matched.

The mistakes and their order are those of `mutations.iter_equation_mutants`, built from the same
pieces (`term_specs`, `ROW_KINDS`); a Lagrangian mistake whose E leaves a row unchanged at every
point gives no mistake of that row (its symbolic E is zero there)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.compiled import to_length
from lagrade.judge.derivatives import euler_lagrange_terms
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression, compile_program, run
from lagrade.judge.fingerprints import Pieces, divided, piece_terms, with_quotients
from lagrade.judge.matching import Stack, every_row, row_fix_is_right, span_arrays
from lagrade.judge.mutations import (
    ROW_KINDS,
    Mutant,
    el_sign_mutant,
    expanded_terms,
    lagrangian_row_mutants,
    one_term_mutants,
    term_specs,
)
from lagrade.judge.rows import Rows, acceleration_blocks, rows_from_values, span_basis
from lagrade.judge.tolerances import NEAR_DUPLICATE, SAME_FACTOR

_FAILS = (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError)


def _float(c) -> float:
    """A catalogue weight (±1, ±2, ½) as a float, converted once per value."""
    found = _FLOATS.get(c)
    if found is None:
        found = _FLOATS[c] = float(c)
    return found


_FLOATS: dict = {}


def _plain_rows(pieces: Sequence[sp.Expr], jets, env: dict) -> tuple[np.ndarray, np.ndarray]:
    """Rows [A | c] of each piece read as an equation: coef (pieces, points, n + 1) and size
    (pieces, points); NaN for a piece that does not evaluate."""
    n_pts, n = len(next(iter(env.values()))), len(jets)
    coef = np.full((len(pieces), n_pts, n + 1), np.nan)
    size = np.full((len(pieces), n_pts), np.nan)
    if not pieces:
        return coef, size
    blocks = acceleration_blocks(jets, env)
    n_all = len(next(iter(blocks.values())))

    def rows_of(exprs):
        terms, owner = piece_terms(exprs)
        values = run(compile_program(terms), blocks, FLOAT)
        v = np.zeros((n_all, len(exprs)))
        s = np.zeros((n_all, len(exprs)))
        for k, x in zip(owner, values, strict=True):
            x = to_length(x, n_all)
            v[:, k] += x
            s[:, k] += np.abs(x)
        rows = rows_from_values(v, s, jets, env)
        return np.moveaxis(rows.coef, 1, 0), np.moveaxis(rows.size, 1, 0)

    with np.errstate(all="ignore"):
        try:
            coef[:], size[:] = rows_of(pieces)
            return coef, size
        except _FAILS:
            pass
        for k, e in enumerate(pieces):  # one does not compile: the others one at a time
            try:
                coef[k], size[k] = (a[0] for a in rows_of([e]))
            except _FAILS:
                continue
    return coef, size


def _lagrangian_rows(pieces: Sequence[sp.Expr], jets, env: dict):
    """Rows of E(piece) for each Lagrangian piece: coef (pieces, points, rows, n + 1) and size
    (pieces, points, rows), from one hyper-dual pass; NaN where a piece does not evaluate."""
    n_pts, n = len(next(iter(env.values()))), len(jets)
    coef = np.full((len(pieces), n_pts, n, n + 1), np.nan)
    size = np.full((len(pieces), n_pts, n), np.nan)
    blocks = acceleration_blocks(jets, env)

    def rows_of(exprs):
        terms, owner = piece_terms(exprs)
        Et, St = euler_lagrange_terms(compile_program(terms), jets, blocks)
        E = np.zeros((len(exprs), *Et.shape[1:]))
        S = np.zeros((len(exprs), *Et.shape[1:]))
        np.add.at(E, owner, Et)
        np.add.at(S, owner, St)
        out = [rows_from_values(E[k], S[k], jets, env) for k in range(len(exprs))]
        return np.stack([r.coef for r in out]), np.stack([r.size for r in out])

    with np.errstate(all="ignore"):
        try:
            coef[:], size[:] = rows_of(pieces)
            return coef, size
        except _FAILS:
            pass
        for k, e in enumerate(pieces):
            try:
                c, s = rows_of([e])
                coef[k], size[k] = c[0], s[0]
            except _FAILS:
                continue
    return coef, size


class RowFingerprints:
    """The equation mistakes of one question as arrays at the eom part's points: the rows of
    every mistake, which the catalogue keeps, and the matching of a student's equation.
    `catalogue`: the question's `Catalogue`."""

    def __init__(self, catalogue: Any) -> None:
        self.catalogue = catalogue
        p = catalogue.problem
        self.problem = p
        self.points = p.points("eom")
        system, jets = p.system, p.jets
        E = system.euler_lagrange
        n = len(jets)
        lag = catalogue.lagrangian_fingerprints
        env = self.points.env
        self._built: dict[int, Mutant] = {}
        self._term_mutants: dict[tuple[int, int], list[Mutant]] = {}
        self._lagrangian_rows: dict[int, dict[int, Mutant]] = {}
        self._per_monomial: dict = {}
        # the pieces read as equations: ∂L/∂q_i, then the rows' terms and their variants
        plain = Pieces()  # the pieces the weights name, by index

        # a mistake: (row, kind, weights over the pieces' rows, how its symbolic mutant is built:
        # ("sign",), ("lagrangian", its Lagrangian mistake), ("term", term, its mistake there))
        specs: list[tuple[int, str, tuple, tuple]] = []
        for i in range(n):
            specs.append(
                (i, "el_sign", (("p", plain(system.generalized_forces[i]), 2.0),), ("sign",))
            )
        # Lagrangian mistakes carried into the equations: the kept ones of the early kinds
        early = [k for k in lag.kept if k < lag.early and lag.specs[k].kind in ROW_KINDS]
        used = sorted({j for k in early for j, _ in lag.specs[k].weights})
        el_coef, el_size = _lagrangian_rows([lag.pieces[j] for j in used], jets, env)
        where = {j: u for u, j in enumerate(used)}
        for k in early:
            w = lag.specs[k].weights
            change = sum(c * el_coef[where[j]] for j, c in w)
            for i in range(n):
                if np.any(change[:, i, :] != 0):  # (NaN too: a mistake that does not evaluate)
                    specs.append(
                        (
                            i,
                            lag.specs[k].kind,
                            tuple(("l", where[j], c) for j, c in w),
                            ("lagrangian", k),
                        )
                    )
        self._terms = [expanded_terms(E[i]) for i in range(n)]
        for i in range(n):
            for t, term in enumerate(self._terms[i]):
                specs_here = term_specs(term, catalogue.parameters, divided)
                for local, (kind, pieces, _) in enumerate(specs_here):
                    weights = tuple(("p", plain(e), _float(c)) for c, e in pieces)
                    specs.append((i, kind, weights, ("term", t, local)))
        self.specs = specs
        p_coef, p_size = with_quotients(plain, lambda e: _plain_rows(e, jets, env), env)
        self._pieces = {"p": (p_coef, p_size), "l": (el_coef, el_size)}
        self.rows, self.sizes = self._mistake_rows()

    def _mistake_rows(self) -> tuple[np.ndarray, np.ndarray]:
        """Each mistake's row (mistakes, points, n + 1) and its size (mistakes, points)."""
        ref = self.problem.reference_rows(self.points)
        R, Rs = ref.coef.astype(float), ref.size.astype(float)
        X = np.empty((len(self.specs), *R[:, 0, :].shape))
        XS = np.empty((len(self.specs), R.shape[0]))
        with np.errstate(all="ignore"):
            for m, (i, _kind, weights, _source) in enumerate(self.specs):
                x, xs = R[:, i, :].copy(), Rs[:, i].copy()
                for table, j, c in weights:
                    coef, size = self._pieces[table]
                    if table == "l":
                        x += c * coef[j][:, i, :]
                        xs += abs(c) * size[j][:, i]
                    else:
                        x += c * coef[j]
                        xs += abs(c) * size[j]
                X[m], XS[m] = x, xs
        return X, XS

    @property
    def kept(self) -> np.ndarray:
        """The mistakes `keepers.row_keeper` keeps, in order: a row that is no consequence of
        the right equations, finite and nonzero, not equal to an earlier kept one."""
        cached = self.__dict__.get("_kept")
        if cached is not None:
            return cached
        p = self.problem
        basis = p.cached(
            "row-basis", self.points, lambda: span_basis(p.reference_rows(self.points))
        )
        Q, rel_ref = basis
        X, XS = self.rows, self.sizes
        with np.errstate(all="ignore"):
            res = X - np.einsum("pij,mpj->mpi", Q, np.einsum("pji,mpj->mpi", Q, X))
            r = np.linalg.norm(res, axis=2)
            s = XS + np.linalg.norm(X, axis=2) * rel_ref
            consequence = np.all(np.abs(r) <= SAME_FACTOR * s, axis=1)
            fp = X.reshape(len(X), -1)
            norm = np.linalg.norm(fp, axis=1)
            valid = ~consequence & np.isfinite(norm) & (norm != 0)
            fp_ok = np.where(np.isfinite(fp), fp, 0.0)
            # einsum, not a BLAS product: a threaded BLAS costs milliseconds to start here
            gram = np.einsum("ik,jk->ij", fp_ok, fp_ok)
            sq = np.einsum("ij,ij->i", fp_ok, fp_ok)
            dist = np.sqrt(np.maximum(sq[:, None] + sq[None, :] - 2 * gram, 0.0))
            # a loose screen: only a mistake near an earlier one is compared exactly
            near = np.tril(dist < NEAR_DUPLICATE * norm[:, None], k=-1) & valid[None, :]
            screened = near.any(axis=1)
        kept: list[int] = []
        for m in np.flatnonzero(valid):
            if screened[m] and kept:
                if np.any(np.linalg.norm(fp[kept] - fp[m], axis=1) < SAME_FACTOR * norm[m]):
                    continue
            kept.append(int(m))
        out = np.array(kept, dtype=int)
        self.__dict__["_kept"] = out
        return out

    def mutant(self, m: int) -> tuple[int, Mutant]:
        """Mistake m as (row, the symbolic mutant the catalogue builds for it)."""
        if m not in self._built:
            p = self.problem
            i, kind, _w, source = self.specs[m]
            if source[0] == "sign":
                built = el_sign_mutant(p.system, p.jets, i)
            elif source[0] == "lagrangian":
                k = source[1]
                if k not in self._lagrangian_rows:
                    lm = self.catalogue.lagrangian_fingerprints.mutant(k)
                    pairs = lagrangian_row_mutants(p.system, p.jets, lm, self._per_monomial)
                    self._lagrangian_rows[k] = dict(pairs)
                built = self._lagrangian_rows[k][i]
            else:  # only the term's own mistakes are built, with its sentences
                key = (i, source[1])
                if key not in self._term_mutants:
                    terms = self._terms[i]
                    self._term_mutants[key] = one_term_mutants(
                        sp.Add(*terms),
                        terms[source[1]],
                        f"your equation for {p.jets[i].name}",
                        self.catalogue.parameters,
                    )
                built = self._term_mutants[key][source[2]]
            if built.kind != kind:
                raise AssertionError(f"catalogue out of step at {m}: {built.kind} ≠ {kind}")
            self._built[m] = built
        return self.specs[m][0], self._built[m]

    def _stack(self, reference: Rows) -> Stack | None:
        """The kept mistaken systems — the reference rows with the mistaken one in place —
        reduced to what the span test needs (`span_arrays`: a QR each), made once."""
        if "_span_stack" in self.__dict__:
            return self.__dict__["_span_stack"]
        kept = self.kept
        stack = None
        if len(kept):
            R, Rs = reference.coef.astype(float), reference.size.astype(float)
            rows = np.array([self.specs[m][0] for m in kept])
            Rm = np.repeat(R[None], len(kept), axis=0)
            Rsm = np.repeat(Rs[None], len(kept), axis=0)
            at = np.arange(len(kept))
            Rm[at, :, rows, :] = self.rows[kept]
            Rsm[at, :, rows] = self.sizes[kept]
            candidates = tuple((int(i), int(m)) for i, m in zip(rows, kept, strict=True))
            with np.errstate(all="ignore"):
                stack = Stack(candidates, at, span_arrays(Rm, Rsm))
        self.__dict__["_span_stack"] = stack
        return stack

    def match(
        self, student: Rows, reference: Rows, basis: tuple, changes: Callable[[int, Mutant], int]
    ) -> Mutant | None:
        """`Catalogue.match_row` on the arrays: of the kept mistaken systems whose rows span the
        student's equation, which is their mistaken row, and whose fix leaves a right equation,
        the one of fewest `changes`, the earliest of equals."""
        stack = self._stack(reference)
        if stack is None:
            return None
        best, fewest = None, None
        for (i, m), x in every_row(stack, student, self.points.group):
            if not row_fix_is_right(student, x, i, reference, basis):
                continue
            _, mutant = self.mutant(m)
            n = changes(i, mutant)
            if fewest is None or n < fewest:
                best, fewest = mutant, n
            if fewest == 1:
                break
        return best
