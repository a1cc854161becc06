"""A mutant that changes a few terms of a reference is evaluated as the reference plus its scaled
pieces (`Combination`): its values, Euler–Lagrange values and equation rows must be those of the
whole mutated expression compiled on its own, and its expression the one the old construction
(`rest ± term`) formed."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.judge.compiled import Combination, Compiled
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import MP, MP_DIGITS
from lagrade.judge.mutations import Mutant, iter_term_mutants, swap_sin_cos
from lagrade.judge.problem import build_problem
from lagrade.judge.rows import equation_rows

from .conftest import HOOP, WEDGE


def _close(a, b, size) -> bool:
    a, b, size = (np.asarray(x, float) for x in (a, b, size))
    return bool(np.all(np.abs(a - b) <= 1e-12 * (size + 1e-300)))


@pytest.mark.parametrize("spec", [WEDGE, HOOP, {"scene": "pendulum_on_cart", "seed": 2}])
def test_combined_mutants_evaluate_as_the_whole_expression(spec):
    problem = build_problem(spec)
    cat = problem.catalogue
    jets = problem.jets
    combined = 0
    with np.errstate(all="ignore"):
        points = problem.points("eom")
        for _i, m in cat.row_mutants:
            mine = cat.compiled(m)
            if not m.pieces:
                continue
            assert isinstance(mine, Combination)
            whole = equation_rows([Compiled.of(m.expr)], jets, points.env)
            fast = cat.mutant_rows(m, points)
            assert _close(fast.coef[:, 0, :], whole.coef[:, 0, :], fast.size[:, 0, None])
            assert _close(fast.nonlinear, whole.nonlinear, fast.size)
            combined += 1
        for part, mutants, fast, whole in (
            (
                "lagrangian",
                cat.lagrangian_mutants,
                cat.el_values,
                lambda c, env: euler_lagrange_values(c, jets, env),
            ),
            ("T", cat.kinetic_mutants, cat.values, lambda c, env: c.values(env)),
        ):
            points = problem.points(part)
            for m in (m for m in mutants if m.pieces):
                value, size = fast(cat.compiled(m), points)
                expected, _ = whole(Compiled.of(m.expr), points.env)
                assert _close(value, np.broadcast_to(expected, value.shape), size), (part, m)
                combined += 1
    assert combined > 20


def test_a_combined_lagrangian_has_the_equations_of_its_sum_at_high_precision():
    """The keepers decide a float-unsure "same dynamics" in mpmath from the hyper-dual values
    of the compiled mutant: a Combination's must be those of the whole expression there too."""
    problem = build_problem(WEDGE)
    cat, jets = problem.catalogue, problem.jets
    points = problem.points("lagrangian")
    env = points.arrays(MP)
    checked = 0
    with mpmath.workdps(MP_DIGITS):
        for m in [m for m in cat.lagrangian_mutants if m.pieces][:6]:
            E, S = euler_lagrange_values(cat.compiled(m), jets, env, MP)
            E_whole, _ = euler_lagrange_values(Compiled.of(m.expr), jets, env, MP)
            for e, w, s in zip(E.ravel(), E_whole.ravel(), S.ravel(), strict=True):
                assert abs(e - w) <= mpmath.mpf(10) ** (5 - MP_DIGITS) * (s + 1)
            checked += 1
    assert checked == 6


def test_a_term_mutant_is_the_expression_the_old_construction_formed():
    """expr = base + Σ c·piece collects like terms to the very sum `rest ± term` was."""
    q, p, a, m, g = sp.symbols("q p a m g")
    E = sp.expand(m * q * sp.cos(a) ** 2 + sp.Rational(3, 2) * g * sp.sin(q) - 2 * p * m + q)
    terms = sp.Add.make_args(E)
    old = []
    for k, term in enumerate(terms):
        rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
        old.append(rest - term)  # wrong_sign
        if term.has(sp.sin, sp.cos):
            old.append(rest + swap_sin_cos(term))
        old += [rest + term / f for f in (m, g) if f in sp.Mul.make_args(term)]
        old += [rest, rest + 2 * term, rest + term / 2]
    new = [x.expr for x in iter_term_mutants(E, "E", [m, g])]
    assert new == old


_small = st.integers(-3, 3).filter(bool)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.tuples(_small, st.integers(0, 3), st.integers(0, 2)), min_size=1, max_size=5),
    st.sampled_from([-2, -1, 1, 2]),
    st.sampled_from([sp.Integer(1), sp.Rational(1, 2), sp.Integer(-1)]),
)
def test_a_combination_has_the_values_of_its_sum(monomials, c1, c2):
    """Property: Σ c·part evaluates as the sympy sum it stands for, at float precision."""
    x, y = sp.symbols("x y", real=True)
    base = sp.Add(*(k * x**i * sp.cos(y) ** j for k, i, j in monomials))
    piece = sp.Add(*(x ** (i + 1) * sp.sin(y) for _, i, _ in monomials[:2]))
    mutant = Mutant("test", "", base, ((sp.Integer(c1), piece), (c2, piece * y)))
    combination = Combination(
        tuple((c, Compiled.of(e)) for c, e in ((sp.Integer(1), base), *mutant.pieces))
    )
    env = {x: np.linspace(-2, 2, 9), y: np.linspace(-1, 3, 9)}
    value, size = combination.values(env)
    whole, _ = Compiled.of(mutant.expr).values(env)
    assert _close(value, np.broadcast_to(whole, value.shape), size)
    assert combination.expr == mutant.expr
