"""An omitted parameter is never taken for a number (issue 12). For every scene and every
parameter, the key's L and EOM with that parameter set to 1 (removed as a factor) are judged
against a label computed here, independently of the judge: sympy's own derivatives of L and a
50-digit evaluation at random points decide whether the changed answer still describes the
same motion (a factor of all of L, an additive constant, an overall factor of one equation)
or not. The handout's values do not matter: the same labels hold when every value is 1 (the
number a dropped m hid behind: the −1 of a difference matched it) and for values drawn by
hypothesis."""

from __future__ import annotations

import dataclasses
import random

import mpmath
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.judge.parts import run_checker
from lagrade.judge.problem import build_problem
from lagrade.mechanics.lagrange import t
from lagrade.notation.printer import plain

mpmath.mp.dps = 50


def _el(L, jets):
    """d/dt ∂L/∂q̇ − ∂L/∂q by sympy's diff and the chain rule (not the project's derivation)."""
    rows = []
    for j in jets:
        p = sp.diff(L, j.dot)
        dt = sp.diff(p, t) + sum(sp.diff(p, k.q) * k.dot + sp.diff(p, k.dot) * k.ddot for k in jets)
        rows.append(dt - sp.diff(L, j.q))
    return rows


def _draw(variant, rng):
    env = {}
    params = variant.parameter_symbols
    for name, dom in variant.domains.items():
        lo, hi = dom.sample_range()
        env[params[name]] = mpmath.mpf(rng.uniform(lo, hi))
    return env


def _jets_at(jets, rng):
    env = {t: mpmath.mpf(rng.uniform(0.1, 3))}
    for j in jets:
        lo, hi = (0.3, 2.0) if j.name in ("r", "rho", "l", "ell") else (-1.5, 1.5)
        env[j.q] = mpmath.mpf(rng.uniform(lo, hi))
        env[j.dot] = mpmath.mpf(rng.uniform(-2, 2))
        env[j.ddot] = mpmath.mpf(rng.uniform(-2, 2))
    return env


def _value(expr, env):
    return mpmath.mpf(
        sp.N(sp.S(expr).xreplace({s: sp.Float(str(v), 50) for s, v in env.items()}), 50)
    )


def _small(x, scale):
    return abs(x) <= mpmath.mpf("1e-30") * max(scale, mpmath.mpf(1))


def lagrangian_label(variant, changed) -> bool:
    """True when L′ gives the same motion: E(L′) = c E(L) with one c > 0 per parameter draw."""
    jets = variant.jets
    ref, new = _el(variant.lagrangian, jets), _el(changed, jets)
    rng = random.Random(7)
    for _ in range(3):
        params = _draw(variant, rng)
        c = None
        for _ in range(4):
            env = params | _jets_at(jets, rng)
            a = [_value(r, env) for r in ref]
            b = [_value(r, env) for r in new]
            scale = max(abs(x) for x in a + b)
            k = max(range(len(a)), key=lambda i: abs(a[i]))
            c = b[k] / a[k] if c is None else c
            if c <= 0 or not all(_small(y - c * x, scale) for x, y in zip(a, b, strict=True)):
                return False
    return True


def eom_label(variant, changed_rows) -> bool:
    """True when every changed row lies in the span of the Euler–Lagrange rows (rows are affine
    in the accelerations: A q̈ + b; a row A′ q̈ + b′ is in the span when b′ = A′ A⁻¹ b)."""
    jets = variant.jets
    ref = _el(variant.lagrangian, jets)
    rng = random.Random(11)
    zero = {j.ddot: 0 for j in jets}

    def affine(row, env):
        b = _value(row.xreplace(zero), env)
        return [_value(sp.diff(row, j.ddot), env) for j in jets], b

    for _ in range(3):
        params = _draw(variant, rng)
        for _ in range(3):
            env = params | _jets_at(jets, rng)
            A, b = zip(*(affine(r, env) for r in ref), strict=True)
            M = mpmath.matrix([list(row) for row in A])
            for row in changed_rows:
                a2, b2 = affine(row, env)
                lam = mpmath.lu_solve(M.T, mpmath.matrix(a2))
                got = sum(lam[i] * b[i] for i in range(len(b)))
                if not _small(b2 - got, max(abs(b2), abs(got), *map(abs, b))):
                    return False
    return True


CASES = [
    (scene_id, name)
    for scene_id in scene_ids()
    for name in get_scene(scene_id).default.parameter_symbols
]


def _problem(scene_id, values_of):
    """The scene's seed-1 variant as a Problem whose handout values are `values_of(name)`."""
    problem = build_problem({"scene": scene_id, "seed": 1})
    params = problem.parameters
    values = {params[n]: float(values_of(n)) for n in params}
    return dataclasses.replace(problem, values=values)


def _judge_both(scene_id, name, values_of):
    problem = _problem(scene_id, values_of)
    variant = problem.variant
    p = variant.parameter_symbols[name]
    L1 = variant.lagrangian.xreplace({p: sp.Integer(1)})
    rows = [r.xreplace({p: sp.Integer(1)}) for r in _el(variant.lagrangian, variant.jets)]
    if L1 == variant.lagrangian:
        pytest.skip(f"{name} does not occur in the L of {scene_id}")
    L_verdict = run_checker(problem, "lagrangian", plain(L1))
    eom_answer = [f"{plain(r)} = 0" for r in rows]
    eom_verdict = run_checker(problem, "eom", eom_answer)
    assert (L_verdict.status == "correct") == lagrangian_label(variant, L1), (
        scene_id,
        name,
        L_verdict,
    )
    assert (eom_verdict.status == "correct") == eom_label(variant, rows), (
        scene_id,
        name,
        eom_verdict,
    )
    return L_verdict, eom_verdict


@pytest.mark.parametrize(("scene_id", "name"), CASES)
def test_parameter_set_to_one_with_every_handout_value_one(scene_id, name):
    """The worst handout: every value 1, so every −1 and every dropped factor matches one."""
    _judge_both(scene_id, name, lambda n: 1.0)


def test_wedge_without_m_is_rejected_when_m_is_one_kg():
    """The case of the issue: wedge seed 2 has m = 1 kg; L and EOM written without m."""
    problem = build_problem({"scene": "wedge", "seed": 2})
    assert problem.variant.values["m"] == 1
    L = "1/2 (X_dot^2 + q_dot^2 + 2 X_dot q_dot cos(alpha)) + 1/2 M X_dot^2 - g (h - q sin(alpha))"
    assert problem.coordinates == ("X", "q")
    assert run_checker(problem, "lagrangian", L).status == "incorrect"
    eom = [
        "X_ddot + q_ddot cos(alpha) + M X_ddot = 0",
        "q_ddot + X_ddot cos(alpha) - g sin(alpha) = 0",
    ]
    assert run_checker(problem, "eom", eom).status == "incorrect"


@settings(
    max_examples=12,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=True,
)
@given(
    case=st.sampled_from(CASES),
    values=st.lists(st.sampled_from([1.0, 2.0, 0.5, 9.81, 1e-3, 3.0]), min_size=12, max_size=12),
)
def test_parameter_set_to_one_whatever_the_handout(case, values):
    scene_id, name = case
    names = sorted(get_scene(scene_id).default.parameter_symbols)
    chosen = dict(zip(names, values, strict=False))
    variant = get_scene(scene_id).variant(1)
    p = variant.parameter_symbols[name]
    if variant.lagrangian.xreplace({p: sp.Integer(1)}) == variant.lagrangian:
        return
    _judge_both(scene_id, name, lambda n: chosen.get(n, 1.0))
