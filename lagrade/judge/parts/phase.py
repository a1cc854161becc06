"""What the parts on phase space share (`hamiltonian`, `hamilton_equations`): reading an answer
in a vocabulary where each momentum p_<q> and its rate are variables, and the question's sample
points carried to phase space.

A point of phase space is the image of a sample point (q, q̇, t) of velocity space under the
Legendre map p = ∂L/∂q̇: there the reference H is the energy function h(q, q̇, t), Hamilton's
equations hold with the rates q̇ (as drawn) and ṗ = ∂L/∂q (Lagrange's equation), so no inverse
of the mass matrix is ever formed to judge an answer. In high precision the momenta are computed
again from the 50-digit points, so that both sides meet the same phase-space point."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import partial
from typing import Any

import sympy as sp

from lagrade.errors import RequestError
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.parts.items import single_text
from lagrade.judge.parts.reading import ADDITIVE_CONSTANTS, Read, not_labelled, read, read_parsed
from lagrade.judge.problem import Problem, parser
from lagrade.judge.sampling import Points
from lagrade.mechanics import HamiltonianSystem, momentum_jet, phase_space

#: The sample points of the parts on phase space: those of `eom` (the mass matrix regular, so
#: the Legendre map is invertible there).
POINTS = "eom"


def phase_system(problem: Problem) -> HamiltonianSystem:
    """The question's H and Hamilton's equations (derived on first use)."""
    return phase_space(problem.system)


def momentum_symbols(problem: Problem) -> tuple[sp.Symbol, ...]:
    return tuple(momentum_jet(j.name).q for j in problem.jets)


def rate_symbols(problem: Problem) -> tuple[sp.Symbol, ...]:
    return tuple(momentum_jet(j.name).dot for j in problem.jets)


def vocabulary(problem: Problem, labels: Sequence[str] = ()):
    """The question's vocabulary with the momenta declared (one per set of labels)."""
    key = tuple(labels)
    cache = problem.__dict__.setdefault("_phase_vocabularies", {})
    if key not in cache:
        cache[key] = parser().Vocabulary(
            problem.coordinates,
            dict(problem.parameters),
            key,
            imaginary_unit=problem.imaginary_unit,
            momenta=True,
        )
    return cache[key]


def read_phase(
    problem: Problem, item: Any, labels: Sequence[str] = (), mode: str = "answer"
) -> Read:
    """One item read with the momenta declared; sympy objects (Python callers, tests) pass."""
    if isinstance(item, sp.Basic):
        return read(problem, item, labels, mode)
    if not isinstance(item, str):
        raise RequestError(f"an answer item must be a string, got {type(item).__name__}")
    p = parser()
    parse = {"answer": p.parse_answer, "equation": p.parse_equation}[mode]
    latex = getattr(item, "latex", None)
    return read_parsed(problem, parse(item, vocabulary(problem, labels), latex=latex))


def read_phase_single(problem: Problem, answer: Any, part: str, label: str) -> Read:
    """A one-expression answer on phase space, `label = …` (H = …) or `… = const` allowed."""
    text = single_text(answer, part)
    labels = [n for n in (label, *ADDITIVE_CONSTANTS) if n not in problem.by_name]
    got = read_phase(problem, text, labels)
    if not got.has_rhs:
        return got
    if got.label == label:
        return got.only_rhs()
    if got.rhs_label in ADDITIVE_CONSTANTS:
        return got.only_lhs()
    raise not_labelled(text)


def phase_env(problem: Problem, points: Points, backend=FLOAT) -> dict:
    """The sample points with the momenta p = ∂L/∂q̇ added (float64: computed once)."""
    if backend is FLOAT:
        return problem.cached("phase-env", points, partial(_phase_env, problem, points, FLOAT))
    return _phase_env(problem, points, backend)


def _phase_env(problem: Problem, points: Points, backend) -> dict:
    env = dict(points.arrays(backend))
    for symbol, p in zip(momentum_symbols(problem), problem.momenta, strict=True):
        env[symbol] = to_length(p.values(points.arrays(backend), backend)[0], points.n, backend)
    return env


def phase_points(problem: Problem, points: Points) -> Points:
    """The points with the momenta, as Points (a witness quotes p_θ)."""
    return problem.cached(
        "phase-points", points, lambda: Points(phase_env(problem, points), points.group)
    )


def velocity_symbols(problem: Problem, symbols) -> list[str]:
    """The velocities and accelerations of coordinates among `symbols`, by name."""
    motion = {j.dot: j.name for j in problem.jets} | {j.ddot: j.name for j in problem.jets}
    return sorted({s.name for s in symbols if s in motion})


def values_at(expr: Compiled, env: Mapping, n: int, backend=FLOAT):
    value, size = expr.values(env, backend)
    return to_length(value, n, backend), to_length(size, n, backend)
