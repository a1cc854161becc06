"""How a student's (valid) transformation equations relate to the statement's: the same map; an
affine relation q = A q' + c between the statement's coordinates q and the student's q' of the
same names (an angle measured the other way or from the other axis, a distance from the other
end or from another origin, two coordinates swapped); or another valid choice altogether.

Found by numbers: at the sample points the statement's coordinates are solved for from the
student's positions (Gauss–Newton from a few starts, every evaluation by lagrade's own compiler),
A = ∂q/∂q' is read off the Jacobians, and the relation is affine when A and c = q − A q' are the
same at every point of a parameter draw (c modulo 2π for an angle the positions repeat after).
It is then put in words, and where it can be, in closed form ("the statement's q is
h/sin(alpha) - q in yours"), the closed form verified at the points: that closed form is also a
way to carry a potential the scene writes in its coordinates (k x²/2) over to the student's.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

from lagrade.errors import UnsupportedExpression
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.derivatives import gradient
from lagrade.judge.equivalence import group_starts
from lagrade.judge.problem import Problem
from lagrade.judge.situation import angles, symbol_text
from lagrade.judge.tolerances import COORDINATE_MAP, ROUNDING, SAME_VALUE
from lagrade.notation import plain

#: Gauss–Newton steps per start; each converges in a few where it converges at all.
_STEPS = 40


@dataclass(frozen=True)
class Relation:
    """The statement's coordinates in the student's. `same`: the very same map. `affine`: q =
    A q' + c at every point; `closed_form` then holds q_j ↦ (A q' + c)_j for every coordinate
    when each offset was found in closed form (and verified), else None. `description` says
    in words how the student's coordinates differ ("your φ is measured the other way from the
    statement's (…)"); empty when they do not."""

    same: bool
    affine: bool
    closed_form: Mapping[sp.Symbol, sp.Expr] | None
    description: str


SAME = Relation(True, True, None, "")


def relate(problem: Problem, positions: Mapping[str, sp.Expr]) -> Relation:
    """How the student's `positions` (keyed like the statement's transformation, in the same
    coordinate names) relate to the statement's transformation equations."""
    variant = problem.variant
    assert variant is not None
    names = list(variant.transformation)
    points = problem.points("transformation")
    coords = [j.q for j in problem.jets]
    theirs = [Compiled.of(variant.transformation[k]) for k in names]
    mine = [Compiled.of(positions[k]) for k in names]
    try:
        with np.errstate(all="ignore"):
            X = _stack(mine, points.env, points.n)
            Y = _stack(theirs, points.env, points.n)
    except UnsupportedExpression:
        return _different(problem)
    ok = np.all(np.isfinite(X), axis=1) & np.all(np.isfinite(Y), axis=1)
    if not ok.any():
        return _different(problem)
    if np.all(np.abs(X - Y)[ok] <= COORDINATE_MAP * (1 + np.abs(X) + np.abs(Y))[ok]):
        return SAME
    env = {s: v[ok] for s, v in points.env.items()}
    group = points.group[ok]
    with np.errstate(all="ignore"):
        found = _affine(theirs, mine, coords, env, group, X[ok])
    if found is None:
        return _different(problem)
    A, offsets, periodic = found
    closed = _closed_form(problem, positions, A, offsets, env, group, X[ok])
    return Relation(False, True, closed, _describe(problem, A, offsets, closed, periodic))


def _different(problem: Problem) -> Relation:
    return Relation(
        False,
        False,
        None,
        "they are a different choice of coordinates, related to the statement's nonlinearly",
    )


def _stack(compiled: Sequence[Compiled], env: Mapping, n: int) -> np.ndarray:
    """(points, components) real values; NaN where a value is not real and finite."""
    columns = []
    for c in compiled:
        v = np.asarray(to_length(c.values(env)[0], n), dtype=complex)
        real = np.where(np.abs(v.imag) <= ROUNDING * (1 + np.abs(v.real)), v.real, np.nan)
        columns.append(real)
    return np.stack(columns, axis=1)


def _jacobian(compiled: Sequence[Compiled], coords: list[sp.Symbol], env: Mapping, n: int):
    """∂(components)/∂q at the points: (points, components, coordinates)."""
    rows = []
    for c in compiled:
        terms = gradient(c, coords, env)
        rows.append(sum(terms) if terms else np.zeros((n, len(coords))))
    return np.stack([np.broadcast_to(r, (n, len(coords))) for r in rows], axis=1).astype(float)


def _at(env: Mapping, coords: list[sp.Symbol], q: np.ndarray) -> dict:
    return {**env, **{c: q[:, k] for k, c in enumerate(coords)}}


def _solve(theirs, coords, env, target: np.ndarray, start: np.ndarray):
    """The statement's q with P(q) = target at each point (Gauss–Newton from `start`), and
    where it converged."""
    n = len(target)
    q = start.copy()
    scale = 1 + np.abs(target)
    done = np.zeros(n, dtype=bool)
    for _ in range(_STEPS):
        here = _at(env, coords, q)
        F = _stack(theirs, here, n) - target
        done = np.all(np.abs(F) <= COORDINATE_MAP * scale / 100, axis=1)
        if done.all() or not np.all(np.isfinite(F)):
            break
        J = _jacobian(theirs, coords, here, n)
        step = -(np.linalg.pinv(J) @ F[:, :, None])[:, :, 0]
        size = np.linalg.norm(step, axis=1, keepdims=True)
        q = q + step / np.maximum(1.0, size)  # a trust region of one unit per step
    return q, done


def _periodic(theirs, coords, env, q: np.ndarray, k: int) -> bool:
    """The statement's positions repeat when coordinate k turns by 2π (an angle)."""
    n = len(q)
    turned = q.copy()
    turned[:, k] += 2 * math.pi
    a = _stack(theirs, _at(env, coords, q), n)
    b = _stack(theirs, _at(env, coords, turned), n)
    return bool(np.all(np.abs(a - b) <= COORDINATE_MAP * (1 + np.abs(a) + np.abs(b))))


def _wrapped(x: np.ndarray) -> np.ndarray:
    """x modulo 2π in (−π, π] (half a turn is π, never −π)."""
    w = (x + math.pi) % (2 * math.pi) - math.pi
    return np.where(np.abs(w + math.pi) <= SAME_VALUE, math.pi, w)


def _constant_per_group(values: np.ndarray, group: np.ndarray, wrap: bool = False) -> bool:
    for g in np.unique(group):
        v = values[group == g]
        d = v - v[0]
        if wrap:
            d = _wrapped(d)
        if not np.all(np.abs(d) <= COORDINATE_MAP * 10 * (1 + np.abs(v[0]))):
            return False
    return True


def _affine(theirs, mine, coords, env, group, target):
    """(A, offsets per point, periodic coordinates) when q = A q' + c, else None."""
    n_pts, n = len(target), len(coords)
    q_mine = np.stack([np.asarray(env[c], dtype=float) for c in coords], axis=1)
    J_mine = _jacobian(mine, coords, env, n_pts)
    starts = [
        q_mine,
        -q_mine,
        math.pi / 2 - q_mine,
        q_mine + math.pi / 2,
        math.pi - q_mine,
        q_mine - math.pi / 2,
        q_mine + math.pi,
        np.full_like(q_mine, 0.5),
    ]
    found = []
    for start in starts:
        q, done = _solve(theirs, coords, env, target, start)
        if not done.all():
            continue
        A = np.linalg.pinv(_jacobian(theirs, coords, _at(env, coords, q), n_pts)) @ J_mine
        if not _constant_per_group(A.reshape(n_pts, n * n), group):
            continue
        periodic = [_periodic(theirs, coords, env, q, k) for k in range(n)]
        offsets = q - (A @ q_mine[:, :, None])[:, :, 0]
        for k in range(n):
            if periodic[k]:
                offsets[:, k] = _wrapped(offsets[:, k])
        if all(_constant_per_group(offsets[:, k], group, periodic[k]) for k in range(n)):
            found.append((_changes(A, offsets), len(found), (A, offsets, periodic)))
            if found[-1][0] <= 1:
                break  # one coordinate changed once: nothing simpler differs
    # Where two branches of the statement's map reach the student's positions (r and θ, or −r
    # and θ + π), the relation that changes least is the one a person means.
    return min(found)[2] if found else None


def _changes(A: np.ndarray, offsets: np.ndarray) -> int:
    """How much a relation changes: coordinates not carried over as they are, and offsets."""
    n = A.shape[1]
    rows = int(np.sum(np.any(np.abs(A[0] - np.eye(n)) > SAME_VALUE, axis=1)))
    return rows + int(np.sum(np.any(np.abs(offsets) > SAME_VALUE, axis=0)))


# --- the relation in closed form -----------------------------------------------------------------


def _recognised(x: float) -> sp.Expr | None:
    """A number as a multiple of π/12 or a simple fraction, when it is one."""
    for denominator in (1, 2, 3, 4, 6, 12):
        k = round(x / math.pi * denominator)
        if k and abs(x - k * math.pi / denominator) <= SAME_VALUE * (1 + abs(x)):
            return sp.Rational(k, denominator) * sp.pi
    f = Fraction(x).limit_denominator(1000)
    if abs(float(f) - x) <= SAME_VALUE * (1 + abs(x)):
        return sp.Rational(f.numerator, f.denominator)
    return None


def _closed_form(problem, positions, A, offsets, env, group, target):
    """q_j ↦ (A q' + c)_j in closed form, verified at the points, or None: A must be a
    matrix of plain numbers, each offset a recognised number, a multiple of π plus or minus a
    parameter, or the solution of a position component that holds it linearly."""
    coords = [j.q for j in problem.jets]
    firsts = np.unique(group_starts(group))
    if not _constant_per_group(A.reshape(len(A), -1), np.zeros(len(A), dtype=int)):
        return None  # A depends on the parameters
    matrix = [
        [_recognised(float(a)) if abs(a) > ROUNDING else sp.S.Zero for a in row] for row in A[0]
    ]
    if any(a is None for row in matrix for a in row):
        return None
    linear = [sum((a * c for a, c in zip(row, coords, strict=True)), sp.S.Zero) for row in matrix]
    closed: dict[sp.Symbol, sp.Expr] = {}
    unknown = {}
    for k, c in enumerate(coords):
        values = offsets[firsts, k]
        offset = _offset(values, env, firsts, problem)
        if offset is None:
            unknown[k] = sp.Dummy(f"c{k}")
            closed[c] = linear[k] + unknown[k]
        else:
            closed[c] = linear[k] + offset
    for k, dummy in unknown.items():
        solved = _solved_offset(problem, closed, dummy, positions, offsets[firsts, k], env, firsts)
        if solved is None:
            return None
        closed[coords[k]] = closed[coords[k]].xreplace({dummy: solved})
    # the closed form must give the student's positions at every point
    variant = problem.variant
    composed = [Compiled.of(e.xreplace(closed)) for e in variant.transformation.values()]
    try:
        Y = _stack(composed, env, len(target))
    except UnsupportedExpression:
        return None
    if not np.all(np.abs(Y - target) <= COORDINATE_MAP * (1 + np.abs(target))):
        return None
    return closed


def _offset(values: np.ndarray, env, firsts, problem: Problem) -> sp.Expr | None:
    """An offset's closed form from its value in each parameter draw: a number, or a π/12
    multiple plus or minus one parameter (an angle measured from the incline: φ + α)."""
    if np.all(np.abs(values - values[0]) <= SAME_VALUE * (1 + abs(values[0]))):
        return _recognised(float(values[0]))
    for symbol in problem.domains:
        p = np.asarray(env[symbol], dtype=float)[firsts]
        for b in (1, -1, 2, -2, sp.Rational(1, 2), sp.Rational(-1, 2)):
            rest = values - float(b) * p
            if np.all(np.abs(rest - rest[0]) <= SAME_VALUE * (1 + np.abs(values))):
                base = _recognised(float(rest[0])) if abs(rest[0]) > ROUNDING else sp.S.Zero
                if base is not None:
                    return base + b * symbol
    return None


def _solved_offset(
    problem: Problem,
    closed: Mapping[sp.Symbol, sp.Expr],
    dummy: sp.Dummy,
    positions: Mapping[str, sp.Expr],
    values: np.ndarray,
    env: Mapping,
    firsts: np.ndarray,
) -> sp.Expr | None:
    """The offset from a position component that holds it linearly (a distance measured from
    the other end: x_M + (c − q) cos α = x_M + h/tan α − q cos α gives c = h/sin α), when the
    solution is free of the coordinates and has the offset's value in each parameter draw."""
    variant = problem.variant
    coords = [j.q for j in problem.jets]
    for name, expr in variant.transformation.items():
        difference = sp.expand(expr.xreplace(closed) - positions[name])
        if not difference.has(dummy):
            continue
        a = sp.diff(difference, dummy)
        if a.has(dummy, *coords) or a == 0:
            continue
        solution = sp.expand(-difference.xreplace({dummy: sp.S.Zero}) / a)
        solution = sp.trigsimp(sp.cancel(solution))
        if solution.has(*coords) or solution.atoms(sp.Dummy):
            continue
        try:
            got = Compiled.of(solution).values({s: np.asarray(v)[firsts] for s, v in env.items()})[
                0
            ]
        except UnsupportedExpression:
            continue
        got = np.asarray(to_length(got, len(firsts)), dtype=complex)
        if np.all(np.abs(got - values) <= COORDINATE_MAP * (1 + np.abs(values))):
            return solution
    return None


# --- the relation in words -----------------------------------------------------------------------


def _describe(
    problem: Problem,
    A: np.ndarray,
    offsets: np.ndarray,
    closed: Mapping[sp.Symbol, sp.Expr] | None,
    periodic: Sequence[bool],
) -> str:
    """How each of the student's coordinates differs from the statement's, joined by "; ":
    "your φ is measured the other way from the statement's (the statement's φ is -phi in
    yours)"."""
    angular = angles(problem)
    jets = problem.jets
    said = []
    for k, j in enumerate(jets):
        row = A[0, k]
        c = offsets[:, k]
        zero = bool(np.all(np.abs(_wrapped(c) if periodic[k] else c) <= SAME_VALUE))
        unit = [i for i in range(len(jets)) if abs(row[i]) > SAME_VALUE]
        if unit == [k] and abs(row[k] - 1) <= SAME_VALUE and zero:
            continue  # this coordinate is the statement's
        words = _words(j.name, jets, row, unit, k, c, zero, j.name in angular)
        if closed is not None:
            formula = shown(closed[j.q], frozenset(problem.coordinates))
            words += f" (the statement's {symbol_text(j.name)} is {formula} in yours)"
        said.append(words)
    return "; ".join(said) if said else "your coordinates are the statement's, written differently"


def shown(expr: sp.Expr, coordinates: frozenset[str] = frozenset()) -> str:
    """An expression as the feedback quotes it: Greek letters and π as such, a coordinate
    with a plus sign first and one with a minus sign after the constants (x_2 - a, π/2 - φ)."""
    names = {s: sp.Symbol(symbol_text(s.name)) for s in expr.free_symbols}
    renamed = expr.xreplace({**names, sp.pi: sp.Symbol("π")})
    moved = {names[s] for s in names if s.name in coordinates}
    terms = sp.Add.make_args(renamed)
    moving = [x for x in terms if x.free_symbols & moved]
    fixed = [x for x in terms if not x.free_symbols & moved]
    leading = bool(moving) and not moving[0].could_extract_minus_sign()
    ordered = moving + fixed if leading else fixed + moving
    text = plain(ordered[0])
    for x in ordered[1:]:
        text += f" - {plain(-x)}" if x.could_extract_minus_sign() else f" + {plain(x)}"
    return text


def _turn(c: np.ndarray) -> str:
    """How far an angle's zero is turned: "quarter", "half" or "other"."""
    w = np.abs(_wrapped(c))
    if np.all(np.abs(w - math.pi / 2) <= SAME_VALUE):
        return "quarter"
    if np.all(np.abs(w - math.pi) <= SAME_VALUE):
        return "half"
    return "other"


def _words(name, jets, row, unit, k, c, zero: bool, angle: bool) -> str:
    mine = f"your {symbol_text(name)}"
    if len(unit) != 1 or abs(abs(row[unit[0]]) - 1) > SAME_VALUE:
        return f"your {symbol_text(name)} is another quantity"
    other = unit[0]
    flipped = row[other] < 0
    if other != k:
        theirs = symbol_text(jets[other].name)
        return (
            f"your {theirs} is what the statement calls {symbol_text(name)}"
            + (", measured the other way" if flipped else "")
            + ("" if zero else ", from another zero")
        )
    if angle:
        turn = _turn(c)
        if flipped:
            if zero:
                return f"{mine} is measured the other way from the statement's"
            return {
                "quarter": f"{mine} is measured from the other axis",
                "half": f"{mine} is measured the other way, from the opposite direction",
            }.get(turn, f"{mine} is measured the other way, from another direction")
        return {
            "quarter": f"{mine} is measured from a direction a quarter turn from the statement's",
            "half": f"{mine} is measured from the opposite direction",
        }.get(turn, f"{mine} is measured from another direction")
    if flipped:
        if zero:
            return f"{mine} is measured in the opposite direction from the statement's"
        return f"{mine} is measured from the other end"
    return f"{mine} is measured from another origin"
