"""The values of a question's mutants at its sample points, each part computed once: a mutant of a
few changed terms is its reference plus the scaled changes (`Combination`), so its values, rows
and Euler–Lagrange values are combinations of its parts' — and a part (the reference, one of its
terms) is shared by many mutants. The mistake catalogue (`catalogue.Catalogue`) and its keepers
read mutants through these."""

from __future__ import annotations

from typing import Any

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Combination, Compiled, weighted
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.matching import full
from lagrade.judge.mutations import Mutant
from lagrade.judge.rows import Rows, equation_rows
from lagrade.judge.sampling import Points


class MutantValues:
    """Compiled mutants and their values at points, cached per question (`problem.cached`)
    and per catalogue (the compiled parts)."""

    problem: Any  # the question (`catalogue.Question`)

    def compiled(self, m: Mutant) -> Compiled | Combination:
        """The mutant compiled: a mutant of a few changed terms as its reference plus the scaled
        changes, each part compiled once for the whole catalogue (`Combination`)."""
        cache = self.__dict__.setdefault("_compiled_cache", {})
        if id(m) not in cache:
            if m.pieces:
                parts = ((sp.Integer(1), m.base), *m.pieces)
                compiled = Combination(tuple((c, self._part(e)) for c, e in parts))
            else:
                compiled = Compiled.of(m.expr)
            cache[id(m)] = (m, compiled)
        return cache[id(m)][1]

    def _part(self, expr: sp.Expr) -> Compiled:
        """expr compiled once per catalogue (a reference and its terms are parts of many
        mutants)."""
        parts = self.__dict__.setdefault("_parts", {})
        if expr not in parts:
            parts[expr] = Compiled.of(expr)
        return parts[expr]

    def values(self, mut: Compiled | Combination, points: Points):
        """The mutant's values and sizes at `points`, (points,) each; a Combination's from its
        parts' values, each computed once per set of points."""
        if isinstance(mut, Combination):
            return mut.combine([self._part_values(part, points) for _, part in mut.parts])
        with np.errstate(all="ignore"):
            return full(mut.values(points.env), points.n)

    def _part_values(self, part: Compiled, points: Points):
        with np.errstate(all="ignore"):
            return self.problem.cached(
                f"values:{id(part)}", points, lambda: full(part.values(points.env), points.n)
            )

    def mutant_rows(self, m: Mutant, points: Points) -> Rows:
        """A row mutant's row at `points`, computed once: the keeper's fingerprint and the row
        stack read the same values. A Combination's rows are its parts' rows combined (rows
        are linear in the equation), each part's computed once per set of points."""
        p = self.problem
        mut = self.compiled(m)

        def make() -> Rows:
            if not isinstance(mut, Combination):
                return equation_rows([mut], p.jets, points.env)
            rows = [self._part_rows(part, points) for _, part in mut.parts]
            coef, size = mut.combine([(r.coef, r.size) for r in rows])
            return Rows(coef, size, weighted(mut.weights, [r.nonlinear for r in rows]))

        with np.errstate(all="ignore"):
            return p.cached(f"row:{id(m)}", points, make)

    def _part_rows(self, part: Compiled, points: Points) -> Rows:
        p = self.problem
        return p.cached(
            f"rows:{id(part)}", points, lambda: equation_rows([part], p.jets, points.env)
        )

    def el_values(self, mut: Compiled | Combination, points: Points):
        """E(mut) and its size at `points`; a Combination's from its parts' (E is linear)."""
        if isinstance(mut, Combination):
            return mut.combine([self.el_values(part, points) for _, part in mut.parts])
        return self.problem.cached(
            f"el:{id(mut)}",
            points,
            lambda: euler_lagrange_values(mut, self.problem.jets, points.env),
        )
