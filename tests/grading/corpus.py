"""A labelled corpus of answers generated from every scene in the bank: correct rewrites of the
reference (expanded, factored, scaled, plus a constant or a total derivative, solved for the
accelerations, row-combined, moved across '=') and single-term mutations (sign, factor, dropped
term, sin/cos swap, wrong coordinate).

Every label is decided here independently of the grader: symbolic derivatives from sympy and
values at 50 digits from `evalf`, at points drawn with Python's own `random` — no part of
lagrade.judge.evaluate or lagrade.judge.equivalence is used. Shared by the tests and by
benchmarks/bench_check.py.
"""

from __future__ import annotations

import random
import zlib
from dataclasses import dataclass, field
from functools import cache

import mpmath
import sympy as sp

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.mechanics import lagrange as mech
from lagrade.notation.printer import plain

DIGITS = 50
POINTS = 5
# Mutation kinds the mistake catalogue covers: a wrong answer of these kinds must be named.
COVERED = {
    "lagrangian": {"sign", "drop", "double", "swap"},
    "momenta": {"sign", "drop", "double", "swap", "other_coordinate"},
    "eom": {"sign", "drop", "double", "swap"},
}


@dataclass(frozen=True)
class Item:
    """One labelled answer: the problem field, the part, the answer as text, the label
    ("correct" | "incorrect" | "V_minus_T"), how it was made, and (for expression-level
    parts) the sympy pair that `simplify` and `equals` are compared on."""

    problem: dict
    part: str
    answer: str | list[str]
    label: str
    kind: str
    pair: tuple[sp.Expr, sp.Expr] | None = field(default=None, compare=False)

    @property
    def covered(self) -> bool:
        return self.label == "incorrect" and self.kind in COVERED.get(self.part, ())


# --- independent high-precision evaluation ------------------------------------------------------


def _points(variant, seed: int, n: int = POINTS) -> list[dict]:
    rng = random.Random(seed)
    pts = []
    for _ in range(n):
        point: dict = {}
        for name, dom in variant.domains.items():
            lo, hi = dom.sample_range()
            point[variant.parameter_symbols[name]] = sp.Rational(
                rng.uniform(lo, hi)
            ).limit_denominator(10**6)
        for j in variant.jets:
            for s in (j.q, j.dot, j.ddot):
                x = rng.uniform(0.3, 2.2) * rng.choice((-1, 1))
                point[s] = sp.Rational(x).limit_denominator(10**6)
        point[mech.t] = sp.Rational(rng.uniform(0.1, 3.0)).limit_denominator(10**6)
        pts.append(point)
    return pts


def _value(expr: sp.Expr, point: dict) -> mpmath.mpf:
    v = sp.N(expr.xreplace(point), DIGITS)
    if v.is_real is False or not v.is_number:
        return mpmath.mpf("nan")
    return mpmath.mpf(sp.Float(v, DIGITS)._mpf_)


def _scale(expr: sp.Expr, point: dict) -> mpmath.mpf:
    return sum((abs(_value(t, point)) for t in sp.Add.make_args(sp.expand(expr))), mpmath.mpf(0))


def same_values(a: sp.Expr, b: sp.Expr, points: list[dict]) -> bool:
    """a = b at every point where the reference b is defined (at least 3 such points); a
    undefined where b is defined counts as different."""
    defined = 0
    with mpmath.workdps(DIGITS):
        for p in points:
            vb = _value(b, p)
            if not mpmath.isfinite(vb):
                continue
            defined += 1
            va = _value(a, p)
            if not mpmath.isfinite(va):
                return False
            if abs(va - vb) > mpmath.mpf(10) ** -35 * (_scale(a, p) + _scale(b, p) + 1e-300):
                return False
    assert defined >= 3, f"reference {b} undefined at too many points"
    return True


def _el(L: sp.Expr, jets) -> list[sp.Expr]:
    return [sp.expand(e) for e in mech.euler_lagrange(L, jets)]


def lagrangian_label(L_answer: sp.Expr, L_ref: sp.Expr, jets, points) -> str:
    """E(L′) = c E(L) with one constant c > 0: correct; c < 0: V_minus_T; else incorrect."""
    Ea, Eb = _el(L_answer, jets), _el(L_ref, jets)
    with mpmath.workdps(DIGITS):
        c = None
        for p in points:
            va = [_value(e, p) for e in Ea]
            vb = [_value(e, p) for e in Eb]
            nb = sum(x * x for x in vb)
            if nb == 0:
                continue
            cp = sum(x * y for x, y in zip(va, vb, strict=True)) / nb
            res = max(abs(x - cp * y) for x, y in zip(va, vb, strict=True))
            size = max(max(abs(x) for x in va), max(abs(y) for y in vb))
            if res > mpmath.mpf(10) ** -35 * size:
                return "incorrect"
            if c is None:
                c = cp
            elif abs(cp - c) > mpmath.mpf(10) ** -35 * abs(c):
                return "incorrect"
    if c is None or abs(c) < mpmath.mpf(10) ** -30:
        return "incorrect"
    return "correct" if c > 0 else "V_minus_T"


def _row(expr: sp.Expr, jets, p) -> list:
    """[A | c] of an equation expr = A q̈ + c at point p (A from symbolic derivatives)."""
    coeffs = [sp.diff(expr, j.ddot) for j in jets]
    const = expr.xreplace({j.ddot: 0 for j in jets})
    return [_value(a, p) for a in coeffs] + [_value(const, p)]


def row_in_span(expr: sp.Expr, reference: list[sp.Expr], jets, points) -> bool:
    """Is the equation a consequence of the reference rows at every point (det [R; row] = 0)?
    Also requires linearity in q̈ (the second derivative in q̈ vanishes)."""
    for j in jets:
        for k in jets:
            if sp.expand(sp.diff(expr, j.ddot, k.ddot)) != 0:
                return False
    with mpmath.workdps(DIGITS):
        for p in points:
            R = [_row(e, jets, p) for e in reference]
            r = _row(expr, jets, p)
            M = mpmath.matrix(R + [r])
            G = M * M.T
            norm = mpmath.mpf(1)
            for row in R + [r]:
                norm *= sum(x * x for x in row)
            if norm == 0:
                return False
            if abs(mpmath.det(G)) > mpmath.mpf(10) ** -30 * norm:
                return False
    return True


def conserved_label(Q: sp.Expr, system: mech.LagrangianSystem, points) -> str:
    """D_t Q = 0 on-shell at every point (q̈ from A q̈ = b at 50 digits), and Q not constant."""
    jets = system.jets
    if all(sp.diff(Q, s) == 0 for j in jets for s in (j.q, j.dot)) and sp.diff(Q, mech.t) == 0:
        return "incorrect"
    DQ = mech.total_derivative(Q, jets)
    A, b = system.mass_matrix, system.forcing
    with mpmath.workdps(DIGITS):
        for p in points:
            Am = mpmath.matrix([[_value(x, p) for x in A.row(i)] for i in range(A.rows)])
            bm = mpmath.matrix([_value(x, p) for x in b])
            acc = mpmath.lu_solve(Am, bm)
            q = dict(p)
            for k, j in enumerate(jets):
                q[j.ddot] = sp.Float(mpmath.nstr(acc[k], DIGITS), DIGITS)
            terms = sp.Add.make_args(sp.expand(DQ))
            vals = [_value(term, q) for term in terms]
            if abs(sum(vals)) > mpmath.mpf(10) ** -30 * (sum(abs(v) for v in vals) + 1e-300):
                return "incorrect"
    return "correct"


def _rank(quantities: list[sp.Expr], jets, point: dict) -> int:
    """Functional independence: the rank of the gradients in (t, q, q̇) at a point (50 digits)."""
    variables = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    with mpmath.workdps(DIGITS):
        rows = [[_value(sp.diff(Q, x), point) for x in variables] for Q in quantities]
        rank, chosen = 0, []
        for row in rows:
            trial = chosen + [row]
            M = mpmath.matrix(trial)
            G = M * M.T
            norm = mpmath.mpf(1)
            for r in trial:
                norm *= sum(x * x for x in r)
            if norm != 0 and abs(mpmath.det(G)) > mpmath.mpf(10) ** -30 * norm:
                chosen, rank = trial, rank + 1
    return rank


# --- mutations ------------------------------------------------------------------------------------


def swap(expr: sp.Expr) -> sp.Expr:
    if isinstance(expr, sp.sin):
        return sp.cos(swap(expr.args[0]))
    if isinstance(expr, sp.cos):
        return sp.sin(swap(expr.args[0]))
    return expr.func(*(swap(a) for a in expr.args)) if expr.args else expr


def single_term_mutations(expr: sp.Expr, jets) -> list[tuple[str, sp.Expr]]:
    """(kind, mutated expr) for each term: sign, drop, double, sin/cos swap, other coordinate."""
    terms = sp.Add.make_args(sp.expand(expr))
    out = []
    for k, term in enumerate(terms):
        rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
        out.append(("sign", rest - term))
        out.append(("drop", rest))
        out.append(("double", rest + 2 * term))
        swapped = swap(term)
        if swapped != term:
            out.append(("swap", rest + swapped))
        if len(jets) >= 2:
            a, b = jets[0], jets[1]
            moved = term.xreplace({a.q: b.q, b.q: a.q, a.dot: b.dot, b.dot: a.dot})
            if moved != term:
                out.append(("coordinate", rest + moved))
    return out


def _thin(items: list, limit: int, seed: int) -> list:
    if len(items) <= limit:
        return items
    return random.Random(seed).sample(items, limit)


# --- the corpus ----------------------------------------------------------------------------------


@cache
def corpus(
    scenes: tuple[str, ...] | None = None, per_part: int = 12, seeds: tuple = (None,)
) -> tuple[Item, ...]:
    """The labelled corpus for `scenes` (default: the whole bank), at most `per_part` mutations
    per part and scene."""
    items: list[Item] = []
    for sid in scenes or tuple(scene_ids()):
        for seed in seeds:
            items += _scene_items(sid, seed, per_part)
    return tuple(items)


def _scene_items(sid: str, seed, per_part: int) -> list[Item]:
    scene = get_scene(sid)
    v = scene.default if seed is None else scene.variant(seed)
    spec = {"scene": sid} if seed is None else {"scene": sid, "seed": seed}
    jets, system = v.jets, v.system
    L, T, V = v.lagrangian, v.kinetic_energy, v.potential_energy
    pts = _points(v, zlib.crc32(sid.encode()) % 1000 + 7, n=8)
    out: list[Item] = []
    rnd = random.Random(sid)

    # Lagrangian: rewrites, then mutations (labels from the Euler–Lagrange equations).
    params = list(v.parameter_symbols.values())
    q0 = jets[0]
    F = q0.q * (jets[1].q if len(jets) > 1 else mech.t) * params[0]
    rewrites = [
        ("expanded", sp.expand(L)),
        ("factored", sp.factor(T) - sp.factor(V)),
        ("scaled", 3 * L / 2),
        ("plus_constant", L + 7 * params[0] * params[-1]),
        ("plus_total_derivative", L + mech.total_derivative(F, jets)),
        (
            "trig",
            sp.expand(L).replace(
                lambda e: isinstance(e, sp.Pow) and isinstance(e.base, sp.cos) and e.exp == 2,
                lambda e: 1 - sp.sin(e.base.args[0]) ** 2,
            ),
        ),
        ("V_minus_T", V - T),
    ]
    mutations = _thin(single_term_mutations(L, jets), per_part, rnd.randrange(10**6))
    for kind, expr in rewrites + mutations:
        label = lagrangian_label(expr, L, jets, pts)
        out.append(Item(spec, "lagrangian", plain(expr), label, kind, (expr, L)))

    # Momenta: each p_j on its own.
    momenta = system.generalized_momenta
    for k, p in enumerate(momenta):

        def answer(e, k=k):
            return [plain(e if i == k else momenta[i]) for i in range(len(jets))]

        cases = [("factored", sp.factor(p))]
        cases += [(kind, e) for kind, e in single_term_mutations(p, jets)]
        for i, other in enumerate(momenta):
            if i != k:
                cases.append(("other_coordinate", other))
        for kind, expr in [cases[0]] + _thin(
            cases[1:], max(2, per_part // len(jets)), rnd.randrange(10**6)
        ):
            label = "correct" if same_values(expr, p, pts) else "incorrect"
            out.append(Item(spec, "momenta", answer(expr), label, kind, (expr, p)))

    # Equations of motion: the rows, rewritten or with one term of one row mutated.
    E = list(system.euler_lagrange)
    eom_cases = [("as_derived", E), ("scaled", [2 * E[0]] + E[1:])]
    if len(E) > 1:
        eom_cases.append(("row_combined", [sp.expand(E[0] + 3 * E[1])] + E[1:]))
    if len(E) == 1:
        A = system.mass_matrix[0, 0]
        eom_cases.append(("solved", [sp.Eq(jets[0].ddot, sp.cancel(system.forcing[0] / A))]))
    moved = [
        sp.Eq(
            sp.Add(*[t for t in sp.Add.make_args(e) if t.has(*[j.ddot for j in jets])]),
            -sp.Add(*[t for t in sp.Add.make_args(e) if not t.has(*[j.ddot for j in jets])]),
        )
        for e in E
    ]
    eom_cases.append(("moved_across", moved))
    muts = []
    for i, e in enumerate(E):
        for kind, m in single_term_mutations(e, jets):
            muts.append((kind, E[:i] + [m] + E[i + 1 :], m))
    for kind, rows in eom_cases:
        out.append(Item(spec, "eom", [_eq_text(r) for r in rows], "correct", kind))
    for kind, rows, m in _thin(muts, per_part, rnd.randrange(10**6)):
        label = "correct" if row_in_span(m, E, jets, pts) else "incorrect"
        out.append(Item(spec, "eom", [_eq_text(r) for r in rows], label, kind))

    # Conserved quantities: the key's, recombined, or mutated.
    key = list(system.conserved_quantities.values())
    if key:
        cons = [("key", key), ("scaled_plus_constant", [3 * key[-1] + 5] + key[:-1])]
        if len(key) > 1:
            cons.append(("sum", [key[0] + key[-1]] + key[1:]))
        for kind, qs in cons:
            out.append(Item(spec, "conserved", [plain(q) for q in qs], "correct", kind))
        for kind, m in _thin(
            single_term_mutations(key[-1], jets), max(3, per_part // 2), rnd.randrange(10**6)
        ):
            qs = key[:-1] + [m]
            label = conserved_label(m, system, pts)
            if label == "correct" and _rank(qs, jets, pts[0]) < _rank(key, jets, pts[0]):
                label = "incorrect"  # conserved, but no longer independent of the others
            out.append(Item(spec, "conserved", [plain(q) for q in qs], label, kind))

    # Expressions: the scene's quantities, rewritten or mutated.
    for name, expr in v.quantities.items():
        qspec = {**spec, "quantity": name}
        cases = [("expanded", sp.expand(expr)), ("rewritten", sp.together(sp.expand_trig(expr)))]
        cases += [(kind, e) for kind, e in _expression_mutations(expr, params)]
        for kind, e in cases:
            label = "correct" if same_values(e, expr, pts) else "incorrect"
            out.append(Item(qspec, "expression", plain(e), label, kind, (e, expr)))
    return out


def _expression_mutations(expr: sp.Expr, params) -> list[tuple[str, sp.Expr]]:
    out = [("swap", swap(expr)), ("double", 2 * expr)]
    free = [p for p in params if expr.has(p)]
    if len(free) >= 2:
        out.append(("wrong_parameter", expr.xreplace({free[0]: free[1], free[1]: free[0]})))
    if isinstance(expr, sp.Pow) and expr.exp == sp.Rational(1, 2):
        out.append(("missing_root", expr.base))
    return [(k, e) for k, e in out if e != expr]


def _eq_text(row) -> str:
    if isinstance(row, sp.Equality):
        return f"{plain(row.lhs)} = {plain(row.rhs)}"
    return f"{plain(row)} = 0"


def expected_status(item: Item) -> str:
    return "incorrect" if item.label == "V_minus_T" else item.label
