"""The mistake catalogue: each common mistake, made on purpose, is named in the feedback in the
student's own terms."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.matching import is_for_row
from lagrade.judge.mutations import Mutant, swap_sin_cos, terms_changed
from lagrade.judge.problem import build_problem
from lagrade.judge.rows import _in_span_float, equation_rows
from lagrade.mechanics.lagrange import t
from lagrade.notation.printer import plain

from .conftest import HOOP, WEDGE, judge

W_T = "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"


@pytest.mark.parametrize(
    "problem, part, answer, kind, words",
    [
        (
            WEDGE,
            "lagrangian",
            "m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"
            " + m g q sin(alpha)",
            "dropped_half",
            "½",
        ),
        (WEDGE, "lagrangian", W_T + " - m g q sin(alpha)", "sign_of_V", "T − V"),
        (
            WEDGE,
            "lagrangian",
            "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha)",
            "missing_cross_term",
            "x_M_dot",
        ),
        (
            WEDGE,
            "lagrangian",
            "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot sin(alpha)) + 1/2 M x_M_dot^2"
            " + m g q cos(alpha)",
            "sin_cos_swapped",
            "sin and cos",
        ),
        (WEDGE, "lagrangian", W_T + " + g q sin(alpha)", "missing_factor", "factor m"),
        (
            HOOP,
            "lagrangian",
            "1/2 m R^2 theta_dot^2 + m g R cos(theta)",
            "missing_driven_term",
            "omega",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = m q_dot + m x_M_dot cos(alpha)", "p_q = m q_dot + m x_M_dot cos(alpha)"],
            "wrong_coordinate",
            "momentum of q",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = (M+m) x_M_dot", "p_q = m q_dot + m x_M_dot cos(alpha)"],
            "missing_cross_term",
            "lacks the term m*q_dot*cos(alpha)",
        ),
        (
            WEDGE,
            "momenta",
            ["p_x_M = (M+m) x_M_dot + m q_dot cos(alpha)", "p_q = m g sin(alpha)"],
            "force_not_momentum",
            "∂L/∂q",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot + m q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = -m g sin(alpha)",
            ],
            "el_sign",
            "minus sign",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot - m q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = m g sin(alpha)",
            ],
            "wrong_sign",
            "wrong sign",
        ),
        (
            WEDGE,
            "eom",
            [
                "(M+m) x_M_ddot + q_ddot cos(alpha) = 0",
                "m q_ddot + m x_M_ddot cos(alpha) = m g sin(alpha)",
            ],
            "missing_factor",
            "factor m",
        ),
        (
            WEDGE,
            "T",
            "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2",
            "missing_cross_term",
            "cross term",
        ),
        (WEDGE, "V", "-m g q cos(alpha)", "sin_cos_swapped", "sin and cos"),
        (
            HOOP,
            "conserved",
            ["1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"],
            "energy_not_conserved",
            "T + V",
        ),
    ],
)
def test_mistake_is_named(problem, part, answer, kind, words):
    v = judge(problem, part, answer)
    assert v.status == "incorrect"
    assert kind in v.mistakes, (v.mistakes, v.feedback)
    assert any(words.lower() in f.lower() for f in v.feedback), v.feedback


def test_cyclic_because_only_the_velocity_is_missing():
    """A coordinate whose velocity is absent from L is not cyclic for that reason."""
    problem = {
        "lagrangian": "m*r**2/2 + m*r*theta_dot**2/2 - k*r",
        "coordinates": ["r", "theta"],
        "parameters": {"m": "positive", "k": "positive"},
    }
    v = judge(problem, "cyclic", ["theta", "r"])
    assert v.mistakes == ("velocity_missing_not_cyclic",)
    assert "only its velocity r_dot is missing" in v.feedback[0]


def test_mutations_that_change_nothing_are_left_out():
    """Dropping the constant m g h from L changes no motion: not a mistake to name."""
    catalogue = build_problem(WEDGE).catalogue
    assert all("g*h*m" not in m.message for m in catalogue.lagrangian_mutants)
    assert any("g*m*q*sin(alpha)" in m.message for m in catalogue.lagrangian_mutants)


def test_catalogue_is_built_for_every_scene():
    from lagrade.bank.registry import scene_ids

    for sid in scene_ids():
        problem = build_problem({"scene": sid})
        cat = problem.catalogue
        if len(sp.Add.make_args(problem.lagrangian)) == 1:
            # The free wheel's ½Iθ̇²: every one-term mutation is a multiple with the same motion.
            assert cat.lagrangian_mutants == [], sid
            continue
        assert cat.lagrangian_mutants, sid
        assert all(m.message for m in cat.lagrangian_mutants)


def test_helpers():
    x = sp.Symbol("x")
    assert plain(x**2 / 2) == "x^2/2"
    assert swap_sin_cos(sp.sin(x) * sp.cos(2 * x)) == sp.cos(x) * sp.sin(2 * x)


# --- the vectorised matching is the one-at-a-time test ------------------------------------------


def _one_at_a_time(candidates, test):
    """The first candidate that passes `test`, skipping those that cannot be evaluated."""
    for c in candidates:
        try:
            with np.errstate(all="ignore"):
                if test(c):
                    return c
        except (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError):
            continue
    return None


def _vanishes(r, size) -> bool:
    return bool(np.all(np.isfinite(r)) and np.all(np.abs(r) <= 1e-9 * size))


def _values(m, points):
    value, size = Compiled.of(m.expr).values(points.env)
    return np.broadcast_to(value, (points.n,)), np.broadcast_to(size, (points.n,))


def _slow_plain(mutants, a, sa, points):
    return _one_at_a_time(
        mutants, lambda m: _vanishes(a - _values(m, points)[0], sa + _values(m, points)[1])
    )


def _slow_offset(mutants, a, sa, points):
    starts = np.searchsorted(points.group, points.group)

    def test(m):
        b, sb = _values(m, points)
        d = a - b
        return _vanishes(d - d[starts], sa + sb + np.abs(d[starts]))

    return _one_at_a_time(mutants, test)


def _slow_lagrangian(problem, answer, points):
    """One mutant at a time: E(answer) = c E(mutant), c ≠ 0 per group, and the mistake's fix
    applied to the answer as written gives a right L; of those, the fewest terms changed
    (constants aside), the first of equals."""
    Ea, Sa = euler_lagrange_values(answer, problem.jets, points.env)
    Er, Sr = euler_lagrange_values(problem.L, problem.jets, points.env)
    moving = {s for j in problem.jets for s in (j.q, j.dot)} | {t}

    def per_group_fit(E, S, target, target_size):
        r, size, factors = np.empty_like(E), np.empty_like(E), []
        for g in np.unique(points.group):
            rows = points.group == g
            den = float(np.sum(target[rows] ** 2))
            if den == 0:
                return None
            c = float(np.sum(E[rows] * target[rows])) / den
            factors.append(c)
            r[rows] = E[rows] - c * target[rows]
            size[rows] = S[rows] + abs(c) * target_size[rows]
        return factors if _vanishes(r, size) else None

    def test(m):
        Eb, Sb = euler_lagrange_values(Compiled.of(m.expr), problem.jets, points.env)
        spans = per_group_fit(Ea, Sa, Eb, Sb)
        if spans is None or any(abs(c) < 1e-9 for c in spans):
            return False
        fixed = per_group_fit(Ea - (Eb - Er), Sa + Sb + Sr, Er, np.zeros_like(Sr))
        return fixed is not None and all(c > 0 for c in fixed)

    true = [m for m in problem.catalogue.lagrangian_mutants if _passes(test, m)]
    counts = lambda term: bool(term.free_symbols & moving)  # noqa: E731
    L = problem.catalogue.split.T - problem.catalogue.split.V
    return min(true, key=lambda m: terms_changed(m, L, counts), default=None)


def _passes(test, candidate) -> bool:
    try:
        with np.errstate(all="ignore"):
            return bool(test(candidate))
    except (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError):
        return False


def _slow_row(problem, student, points):
    """One row mutant at a time: the mutated system spans the student's equation, which is its
    mutated row, and undoing the mistake in the equation as written (either sign) leaves a
    right equation; of those, the fewest terms changed, the first of equals."""
    jets = problem.jets
    s = equation_rows([student], jets, points.env)
    ref = equation_rows(problem.euler_lagrange, jets, points.env)
    E = problem.system.euler_lagrange

    def test(pair):
        i, m = pair
        rows = equation_rows([Compiled.of(m.expr)], jets, points.env)
        R, Rs = ref.coef.astype(float).copy(), ref.size.astype(float).copy()
        R[:, i, :], Rs[:, i] = rows.coef[:, 0, :], rows.size[:, 0]
        in_span = _vanishes(*_in_span_float(s.coef[:, 0, :], s.size[:, 0], R, Rs))
        # and the student's equation is the mutated row itself (issue 12: the row named)
        if not (in_span and is_for_row(s.coef[:, 0, :].astype(float), R, i, points.group)):
            return False
        delta = rows.coef[:, 0, :].astype(float) - ref.coef[:, i, :].astype(float)
        scale = s.size[:, 0] + np.linalg.norm(delta, axis=1) + ref.size[:, i]
        x = s.coef[:, 0, :].astype(float)
        return any(
            _vanishes(*_in_span_float(x - sign * delta, scale, ref.coef, ref.size))
            for sign in (1.0, -1.0)
        )

    true = [pair for pair in problem.catalogue.row_mutants if _passes(test, pair)]
    found = min(true, key=lambda pair: terms_changed(pair[1], E[pair[0]]), default=None)
    return None if found is None else found[1]


@pytest.mark.parametrize("spec", [WEDGE, HOOP, {"scene": "wedge", "seed": 3}])
def test_vectorised_matching_names_the_same_mutant_as_one_at_a_time(spec):
    """Each match tests all mutants at once; it must return what testing them one by one in
    the catalogue's order returns (of the true explanations, the fewest terms changed; the
    first, most specific, of equals), for answers that are mutants, multiples or shifts of
    mutants, and right answers (no match)."""
    problem = build_problem(spec)
    cat = problem.catalogue
    named = 0
    with np.errstate(all="ignore"):
        points = problem.points("lagrangian")
        ms = cat.lagrangian_mutants
        for e in [m.expr for m in ms] + [3 * m.expr for m in ms[:4]] + [problem.lagrangian]:
            a = Compiled.of(e)
            got = cat.match_lagrangian(a, points)
            assert got is _slow_lagrangian(problem, a, points), e
            named += got is not None
        for part, ms, match, slow in (
            ("T", cat.kinetic_mutants, cat.match_plain, _slow_plain),
            ("V", cat.potential_mutants, cat.match_offset, _slow_offset),
            ("conserved", cat.conserved_mutants, cat.match_offset, _slow_offset),
        ):
            points = problem.points(part)
            for e in [m.expr for m in ms] + [m.expr + 1 for m in ms] + [2 * m.expr for m in ms]:
                a = Compiled.of(e)
                got = match(ms, a, points)
                assert got is slow(ms, *_values(Mutant("", "", e), points), points), (part, e)
                named += got is not None
        points = problem.points("eom")
        E = problem.system.euler_lagrange
        pairs = cat.row_mutants
        answers = [m.expr for _, m in pairs] + [2 * m.expr + E[-1 - i] for i, m in pairs[:4]]
        for e in [*answers, *E]:
            a = Compiled.of(e)
            got = cat.match_row(a, points)
            assert got is _slow_row(problem, a, points), e
            named += got is not None
    # every mutant, given as the answer, is named (itself or an earlier equivalent one)
    sizes = [cat.lagrangian_mutants, cat.kinetic_mutants, cat.potential_mutants]
    assert named >= sum(map(len, sizes)) + len(cat.conserved_mutants) + len(pairs)


def test_matching_skips_mutants_that_cannot_be_evaluated_and_follows_the_list():
    """A mutant that fails to compile is never named; a list changed in place is re-stacked."""
    problem = build_problem(WEDGE)
    cat = problem.catalogue
    points = problem.points("T")
    T = problem.kinetic_energy
    bad = Mutant("bad", "cannot be evaluated", sp.Function("f")(sp.Symbol("q")))
    twice = Mutant("twice", "twice T", 2 * T)
    mutants = [bad, twice]
    assert cat.match_plain(mutants, Compiled.of(2 * T), points) is twice
    assert cat.match_plain([bad], Compiled.of(2 * T), points) is None
    mutants[1] = Mutant("thrice", "thrice T", 3 * T)
    assert cat.match_plain(mutants, Compiled.of(2 * T), points) is None
    assert cat.match_plain(mutants, Compiled.of(3 * T), points) is mutants[1]


def test_the_equations_of_a_mistaken_lagrangian_are_derived_from_the_change_alone():
    """The catalogue forms E(L_mut) as E(L) + E(L_mut − L); that must be the very expression
    that differentiating L_mut whole gives, so that the rows (and the feedback) are unchanged."""
    from lagrade.bank.registry import scene_ids
    from lagrade.judge.mutations import KINETIC_KINDS, iter_equation_mutants
    from lagrade.mechanics.lagrange import LagrangianSystem

    checked = 0
    for sid in scene_ids():
        problem = build_problem({"scene": sid, "seed": 1})
        system, jets = problem.system, problem.jets
        early = [
            m
            for m in problem.catalogue._lagrangian_early
            if m.kind == "sign_of_V" or m.kind in KINETIC_KINDS
        ]
        whole = []
        for m in early:
            rows = LagrangianSystem(m.expr, jets).euler_lagrange
            for i, row in enumerate(rows):
                if sp.expand(row - system.euler_lagrange[i]) != 0:
                    whole.append((i, m.kind, row))
        derived = [
            (i, m.kind, m.expr)
            for i, m in iter_equation_mutants(system, jets, early, [])
            if m.kind == "sign_of_V" or m.kind in KINETIC_KINDS
        ]
        assert derived == whole, sid
        checked += len(whole)
    assert checked > 50


def _rebuilt_swap(expr):
    """swap_sin_cos as it was: every node rebuilt."""
    if isinstance(expr, sp.sin | sp.cos):
        return (sp.cos if isinstance(expr, sp.sin) else sp.sin)(_rebuilt_swap(expr.args[0]))
    return expr.func(*map(_rebuilt_swap, expr.args)) if expr.args else expr


def test_swap_sin_cos_keeps_what_has_no_trig():
    """A subtree without sin or cos comes back as itself (not rebuilt), and a swapped tree is
    the one a full rebuild gives, printed alike."""
    x, m, g = sp.symbols("x m g", positive=True)
    plain_term = m * g * x**2 / 2
    assert swap_sin_cos(plain_term) is plain_term
    term = m * x**2 * sp.sin(x) ** 2 / 2 + g * sp.cos(2 * x) + g * m * x
    swapped = m * x**2 * sp.cos(x) ** 2 / 2 + g * sp.sin(2 * x) + g * m * x
    assert swap_sin_cos(term) == swapped
    assert sp.srepr(swap_sin_cos(term)) == sp.srepr(_rebuilt_swap(term))
