"""The Lagrangian mistakes of the catalogue as fingerprints: each mistake's Euler–Lagrange values
at the question's points, built once per question from the values of a few pieces — the
reference's terms, their sin↔cos swaps, a term without a parameter factor, T, V, a body's T —
because every catalogued mistake of L is the reference plus a few scaled pieces (or, for sin and
cos swapped throughout, one piece alone), and E is linear. One hyper-dual pass gives E of every
piece; the mistakes' values are a matrix product; a wrong answer is matched against all of them
in one vectorised step, by the catalogue's own tests (`matching`). Sympy builds the sentence of
the mistake that matched, and nothing else.

The mistakes, their order and which are kept are those of `Catalogue.lagrangian` (the same
generators' structure, `lagrangian_specs`; a test holds the kinds in step): a mistake is named
exactly when the symbolic catalogue names it."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from itertools import chain
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.derivatives import euler_lagrange_terms
from lagrade.judge.evaluate import UnsupportedExpression, compile_program, top_terms
from lagrade.judge.matching import (
    Stack,
    every_lagrangian,
    lagrangian_arrays,
    lagrangian_fix_is_right,
)
from lagrade.judge.mutations import (
    Mutant,
    expanded_terms,
    swap_sin_cos,
    term_specs,
    velocities_in,
)
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import SAME_DYNAMICS_SUSPECT, SAME_VALUE, SURE_EQUAL
from lagrade.mechanics import Jet, SceneVariant


@dataclass(frozen=True)
class Spec:
    """One catalogued mistake of L: `base` × L + Σ weight × piece."""

    kind: str
    base: float
    weights: tuple[tuple[int, float], ...]


class _Pieces:
    """Distinct pieces (sympy, or a quotient: `divided`), by index."""

    def __init__(self) -> None:
        self.exprs: list = []
        self._index: dict = {}

    def __call__(self, expr) -> int:
        if expr not in self._index:
            self._index[expr] = len(self.exprs)
            self.exprs.append(expr)
        return self._index[expr]


def lagrangian_specs(
    T: sp.Expr,
    V: sp.Expr,
    variant: SceneVariant | None,
    jets: Sequence[Jet],
    parameters: Sequence[sp.Symbol],
) -> tuple[list[sp.Expr], list[Spec], int]:
    """The pieces and the mistakes of `Catalogue.lagrangian`, in its order: sign of V, the ½ of
    all of T, per body (`body_mutants`), per kinetic term (`kinetic_mutants`), sin and cos
    swapped throughout, and the single-term mistakes of T − V (`term_specs`); and how many
    are of the early kinds (those before sin and cos swapped throughout)."""
    piece = _Pieces()
    specs = [
        Spec("sign_of_V", 1.0, ((piece(V), 2.0),)),
        Spec("dropped_half_all", 1.0, ((piece(T), 1.0),)),
    ]
    if variant is not None and len(variant.bodies) >= 2:
        for body in variant.bodies:
            Tb = sp.expand(body.kinetic_energy(variant.jets))
            if Tb == 0:
                continue
            specs.append(Spec("dropped_half", 1.0, ((piece(Tb), 1.0),)))
            specs.append(Spec("missing_body", 1.0, ((piece(Tb), -1.0),)))
    for term in expanded_terms(T):
        vel = velocities_in(term, jets)
        coeff = term.as_coeff_Mul()[0]
        if vel and isinstance(coeff, sp.Rational) and coeff.q % 2 == 0:
            specs.append(Spec("dropped_half", 1.0, ((piece(term), 1.0),)))
        if len(vel) >= 2:
            specs.append(Spec("missing_cross_term", 1.0, ((piece(term), -1.0),)))
        if not vel:
            specs.append(Spec("missing_driven_term", 1.0, ((piece(term), -1.0),)))
    early = len(specs)
    specs.append(Spec("sin_cos_swapped", 0.0, ((piece(swap_sin_cos(T - V)), 1.0),)))
    for term in expanded_terms(T - V):
        for kind, pieces, _ in term_specs(term, parameters, divided):
            specs.append(Spec(kind, 1.0, tuple((piece(e), float(c)) for c, e in pieces)))
    return piece.exprs, specs, early


def divided(term: sp.Expr, p: sp.Symbol) -> tuple:
    """The piece term/p as the fingerprints hold it: term's values over p's (p is a constant,
    so E(term/p) = E(term)/p), without forming the quotient in sympy."""
    return ("/", term, p)


def with_quotients(pieces: Sequence, values: Callable[[list], tuple], env: dict) -> tuple:
    """`values` of the sympy pieces, (pieces, points, …) each of value and size, and of each
    quotient piece (`divided`) its term's values over p's at the points."""
    plain = [k for k, e in enumerate(pieces) if not isinstance(e, tuple)]
    V, S = values([pieces[k] for k in plain])
    out_v = np.full((len(pieces), *V.shape[1:]), np.nan)
    out_s = np.full((len(pieces), *S.shape[1:]), np.nan)
    out_v[plain], out_s[plain] = V, S
    at = {pieces[k]: k for k in plain}
    for k, e in enumerate(pieces):
        if isinstance(e, tuple):
            _, term, p = e
            d = np.asarray(env[p], float)
            with np.errstate(all="ignore"):
                out_v[k] = out_v[at[term]] / d.reshape(-1, *([1] * (V.ndim - 2)))
                out_s[k] = out_s[at[term]] / np.abs(d).reshape(-1, *([1] * (S.ndim - 2)))
    return out_v, out_s


def _piece_values(pieces: Sequence, jets: Sequence[Jet], env: dict):
    """E and size of each piece (pieces, points, coordinates), NaN for a piece that does not
    compile or evaluate; each piece as the sum of its top-level terms, as `Compiled` sums them."""
    return with_quotients(pieces, lambda exprs: _sympy_piece_values(exprs, jets, env), env)


class Pieces(list):
    """The distinct expressions a table of mistakes is weighted over, in the order first met:
    calling it with an expression gives that expression's index, adding it when new (each
    piece is evaluated once however many mistakes weigh it)."""

    def __init__(self) -> None:
        super().__init__()
        self._index: dict = {}

    def __call__(self, e: sp.Expr) -> int:
        if e not in self._index:
            self._index[e] = len(self)
            self.append(e)
        return self._index[e]


def piece_terms(pieces: Sequence[sp.Expr]) -> tuple[list, list[int]]:
    """The top-level terms of every piece, and the piece each belongs to: one program evaluates
    all pieces, each summed from its terms as `Compiled` sums them (so are their sizes)."""
    terms, owner = [], []
    for k, e in enumerate(pieces):
        for term in top_terms(sp.S(e)):
            terms.append(term)
            owner.append(k)
    return terms, owner


def _sympy_piece_values(pieces: Sequence[sp.Expr], jets: Sequence[Jet], env: dict):
    terms, owner = piece_terms(pieces)
    n_pts, n = len(next(iter(env.values()))), len(jets)
    E = np.zeros((len(pieces), n_pts, n))
    S = np.zeros((len(pieces), n_pts, n))
    try:
        Et, St = euler_lagrange_terms(compile_program(terms), jets, env)
        np.add.at(E, owner, Et)
        np.add.at(S, owner, St)
        return E, S
    except (UnsupportedExpression, ValueError, ZeroDivisionError):
        pass
    for k, e in enumerate(pieces):  # one piece does not compile: the others one at a time
        try:
            Et, St = euler_lagrange_terms(compile_program(top_terms(sp.S(e))), jets, env)
            E[k], S[k] = Et.sum(axis=0), St.sum(axis=0)
        except (UnsupportedExpression, ValueError, ZeroDivisionError):
            E[k] = S[k] = np.nan
    return E, S


class LagrangianFingerprints:
    """The Lagrangian mistakes of one question as arrays: E and its size per mistake at a set of
    points (`values`), which of them the catalogue keeps, and the matching of an answer.
    `catalogue`: the question's `Catalogue` (its split, its reference values, and — for the one
    mistake that matched — the symbolic mutant with its sentence)."""

    def __init__(self, catalogue: Any) -> None:
        p = catalogue.problem
        self.catalogue = catalogue
        split = catalogue.split
        self.pieces, self.specs, self.early = lagrangian_specs(
            split.T, split.V, p.variant, p.jets, catalogue.parameters
        )
        m, k = len(self.specs), len(self.pieces)
        self.base = np.array([s.base for s in self.specs])
        self.weights = np.zeros((m, k))
        for i, s in enumerate(self.specs):
            for j, w in s.weights:
                self.weights[i, j] += w
        self._values: dict[int, tuple] = {}
        self._mutants: list[Mutant] = []
        self._source: Iterator[Mutant] | None = None

    def values(self, points: Points) -> tuple[np.ndarray, np.ndarray]:
        """E and its size of every mistake at `points`: (mistakes, points, coordinates)."""
        key = id(points)
        if key not in self._values:
            p = self.catalogue.problem
            with np.errstate(all="ignore"):
                E, S = _piece_values(self.pieces, p.jets, points.env)
                Er, Sr = self.catalogue.el_values(p.L, points)
                Em = self.base[:, None, None] * Er + np.einsum("mk,kpn->mpn", self.weights, E)
                Sm = np.abs(self.base)[:, None, None] * Sr + np.einsum(
                    "mk,kpn->mpn", np.abs(self.weights), S
                )
            self._values[key] = (points, Em, Sm)
        return self._values[key][1:]

    def mutant(self, i: int) -> Mutant:
        """Mistake i as the symbolic catalogue builds it (its sentence, its expression)."""
        if self._source is None:
            c = self.catalogue
            self._source = chain(c._lagrangian_early, c._lagrangian_late())
        while len(self._mutants) <= i:
            self._mutants.append(next(self._source))
        m = self._mutants[i]
        if m.kind != self.specs[i].kind:
            raise AssertionError(f"catalogue out of step at {i}: {m.kind} ≠ {self.specs[i].kind}")
        return m

    @property
    def kept(self) -> np.ndarray:
        """The mistakes the catalogue keeps, in order (`keepers.keeper` in mode "el", at the
        Lagrangian part's points): those with a finite, nonzero fingerprint, not the reference's
        dynamics, and not equal to the reference's fingerprint or an earlier kept one."""
        cached = self.__dict__.get("_kept")
        if cached is not None:
            return cached
        from lagrade.judge.keepers import same_dynamics

        c = self.catalogue
        points = c.problem.points("lagrangian")
        E, _ = self.values(points)
        Er, Sr = c.el_values(c.problem.L, points)
        fp = E.reshape(len(E), -1)
        ref = Er.ravel()
        with np.errstate(all="ignore"):
            valid = np.all(np.isfinite(fp), axis=1) & np.any(fp != 0, axis=1)
            same, unsure = self._same_dynamics(E, points)
            big = np.max(np.abs(fp), axis=1)
            close = np.max(
                np.abs(fp[:, None, :] - fp[None, :, :]), axis=2
            ) <= SAME_VALUE * np.maximum(big[:, None], np.maximum(big[None, :], 1e-300))
            if np.any(ref):
                scale = np.maximum(np.max(np.abs(ref)), np.maximum(big, 1e-300))
                like_ref = np.max(np.abs(fp - ref), axis=1) <= SAME_VALUE * scale
            else:
                like_ref = np.zeros(len(fp), dtype=bool)
        kept: list[int] = []
        for i in range(len(fp)):
            if not valid[i]:
                continue
            if same[i] or (unsure[i] and same_dynamics(c, self.mutant(i), c.problem.L, points)):
                continue
            if like_ref[i] or (kept and np.any(close[i, kept])):
                continue
            kept.append(i)
        out = np.array(kept, dtype=int)
        self.__dict__["_kept"] = out
        return out

    def _same_dynamics(self, E: np.ndarray, points: Points) -> tuple[np.ndarray, np.ndarray]:
        """Per mistake, E = c E(L) with c per parameter group of one sign (`keepers.same_dynamics`)
        where float64 settles it: (same, unsure). Sure when the residual is far below or far
        above every threshold of `decide` (the sizes here add the same terms in another order);
        the rest is decided the symbolic way."""
        c = self.catalogue
        Er, Sr = c.el_values(c.problem.L, points)
        _, S = self.values(points)
        group = points.group
        num = np.stack([np.bincount(group, np.sum(e * Er, axis=1)) for e in E])
        den = np.bincount(group, np.sum(Er * Er, axis=1))
        f = np.where(den != 0, num / np.where(den != 0, den, 1.0), 0.0)
        per_point = f[:, group][:, :, None]
        r = np.abs(E - per_point * Er)
        s = S + np.abs(per_point) * Sr
        ratio = np.where((s == 0) & (r == 0), 0.0, r / s).reshape(len(E), -1)
        finite = np.all(np.isfinite(ratio), axis=1)
        worst = np.max(np.where(np.isfinite(ratio), ratio, 0.0), axis=1)
        equal = finite & (worst <= SURE_EQUAL)
        different = finite & (worst >= SAME_DYNAMICS_SUSPECT)
        one_sign = np.all(f > 0, axis=1) | np.all(f < 0, axis=1)
        return equal & one_sign, ~(equal | different)

    def match(
        self,
        answer_el: tuple[np.ndarray, np.ndarray],
        reference_el: tuple[np.ndarray, np.ndarray],
        points: Points,
        changes: Callable[[Mutant], int],
    ) -> Mutant | None:
        """`Catalogue.match_lagrangian` on the arrays: of the kept mistakes with E(answer) = c
        E(mistake) whose fix leaves a right L, the one of fewest `changes`, the earliest of
        equals."""
        kept = self.kept
        if not len(kept):
            return None
        stacks = self.__dict__.setdefault("_stacks", {})
        if id(points) not in stacks:  # what c needs of the kept mistakes, once per points
            E, S = self.values(points)
            arrays = lagrangian_arrays(E[kept], S[kept], points.group)
            stacks[id(points)] = (points, Stack(tuple(kept), np.arange(len(kept)), arrays))
        stack = stacks[id(points)][1]
        best, fewest = None, None
        for i, Ei, Si in every_lagrangian(stack, answer_el):
            if not lagrangian_fix_is_right(answer_el, (Ei, Si), reference_el, points.group):
                continue
            m = self.mutant(int(i))
            n = changes(m)
            if fewest is None or n < fewest:
                best, fewest = m, n
            if fewest == 1:
                break
        return best
