"""The mistakes students make with Lagrangians, derived per question from its reference and
recognised by numeric fingerprint, so that feedback names the mistake in the student's own terms
("your L lacks the cross term in x_M_dot*q_dot") instead of only saying "wrong".

Each mutation is a function of the reference that produces a wrong answer of a known kind (the
½ dropped on a kinetic term, T + V, a missing cross term, sin and cos swapped, the ω² term of a
driven constraint left out, the momentum of another coordinate, a term with the wrong sign or a
missing factor). A student's answer matches a mutation when it is equivalent to it by the same
test that judges answers (E(L′) = c E(L_mut), span of the mutated rows, …) at the same points.
Mutations that do not change what is judged (dropping the constant m g h from L) are left out.
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.equivalence import (
    Compiled,
    Points,
    equation_rows,
    euler_lagrange_values,
    in_span,
    lagrangians_match,
)
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.mechanics.lagrange import Jet, LagrangianSystem
from lagrade.notation.printer import as_typed


@dataclass(frozen=True)
class Mutant:
    """A wrong answer of a known kind: `kind` for tests and statistics, `message` for the
    student, `expr` the mutated reference."""

    kind: str
    message: str
    expr: sp.Expr


def swap_sin_cos(expr: sp.Expr) -> sp.Expr:
    """expr with every sin(u) written as cos(u) and every cos(u) as sin(u)."""
    if isinstance(expr, sp.sin):
        return sp.cos(swap_sin_cos(expr.args[0]))
    if isinstance(expr, sp.cos):
        return sp.sin(swap_sin_cos(expr.args[0]))
    if not expr.args:
        return expr
    return expr.func(*(swap_sin_cos(a) for a in expr.args))


def _terms(expr: sp.Expr) -> tuple[sp.Expr, ...]:
    return sp.Add.make_args(sp.expand(expr))


def _velocities(term: sp.Expr, jets: Sequence[Jet]) -> list[sp.Symbol]:
    return [j.dot for j in jets if term.has(j.dot)]


def _factors(term: sp.Expr, parameters: Iterable[sp.Symbol]) -> list[sp.Symbol]:
    """Parameters that multiply the term (not those inside a function's argument)."""
    factors = sp.Mul.make_args(term)
    bases = {f.base if isinstance(f, sp.Pow) else f for f in factors}
    return [p for p in parameters if p in bases]


def term_mutants(expr: sp.Expr, what: str, parameters: Sequence[sp.Symbol]) -> list[Mutant]:
    """Single-term mutations of expr: a term with the wrong sign, left out, with sin and cos
    swapped, twice or half its size, without one of its parameter factors."""
    terms = _terms(expr)
    out: list[Mutant] = []
    for k, term in enumerate(terms):
        rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
        shown = as_typed(term)
        out.append(
            Mutant("wrong_sign", f"the term {shown} in {what} has the wrong sign", rest - term)
        )
        if term.has(sp.sin) or term.has(sp.cos):
            swapped = swap_sin_cos(term)
            if swapped != term:
                out.append(
                    Mutant(
                        "sin_cos_swapped",
                        f"sin and cos are swapped in the term {shown} of {what}",
                        rest + swapped,
                    )
                )
        for p in _factors(term, parameters):
            out.append(
                Mutant(
                    "missing_factor",
                    f"the term {shown} in {what} lacks the factor {p}",
                    rest + term / p,
                )
            )
        out.append(Mutant("missing_term", f"{what} lacks the term {shown}", rest))
        out.append(
            Mutant("factor_two", f"the term {shown} in {what} is twice too large", rest + 2 * term)
        )
        out.append(
            Mutant(
                "factor_half",
                f"the term {shown} in {what} is half what it should be",
                rest + term / 2,
            )
        )
    return out


def kinetic_mutants(T: sp.Expr, jets: Sequence[Jet], what: str) -> list[Mutant]:
    """Mistakes in T itself: the ½ dropped on one term or on all of T, a missing cross term, a
    missing term of the prescribed motion (centripetal, ω²)."""
    out: list[Mutant] = []
    terms = _terms(T)
    for k, term in enumerate(terms):
        rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
        vel = _velocities(term, jets)
        coeff = term.as_coeff_Mul()[0]
        if vel and isinstance(coeff, sp.Rational) and coeff.q % 2 == 0:
            out.append(
                Mutant(
                    "dropped_half",
                    f"the ½ is missing in the kinetic term {as_typed(term)} of {what}",
                    rest + 2 * term,
                )
            )
        if len(vel) >= 2:
            cross = as_typed(sp.Mul(*vel))
            out.append(
                Mutant("missing_cross_term", f"{what} lacks the cross term in {cross}", rest)
            )
        if not vel:
            out.append(
                Mutant(
                    "missing_driven_term",
                    f"{what} lacks the term {as_typed(term)} from the prescribed motion "
                    "(the centripetal "
                    "or ω² term of the kinetic energy)",
                    rest,
                )
            )
    return out


# What a mutant may raise when it is compiled or evaluated: such a mutant is never matched.
_SKIPPED = (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError)


@dataclass(frozen=True)
class _Stack:
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


@dataclass(frozen=True)
class Split:
    """L = T − V: from the scene, or for an ad-hoc L by terms (terms with a velocity form T)."""

    T: sp.Expr
    V: sp.Expr


class Catalogue:
    """The mutations of one question, built on first use per part, and the matching of an
    answer against them."""

    def __init__(self, problem: Any):  # a lagrade.judge.problem.Problem (which imports this)
        self.problem = problem

    # --- the reference's parts -----------------------------------------------------------------
    @cached_property
    def split(self) -> Split:
        p = self.problem
        if p.variant is not None:
            return Split(p.variant.kinetic_energy, p.variant.potential_energy)
        L = sp.expand(p.system.L)
        T = sp.Add(*(x for x in _terms(L) if _velocities(x, p.jets)))
        return Split(T, sp.expand(T - L))

    def _body_mutants(self, what: str) -> list[Mutant]:
        """Per body of a scene: its kinetic energy without the ½, or left out."""
        v = self.problem.variant
        if v is None or len(v.bodies) < 2:
            return []
        T = self.split.T
        out = []
        for body in v.bodies:
            Tb = sp.expand(body.kinetic_energy(v.jets))
            if Tb == 0:
                continue
            out.append(
                Mutant(
                    "dropped_half",
                    f"the ½ is missing in the kinetic energy of the {body.name} in {what}",
                    T + Tb,
                )
            )
            out.append(
                Mutant(
                    "missing_body", f"{what} lacks the kinetic energy of the {body.name}", T - Tb
                )
            )
        return out

    @property
    def parameters(self) -> list[sp.Symbol]:
        return list(self.problem.parameters.values())

    # --- Lagrangian ------------------------------------------------------------------------------
    @cached_property
    def lagrangian_mutants(self) -> list[Mutant]:
        T, V = self.split.T, self.split.V
        out = [
            Mutant("sign_of_V", "your L adds V instead of subtracting it (L = T − V)", T + V),
            Mutant("dropped_half_all", "the ½ is missing in the kinetic energy", 2 * T - V),
        ]
        out += [Mutant(m.kind, m.message, m.expr - V) for m in self._body_mutants("your L")]
        out += [
            Mutant(m.kind, m.message, m.expr - V)
            for m in kinetic_mutants(T, self.problem.jets, "your L")
        ]
        out.append(
            Mutant("sin_cos_swapped", "sin and cos are swapped in your L", swap_sin_cos(T - V))
        )
        out += term_mutants(T - V, "your L", self.parameters)
        return self._distinct(out, "el", self.problem.L)

    # --- T and V ----------------------------------------------------------------------------------
    @cached_property
    def kinetic_mutants(self) -> list[Mutant]:
        T = self.split.T
        out = [Mutant("dropped_half_all", "the ½ is missing in your T", 2 * T)]
        out += self._body_mutants("your T")
        out += kinetic_mutants(T, self.problem.jets, "your T")
        out.append(Mutant("sin_cos_swapped", "sin and cos are swapped in your T", swap_sin_cos(T)))
        out += term_mutants(T, "your T", self.parameters)
        return self._distinct(out, "plain", Compiled.of(T))

    @cached_property
    def potential_mutants(self) -> list[Mutant]:
        V = self.split.V
        out = [Mutant("sign_of_V", "your V has the wrong sign (height measured downwards?)", -V)]
        out.append(Mutant("sin_cos_swapped", "sin and cos are swapped in your V", swap_sin_cos(V)))
        out += term_mutants(V, "your V", self.parameters)
        return self._distinct(out, "offset", Compiled.of(V))

    # --- momenta --------------------------------------------------------------------------------
    def momentum_mutants(self, k: int) -> list[Mutant]:
        cache = self.__dict__.setdefault("_momentum", {})
        if k not in cache:
            cache[k] = self._momentum_mutants(k)
        return cache[k]

    def _momentum_mutants(self, k: int) -> list[Mutant]:
        p = self.problem
        jets = p.jets
        name = jets[k].name
        what = f"your p_{name}"
        momenta = p.system.generalized_momenta
        out: list[Mutant] = []
        for i, j in enumerate(jets):
            if i != k:
                out.append(
                    Mutant(
                        "wrong_coordinate",
                        f"{what} is the momentum of {j.name} (∂L/∂{j.name}_dot), not of {name}",
                        momenta[i],
                    )
                )
        out.append(
            Mutant(
                "force_not_momentum",
                f"{what} is ∂L/∂{name}; the momentum is ∂L/∂{name}_dot",
                sp.diff(p.system.L, jets[k].q),
            )
        )
        for m in self.lagrangian_mutants:
            if m.kind in (
                "dropped_half",
                "missing_cross_term",
                "missing_driven_term",
                "dropped_half_all",
            ):
                pk = sp.expand(sp.diff(m.expr, jets[k].dot))
                out.append(Mutant(m.kind, _momentum_message(m, what, momenta[k], pk), pk))
        out += term_mutants(momenta[k], what, self.parameters)
        return self._distinct(out, "plain", Compiled.of(momenta[k]))

    # --- equations of motion ----------------------------------------------------------------------
    @cached_property
    def row_mutants(self) -> list[tuple[int, Mutant]]:
        """(row, mutant) pairs: row `row` of the EL equations replaced by the mutant."""
        p = self.problem
        jets = p.jets
        E = p.system.euler_lagrange
        out: list[tuple[int, Mutant]] = []
        for i, j in enumerate(jets):
            what = f"the equation for {j.name}"
            flipped = sp.expand(E[i] + 2 * sp.diff(p.system.L, j.q))  # D_t p + ∂L/∂q
            out.append(
                (
                    i,
                    Mutant(
                        "el_sign",
                        f"{what} has d/dt(∂L/∂{j.name}_dot) + ∂L/∂{j.name}; Lagrange's "
                        "equation has a minus sign",
                        flipped,
                    ),
                )
            )
        for m in self.lagrangian_mutants:
            if m.kind in (
                "sign_of_V",
                "dropped_half",
                "missing_cross_term",
                "missing_driven_term",
                "dropped_half_all",
            ):
                try:
                    rows = LagrangianSystem(m.expr, jets).euler_lagrange
                except Exception:  # noqa: BLE001 - a mutant we cannot differentiate is skipped
                    continue
                for i, row in enumerate(rows):
                    if sp.expand(row - E[i]) != 0:
                        msg = m.message.replace(
                            "your L", f"the L behind your equation for {jets[i].name}"
                        )
                        out.append((i, Mutant(m.kind, msg, row)))
        for i, j in enumerate(jets):
            for m in term_mutants(E[i], f"your equation for {j.name}", self.parameters):
                out.append((i, m))
        return self._distinct_rows(out)

    # --- conserved quantities --------------------------------------------------------------------
    @cached_property
    def conserved_mutants(self) -> list[Mutant]:
        p = self.problem
        sys_ = p.system
        out: list[Mutant] = []
        T, V = self.split.T, self.split.V
        h = sys_.energy_function
        if sp.expand(T + V - h) != 0:
            out.append(
                Mutant(
                    "energy_not_conserved",
                    "T + V is not conserved here: the constraint moves, so energy flows in "
                    "and out; "
                    "the Jacobi integral h = Σ q̇ ∂L/∂q̇ − L is",
                    T + V,
                )
            )
        cyclic = set(sys_.cyclic_coordinates)
        for j, pj in zip(p.jets, sys_.generalized_momenta, strict=True):
            if j.name not in cyclic:
                out.append(
                    Mutant(
                        "momentum_not_conserved",
                        f"p_{j.name} is not conserved: {j.name} is not cyclic "
                        f"(L depends on {j.name})",
                        pj,
                    )
                )
        out.append(
            Mutant("lagrangian_not_conserved", "L itself is not a conserved quantity", sys_.L)
        )
        return out

    # --- a reference expression ------------------------------------------------------------------
    @cached_property
    def expression_mutants(self) -> list[Mutant]:
        """The usual slips with a closed-form result: sin for cos, the sign, upside down."""
        ref = self.problem.reference_expression.expr
        return [
            Mutant("sin_cos_swapped", "sin and cos are swapped", swap_sin_cos(ref)),
            Mutant("wrong_sign", "the sign is wrong", -ref),
            Mutant(
                "reciprocal",
                "your answer is upside down (the reciprocal of the right one)",
                1 / ref,
            ),
        ]

    # --- matching ---------------------------------------------------------------------------------
    # A wrong answer is tested against every mutant of its part, so each match tests all of
    # them at once: the mutants' values at the points are stacked once per set of points, and
    # a few array operations per answer find the first mutant that matches (the catalogue's
    # order puts the most specific first). The tests are those of the one-at-a-time loop.

    def match_lagrangian(
        self,
        answer: Compiled,
        points: Points,
        answer_el: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> Mutant | None:
        """The mutant with E(answer) = c E(mutant), c ≠ 0 per parameter group (float64 only:
        a diagnosis names a likely mistake, the verdict is decided elsewhere). `answer_el`:
        E(answer) and its size at the points, when the verdict has computed them already."""
        if answer_el is None:
            answer_el = euler_lagrange_values(answer, self.problem.jets, points.env)
        Ea, Sa = answer_el
        stack = self._el_stack(points)
        if stack is None:
            return None
        Eb, Sb, den, in_group, group_of = stack.arrays
        with np.errstate(all="ignore"):
            # least-squares c per mutant and group; a non-finite value leaves c or r non-finite
            # for that mutant only (rows are independent), so it does not match, as before
            c = np.einsum("mpk,pk->mp", Eb, Ea) @ in_group / den  # (mutants, groups)
            ok = np.all((den != 0) & (np.abs(c) >= 1e-9), axis=1)
            c = c[:, group_of, None]  # per point: (mutants, points, 1)
            ok &= _vanish_rows(Ea - c * Eb, Sa + np.abs(c) * Sb)
        return stack.first(ok)

    def match_plain(
        self, mutants: Sequence[Mutant], answer: Compiled, points: Points
    ) -> Mutant | None:
        """The first mutant with the answer's values at the points."""
        with np.errstate(all="ignore"):
            a, sa = _full(answer.values(points.env), points.n)
        stack = self._value_stack(mutants, points)
        if stack is None:
            return None
        b, sb = stack.arrays
        with np.errstate(all="ignore"):
            return stack.first(_vanish_rows(a - b, sa + sb))

    def match_offset(
        self, mutants: Sequence[Mutant], answer: Compiled, points: Points
    ) -> Mutant | None:
        """The first mutant the answer equals up to a constant per parameter group (V, a
        conserved quantity)."""
        with np.errstate(all="ignore"):
            a, sa = _full(answer.values(points.env), points.n)
        stack = self._value_stack(mutants, points)
        if stack is None:
            return None
        b, sb = stack.arrays
        starts = np.searchsorted(points.group, points.group)
        with np.errstate(all="ignore"):
            d = a - b
            return stack.first(_vanish_rows(d - d[:, starts], sa + sb + np.abs(d[:, starts])))

    def match_row(self, student: Compiled, points: Points) -> Mutant | None:
        """The mutation whose mutated system has the student's equation in its span."""
        p = self.problem
        with np.errstate(all="ignore"):
            s = equation_rows([student], p.jets, points.env)
        stack = self._row_stack(points)
        if stack is None:
            return None
        Q, rel_ref = stack.arrays
        x, xs = s.coef[:, 0, :].astype(float), s.size[:, 0].astype(float)
        with np.errstate(all="ignore"):
            # _in_span_float's test, its answer-independent part precomputed per mutant:
            # x minus its projection on the mutated system's rows
            res = x - np.einsum("mpij,mpj->mpi", Q, np.einsum("mpji,pj->mpi", Q, x))
            r = np.linalg.norm(res, axis=2)
            size = xs + np.linalg.norm(x, axis=1) * rel_ref
            found = stack.first(_vanish_rows(r, size))
        return None if found is None else found[1]

    def match(self, mutants: Sequence[Mutant], test: Callable[[Compiled], bool]) -> Mutant | None:
        """The first mutant the answer matches by `test(compiled mutant)` (a test that is not
        a fixed array operation, so one mutant at a time)."""
        for m in mutants:
            try:
                with np.errstate(all="ignore"):
                    if test(self._compiled(m)):
                        return m
            except _SKIPPED:
                continue
        return None

    def warm(self, part: str, points: Points) -> None:
        """Build the stacks that `part`'s matching uses at `points`, so that the first wrong
        answer to a question pays no more than the others (called when a question is prepared)."""
        if part == "lagrangian":
            self._el_stack(points)
        elif part == "T":
            self._value_stack(self.kinetic_mutants, points)
        elif part == "V":
            self._value_stack(self.potential_mutants, points)
        elif part == "momenta":
            for k in range(len(self.problem.jets)):
                self._value_stack(self.momentum_mutants(k), points)
        elif part == "eom":
            self._row_stack(points)
        elif part == "conserved":
            self._value_stack(self.conserved_mutants, points)
        elif part == "expression":
            self._value_stack(self.expression_mutants, points)

    # --- stacks of mutant values, per set of points ----------------------------------------------
    def _stack(
        self,
        name: str,
        candidates: Sequence,
        points: Points,
        evaluate: Callable[[Any], tuple[np.ndarray, ...]],
        finish: Callable[..., tuple],
    ) -> _Stack | None:
        """`finish(evaluate(c) for each candidate c, stacked)`, built once per candidates and
        points; None when no candidate evaluates. Candidates that fail to compile or evaluate
        are left out, as the one-at-a-time loop skipped them."""

        def build() -> _Stack:
            index, rows = [], []
            with np.errstate(all="ignore"):
                for k, c in enumerate(candidates):
                    try:
                        rows.append(evaluate(c))
                    except _SKIPPED:
                        continue
                    index.append(k)
                arrays = finish(*(np.stack(a) for a in zip(*rows, strict=True))) if rows else ()
            return _Stack(tuple(candidates), np.array(index, dtype=int), arrays)

        stack = self.problem.cached(f"{name}:{id(candidates)}", points, build)
        if not stack.of(candidates):
            stack = build()  # the sequence changed in place since the stack was built
        return stack if len(stack.index) else None

    def _el_stack(self, points: Points) -> _Stack | None:
        """The mutants' E and its size (mutants, points, coordinates), Σ E² per parameter
        group (the denominator of c), and the point-to-group map."""

        def finish(Eb, Sb):
            groups, group_of = np.unique(points.group, return_inverse=True)
            in_group = (group_of[:, None] == np.arange(len(groups))).astype(float)
            return Eb, Sb, np.sum(Eb**2, axis=2) @ in_group, in_group, group_of

        return self._stack(
            "el-stack",
            self.lagrangian_mutants,
            points,
            lambda m: self._el_values(self._compiled(m), points),
            finish,
        )

    def _value_stack(self, mutants: Sequence[Mutant], points: Points) -> _Stack | None:
        """The mutants' values and sizes, (mutants, points)."""
        return self._stack(
            "value-stack",
            mutants,
            points,
            lambda m: _full(self._compiled(m).values(points.env), points.n),
            lambda b, sb: (b, sb),
        )

    def _row_stack(self, points: Points) -> _Stack | None:
        """Per row mutant, the reference rows with its row in place of row i, at every point,
        reduced to what the span test of _in_span_float needs that does not depend on the
        answer: an orthonormal basis Q (mutants, points, n + 1, rows) of the rows (the QR is
        the costly part) and the relative size of their terms (mutants, points)."""
        p = self.problem
        with np.errstate(all="ignore"):
            ref = p.cached(
                "rows", points, lambda: equation_rows(p.euler_lagrange, p.jets, points.env)
            )

        def evaluate(pair):
            i, m = pair
            rows = equation_rows([self._compiled(m)], p.jets, points.env)
            R = ref.coef.astype(float).copy()
            Rs = ref.size.astype(float).copy()
            R[:, i, :] = rows.coef[:, 0, :]
            Rs[:, i] = rows.size[:, 0]
            return R, Rs

        def finish(R, Rs):
            Q, _ = np.linalg.qr(np.swapaxes(R, -1, -2))
            norm = np.linalg.norm(R, axis=-1)
            rel_ref = np.max(np.where(norm > 0, Rs / np.where(norm > 0, norm, 1), 0), axis=-1)
            return Q, rel_ref

        return self._stack("row-stack", self.row_mutants, points, evaluate, finish)

    # --- helpers ----------------------------------------------------------------------------------
    def _compiled(self, m: Mutant) -> Compiled:
        cache = self.__dict__.setdefault("_compiled_cache", {})
        if id(m) not in cache:
            cache[id(m)] = (m, Compiled.of(m.expr))
        return cache[id(m)][1]

    def _el_values(self, mut: Compiled, points: Points):
        return self.problem.cached(
            f"el:{id(mut)}",
            points,
            lambda: euler_lagrange_values(mut, self.problem.jets, points.env),
        )

    def _fingerprint(self, compiled: Compiled, mode: str, points: Points) -> np.ndarray | None:
        """What the part's test sees of an answer: E(L) normalised (L is judged up to a factor),
        plain values, or values up to a constant per parameter group (V)."""
        if mode == "el":
            v = self._el_values(compiled, points)[0].ravel()
            norm = np.linalg.norm(v)
            return None if norm == 0 else v / norm * np.sign(v[np.argmax(np.abs(v))])
        v = np.broadcast_to(np.asarray(compiled.values(points.env)[0], float), (points.n,))
        if mode == "offset":
            v = v - v[np.searchsorted(points.group, points.group)]
        return v

    def _distinct(self, mutants: list[Mutant], mode: str, reference: Compiled) -> list[Mutant]:
        """Drop mutants that change nothing the part's test sees, and duplicates (the first,
        most specific, wins), by fingerprint at the part's points."""
        part = {"el": "lagrangian", "plain": "momenta", "offset": "V"}[mode]
        points = self.problem.points(part)
        with np.errstate(all="ignore"):
            seen = [self._fingerprint(reference, mode, points)]
            kept = []
            for m in mutants:
                try:
                    fp = self._fingerprint(self._compiled(m), mode, points)
                except (UnsupportedExpression, ValueError, ZeroDivisionError):
                    continue
                if fp is None or not np.all(np.isfinite(fp)):
                    continue
                if mode == "el" and self._same_dynamics(m, reference, points):
                    continue  # e.g. ½θ̇² for ½Iθ̇²: a parameter factor, the same motion
                if any(o is not None and _close(fp, o) for o in seen):
                    continue
                seen.append(fp)
                kept.append(m)
        return kept

    def _same_dynamics(self, m: Mutant, reference: Compiled, points) -> bool:
        """A 'mistake' whose Euler–Lagrange equations are a multiple of the reference's is no
        mistake: the Lagrangian check accepts it, so the catalogue must not name it."""
        match = lagrangians_match(self._compiled(m), reference, self.problem.jets, points)
        return bool(match.outcome.equal) and all(c > 0 for c in match.factors)

    def _distinct_rows(self, pairs: list[tuple[int, Mutant]]) -> list[tuple[int, Mutant]]:
        p = self.problem
        points = p.points("eom")
        ref = equation_rows(p.euler_lagrange, p.jets, points.env)
        kept, seen = [], []
        for i, m in pairs:
            try:
                rows = equation_rows([self._compiled(m)], p.jets, points.env)
            except (UnsupportedExpression, ValueError, ZeroDivisionError):
                continue
            r, s = in_span(rows, ref, 0)
            if np.all(np.abs(r) <= 1e-8 * s):
                continue  # the mutated row is still a consequence of the right equations
            fp = rows.coef[:, 0, :].ravel()
            norm = np.linalg.norm(fp)
            if not np.isfinite(norm) or norm == 0:
                continue
            fp = fp / norm
            if any(min(np.linalg.norm(fp - o), np.linalg.norm(fp + o)) < 1e-8 for _, o in seen):
                continue
            seen.append((i, fp))
            kept.append((i, m))
        return kept


def _full(pair, n: int) -> tuple[np.ndarray, np.ndarray]:
    value, size = pair
    return (
        np.broadcast_to(np.asarray(value, float), (n,)),
        np.broadcast_to(np.asarray(size, float), (n,)),
    )


def _vanish_rows(r: np.ndarray, size: np.ndarray) -> np.ndarray:
    """Per leading row (one per mutant): finite and within rounding of its terms everywhere."""
    r, size = r.reshape(len(r), -1), size.reshape(len(size), -1)
    return np.all(np.isfinite(r) & (np.abs(r) <= 1e-9 * size), axis=1)


def _close(a: np.ndarray, b: np.ndarray) -> bool:
    scale = max(np.max(np.abs(a)), np.max(np.abs(b)), 1e-300)
    return a.shape == b.shape and float(np.max(np.abs(a - b))) <= 1e-9 * scale


def _momentum_message(m: Mutant, what: str, right: sp.Expr, wrong: sp.Expr) -> str:
    missing = sp.expand(right - wrong)
    if m.kind in ("missing_cross_term", "missing_driven_term") and missing != 0:
        return f"{what} lacks the term {as_typed(missing)}"
    return m.message.replace("your L", what)
