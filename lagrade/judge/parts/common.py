"""Building blocks the part checkers share: which parameters are sampled, where an answer
differs, the method that decided, and the verdict of a wrong single expression."""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import Outcome
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.mutations import Mutant
from lagrade.judge.parts.reading import Read
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points
from lagrade.judge.situation import situation
from lagrade.judge.verdict import Verdict


def free_parameters(problem: Problem, *exprs: sp.Expr) -> frozenset[sp.Symbol]:
    """The parameters sampled over their domains: all of them, except one the answer leaves out
    while writing its handout value as a number (`m 9.81 q` for m g q): that one keeps the
    value. A parameter that is merely missing is never pinned — with SI values (e = 1.6e-19 C)
    a dropped term would be 1e-19 of the rest and slip through any tolerance."""
    if not problem.values:  # no handout numbers: nothing can be pinned
        return frozenset(problem.domains)
    syms = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    numbers = [abs(float(n)) for e in exprs for n in e.atoms(sp.Number) if n != 0]
    pinned = {
        s
        for s, value in problem.values.items()
        if s not in syms
        and value
        and any(abs(n - abs(value)) <= 1e-3 * abs(value) for n in numbers)
    }
    return frozenset(s for s in problem.domains if s not in pinned)


def witness_point(
    points: Points, outcome: Outcome, *exprs: sp.Expr | Compiled
) -> dict[str, float] | None:
    """The point where the answers differ, in the symbols of `exprs` (all, without them)."""
    if outcome.where is None:
        return None
    syms = (
        set().union(*(e.symbols if isinstance(e, Compiled) else e.free_symbols for e in exprs))
        if exprs
        else None
    )
    return points.point(outcome.where, syms)


def where_text(witness: Mapping[str, float] | None, problem: Problem | None = None) -> str:
    """Where a wrong answer shows, as a situation: " (for example at θ = 0.3 rad with the
    system at rest)" (see `lagrade.judge.situation`); nothing without a point."""
    if not witness:
        return ""
    return f" (for example {situation(witness, problem)})"


def method_name(*outcomes: Outcome) -> str:
    return "numeric+mpmath50" if any(o.method.endswith("mpmath50") for o in outcomes) else "numeric"


def ratio_text(c: float) -> str:
    f = Fraction(c).limit_denominator(1000)
    return str(f) if abs(float(f) - c) <= 1e-9 * max(1, abs(c)) else f"{c:.6g}"


def reference_el(problem: Problem, points: Points):
    ref = problem.L
    cached = problem.cached(
        "el", points, lambda: euler_lagrange_values(ref, problem.jets, points.env)
    )

    def values(backend):
        if backend is FLOAT:
            return cached
        return euler_lagrange_values(ref, problem.jets, points.arrays(backend), backend)

    return values


def as_sentence(text: str) -> str:
    if text.split(" ", 1)[0] in ("your", "the", "sin"):
        text = text[0].upper() + text[1:]
    return text if text.endswith(".") else text + "."


def incorrect(
    part: str,
    got: Read,
    mutant: Mutant | None,
    sentence: str,
    witness: Mapping[str, float] | None,
    method: str,
    problem: Problem | None = None,
) -> Verdict:
    """A wrong single-expression answer: the named mistake (when the catalogue knows it),
    then what is wrong, with a point where it shows."""
    feedback = [as_sentence(mutant.message)] if mutant is not None else []
    feedback.append(sentence + where_text(witness, problem) + ".")
    mistakes = (mutant.kind,) if mutant is not None else ()
    return Verdict(
        part,
        "incorrect",
        0.0,
        tuple(feedback),
        got.echo,
        method,
        witness=witness,
        mistakes=mistakes,
    )
