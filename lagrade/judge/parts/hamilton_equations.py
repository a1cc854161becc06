"""The `hamilton_equations` part: q̇_j = ∂H/∂p_j and ṗ_j = −∂H/∂q_j, one equation per line,
judged as a system like `eom` (any row operations, solved forms, multiplied through).

The unknowns are the 2n rates (q̇, ṗ): each line must be linear in them (`rows.equation_rows`
with the rates in the place of the accelerations), and at each phase-space point (`phase`) the
reference system is the identity on the rates with right sides q̇ (as drawn) and ṗ = ∂L/∂q
(Lagrange's equation), so a line lies in the span of the reference rows exactly when it holds
with the reference rates put in. The set is complete when its rows have rank 2n.

Named mistakes: a sign slip in ṗ = −∂H/∂q (or in q̇ = ∂H/∂p), q̇ = p where q̇ = p/m (the mass
not divided out), a second-order equation (an Euler–Lagrange equation, with accelerations), a
line that says nothing."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import decide
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.parts.common import (
    equations_needed,
    method_name,
    too_few_independent,
    where_text,
    witness_point,
)
from lagrade.judge.parts.items import list_items
from lagrade.judge.parts.phase import (
    POINTS,
    momentum_symbols,
    phase_env,
    phase_points,
    phase_system,
    rate_symbols,
    read_phase,
    values_at,
)
from lagrade.judge.parts.reading import Lines, Read, read_lines
from lagrade.judge.problem import Problem
from lagrade.judge.rows import equation_rows, row_rank
from lagrade.judge.sampling import Points
from lagrade.judge.situation import symbol_text
from lagrade.judge.tolerances import ROUNDING, SAME_VALUE
from lagrade.judge.verdict import Verdict, invalid
from lagrade.mechanics import Jet, NotQuadratic
from lagrade.notation import plain

PART = "hamilton_equations"


def rate_jets(problem: Problem) -> tuple[Jet, ...]:
    """The 2n unknowns as jets whose `ddot` is the rate (q̇_j, then ṗ_j): what `rows` treats as
    the accelerations of a Lagrangian system."""
    coordinates = [Jet(j.name, j.q, j.dot, j.dot) for j in problem.jets]
    momenta = [
        Jet(p.name, p, r, r)
        for p, r in zip(momentum_symbols(problem), rate_symbols(problem), strict=True)
    ]
    return (*coordinates, *momenta)


def _rates_env(problem: Problem, points: Points, backend=FLOAT) -> dict:
    """The phase-space points with drawn rates: q̇ as sampled, ṗ drawn like an acceleration
    (for the test of linearity only; the reference rates come from `_reference_rates`)."""
    env = dict(phase_env(problem, points, backend))
    for j, r in zip(problem.jets, rate_symbols(problem), strict=True):
        env[r] = points.arrays(backend)[j.ddot]
    return env


def _reference_rates(problem: Problem, points: Points, backend=FLOAT) -> dict:
    """The rates of the motion at each point: q̇ (the point's own) and ṗ_j = ∂L/∂q_j."""
    env = dict(phase_env(problem, points, backend))
    for k, (j, r) in enumerate(zip(problem.jets, rate_symbols(problem), strict=True)):
        force = problem.compiled_reference(
            f"F{k}", lambda k=k: problem.system.generalized_forces[k]
        )
        env[r] = values_at(force, points.arrays(backend), points.n, backend)[0]
        env[j.dot] = points.arrays(backend)[j.dot]
    return env


def read_hamilton_equations(problem: Problem, answer: Any) -> Lines:
    """Hamilton's equations, one per item, in the coordinates, momenta and their rates."""
    return read_lines(
        list_items(answer, PART), lambda item: read_phase(problem, item, (), "equation")
    )


def check_hamilton_equations(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    lines = read_hamilton_equations(problem, answer)
    if not lines.reads:
        return invalid(PART, "Give Hamilton's equations, one per line.")
    reads = lines.reads
    entry = [k for k, e in enumerate(lines.entries) if isinstance(e, Read)]
    total = len(lines.entries)
    n2 = 2 * len(problem.jets)
    points = problem.points(POINTS)
    jets = rate_jets(problem)
    feedback, mistakes, outcomes = lines.feedback(), [], []
    right: list[int] = []
    wrong = 0
    witness = None
    with np.errstate(all="ignore"):
        rows = equation_rows([r.compiled for r in reads], jets, _rates_env(problem, points))
    for k, got in enumerate(reads):
        label = f"Equation {entry[k] + 1} ({got.echo})" if total > 1 else "Your equation"
        if any(j.ddot in got.symbols for j in problem.jets):
            feedback.append(
                f"{label} holds an acceleration: Hamilton's equations are first order, in the "
                "rates of the coordinates and the momenta."
            )
            mistakes.append("second_order")
            wrong += 1
            continue
        if not _linear(rows, k):
            feedback.append(
                f"{label} is not linear in the rates, so it is not one of Hamilton's equations."
            )
            wrong += 1
            continue
        coef = rows.coef[:, k, :n2].astype(float)
        if np.all(
            np.abs(coef) <= ROUNDING * np.maximum(rows.size[:, k].astype(float), 1e-300)[:, None]
        ):
            feedback.append(
                f"{label} holds no rate (q̇ or ṗ); it is not one of Hamilton's equations."
            )
            mistakes.append("no_rate")
            wrong += 1
            continue
        out = decide(lambda b, c=got.compiled: _holds(problem, c, points, b))
        outcomes.append(out)
        if out.equal:
            right.append(k)
            continue
        wrong += 1
        ans = got.compiled
        witness = witness or witness_point(phase_points(problem, points), out, ans)
        kind = _sign_slip(problem, ans, points)
        mass = "" if kind else _mass_kept(problem, ans, points)
        if kind:
            feedback.append(f"{label}: {_SIGN[kind]}")
            mistakes.append(kind)
        elif mass:
            feedback.append(f"{label} {mass}")
            mistakes.append("mass_not_divided")
        else:
            feedback.append(
                f"{label} does not follow from H"
                + where_text(witness_point(phase_points(problem, points), out, ans), problem)
                + "."
            )
    rank = row_rank(rows.coef[:, :, : n2 + 1].astype(float), right) if right else 0
    if not wrong and not lines.unreadable and rank == n2:
        notes = (
            (f"You gave {len(reads)} equations; {n2} of them are independent.",)
            if len(reads) > n2
            else ()
        )
        return Verdict(PART, "correct", 1.0, notes, lines.echoes, method_name(*outcomes))
    if not wrong and not lines.unreadable:
        n = len(problem.jets)
        feedback.append(too_few_independent(rank, n2, n, len(reads), " (q̇ and ṗ for each)"))
        mistakes.append("too_few_equations")
        score = rank / n2
    else:
        score = len(right) / max(total, n2)
        if total < n2 and not wrong:
            each = " (q̇ and ṗ for each)"
            feedback.append(f"{equations_needed(len(problem.jets), n2, each)}.")
    return Verdict(
        PART,
        "incorrect",
        float(min(score, 1.0)),
        tuple(feedback),
        lines.echoes,
        method_name(*outcomes),
        witness=witness,
        mistakes=tuple(mistakes),
    )


def _linear(rows, k: int) -> bool:
    nonlinear = np.abs(rows.nonlinear[:, k].astype(float))
    return bool(np.all(nonlinear <= SAME_VALUE * np.maximum(rows.size[:, k].astype(float), 1e-300)))


def _holds(problem: Problem, equation: Compiled, points: Points, backend):
    """The line with the reference rates put in (zero when it is in the reference's span)."""
    env = _reference_rates(problem, points, backend)
    return values_at(equation, env, points.n, backend)


_SIGN = {
    "sign_p_dot": "the sign of ṗ is wrong: ṗ_j = −∂H/∂q_j.",
    "sign_q_dot": "the sign of q̇ is wrong: q̇_j = +∂H/∂p_j.",
}


def _sign_slip(problem: Problem, answer: Compiled, points: Points) -> str:
    """Which rate, negated in the reference motion, makes the line hold: the sign slip named."""
    try:
        with np.errstate(all="ignore"):
            env = _reference_rates(problem, points)
            for kind, symbols in (
                ("sign_p_dot", rate_symbols(problem)),
                ("sign_q_dot", [j.dot for j in problem.jets]),
            ):
                flipped = env | {s: -env[s] for s in symbols}
                value, size = values_at(answer, flipped, points.n)
                changed = values_at(answer, env, points.n)[0]
                if np.all(
                    np.abs(value) <= SAME_VALUE * np.maximum(size, 1e-300)
                ) and not np.allclose(changed, value):
                    return kind
    except (UnsupportedExpression, ValueError):
        pass
    return ""


def _mass_kept(problem: Problem, answer: Compiled, points: Points) -> str:
    """The sentence of q̇ = p for q̇ = p/m: the line holds, in the reference motion, with q̇_k
    A_kk times what it is (A the mass matrix: the mass, m l², … of q_k) and not as it is; or
    "" when no coordinate's line is that."""
    try:
        hs = phase_system(problem)
        with np.errstate(all="ignore"):
            env = _reference_rates(problem, points)
            held = values_at(answer, env, points.n)[0]
            for k, j in enumerate(problem.jets):
                A_kk = hs.velocity_matrix[k, k]
                if A_kk == 1:
                    continue
                mass = problem.compiled_reference(f"A{k}{k}", lambda e=A_kk: e)
                scaled = env | {j.dot: values_at(mass, env, points.n)[0] * env[j.dot]}
                value, size = values_at(answer, scaled, points.n)
                if np.all(
                    np.abs(value) <= SAME_VALUE * np.maximum(size, 1e-300)
                ) and not np.allclose(held, value):
                    q_dot, shown = symbol_text(j.name, 1), plain(A_kk)
                    return (
                        f"gives {q_dot} as {shown} times what it is: the mass ({shown}) is not "
                        "divided out (q̇ = p/m, not p)."
                    )
    except (UnsupportedExpression, ValueError, NotQuadratic):
        pass
    return ""


__all__ = ["check_hamilton_equations", "rate_jets"]
