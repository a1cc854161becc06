"""Formulas of an answer key as an instructor would write them: collected by the monomials of
the velocities and accelerations, each coefficient factored — ½(m₁ + m₂)Ẋ², not
Ẋ²m₁/2 + Ẋ²m₂/2, and m₁m₂ρ̇²/(2(m₁ + m₂)), not the expanded square in the denominator. For
display only: what the grader checks and the key's typed answers are not touched."""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp


def tidy(expr: sp.Expr, motion: Iterable[sp.Symbol]) -> sp.Expr:
    """`expr` collected in the `motion` symbols (q̇, q̈), each coefficient factored; the
    expression unchanged when it is not a polynomial in them."""
    motion = [s for s in motion if expr.has(s)]
    expanded = sp.expand(expr)
    if not motion:
        return sp.factor(expanded) if expanded.is_Add and len(expanded.args) <= 12 else expr
    groups = sp.collect(expanded, motion, evaluate=False)
    if any(k != 1 and not k.free_symbols <= set(motion) for k in groups):
        return expr
    return sp.Add(*(_factored(c) * k for k, c in groups.items()))


def _factored(coefficient: sp.Expr) -> sp.Expr:
    """A coefficient factored (over a common denominator), or as it was when that is longer."""
    factored = sp.factor(sp.together(coefficient))
    return factored if sp.count_ops(factored) <= sp.count_ops(coefficient) else coefficient
