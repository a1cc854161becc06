"""The `hamiltonian` part: H(q, p, t) = Σ p_j q̇_j − L written in the coordinates and the momenta,
judged by its values on phase space (`phase`): at the image (q, p(q, q̇), t) of each sample point
the answer must equal the energy function h(q, q̇, t), up to a constant (another zero of the
potential, said in the feedback).

The named mistakes, each a fingerprint of values at the same points:

    velocities        H written with q̇ (h itself, or anything else, in the velocities)
    lagrangian        H = L = T − V written in the momenta
    velocity_is_p     each q̇ replaced by its momentum (θ̇ → p_θ instead of p_θ/(m l²))
    multiplied        each q̇ replaced by A p (the mass multiplied instead of divided)
    missing_offset    ½ pᵀA⁻¹p + U: the shift p − c of the momenta at rest (p − e A of a charge,
                      a moving support's share) left out
    sign_of_V         K + U − 2 V: V (free of velocities) subtracted instead of added
    dropped_half      2 K + U: the ½ of the kinetic part left out
    energy            T + V where the scene's H is not the energy (a moving constraint)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import decide
from lagrade.judge.equivalence import offset_removed
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.parts.common import method_name, named_finding, where_text, witness_point
from lagrade.judge.parts.phase import (
    POINTS,
    momentum_symbols,
    phase_env,
    phase_points,
    phase_system,
    rate_symbols,
    read_phase_single,
    values_at,
    velocity_symbols,
)
from lagrade.judge.parts.reading import Read
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import H_MATCH, SAME_VALUE
from lagrade.judge.verdict import Verdict

PART = "hamiltonian"


def read_hamiltonian(problem: Problem, answer: Any) -> Read:
    """A Hamiltonian in the coordinates and momenta, `H = …` allowed."""
    return read_phase_single(problem, answer, PART, "H")


def check_hamiltonian(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = read_hamiltonian(problem, answer)
    names = velocity_symbols(problem, got.symbols)
    if names:
        return _with_velocities(problem, got, names)
    rates = [s.name for s in rate_symbols(problem) if s in got.symbols]
    if rates:
        return Verdict(
            PART,
            "incorrect",
            0.0,
            (
                "H is a function of the coordinates, the momenta and t; it holds no rate "
                f"({', '.join(rates)}).",
            ),
            got.echo,
            "structure",
            mistakes=("rates",),
        )
    points = problem.points(POINTS)
    h = problem.compiled_reference("h", lambda: problem.system.energy_function)
    out = decide(_residual(problem, got.compiled, h, points, shifted=False))
    if out.equal:
        return Verdict(PART, "correct", 1.0, (), got.echo, method_name(out))
    shifted = decide(_residual(problem, got.compiled, h, points, shifted=True))
    if shifted.equal:
        note = (
            "Your H differs from Σ p q̇ − L by a constant (another zero of the potential); "
            "that changes no motion.",
        )
        return Verdict(PART, "correct", 1.0, note, got.echo, method_name(out, shifted))
    ans = got.compiled
    witness = witness_point(phase_points(problem, points), out, ans)
    kind, message = _diagnose(problem, ans, points)
    where = where_text(witness, problem)
    # one sentence: the named mistake where it shows, else what H is not
    said = "Your H is not Σ p_j q̇_j − L written in the momenta"
    feedback = [named_finding(message, where) if kind else f"{said}{where}."]
    mistakes = [kind] if kind else []
    return Verdict(
        PART,
        "incorrect",
        0.0,
        tuple(feedback),
        got.echo,
        method_name(out),
        witness=witness,
        mistakes=tuple(mistakes),
    )


def _residual(
    problem: Problem, answer: Compiled, reference: Compiled, points: Points, shifted: bool
):
    """answer(q, p, t) − h(q, q̇, t) at the phase-space images of the points; `shifted`: its
    spread within each parameter group (equal up to a constant)."""

    def residual(backend):
        env = phase_env(problem, points, backend)
        a, sa = values_at(answer, env, points.n, backend)
        b, sb = values_at(reference, env, points.n, backend)
        d = a - b
        if not shifted:
            return d, sa + sb
        rest, first = offset_removed(d, points.group)
        return rest, sa + sb + first

    return residual


def _with_velocities(problem: Problem, got: Read, names: list[str]) -> Verdict:
    """H written in the velocities: say so, and whether it is h itself (then only the variables
    are wrong)."""
    momenta = ", ".join(s.name for s in momentum_symbols(problem))
    sentence = (
        f"H must be written in the coordinates and the momenta ({momenta}), not in the "
        f"velocities ({', '.join(names)}): solve p = ∂L/∂q̇ for the velocities and put them in."
    )
    feedback = [sentence]
    points = problem.points(POINTS)
    h = problem.compiled_reference("h", lambda: problem.system.energy_function)
    if not any(j.ddot in got.symbols for j in problem.jets):
        try:
            same = decide(lambda b: _velocity_residual(got.compiled, h, points, b)).equal
        except (UnsupportedExpression, ValueError):
            same = False
        if same:
            feedback.append(
                "As a function of the velocities it is the energy function h = Σ p q̇ − L, "
                "which is right."
            )
    return Verdict(
        PART, "incorrect", 0.0, tuple(feedback), got.echo, "structure", mistakes=("velocities",)
    )


def _velocity_residual(answer: Compiled, reference: Compiled, points: Points, backend):
    env = points.arrays(backend)
    a, sa = values_at(answer, env, points.n, backend)
    b, sb = values_at(reference, env, points.n, backend)
    return a - b, sa + sb


# --- the catalogue of named mistakes ----------------------------------------------------------


def _diagnose(problem: Problem, answer: Compiled, points: Points) -> tuple[str, str]:
    """(kind, sentence) of the first fingerprint the answer matches, or ("", "")."""
    try:
        with np.errstate(all="ignore"):
            env = phase_env(problem, points)
            a, sa = values_at(answer, env, points.n)
            for kind, message, values in _fingerprints(problem, points):
                f = values()
                if f is None:
                    continue
                if _matches(a, sa, f, points):
                    return kind, message
    except (UnsupportedExpression, ValueError, np.linalg.LinAlgError):
        pass
    return "", ""


def _matches(a, sa, f, points: Points) -> bool:
    """a equals the fingerprint f at every point, or up to a constant within each group."""
    a, f = np.asarray(a, float), np.asarray(f, float)
    size = np.abs(sa) + np.abs(f)
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(f))):
        return False
    d = a - f
    rest, first = offset_removed(d, points.group)
    return bool(
        np.all(np.abs(d) <= H_MATCH * size) or np.all(np.abs(rest) <= H_MATCH * (size + first))
    )


def _fingerprints(problem: Problem, points: Points) -> list[tuple[str, str, Callable]]:
    env = points.env
    n, jets = points.n, problem.jets
    hs = phase_system(problem)
    p_values = [phase_env(problem, points)[s] for s in momentum_symbols(problem)]

    def at(name: str, make, velocities=None):
        expr = problem.compiled_reference(name, make)
        where = (
            env
            if velocities is None
            else env | dict(zip([j.dot for j in jets], velocities, strict=True))
        )
        return values_at(expr, where, n)[0]

    def energy_function_at(velocities):
        return at("h", lambda: problem.system.energy_function, velocities)

    def matrix(name: str, make) -> np.ndarray:
        M = make()
        rows = [
            [at(f"{name}{i}{k}", lambda e=M[i, k]: e) for k in range(M.cols)] for i in range(M.rows)
        ]
        return np.moveaxis(
            np.array(np.broadcast_arrays(*[x for r in rows for x in r]), float), 0, -1
        ).reshape(n, M.rows, M.cols)

    def multiplied():
        A = matrix("A", lambda: hs.velocity_matrix)
        p = np.stack(p_values, axis=-1)
        return energy_function_at(list(np.einsum("nij,nj->ni", A, p).T))

    def missing_offset():
        c = [at(f"c{k}", lambda e=hs.momentum_offset[k]: e) for k in range(len(jets))]
        c = np.stack(np.broadcast_arrays(*c), axis=-1)
        if np.all(c == 0):
            return None
        A = matrix("A", lambda: hs.velocity_matrix)
        p = np.stack(p_values, axis=-1)
        kinetic = 0.5 * np.einsum("ni,ni->n", p, np.linalg.solve(A, p[..., None])[..., 0])
        return kinetic + at("U", lambda: hs.effective_potential)

    def dropped_half():  # 2 K + U: K = h − U at the image points
        U = at("U", lambda: hs.effective_potential)
        return 2 * energy_function_at(None) - U

    def sign_of_V():  # K + U − 2 V: the potential (free of velocities) with the wrong sign
        V = problem.catalogue.split.V
        if V == 0 or any(V.has(j.dot) for j in jets):
            return None
        return energy_function_at(None) - 2 * at("V", lambda: V)

    def energy():
        if not problem.has_bodies:
            return None
        E = at("E", lambda: problem.kinetic_energy + problem.potential_energy)
        h = energy_function_at(None)
        return None if np.allclose(E, h, rtol=SAME_VALUE, atol=0) else E

    p_names = ", ".join(s.name for s in momentum_symbols(problem))
    return [
        (
            "lagrangian",
            "Your H is the Lagrangian L = T − V written in the momenta; H = Σ p q̇ − L.",
            lambda: at("L", lambda: problem.system.L),
        ),
        (
            "sign_of_V",
            "V has the wrong sign in your H: H = Σ p q̇ − L adds V.",
            sign_of_V,
        ),
        (
            "dropped_half",
            "The ½ is missing in the kinetic part of your H (p²/(2 m) for one body; "
            "½ (p − c)ᵀ A⁻¹ (p − c) in general).",
            dropped_half,
        ),
        (
            "velocity_is_p",
            "Your H puts each momentum where its velocity was (q̇ = p); solve p = ∂L/∂q̇ for the "
            "velocities instead.",
            lambda: energy_function_at(p_values),
        ),
        (
            "multiplied",
            "Your H has the velocities as the mass matrix times the momenta; q̇ = A⁻¹ (p − c) "
            "divides by the masses.",
            multiplied,
        ),
        (
            "missing_offset",
            f"Your H lacks the shift of the momenta by the part they have at rest (c = ∂L/∂q̇ "
            f"at q̇ = 0: e A for a charge, the share of a moving support or frame): it is "
            f"written in ({p_names}) where H needs p − c.",
            missing_offset,
        ),
        (
            "energy",
            "Your H is the energy T + V, but here H = Σ p q̇ − L is not T + V (the constraints "
            "move with time).",
            energy,
        ),
    ]


__all__ = ["check_hamiltonian"]
