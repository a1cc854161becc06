"""The mistakes of a generalized momentum p_k as fingerprints: each mistake's values at the momenta
part's points — another coordinate's momentum, ∂L/∂q_k, the p_k of a Lagrangian mistake (p_k
plus ∂piece/∂q̇_k of its pieces, from one dual pass), a single-term mistake of p_k — made once per
question, kept and matched (the first that equals the answer) in arrays, as
`Catalogue.momentum(k)` lists, keeps (`keepers.keeper` in mode "plain") and `match_plain` matches
them; sympy builds the sentence of the mistake that matched."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.derivatives import gradient
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression, compile_program, run
from lagrade.judge.fingerprints import Pieces, divided, piece_terms, with_quotients
from lagrade.judge.matching import full, vanish_rows
from lagrade.judge.mutations import (
    KINETIC_KINDS,
    Mutant,
    expanded_terms,
    force_mutant,
    lagrangian_momentum_mutant,
    one_term_mutants,
    term_specs,
    trig_factor_mutant,
    trig_factors,
    wrong_coordinate_mutant,
)
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import SAME_VALUE

_FAILS = (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError)


def _each(pieces: Sequence[sp.Expr], values_of) -> tuple[np.ndarray, np.ndarray]:
    """`values_of(terms)` → per-term arrays, summed per piece with their sizes: all pieces in
    one program, or one at a time when one does not compile (NaN for it)."""

    def of(exprs):
        terms, owner = piece_terms(exprs)
        per_term = values_of(terms)
        n_pts = per_term[0].shape[0] if per_term else 0
        v = np.zeros((len(exprs), n_pts))
        s = np.zeros((len(exprs), n_pts))
        for k, x in zip(owner, per_term, strict=True):
            v[k] += x
            s[k] += np.abs(x)
        return v, s

    with np.errstate(all="ignore"):
        try:
            return of(pieces)
        except _FAILS:
            pass
        out = []
        for e in pieces:
            try:
                out.append(of([e]))
            except _FAILS:
                out.append(None)
    shape = next((v.shape[1] for v in (o[0] for o in out if o is not None)), 0)
    nan = np.full((1, shape), np.nan)
    return (
        np.concatenate([o[0] if o is not None else nan for o in out]),
        np.concatenate([o[1] if o is not None else nan for o in out]),
    )


class MomentumFingerprints:
    """The mistakes of p_k as arrays at the momenta part's points. `catalogue`: the question's
    `Catalogue`."""

    def __init__(self, catalogue: Any, k: int) -> None:
        p = catalogue.problem
        self.catalogue, self.problem, self.k = catalogue, p, k
        self.points = p.points("momenta")
        system, jets = p.system, p.jets
        env = self.points.env
        n_pts = len(self.points.group)
        lag = catalogue.lagrangian_fingerprints
        plain = Pieces()  # the pieces the weights name, by index

        # a mistake: (kind, base weight of p_k, weights, how its symbolic mutant is built)
        specs: list[tuple[str, float, tuple, tuple]] = []
        for i in range(len(jets)):
            if i != k:
                w = (("v", plain(system.generalized_momenta[i]), 1.0),)
                specs.append(("wrong_coordinate", 0.0, w, ("coordinate", i)))
        specs.append(
            (
                "force_not_momentum",
                0.0,
                (("v", plain(system.generalized_forces[k]), 1.0),),
                ("force",),
            )
        )
        early = [j for j in lag.kept if j < lag.early and lag.specs[j].kind in KINETIC_KINDS]
        used = sorted({q for j in early for q, _ in lag.specs[j].weights})
        where = {q: u for u, q in enumerate(used)}
        for j in early:
            w = tuple(("g", where[q], c) for q, c in lag.specs[j].weights)
            specs.append((lag.specs[j].kind, 1.0, w, ("lagrangian", int(j))))
        self._terms = expanded_terms(system.generalized_momenta[k])
        for t, term in enumerate(self._terms):
            for local, (kind, pieces, _) in enumerate(
                term_specs(term, catalogue.parameters, divided)
            ):
                w = tuple(("v", plain(e), float(c)) for c, e in pieces)
                specs.append((kind, 1.0, w, ("term", t, local)))
        # a sin or cos dropped from one term of several (a momentum of one term without its
        # factor is the momenta part's own sentence, "p_φ is ∂L/∂φ̇ without its factor sin²θ")
        for t, term in enumerate(self._terms if len(self._terms) > 1 else ()):
            for local, f in enumerate(trig_factors(term)):
                w = (("v", plain(term), -1.0), ("v", plain(term / f), 1.0))
                specs.append(("missing_factor", 1.0, w, ("trig", t, local)))
        self.specs = specs
        with np.errstate(all="ignore"):
            values = with_quotients(
                plain,
                lambda exprs: _each(
                    exprs,
                    lambda terms: [
                        to_length(x, n_pts) for x in run(compile_program(terms), env, FLOAT)
                    ],
                ),
                env,
            )
            slopes = _each(
                [lag.pieces[q] for q in used],
                lambda terms: [
                    g[:, 0]
                    for g in gradient(
                        Compiled(sp.S.Zero, compile_program(terms)), [jets[k].dot], env
                    )
                ],
            )
            ref_v, ref_s = full(p.momenta[k].values(env), n_pts)
            tables = {"v": values, "g": slopes}
            V = np.empty((len(specs), n_pts))
            S = np.empty((len(specs), n_pts))
            for m, (_kind, base, weights, _source) in enumerate(specs):
                v, s = base * ref_v, abs(base) * ref_s
                for table, j, c in weights:
                    v = v + c * tables[table][0][j]
                    s = s + abs(c) * tables[table][1][j]
                V[m], S[m] = v, s
        self.values, self.sizes = V, S
        self._reference = ref_v
        self._built: dict[int, Mutant] = {}
        self._term_mutants: dict[int, list[Mutant]] = {}

    @property
    def kept(self) -> np.ndarray:
        """The mistakes `keepers.keeper` (mode "plain") keeps, in order: finite, and not equal
        to the reference's values or an earlier kept one's (to 1e-9 of the larger)."""
        cached = self.__dict__.get("_kept")
        if cached is not None:
            return cached
        fp, ref = self.values, np.asarray(self._reference, float)
        with np.errstate(all="ignore"):
            valid = np.all(np.isfinite(fp), axis=1)
            big = np.max(np.abs(fp), axis=1)
            close = np.max(
                np.abs(fp[:, None, :] - fp[None, :, :]), axis=2
            ) <= SAME_VALUE * np.maximum(big[:, None], np.maximum(big[None, :], 1e-300))
            scale = np.maximum(np.max(np.abs(ref)), np.maximum(big, 1e-300))
            like_ref = np.max(np.abs(fp - ref), axis=1) <= SAME_VALUE * scale
        kept: list[int] = []
        for m in np.flatnonzero(valid & ~like_ref):
            if kept and np.any(close[m, kept]):
                continue
            kept.append(int(m))
        out = np.array(kept, dtype=int)
        self.__dict__["_kept"] = out
        return out

    def mutant(self, m: int) -> Mutant:
        """Mistake m as the symbolic catalogue builds it (its sentence, its expression)."""
        if m not in self._built:
            p, k = self.problem, self.k
            kind, _base, _w, source = self.specs[m]
            if source[0] == "coordinate":
                built = wrong_coordinate_mutant(p.system, p.jets, k, source[1])
            elif source[0] == "force":
                built = force_mutant(p.system, p.jets, k)
            elif source[0] == "lagrangian":
                lm = self.catalogue.lagrangian_fingerprints.mutant(source[1])
                built = lagrangian_momentum_mutant(p.system, p.jets, k, lm)
            elif source[0] == "trig":
                term = self._terms[source[1]]
                f = trig_factors(term)[source[2]]
                built = trig_factor_mutant(
                    sp.Add(*self._terms), term, f, f"your p_{p.jets[k].name}"
                )
            else:
                if source[1] not in self._term_mutants:
                    self._term_mutants[source[1]] = one_term_mutants(
                        sp.Add(*self._terms),
                        self._terms[source[1]],
                        f"your p_{p.jets[k].name}",
                        self.catalogue.parameters,
                    )
                built = self._term_mutants[source[1]][source[2]]
            if built.kind != kind:
                raise AssertionError(f"catalogue out of step at {m}: {built.kind} ≠ {kind}")
            self._built[m] = built
        return self._built[m]

    def match(
        self,
        answer: tuple[np.ndarray, np.ndarray],
        points: Points,
        admits: Callable[[int], bool] | None = None,
    ) -> Mutant | None:
        """The first kept mistake with the answer's values (`matching.first_plain`) that
        `admits` (given the mistake's index) lets be said. When it admits none of them, a
        mistake of p_k's own terms that `kept` left out as a duplicate of one it refused is
        still true: a doubled m ẏ in the charged particle's p_y = m ẏ + e B x is the p_y of
        "the ½ is missing in T", refused when the other momenta are right, and is "the term
        m ẏ in your p_y is twice too large"."""
        assert points is self.points, "momentum mistakes are matched at the momenta part's points"
        kept = self.kept
        if not len(kept):
            return None
        a, sa = answer
        with np.errstate(all="ignore"):
            ok = vanish_rows(a - self.values[kept], sa + self.sizes[kept])
        hits = [int(kept[hit]) for hit in np.flatnonzero(ok)]
        for m in hits:
            if admits is None or admits(m):
                return self.mutant(m)
        if not hits or len(self._terms) < 2:  # one term scaled: the part says "p is twice …"
            return None
        # the mistakes of p_k's own terms (a sentence about L says more than p_k shows)
        listed = set(kept.tolist())
        duplicates = [
            m for m, spec in enumerate(self.specs) if m not in listed and spec[3][0] != "lagrangian"
        ]
        if not duplicates:
            return None
        with np.errstate(all="ignore"):
            same = vanish_rows(a - self.values[duplicates], sa + self.sizes[duplicates])
        return next((self.mutant(m) for m, hit in zip(duplicates, same, strict=True) if hit), None)

    def lagrangian_source(self, m: int) -> int | None:
        """The Lagrangian mistake that mistake m is the p_k of, or None."""
        source = self.specs[m][3]
        return source[1] if source[0] == "lagrangian" else None

    def of_lagrangian(self, j: int) -> tuple[np.ndarray, np.ndarray] | None:
        """The values and sizes of p_k of Lagrangian mistake j, or None when not listed."""
        for m, spec in enumerate(self.specs):
            if spec[3] == ("lagrangian", j):
                return self.values[m], self.sizes[m]
        return None
