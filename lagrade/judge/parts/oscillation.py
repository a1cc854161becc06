"""The `equilibrium` and `normal_modes` parts: a stable equilibrium at rest (coordinate values) and
the angular frequencies of small oscillations about it (a list, in any order).

Both are judged by physics at sample points of the parameters, never by the key's form:

- equilibrium    the values make ∂U/∂q vanish (U = −L at rest, `mechanics.oscillations`) and
                 K = ∂²U/∂q∂q is positive there on M = A (every generalized eigenvalue λ ≥ 0,
                 a zero one only along a free direction). Any stable equilibrium earns credit;
                 a coordinate that the key leaves free may be left out.
- normal_modes   each frequency given equals one of √λ of K a = λ M a at the key's stable
                 equilibrium (scipy's symmetric-definite eigensolver at each point), each mode
                 once; ω = 0 for a zero mode may be given or left out.

The parameters are drawn where the key's equilibrium exists and is stable (a hoop's off-axis
one needs ω² R > g); when the frequencies have no closed form the handout's values alone are
used. Named mistakes: an unstable equilibrium, a point that is no equilibrium, ω² for ω, the
frequency in cycles (ω/2π) or the period (2π/ω) for ω, √2 ω or ω/√2 (a ½ of T or V lost),
one coordinate's frequency alone √(K_kk/M_kk) (the coupling ignored), a frequency of no mode.
Frequencies a sentence quotes are at the handout's values where the equilibrium is stable
there, else at the first point drawn (`quoted_point`); the verdict's witness holds those
values."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import ParseError, RequestError, UnsupportedExpression
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.decision import decide
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.parts.common import where_text
from lagrade.judge.parts.items import list_items, without_none
from lagrade.judge.parts.reading import Lines, Read, read, read_labelled, read_lines
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points, seed_for
from lagrade.judge.situation import rounded, symbol_text
from lagrade.judge.tolerances import DIFFERENT_ABOVE, ROUNDING, SAME_FREQUENCY
from lagrade.judge.verdict import Verdict, invalid
from lagrade.mechanics import (
    ZERO_MODE,
    SmallOscillations,
    deciding_values,
    frequencies_from,
    generalized_eigenvalues,
    phase_space,
    small_oscillations,
)


def oscillations(problem: Problem) -> SmallOscillations:
    """The question's equilibria and modes, the stable one chosen at the handout's values (the
    middle of each domain where a value is missing: an ad-hoc Lagrangian)."""
    return small_oscillations(problem.system, deciding_values(problem.values, problem.domains))


def _stable(problem: Problem, part: str):
    osc = oscillations(problem)
    if osc.why_not is not None:
        raise RequestError(f"part {part!r} needs a stable equilibrium, and here {osc.why_not}")
    return osc


def _matrices(problem: Problem) -> dict:
    """Compiled once: U's gradient and Hessian and A (in q and the parameters), and the key's
    equilibrium with its K and M (in the parameters)."""
    cache = problem.__dict__.setdefault("_oscillation", {})
    if not cache:
        osc = oscillations(problem)
        hs = phase_space(problem.system)
        qs = [j.q for j in problem.jets]
        U = hs.effective_potential
        cache["gradient"] = [Compiled.of(sp.diff(U, q)) for q in qs]
        cache["hessian"] = [[Compiled.of(e) for e in row] for row in sp.hessian(U, qs).tolist()]
        cache["A"] = [[Compiled.of(e) for e in row] for row in hs.velocity_matrix.tolist()]
        eq = osc.stable
        cache["at"] = {q: Compiled.of(sp.S(v)) for q, v in eq.at.items()}
        cache["K"] = [[Compiled.of(e) for e in row] for row in eq.stiffness.tolist()]
        cache["M"] = [[Compiled.of(e) for e in row] for row in eq.mass.tolist()]
        cache["free"] = len(eq.free)
    return cache


def _matrix_at(entries, env: Mapping, n: int) -> np.ndarray:
    rows = [[to_length(e.values(env)[0], n).astype(float) for e in row] for row in entries]
    return np.moveaxis(np.array(rows, float), -1, 0)  # (points, k, k)


def _stable_at(K: np.ndarray, M: np.ndarray, free: int) -> np.ndarray:
    """Per point: M positive definite, every λ ≥ 0, and no more zero modes than `free`."""
    out = np.zeros(len(K), dtype=bool)
    for i in range(len(K)):
        if not (np.all(np.isfinite(K[i])) and np.all(np.isfinite(M[i]))):
            continue
        if not np.all(np.linalg.eigvalsh(M[i]) > 0):
            continue
        lam = generalized_eigenvalues(K[i], M[i])
        top = max(float(np.abs(lam).max()), 1e-300)
        zero = int(np.sum(np.abs(lam) <= ZERO_MODE * top))
        out[i] = bool(np.all(lam > -ZERO_MODE * top)) and zero <= free
    return out


def oscillation_points(problem: Problem) -> Points:
    """Parameter draws where the key's equilibrium exists and is stable (q, q̇ as drawn are not
    used); the handout's values alone when the frequencies have no closed form."""
    cache = problem.__dict__.setdefault("_oscillation_points", {})
    if "points" not in cache:
        osc, compiled = oscillations(problem), _matrices(problem)
        free = frozenset(problem.domains) if osc.frequencies is not None else frozenset()

        def valid(env):
            n = len(next(iter(env.values())))
            with np.errstate(all="ignore"):
                ok = np.ones(n, dtype=bool)
                for c in compiled["at"].values():
                    ok &= np.isfinite(to_length(c.values(env)[0], n).astype(complex)).real
                K = _matrix_at(compiled["K"], env, n)
                M = _matrix_at(compiled["M"], env, n)
            return ok & _stable_at(K, M, compiled["free"])

        cache["points"] = problem.space.draw(seed_for(problem.key, "oscillation"), free, valid)
    return cache["points"]


def reference_frequencies(problem: Problem, points: Points) -> np.ndarray:
    """√λ at each point, ascending (points, n), zero modes as 0."""

    def make():
        compiled = _matrices(problem)
        with np.errstate(all="ignore"):
            K = _matrix_at(compiled["K"], points.env, points.n)
            M = _matrix_at(compiled["M"], points.env, points.n)
        return np.array([frequencies_from(K[i], M[i]) for i in range(points.n)])

    return problem.cached("frequencies", points, make)


def prepare_oscillations(problem: Problem) -> None:
    """Derive before the student's clock starts what both parts need: the equilibria (sympy's
    solver: up to a few seconds for a turning hoop), the draws, the reference frequencies.
    Nothing when the scene has no stable equilibrium (the checker then says why)."""
    if oscillations(problem).why_not is None:
        reference_frequencies(problem, oscillation_points(problem))


def _parameters_only(problem: Problem, got: Read, what: str) -> None:
    motion = {s for j in problem.jets for s in (j.q, j.dot, j.ddot)}
    if got.symbols & motion:
        raise ParseError(
            f"{what} is a value in the parameters; it holds no coordinate or velocity.",
            (0, len(str(got.echo))),
            str(got.echo),
        )


# --- equilibrium --------------------------------------------------------------------------------


def read_equilibrium(problem: Problem, answer: Any) -> Lines:
    """An equilibrium, one `coordinate = value` (or a bare value) per item."""
    return read_lines(list_items(answer, "equilibrium"), partial(read, problem))


def read_normal_modes(problem: Problem, answer: Any) -> Lines:
    """Angular frequencies, one per item (`omega = …` allowed); `none` for none."""
    return _read_frequencies(problem, without_none(list_items(answer, "normal_modes")))


def _read_frequencies(problem: Problem, items: list) -> Lines:
    return read_lines(items, lambda item: read_labelled(problem, item, ("omega", "w")))


def check_equilibrium(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    osc = _stable(problem, "equilibrium")
    names = list(problem.coordinates)
    lines = read_equilibrium(problem, answer)
    reads = lines.reads
    values: dict[sp.Symbol, Read] = {}
    feedback = lines.feedback()
    bare = [r for r in reads if not r.has_rhs]
    if bare and len(bare) != len(reads):
        return invalid("equilibrium", "Write each value as coordinate = value.", lines.echoes)
    if bare:
        if len(bare) != len(names):
            return invalid(
                "equilibrium",
                f"Give the value of each coordinate ({', '.join(names)}), as coordinate = value.",
                lines.echoes,
            )
        pairs = list(zip(problem.jets, bare, strict=True))
    else:
        pairs = []
        for r in reads:
            jet = next((j for j in problem.jets if r.label in (j.name, j.dot.name)), None)
            if jet is None:
                return invalid(
                    "equilibrium",
                    f"Write each value as coordinate = value (coordinates: {', '.join(names)}).",
                    lines.echoes,
                )
            if r.label == jet.dot.name:
                continue  # "θ̇ = 0": at rest, as every equilibrium here is
            pairs.append((jet, r.only_rhs()))
    for jet, r in pairs:
        if jet.q in values:
            return invalid("equilibrium", f"{jet.name} is given twice.", lines.echoes)
        _parameters_only(problem, r, f"The value of {jet.name}")
        values[jet.q] = r
    key_free = set(osc.stable.free)
    missing = [j.name for j in problem.jets if j.q not in values and j.name not in key_free]
    if missing:
        feedback.append(f"Give the value of {', '.join(missing)} at the equilibrium.")
        return _wrong(feedback, lines.echoes, "missing_coordinate")
    points = oscillation_points(problem)
    compiled = _matrices(problem)

    def env_at(backend):
        env = dict(points.arrays(backend))
        for q, r in values.items():
            env[q] = to_length(r.compiled.values(env, backend)[0], points.n, backend)
        return env

    def residual(backend):
        """∂U/∂q at the answer, against the size of its terms at the drawn (generic) q too:
        at an equilibrium the terms themselves vanish (m g l cos(π/2))."""
        env, generic = env_at(backend), points.arrays(backend)
        parts = [g.values(env, backend) for g in compiled["gradient"]]
        scale = [g.values(generic, backend)[1] for g in compiled["gradient"]]
        r = np.stack([to_length(v, points.n, backend) for v, _ in parts], axis=-1)
        s = np.stack(
            [
                to_length(s, points.n, backend) + to_length(g, points.n, backend)
                for (_, s), g in zip(parts, scale, strict=True)
            ],
            axis=-1,
        )
        return r, s

    try:
        out = decide(residual)
    except UnsupportedExpression as error:
        return invalid("equilibrium", f"Cannot evaluate your answer: {error}.", lines.echoes)
    shown = ", ".join(f"{q.name} = {_value_echo(values[q])}" for q in values)
    if not out.equal:
        witness = _handout_shows(problem, points, values, compiled)
        if witness is None and out.where is not None:
            witness = points.point(out.where, set(problem.domains))
        feedback.append(
            f"The system does not stay at rest at {shown}: ∂U/∂q ≠ 0 there (U = −L at rest)"
            + where_text(witness, problem)
            + "."
        )
        return _wrong(feedback, lines.echoes, "not_equilibrium", out.method, witness)
    with np.errstate(all="ignore"):
        env = env_at(FLOAT)
        K = _matrix_at(compiled["hessian"], env, points.n)
        M = _matrix_at(compiled["A"], env, points.n)
    stable = _stable_at(K, M, len(key_free))
    if not np.all(stable):
        feedback.append(
            f"{shown} is an equilibrium, but not a stable one: U has a maximum or a saddle "
            "there, so a small push grows."
        )
        return _wrong(feedback, lines.echoes, "unstable", out.method)
    if feedback:  # an unreadable line beside a right answer
        return _wrong(feedback, lines.echoes, "", out.method)
    return Verdict("equilibrium", "correct", 1.0, (), lines.echoes, out.method)


def _value_echo(got: Read) -> str:
    """The value as read, without the `name =` of its line."""
    echo = str(got.echo)
    return echo.split("=", 1)[1].strip() if "=" in echo else echo


def _wrong(feedback, echoes, kind: str, method: str = "numeric", witness=None) -> Verdict:
    mistakes = (kind,) if kind else ()
    return Verdict(
        "equilibrium",
        "incorrect",
        0.0,
        tuple(feedback),
        echoes,
        method,
        witness=witness,
        mistakes=mistakes,
    )


# --- normal modes -------------------------------------------------------------------------------


def check_normal_modes(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    _stable(problem, "normal_modes")
    items = without_none(list_items(answer, "normal_modes"))
    points = oscillation_points(problem)
    ref = reference_frequencies(problem, points)
    top = ref.max(axis=1, keepdims=True)
    nonzero = ref > ZERO_MODE * np.maximum(top, 1e-300)
    zero_modes = int((~nonzero[0]).sum())
    modes = [k for k in range(ref.shape[1]) if nonzero[0, k]]
    if not items and not modes:  # "none": nothing oscillates (a free wheel)
        return Verdict("normal_modes", "correct", 1.0, (), "none", "numeric")
    lines = _read_frequencies(problem, items)
    if not lines.reads:
        return invalid("normal_modes", "Give the angular frequencies, separated by commas.")
    feedback, mistakes = lines.feedback(), []
    used = np.zeros(ref.shape, dtype=bool)
    right = wrong = 0
    quoted: Quoted | None = None  # where a sentence quotes the frequencies
    for got in lines.reads:
        _parameters_only(problem, got, "A frequency")
        try:
            with np.errstate(all="ignore"):
                value = to_length(got.compiled.values(points.env)[0], points.n)
        except UnsupportedExpression as error:
            return invalid("normal_modes", f"Cannot evaluate your answer: {error}.", lines.echoes)
        value = np.asarray(value, dtype=complex)
        if np.all(np.abs(value) <= ROUNDING * top[:, 0]):
            if zero_modes:
                continue  # ω = 0 of a zero mode: true, and not required
            feedback.append(f"{got.echo}: this system has no zero mode; every mode oscillates.")
            mistakes.append("zero_mode")
            wrong += 1
            continue
        if _mode(value, ref, modes, used):
            right += 1
            continue
        wrong += 1
        kind = _slip(value, ref, modes)
        alone = "" if kind else uncoupled(problem, value, points)
        if kind:
            feedback.append(f"{got.echo}: {_SLIPS[kind]}")
            mistakes.append(kind)
        elif _mode(value, ref, modes, np.zeros(ref.shape, dtype=bool)):
            feedback.append(f"{got.echo} is a normal-mode frequency given twice.")
            mistakes.append("repeated")
        elif alone:
            feedback.append(f"{got.echo}: {uncoupled_text(alone)}")
            mistakes.append("uncoupled")
        else:
            quoted = quoted or quoted_point(problem, points)
            feedback.append(
                f"{got.echo} is not a normal-mode frequency ({quoted.where}, the frequencies "
                f"are {quoted.shown()} rad/s)."
            )
    missing = len(modes) - right
    if missing and not wrong:
        noun = "frequency is" if missing == 1 else "frequencies are"
        feedback.append(f"{missing} normal-mode {noun} missing ({len(modes)} in all).")
        mistakes.append("missing_mode")
    score = right / max(len(modes), right + wrong)
    status = (
        "correct" if right == len(modes) and not wrong and not lines.unreadable else "incorrect"
    )
    return Verdict(
        "normal_modes",
        status,
        1.0 if status == "correct" else float(score),
        tuple(feedback),
        lines.echoes,
        "numeric",
        witness=quoted.witness if quoted else None,
        mistakes=tuple(mistakes),
    )


def _handout_shows(problem: Problem, points: Points, values: dict, compiled: dict):
    """The handout's parameter values, by name, when ∂U/∂q at the student's point is clearly
    not zero there: the example a student can check on their own sheet. None without a full
    handout, or where the student's point happens to be at rest for those values."""
    handout = {s: np.array([float(v)]) for s, v in problem.values.items()}
    if not handout or any(s not in handout for s in problem.domains):
        return None
    env = {s: v[:1] for s, v in points.env.items()} | handout
    with np.errstate(all="ignore"):
        for q, r in values.items():
            env[q] = to_length(r.compiled.values(env)[0], 1)
        parts = [g.values(env) for g in compiled["gradient"]]
        r = np.array([float(np.real(to_length(v, 1)[0])) for v, _ in parts])
        size = np.array([float(np.real(to_length(s, 1)[0])) for _, s in parts])
    if not (np.all(np.isfinite(r)) and np.any(np.abs(r) > DIFFERENT_ABOVE * size)):
        return None
    return {s.name: float(f"{float(v[0]):.6g}") for s, v in handout.items()}


@dataclass(frozen=True)
class Quoted:
    """Where a sentence quotes the frequencies: the words that say where, the parameter values
    (the verdict's witness), and K and M there."""

    where: str
    witness: dict[str, float]
    env: dict  # that one point, for evaluating the student's expressions there
    K: np.ndarray
    M: np.ndarray

    def frequencies(self) -> np.ndarray:
        """The oscillating modes' ω there, ascending."""
        w = frequencies_from(self.K, self.M)
        return w[w > ZERO_MODE * max(float(w.max(initial=0.0)), 1e-300)]

    def shown(self) -> str:
        return ", ".join(rounded(float(w)) for w in self.frequencies())


def quoted_point(problem: Problem, points: Points) -> Quoted:
    """Where frequencies are quoted: at the handout's values, numbers the student can reproduce
    from their own sheet, when the key's equilibrium is stable there; else at the first point
    drawn, saying so (the witness holds its parameter values either way)."""
    compiled = _matrices(problem)
    first = {s: v[:1] for s, v in points.env.items()}
    handout = {s: np.array([float(v)]) for s, v in problem.values.items()}
    if handout and all(s in handout for s in problem.domains):
        env = first | handout
        with np.errstate(all="ignore"):
            K, M = _matrix_at(compiled["K"], env, 1), _matrix_at(compiled["M"], env, 1)
        if _stable_at(K, M, compiled["free"])[0]:
            witness = {s.name: float(f"{float(v[0]):.6g}") for s, v in handout.items()}
            return Quoted("with your handout's values", witness, env, K[0], M[0])
    with np.errstate(all="ignore"):
        K, M = _matrix_at(compiled["K"], first, 1), _matrix_at(compiled["M"], first, 1)
    witness = points.point(0, set(problem.domains))
    return Quoted("at the first point drawn", witness, first, K[0], M[0])


def uncoupled(problem: Problem, value: np.ndarray, points: Points) -> str:
    """The coordinate q_k whose frequency alone, √(K_kk/M_kk) (the others held fixed), `value`
    equals at every point; "" when none. Said only of a value that is no mode's frequency."""
    compiled = _matrices(problem)
    with np.errstate(all="ignore"):
        K = _matrix_at(compiled["K"], points.env, points.n)
        M = _matrix_at(compiled["M"], points.env, points.n)
        if len(problem.jets) < 2:
            return ""
        for k, jet in enumerate(problem.jets):
            alone = np.sqrt(K[:, k, k] / M[:, k, k])
            if np.all(alone > 0) and np.all(np.abs(value - alone) <= SAME_FREQUENCY * alone):
                return jet.name
    return ""


def uncoupled_text(name: str) -> str:
    return (
        f"this is √(K/M) of {symbol_text(name)} alone, the frequency if the other coordinates "
        "were held fixed; they are coupled, so the modes solve K a = ω² M a."
    )


def _mode(value: np.ndarray, ref: np.ndarray, modes: list[int], used: np.ndarray) -> bool:
    """Whether `value` equals, at every point, a mode not yet taken there (`used`: points ×
    modes, updated when it does). Matched point by point: the order of the frequencies may
    change from one parameter draw to another (k < k_z in one, k > k_z in the next), and a
    degenerate pair is two modes."""
    taken = []
    for i in range(len(value)):
        k = next(
            (
                k
                for k in modes
                if not used[i, k] and abs(value[i] - ref[i, k]) <= SAME_FREQUENCY * abs(ref[i, k])
            ),
            None,
        )
        if k is None:
            return False
        taken.append(k)
    used[np.arange(len(value)), taken] = True
    return True


_SLIPS = {
    "squared": "this is ω², not the angular frequency ω.",
    "cycles": "this is the frequency ω/2π in cycles per second; the question asks for ω.",
    "period": "this is the period 2π/ω, not the angular frequency ω.",
    "factor_two": "this is √2 times a normal-mode frequency: its ω² is twice what it should be.",
    "factor_half": "this is a normal-mode frequency divided by √2: its ω² is half what it "
    "should be.",
}


def _slip(value: np.ndarray, ref: np.ndarray, modes: list[int]) -> str:
    """The slip whose f(ω) of some mode `value` is at every point, matched point by point as
    `_mode` matches (the frequencies' order changes between draws: k < k_z in one, k > k_z in
    the next)."""
    for kind, f in (
        ("squared", lambda w: w**2),
        ("cycles", lambda w: w / (2 * np.pi)),
        ("period", lambda w: 2 * np.pi / w),
        ("factor_two", lambda w: np.sqrt(2) * w),
        ("factor_half", lambda w: w / np.sqrt(2)),
    ):
        with np.errstate(all="ignore"):
            target = f(ref[:, modes])  # (points, modes)
            near = np.abs(value[:, None] - target) <= SAME_FREQUENCY * np.abs(target)
        if np.all(np.any(near, axis=1)):
            return kind
    return ""


__all__ = ["check_equilibrium", "check_normal_modes", "oscillations", "prepare_oscillations"]
