"""Building blocks the part checkers share: which parameters are sampled, where an answer
differs, the method that decided, and the verdict of a wrong single expression."""

from __future__ import annotations

import re
from collections.abc import Mapping
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from lagrade.errors import UnsupportedExpression
from lagrade.judge.compiled import Compiled
from lagrade.judge.decision import Decision
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.dimensions import dimension, dimensions_of, hint_for, tells
from lagrade.judge.equivalence import offset_removed
from lagrade.judge.evaluate import FLOAT, MP, MP_DIGITS
from lagrade.judge.mutations import Mutant
from lagrade.judge.parts.reading import Read
from lagrade.judge.problem import Problem
from lagrade.judge.rows import equation_rows, lagrangian_rows
from lagrade.judge.sampling import Points
from lagrade.judge.situation import coordinate_units, rounded, situation, symbol_text
from lagrade.judge.tolerances import AS_TYPED, SAME_VALUE
from lagrade.judge.verdict import Verdict
from lagrade.mechanics import t as time

#: A number as typed: 9.81, 8, 6.674e-11 (not the digits of a name such as m_1).
_NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")


def handout_numbers(problem: Problem, got: Read, reference: Compiled | None = None) -> str:
    """The one rule for handout values put into a wrong symbolic answer: the parameters that
    the reference uses, that have a handout value and that the answer leaves out, named all
    when the answer is the reference with their values put in (up to a constant), else those
    whose value (or its square: ω² = 64) the answer holds as a typed number. The sentence
    saying so, or nothing."""
    syms = got.symbols
    used = reference.symbols if reference is not None else frozenset(problem.domains)
    left_out = [s for s, value in problem.values.items() if s in used and s not in syms and value]
    if not left_out:
        return ""
    if reference is not None and _is_reference_with_values(problem, got, reference, left_out):
        # those whose value mattered: not h of a dropped constant m g h, say
        named = [
            s
            for s in left_out
            if not _is_reference_with_values(problem, got, reference, left_out, keep=s)
        ]
    else:
        echo = got.echo if isinstance(got.echo, str) else " ".join(map(str, got.echo))
        typed = [n for n in _NUMBER.findall(echo) if "." in n or float(n) > 2]
        named = [s for s in left_out if _typed_value(problem.values[s], typed)]
    if not named:
        return ""
    names = [symbol_text(s.name) for s in sorted(named, key=lambda s: s.name)]
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    them = "it" if len(names) == 1 else "them"
    return (
        f"Your answer puts in the handout's value for {listed}; write {them} as "
        f"{'a symbol' if len(names) == 1 else 'symbols'}: a symbolic answer must hold for "
        "every value, not only the handout's."
    )


def _typed_value(value: float, typed: list[str]) -> bool:
    value = abs(float(value))
    return any(abs(float(n) - v) <= AS_TYPED * v for n in typed for v in (value, value * value))


def _is_reference_with_values(
    problem: Problem,
    got: Read,
    reference: Compiled,
    left_out: list[sp.Symbol],
    keep: sp.Symbol | None = None,
) -> bool:
    """The answer equals the reference with the handout values of `left_out` (but `keep`) put
    in, up to a constant (the zero of V, a dropped constant of L), at the hint's own points."""
    values = {s: sp.Float(problem.values[s]) for s in left_out if s != keep}
    points = problem.points("handout values")
    try:
        answer = got.compiled
        plugged = Compiled.of(reference.expr.xreplace(values))
        with np.errstate(all="ignore"):
            a, sa = answer.values(points.env)
            b, sb = plugged.values(points.env)
    except (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError):
        return False
    d = np.broadcast_to(np.asarray(a - b, dtype=complex), (points.n,))
    size = np.broadcast_to(np.abs(sa) + np.abs(sb), (points.n,))
    ok = np.isfinite(d) & np.isfinite(size)
    if ok.sum() < 3:
        return False
    rest, first = offset_removed(d, points.group)  # a constant per parameter draw
    return bool(np.all(np.abs(rest)[ok] <= AS_TYPED * (size + first)[ok]))


def witness_point(
    points: Points, outcome: Decision, *exprs: sp.Expr | Compiled
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


def where_text(
    witness: Mapping[str, float] | None, problem: Problem | None = None, values: str = ""
) -> str:
    """Where a wrong answer shows, as a situation: " (for example at θ = 0.3 rad with the
    system at rest)" (see `lagrade.judge.situation`), then what each side gives there when
    `values` says it (", where your T is 0.412 and the reference's is 0.623"); nothing
    without a point."""
    if not witness:
        return ""
    if values:  # the accelerations compared are not part of the situation
        witness = {k: v for k, v in witness.items() if not k.endswith("_ddot")} or witness
    return f" (for example {situation(witness, problem)}{values})"


def _handout_values(problem: Problem) -> dict[sp.Symbol, np.ndarray] | None:
    """The handout's parameter values (the student's own variant) as a one-point env, or None
    when some parameter has none (an ad-hoc question without a handout)."""
    if not problem.values or any(s not in problem.values for s in problem.domains):
        return None
    return {s: np.array([float(v)]) for s, v in problem.values.items()}


def _motion(problem: Problem) -> set[sp.Symbol]:
    return {j.q for j in problem.jets} | {j.dot for j in problem.jets}


def _handout_point(problem: Problem, points: Points, i: int, symbols: set) -> dict | None:
    """Sample point i as a one-point env, with the handout's parameter values in place of the
    sampled ones, so that every parameter value quoted is the student's own. A formula in the
    parameters alone is quoted at the handout's values (`handout_witness`), or as sampled
    when there is no handout (an ad-hoc question: nothing else to quote). The numbers quoted
    must be ones a student can reproduce. None when a state is quoted and some parameter has
    no handout value."""
    env = {s: np.array([float(np.ravel(v)[i] if np.ndim(v) else v)]) for s, v in points.env.items()}
    motion = _motion(problem)
    handout = _handout_values(problem)
    if not symbols & motion:
        return env if handout is None else {**env, **handout}
    # the state as the sentence quotes it (three significant figures: `situation.rounded`), so
    # that what is computed there is what a student computes from the quoted numbers; t too (a
    # drive of ω = 200 rad/s turns by 10⁻³ rad between t = 2.53848 s and the quoted 2.54 s)
    quoted = motion | {time}
    env.update({s: np.array([float(f"{env[s][0]:.3g}")]) for s in quoted if s in env})
    return None if handout is None else {**env, **handout}


def handout_witness(
    problem: Problem, points: Points, outcome: Decision, answer: Compiled, reference: Compiled
) -> dict[str, float] | None:
    """Where a wrong answer shows, in numbers the student was given: for a formula in the
    parameters alone, the handout's values (the student's own variant) rather than a sampled
    point; no point at all when both sides look the same there (three significant figures),
    rather than a point the student never saw. Otherwise `witness_point`."""
    witness = witness_point(points, outcome, answer, reference)
    symbols = answer.symbols | reference.symbols
    if witness is None or symbols & _motion(problem) or _handout_values(problem) is None:
        return witness
    env = _handout_point(problem, points, outcome.where, symbols)
    try:
        with np.errstate(all="ignore"):
            mine, theirs = (_value_at(e, env) for e in (answer, reference))
    except UnsupportedExpression:
        return None
    if np.isfinite(mine) == np.isfinite(theirs) and (
        not np.isfinite(mine) or _shown_pair(float(np.real(mine)), float(np.real(theirs))) is None
    ):
        return None
    names = {s: s.name for s in symbols if s in env}
    return {names[s]: float(env[s][0]) for s in sorted(names, key=names.get)}


def _shown_pair(mine: float, theirs: float) -> tuple[str, str] | None:
    """Both values rounded (3 significant figures), when they are finite and look different."""
    if not (np.isfinite(mine) and np.isfinite(theirs)):
        return None
    shown = rounded(float(mine)), rounded(float(theirs))
    return shown if shown[0] != shown[1] else None


def _value_at(expr: Compiled, env: Mapping) -> complex | float:
    """expr's value at a one-point env; in high precision when float64 has none there (an
    intermediate past float range: M^20/m^19 of SI masses), as a float when it fits one."""
    value = np.ravel(expr.values(env)[0])[0]
    if np.isfinite(value):
        return value
    with mpmath.workdps(MP_DIGITS):
        mp_env = {s: MP.array(v) for s, v in env.items()}
        try:
            exact = np.ravel(expr.values(mp_env, MP)[0])[0]
            return float(exact) if mpmath.isfinite(exact) else np.nan
        except (ZeroDivisionError, ValueError, OverflowError, TypeError):
            return np.nan


def values_text(
    problem: Problem, points: Points, outcome: Decision, answer: Compiled, reference: Compiled,
    what: str, unit: str = "",
) -> str:  # fmt: skip
    """ ", where your T is 0.412 and the reference's is 0.623" at the witness of `outcome`
    (handout parameter values), or nothing when that is not cheap and clear."""
    if outcome.where is None:
        return ""
    env = _handout_point(problem, points, outcome.where, answer.symbols | reference.symbols)
    if env is None:
        return ""
    try:
        with np.errstate(all="ignore"):
            mine, theirs = (_value_at(e, env) for e in (answer, reference))
    except UnsupportedExpression:  # a symbol without a value here: say nothing, never guess
        return ""
    if not (np.isfinite(mine) and np.isfinite(theirs)):  # say which side is undefined there
        side = f"your {what}" if not np.isfinite(mine) else f"the expected {what}"
        return f", where {side} is undefined" if np.isfinite(mine) != np.isfinite(theirs) else ""
    if np.iscomplexobj(mine) or np.iscomplexobj(theirs):  # rounded reals only
        return ""
    pair = _shown_pair(float(mine), float(theirs))
    if pair is None:
        return ""
    suffix = f" {unit}" if unit else ""
    mine = suffix if suffix and _same_dimension(problem, answer, reference) else ""
    return f", where your {what} is {pair[0]}{mine} and the reference's is {pair[1]}{suffix}"


def _same_dimension(problem: Problem, answer: Compiled, reference: Compiled) -> bool:
    """Whether the answer has the reference's dimension, so that the reference's unit may be
    put after the answer's value too (sqrt(l/g) is no angular velocity: "your answer is
    0.16", not "0.16 rad/s"). False when a dimension cannot be told."""
    known = dimensions_of(problem)
    if not known:
        return False
    mine, theirs = (dimension(e.expr, known) for e in (answer, reference))
    return mine is not None and mine == theirs and not isinstance(mine, str)


def acceleration_text(
    problem: Problem,
    points: Points,
    outcome: Decision,
    equation: Compiled,
    position: int | None = None,
) -> str:
    """ ", where your equation gives θ̈ = −3.2 rad/s² and the reference θ̈ = −9.81 rad/s²" at
    the witness (handout parameter values). With several coordinates the accelerations are
    coupled: the equation is read for the coordinate of its `position` in a list of one
    equation per coordinate (else for the acceleration it weighs most), the others taken as
    Lagrange's equations give them, and the sentence says so. Nothing when not clear."""
    if outcome.where is None:
        return ""
    jets = problem.jets
    env = _handout_point(problem, points, outcome.where, {j.q for j in jets})
    if env is None:
        return ""
    n = len(jets)
    try:
        with np.errstate(all="ignore"):
            mine = equation_rows([equation], jets, env).coef[0, 0].astype(float)
            rows = lagrangian_rows(problem.L, jets, env).coef[0].astype(float)
            reference = np.linalg.solve(rows[:, :n], -rows[:, n])  # every q̈ of the motion
    except (UnsupportedExpression, np.linalg.LinAlgError):
        return ""
    k = (
        position
        if position is not None and mine[position] != 0
        else int(np.argmax(np.abs(mine[:n])))
    )
    if mine[k] == 0:
        return ""
    others = [j for j in range(n) if j != k]
    with np.errstate(all="ignore"):
        gives = -(mine[n] + sum(mine[j] * reference[j] for j in others)) / mine[k]
    pair = _shown_pair(gives, reference[k])
    if pair is None:
        return ""
    name = symbol_text(jets[k].name, 2)
    unit = _acceleration_unit(problem, jets[k].name)
    taken = ""
    if others:
        values = [
            f"{symbol_text(jets[j].name, 2)} = {rounded(float(reference[j]))}"
            f"{_acceleration_unit(problem, jets[j].name)}"
            for j in others
        ]
        pronoun = "it" if len(others) == 1 else "them"
        taken = f" (with {', '.join(values)} as Lagrange's equations give {pronoun})"
    return (
        f", where your equation gives {name} = {pair[0]}{unit} and the reference "
        f"{name} = {pair[1]}{unit}{taken}"
    )


def _acceleration_unit(problem: Problem, name: str) -> str:
    unit = coordinate_units(problem)[name][2]
    return f" {unit}" if unit else ""


def method_name(*outcomes: Decision) -> str:
    return "numeric+mpmath50" if any(o.method.endswith("mpmath50") for o in outcomes) else "numeric"


def ratio_text(c: float) -> str:
    """A factor as a student reads it: a simple fraction (2, 1/2, 3/2) when c is one, else six
    significant digits (1e+40, never the float's 40 digits of rounding, nor 0 for 1e-40)."""
    if 1e-6 <= abs(c) <= 1e6:  # not a tolerance: the factors shown as fractions
        f = Fraction(c).limit_denominator(1000)
        if abs(float(f) - c) <= SAME_VALUE * abs(c):
            return str(f)
    return f"{c:.6g}"


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


def counted(n: int, noun: str) -> str:
    """n and the noun, in the singular for one: "1 coordinate", "2 coordinates"."""
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def equations_needed(coordinates: int, equations: int, each: str = "") -> str:
    """ "2 coordinates need 2 equations" (`each`: what each coordinate needs, in brackets)."""
    need = "needs" if coordinates == 1 else "need"
    return f"{counted(coordinates, 'coordinate')} {need} {counted(equations, 'equation')}{each}"


def too_few_independent(
    rank: int, needed: int, coordinates: int, given: int, each: str = ""
) -> str:
    """Right equations that are too few: "only 1 of them is independent; 2 coordinates need 2
    equations" (`given`: how many the student wrote; one is simply right, and too few)."""
    if given == 1:
        return f"Your equation is right; {equations_needed(coordinates, needed, each)}."
    are = "is" if rank == 1 else "are"
    return (
        f"Your equations are right but only {rank} of them {are} independent; "
        f"{equations_needed(coordinates, needed, each)}."
    )


def as_sentence(text: str) -> str:
    if text.split(" ", 1)[0] in ("your", "the", "sin"):
        text = text[0].upper() + text[1:]
    return text if text.endswith(".") else text + "."


def named_finding(message: str, where: str) -> str:
    """One sentence for a named mistake and where it shows ("Your V has the wrong sign (height
    measured downwards?) (for example at q = −1.75)."): the generic "Your V is not the potential
    energy …" beside it would say the same thing twice."""
    return as_sentence(message).removesuffix(".") + where + "."


def incorrect(
    part: str,
    got: Read,
    mutant: Mutant | None,
    sentence: str,
    witness: Mapping[str, float] | None,
    method: str,
    problem: Problem | None = None,
    values: str = "",
    reference: Compiled | None = None,
) -> Verdict:
    """A wrong single-expression answer: the named mistake (when the catalogue knows it),
    then what is wrong, with a point where it shows."""
    where = where_text(witness, problem, values)
    feedback = [named_finding(mutant.message, where) if mutant else sentence + where + "."]
    if problem is not None:
        expected = {"T": "kinetic", "V": "energy"}.get(part, "")
        dimensions = hint_for(problem, got, expected) if tells(mutant) else ""
        hints = [handout_numbers(problem, got, reference), dimensions]
        feedback += [hint for hint in hints if hint]
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
