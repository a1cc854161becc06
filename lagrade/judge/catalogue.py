"""The mistakes students make with Lagrangians, derived per question from its reference and
recognised by numeric fingerprint, so that feedback names the mistake in the student's own terms
("your L lacks the cross term in x_M_dot*q_dot") instead of only saying "wrong".

Each mutation is a function of the reference that produces a wrong answer of a known kind (the
½ dropped on a kinetic term, T + V, a missing cross term, sin and cos swapped, the ω² term of a
driven constraint left out, the momentum of another coordinate, a term with the wrong sign or a
missing factor): those are in `mutations`. A student's answer matches a mutation when it is
equivalent to it by the same test that judges answers (E(L′) = c E(L_mut), span of the mutated
rows, …) at the same points: `matching` runs those tests on all of a part's mutations at once.
Mutations that do not change what is judged (dropping the constant m g h from L) are left out.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Protocol, TypeVar

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.equivalence import lagrangians_match
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.matching import (
    SKIPPED,
    Stack,
    first_lagrangian,
    first_offset,
    first_plain,
    first_row,
    full,
    lagrangian_arrays,
    span_arrays,
    stacked,
)
from lagrade.judge.mutations import (
    Mutant,
    body_mutants,
    conserved_mutants,
    equation_mutants,
    expanded_terms,
    expression_mutants,
    kinetic_mutants,
    momentum_mutants,
    swap_sin_cos,
    term_mutants,
    velocities_in,
)
from lagrade.judge.rows import equation_rows, in_span
from lagrade.judge.sampling import Points
from lagrade.mechanics.lagrange import Jet, LagrangianSystem
from lagrade.mechanics.scene import SceneVariant

_T = TypeVar("_T")


class Question(Protocol):
    """What the catalogue uses of its question (a `lagrade.judge.problem.Problem`)."""

    jets: tuple[Jet, ...]
    parameters: dict[str, sp.Symbol]
    variant: SceneVariant | None

    @property
    def system(self) -> LagrangianSystem: ...

    @property
    def L(self) -> Compiled: ...

    @property
    def euler_lagrange(self) -> tuple[Compiled, ...]: ...

    @property
    def reference_expression(self) -> Compiled: ...

    def points(self, part: str) -> Points: ...

    def cached(self, name: str, points: Points, make: Callable[[], _T]) -> _T: ...


@dataclass(frozen=True)
class Split:
    """L = T − V: from the scene, or for an ad-hoc L by terms (terms with a velocity form T)."""

    T: sp.Expr
    V: sp.Expr


class Catalogue:
    """The mutations of one question, built on first use per part and kept when the part's test
    tells them apart, and the matching of an answer against them."""

    def __init__(self, problem: Question):
        self.problem = problem

    # --- the reference's parts -----------------------------------------------------------------
    @cached_property
    def split(self) -> Split:
        p = self.problem
        if p.variant is not None:
            return Split(p.variant.kinetic_energy, p.variant.potential_energy)
        L = sp.expand(p.system.L)
        T = sp.Add(*(x for x in expanded_terms(L) if velocities_in(x, p.jets)))
        return Split(T, sp.expand(T - L))

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
        out += [
            Mutant(m.kind, m.message, m.expr - V)
            for m in body_mutants(self.problem.variant, T, "your L")
        ]
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
        out += body_mutants(self.problem.variant, T, "your T")
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

    # --- momenta, equations of motion, conserved quantities, a reference expression ------------
    def momentum_mutants(self, k: int) -> list[Mutant]:
        cache = self.__dict__.setdefault("_momentum", {})
        if k not in cache:
            p = self.problem
            out = momentum_mutants(p.system, p.jets, k, self.lagrangian_mutants, self.parameters)
            reference = Compiled.of(p.system.generalized_momenta[k])
            cache[k] = self._distinct(out, "plain", reference)
        return cache[k]

    @cached_property
    def row_mutants(self) -> list[tuple[int, Mutant]]:
        """(row, mutant) pairs: row `row` of the EL equations replaced by the mutant."""
        p = self.problem
        pairs = equation_mutants(p.system, p.jets, self.lagrangian_mutants, self.parameters)
        return self._distinct_rows(pairs)

    @cached_property
    def conserved_mutants(self) -> list[Mutant]:
        p = self.problem
        return conserved_mutants(p.system, p.jets, self.split.T, self.split.V)

    @cached_property
    def expression_mutants(self) -> list[Mutant]:
        """The usual slips with a closed-form result: sin for cos, the sign, upside down."""
        return expression_mutants(self.problem.reference_expression.expr)

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
        stack = self._el_stack(points)
        return None if stack is None else first_lagrangian(stack, answer_el)

    def match_plain(
        self, mutants: Sequence[Mutant], answer: Compiled, points: Points
    ) -> Mutant | None:
        """The first mutant with the answer's values at the points."""
        with np.errstate(all="ignore"):
            values = full(answer.values(points.env), points.n)
        stack = self._value_stack(mutants, points)
        return None if stack is None else first_plain(stack, values)

    def match_offset(
        self, mutants: Sequence[Mutant], answer: Compiled, points: Points
    ) -> Mutant | None:
        """The first mutant the answer equals up to a constant per parameter group (V, a
        conserved quantity)."""
        with np.errstate(all="ignore"):
            values = full(answer.values(points.env), points.n)
        stack = self._value_stack(mutants, points)
        return None if stack is None else first_offset(stack, values, points)

    def match_row(self, student: Compiled, points: Points) -> Mutant | None:
        """The mutation whose mutated system has the student's equation in its span."""
        p = self.problem
        with np.errstate(all="ignore"):
            s = equation_rows([student], p.jets, points.env)
        stack = self._row_stack(points)
        if stack is None:
            return None
        found = first_row(stack, s)
        return None if found is None else found[1]

    def match(self, mutants: Sequence[Mutant], test: Callable[[Compiled], bool]) -> Mutant | None:
        """The first mutant the answer matches by `test(compiled mutant)` (a test that is not
        a fixed array operation, so one mutant at a time)."""
        for m in mutants:
            try:
                with np.errstate(all="ignore"):
                    if test(self._compiled(m)):
                        return m
            except SKIPPED:
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
    def _el_stack(self, points: Points) -> Stack | None:
        """The Lagrangian mutants' E, its size, and what c needs (`lagrangian_arrays`)."""
        return stacked(
            self.problem.cached,
            "el-stack",
            self.lagrangian_mutants,
            points,
            lambda m: self._el_values(self._compiled(m), points),
            lambda Eb, Sb: lagrangian_arrays(Eb, Sb, points.group),
        )

    def _value_stack(self, mutants: Sequence[Mutant], points: Points) -> Stack | None:
        """The mutants' values and sizes, (mutants, points)."""
        return stacked(
            self.problem.cached,
            "value-stack",
            mutants,
            points,
            lambda m: full(self._compiled(m).values(points.env), points.n),
            lambda b, sb: (b, sb),
        )

    def _row_stack(self, points: Points) -> Stack | None:
        """Per row mutant, the reference rows with its row in place of row i, at every point,
        reduced to what the span test needs (`span_arrays`)."""
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

        return stacked(p.cached, "row-stack", self.row_mutants, points, evaluate, span_arrays)

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

    # --- keeping the mutants the part's test tells apart ------------------------------------------
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


def _close(a: np.ndarray, b: np.ndarray) -> bool:
    scale = max(np.max(np.abs(a)), np.max(np.abs(b)), 1e-300)
    return a.shape == b.shape and float(np.max(np.abs(a - b))) <= 1e-9 * scale
