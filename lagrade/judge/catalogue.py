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

The Lagrangian and equation mistakes are matched as fingerprints (`fingerprints`,
`row_fingerprints`): their values are arrays made once per question from the values of a few
pieces, and the symbolic mutant (its sentence) is built only for the one that matched; the lazy
lists of symbolic mutants (`lagrangian`, `rows`) list the same mistakes, for the other parts
that derive theirs from them (momenta, equations) and for the tests that hold the two to the
same names.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from itertools import chain, islice
from typing import Protocol, TypeVar, Union

import numpy as np
import sympy as sp

import lagrade.judge.keepers as keepers
from lagrade.judge.clocks import Budget, set_aside
from lagrade.judge.compiled import Compiled
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.fingerprints import LagrangianFingerprints
from lagrade.judge.lazylist import LazyList
from lagrade.judge.matching import (
    SKIPPED,
    Stack,
    first_offset,
    first_plain,
    full,
    stacked,
    vanish_rows,
)
from lagrade.judge.momentum_fingerprints import MomentumFingerprints
from lagrade.judge.mutant_values import MutantValues
from lagrade.judge.mutations import (
    Mutant,
    body_mutants,
    conserved_mutants,
    expanded_terms,
    expression_mutants,
    inertia_mutants,
    iter_term_mutants,
    kinetic_mutants,
    swap_sin_cos,
    terms_changed,
    velocities_in,
)
from lagrade.judge.row_fingerprints import RowFingerprints
from lagrade.judge.rows import Rows, equation_rows, span_basis
from lagrade.judge.sampling import Points
from lagrade.mechanics import Jet, LagrangianSystem, SceneVariant, t

_T = TypeVar("_T")

#: What a part's matching reads: a lazily built catalogue list, or a plain list of mutants.
Mutants = Union[LazyList[Mutant], Sequence[Mutant]]  # noqa: UP007 - a runtime alias


class Question(Protocol):
    """What the catalogue uses of its question (a `lagrade.judge.problem.Problem`)."""

    jets: tuple[Jet, ...]
    parameters: dict[str, sp.Symbol]
    variant: SceneVariant | None
    budget: Budget

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

    def peek(self, name: str, points: Points) -> object | None: ...

    def reference_rows(self, points: Points) -> Rows: ...


@dataclass(frozen=True)
class Split:
    """L = T − V: from the scene, or for an ad-hoc L by terms (terms with a velocity form T)."""

    T: sp.Expr
    V: sp.Expr


#: Points where a nonzero answer's values are not zero that a diagnosis needs.
MIN_EVIDENCE = 3


def underflowed(answer: Compiled, values: tuple[np.ndarray, np.ndarray]) -> bool:
    """A nonzero answer whose values are 0 at (nearly) every point — (x − b)^5001 at
    |x − b| < 0.86 underflows — matches any mutant that underflows too: no evidence, so no
    mistake is named (when unsure, say less, never something false)."""
    size = values[1]  # the values first: the answer's sympy form is built only when they say so
    return np.count_nonzero(size > 0) < min(MIN_EVIDENCE, size.size) and answer.expr != 0


class Catalogue(MutantValues):
    """The mutations of one question, built on demand per part — only when a wrong answer needs a
    diagnosis, and then only as far as the first mutant that matches (`LazyList`) — and kept
    when the part's test tells them apart; and the matching of an answer against them.

    Building is the question's work, not the student's: it runs `set_aside` from the part's
    clock, charged to the question's preparation budget (`Question.budget`)."""

    def __init__(self, problem: Question):
        self.problem = problem

    # --- the reference's parts -----------------------------------------------------------------
    @cached_property
    def split(self) -> Split:
        p = self.problem
        if p.variant is not None and not p.variant.scene.given_by_lagrangian:
            return Split(p.variant.kinetic_energy, p.variant.potential_energy)
        L = sp.expand(p.system.L)
        T = sp.Add(*(x for x in expanded_terms(L) if velocities_in(x, p.jets)))
        return Split(T, sp.expand(T - L))

    @cached_property
    def _split_lagrangian(self) -> tuple[sp.Expr, set]:
        """T − V as the mutants are made from it, and the symbols of motion (a constant, free
        of them, changes no motion)."""
        moving = {x for j in self.problem.jets for x in (j.q, j.dot)}
        return self.split.T - self.split.V, moving | {t}

    @property
    def parameters(self) -> list[sp.Symbol]:
        return list(self.problem.parameters.values())

    # --- Lagrangian ------------------------------------------------------------------------------
    @cached_property
    def _lagrangian_early(self) -> list[Mutant]:
        """The Lagrangian mutants of the whole-L and kinetic kinds, in catalogue order: every
        mistake a momentum or an equation of motion inherits from L is among them."""
        T, V = self.split.T, self.split.V
        out = [
            Mutant("sign_of_V", "your L adds V instead of subtracting it (L = T − V)", T + V),
            Mutant("dropped_half_all", "the ½ is missing in the kinetic energy", 2 * T - V),
        ]
        out += [
            Mutant(m.kind, m.said, m.expr - V)
            for m in body_mutants(self.problem.variant, T, "your L")
        ]
        out += [
            Mutant(m.kind, m.said, m.expr - V)
            for m in kinetic_mutants(T, self.problem.jets, "your L")
        ]
        return out

    def _lagrangian_late(self) -> Iterator[Mutant]:
        """The later Lagrangian mutants, each built once for every reader (the lazy list and
        the fingerprints' sentence of a match read the same objects)."""
        built = self.__dict__.setdefault("_late_built", [])
        k = 0
        while True:
            if k == len(built):
                source = self.__dict__.get("_late_source")
                if source is None:  # fresh, or interrupted mid-item: start past what is built
                    source = islice(self._late_items(), len(built), None)
                    self.__dict__["_late_source"] = source
                try:
                    item = next(source, None)
                except BaseException:
                    self.__dict__["_late_source"] = None
                    raise
                if item is None:
                    return
                built.append(item)
            yield built[k]
            k += 1

    def _late_items(self) -> Iterator[Mutant]:
        T, V = self.split.T, self.split.V
        yield Mutant("sin_cos_swapped", "sin and cos are swapped in your L", swap_sin_cos(T - V))
        yield from iter_term_mutants(T - V, "your L", self.parameters)

    @cached_property
    def lagrangian(self) -> LazyList[Mutant]:
        """The Lagrangian mutants, built on demand."""

        def make():
            source = chain(self._lagrangian_early, self._lagrangian_late())
            return source, self._keeper("el", lambda: self.problem.L)

        return LazyList(make)

    @property
    def lagrangian_mutants(self) -> list[Mutant]:
        return self.lagrangian.all()

    # --- T and V ----------------------------------------------------------------------------------
    @cached_property
    def kinetic(self) -> LazyList[Mutant]:
        def make():
            T = self.split.T

            def source():
                yield Mutant("dropped_half_all", "the ½ is missing in your T", 2 * T)
                yield from body_mutants(self.problem.variant, T, "your T")
                yield from kinetic_mutants(T, self.problem.jets, "your T")
                yield from inertia_mutants(self.problem.variant, T, "your T")
                yield Mutant(
                    "sin_cos_swapped", "sin and cos are swapped in your T", swap_sin_cos(T)
                )
                yield from iter_term_mutants(T, "your T", self.parameters)

            return source(), self._keeper("plain", lambda: Compiled.of(T))

        return LazyList(make)

    @property
    def kinetic_mutants(self) -> list[Mutant]:
        return self.kinetic.all()

    @cached_property
    def potential(self) -> LazyList[Mutant]:
        def make():
            V = self.split.V

            def source():
                yield Mutant(
                    "sign_of_V", "your V has the wrong sign (height measured downwards?)", -V
                )
                yield Mutant(
                    "sin_cos_swapped", "sin and cos are swapped in your V", swap_sin_cos(V)
                )
                yield from iter_term_mutants(V, "your V", self.parameters)

            return source(), self._keeper("offset", lambda: Compiled.of(V))

        return LazyList(make)

    @property
    def potential_mutants(self) -> list[Mutant]:
        return self.potential.all()

    # --- momenta, equations of motion, conserved quantities, a reference expression ------------
    def momentum(self, k: int) -> LazyList[Mutant]:
        """The mutants of p_k, built on demand (the mistakes of `momentum_fingerprints`, kept
        one at a time by the symbolic keeper)."""
        cache = self.__dict__.setdefault("_momentum", {})
        if k not in cache:
            p = self.problem

            def make():
                table = self.momentum_fingerprints(k)
                source = (table.mutant(m) for m in range(len(table.specs)))
                keep = self._keeper("plain", lambda: Compiled.of(p.system.generalized_momenta[k]))
                return source, keep

            cache[k] = LazyList(make)
        return cache[k]

    def momentum_fingerprints(self, k: int) -> MomentumFingerprints:
        """The mistakes of p_k as arrays (`momentum_fingerprints`): what `match_momentum` reads."""
        cache = self.__dict__.setdefault("_momentum_tables", {})
        if k not in cache:
            with set_aside(self.problem.budget):
                table = MomentumFingerprints(self, k)
                _ = table.kept
            cache[k] = table
        return cache[k]

    def match_momentum(
        self,
        k: int,
        answer: Compiled,
        points: Points,
        others: Mapping[int, Compiled] | None = None,
    ) -> Mutant | None:
        """The first mistake of p_k with the answer's values at the points (`match_plain` on
        the fingerprints) whose sentence is true of the whole answer. A mistake of L that
        the sentence names as L's ("the ½ is missing in the kinetic energy") implies a
        correction of every momentum: it is said only when each other momentum the student
        gave (`others`, by coordinate; None for p_k asked about alone) is that L's too, so
        that the correction makes them all right; else the next mistake that matches, one of
        p_k alone, is named."""
        with np.errstate(all="ignore"):
            values = full(answer.values(points.env), points.n)
        if underflowed(answer, values):
            return None
        table = self.momentum_fingerprints(k)
        return table.match(values, points, lambda m: self._whole_claim_holds(k, m, others))

    def _whole_claim_holds(self, k: int, m: int, others: Mapping[int, Compiled] | None) -> bool:
        """Mistake m of p_k, if a mistake of L said of L, is the mistake of every momentum."""
        table = self.momentum_fingerprints(k)
        j = table.lagrangian_source(m)
        if j is None or f"p_{self.problem.jets[k].name}" in table.mutant(m).message:
            return True  # a sentence about p_k alone, true by p_k's values
        if others is None:  # p_k asked about alone (no answer around it): its values decide
            return True
        n = len(self.problem.jets)
        if set(others) != set(range(n)) - {k}:
            return False  # a momentum missing or unread: the correction cannot be checked
        points = table.points
        for i, other in others.items():
            expected = self.momentum_fingerprints(i).of_lagrangian(j)
            if expected is None:
                return False
            with np.errstate(all="ignore"):
                a, sa = full(other.values(points.env), points.n)
                if not vanish_rows((a - expected[0])[None], (sa + expected[1])[None])[0]:
                    return False
        return True

    def momentum_mutants(self, k: int) -> list[Mutant]:
        return self.momentum(k).all()

    @cached_property
    def rows(self) -> LazyList[tuple[int, Mutant]]:
        """(row, mutant) pairs, built on demand: row `row` of the EL equations replaced by the
        mutant (the mistakes of `row_fingerprints`, kept one at a time by `row_keeper`)."""

        def make():
            table = self.row_fingerprints
            source = (table.mutant(m) for m in range(len(table.specs)))
            return source, self._row_keeper()

        return LazyList(make)

    @cached_property
    def row_fingerprints(self) -> RowFingerprints:
        """The equation mistakes as arrays (`row_fingerprints`): what `match_row` reads."""
        with set_aside(self.problem.budget):
            return RowFingerprints(self)

    @property
    def row_mutants(self) -> list[tuple[int, Mutant]]:
        return self.rows.all()

    @cached_property
    def conserved_mutants(self) -> list[Mutant]:
        p = self.problem
        with set_aside(p.budget):
            return conserved_mutants(p.system, p.jets, self.split.T, self.split.V)

    @cached_property
    def expression_mutants(self) -> list[Mutant]:
        """The usual slips with a closed-form result: sin for cos, the sign, upside down."""
        return expression_mutants(self.problem.reference_expression.expr)

    # --- matching ---------------------------------------------------------------------------------
    # A wrong answer is tested against the mutants of its part a chunk at a time: the mutants'
    # values at the points are stacked once per chunk and set of points, and a few array
    # operations per answer find the first mutant that matches (the catalogue's order puts the
    # most specific first). Later chunks are built only when the earlier ones have no match.
    # The tests are those of the one-at-a-time loop.

    def match_lagrangian(
        self,
        answer: Compiled,
        points: Points,
        answer_el: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> Mutant | None:
        """The mistake that explains the answer: a mutant with E(answer) = c E(mutant), c ≠ 0
        per parameter group, whose fix, applied to the answer as written, gives a right L
        (`lagrangian_fix_is_right`); of several, the one that changes the fewest terms (float64
        only: a diagnosis names a mistake, the verdict is decided elsewhere). `answer_el`:
        E(answer) and its size at the points, when the verdict has computed them already."""
        if answer_el is None:
            answer_el = euler_lagrange_values(answer, self.problem.jets, points.env)
        reference_el = self.el_values(self.problem.L, points)
        L, moving = self._split_lagrangian
        counted = self.__dict__.setdefault("_changes", {})  # a mutant's count, once

        def changes(m: Mutant) -> int:
            key = ("el-stack", id(m))
            if key not in counted:
                counted[key] = terms_changed(m, L, lambda term: bool(term.free_symbols & moving))
            return counted[key]

        with set_aside(self.problem.budget):
            table = self.lagrangian_fingerprints
            table.values(points)
            _ = table.kept
        return table.match(answer_el, reference_el, points, changes)

    @cached_property
    def lagrangian_fingerprints(self) -> LagrangianFingerprints:
        """The Lagrangian mistakes as arrays (`fingerprints`): what `match_lagrangian` reads."""
        return LagrangianFingerprints(self)

    def match_plain(self, mutants: Mutants, answer: Compiled, points: Points) -> Mutant | None:
        """The first mutant with the answer's values at the points."""
        with np.errstate(all="ignore"):
            values = full(answer.values(points.env), points.n)
        if underflowed(answer, values):
            return None
        return self._first(
            mutants,
            "value-stack",
            points,
            lambda chunk: self._value_stack(chunk, points),
            lambda stack: first_plain(stack, values),
        )

    def match_offset(self, mutants: Mutants, answer: Compiled, points: Points) -> Mutant | None:
        """The first mutant the answer equals up to a constant per parameter group (V, a
        conserved quantity)."""
        with np.errstate(all="ignore"):
            values = full(answer.values(points.env), points.n)
        if underflowed(answer, values):
            return None
        return self._first(
            mutants,
            "value-stack",
            points,
            lambda chunk: self._value_stack(chunk, points),
            lambda stack: first_offset(stack, values, points),
        )

    def match_row(self, student: Compiled, points: Points) -> Mutant | None:
        """The mistake that explains the student's equation: a mutation whose mutated system
        has the equation in its span, for the row the mistake is in, and whose fix, applied to
        the equation as the student wrote it, gives a right equation (`row_fix_is_right`); of
        several, the one that changes the fewest terms of what the student wrote."""
        p = self.problem
        with np.errstate(all="ignore"):
            s = equation_rows([student], p.jets, points.env)
        reference = p.reference_rows(points)
        basis = p.cached("row-basis", points, lambda: span_basis(reference))
        E = p.system.euler_lagrange
        counted = self.__dict__.setdefault("_changes", {})

        def changes(i: int, m: Mutant) -> int:
            key = ("row-stack", id(m))
            if key not in counted:
                counted[key] = terms_changed(m, E[i])
            return counted[key]

        table = self.row_fingerprints
        assert points is table.points, "equation mistakes are matched at the eom part's points"
        with set_aside(p.budget):
            _ = table.kept
        return table.match(s, reference, basis, changes)

    def match(self, mutants: Sequence[Mutant], test: Callable[[Compiled], bool]) -> Mutant | None:
        """The first mutant the answer matches by `test(compiled mutant)` (a test that is not
        a fixed array operation, so one mutant at a time)."""
        for m in mutants:
            try:
                with np.errstate(all="ignore"):
                    if test(self.compiled(m)):
                        return m
            except SKIPPED:
                continue
        return None

    def _first(
        self, mutants: Mutants, name: str, points: Points, stack_of: Callable, test: Callable
    ):
        """The first candidate `test` finds in the stacks of `mutants`, chunk by chunk. Building
        a chunk and its stack is the question's work (set aside from the part's clock); a chunk
        whose stack at `points` (`name`) is built already is read without the clock switch."""
        budget = self.problem.budget
        if not isinstance(mutants, LazyList):
            if self._ready(name, mutants, points):
                stack = stack_of(mutants)
            else:
                with set_aside(budget):
                    stack = stack_of(mutants)
            return None if stack is None else test(stack)
        k = 0
        while True:
            chunk = mutants.built(k)
            if chunk is not None and self._ready(name, chunk, points):
                stack = stack_of(chunk)
            else:
                with set_aside(budget):
                    chunk = mutants.chunk(k)
                    stack = None if chunk is None else stack_of(chunk)
            if chunk is None:
                return None
            if stack is not None:
                found = test(stack)
                if found is not None:
                    return found
            k += 1

    def _ready(self, name: str, candidates: Sequence, points: Points) -> bool:
        """The stack `name` of `candidates` at `points` is built (reading it does no work)."""
        stack = self.problem.peek(f"{name}:{id(candidates)}", points)
        return stack is not None and stack.of(candidates)

    def warm(self, part: str, points: Points) -> None:
        """Build every mutant `part`'s matching uses and their stacks at `points`, so that a
        process forked afterwards (`lagrade grade` warms its parent) shares them."""
        p = self.problem
        if part in ("lagrangian", "eom", "momenta"):  # matched by fingerprints: their arrays
            with set_aside(p.budget):
                if part == "lagrangian":
                    self.lagrangian_fingerprints.values(points)
                    _ = self.lagrangian_fingerprints.kept
                elif part == "eom":
                    _ = self.row_fingerprints.kept
                else:
                    for k in range(len(p.jets)):
                        self.momentum_fingerprints(k)
            return
        which: dict[str, Callable[[], list]] = {
            "T": lambda: [(self.kinetic, self._value_stack)],
            "V": lambda: [(self.potential, self._value_stack)],
            "conserved": lambda: [(self.conserved_mutants, self._value_stack)],
            "expression": lambda: [(self.expression_mutants, self._value_stack)],
        }
        if part not in which:
            return
        with set_aside(p.budget):
            for mutants, stack_of in which[part]():
                if isinstance(mutants, LazyList):
                    mutants.all()
                    for chunk in mutants.chunks():
                        stack_of(chunk, points)
                else:
                    stack_of(mutants, points)

    # --- stacks of mutant values, per set of points ----------------------------------------------
    def _value_stack(self, mutants: Sequence[Mutant], points: Points) -> Stack | None:
        """The mutants' values and sizes, (mutants, points)."""
        return stacked(
            self.problem.cached,
            "value-stack",
            mutants,
            points,
            lambda m: self.values(self.compiled(m), points),
            lambda b, sb: (b, sb),
        )

    def _keeper(self, mode: str, reference_of: Callable[[], Compiled]) -> Callable[[Mutant], bool]:
        return keepers.keeper(self, mode, reference_of)

    def _row_keeper(self) -> Callable[[tuple[int, Mutant]], bool]:
        return keepers.row_keeper(self)
