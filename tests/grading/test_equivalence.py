"""The numeric core: the whitelist evaluator, term-scaled tolerances, 50-digit confirmation,
Euler–Lagrange values by hyper-dual numbers, spans and accelerations at sample points."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.bank import get_scene
from lagrade.judge.compiled import Compiled, finite_mask
from lagrade.judge.decision import decide
from lagrade.judge.derivatives import euler_lagrange_values, time_derivative_on_shell
from lagrade.judge.equivalence import affine_match, expressions_equal, lagrangians_match
from lagrade.judge.evaluate import MP, UnsupportedExpression, compile_program, run
from lagrade.judge.rows import equation_rows, in_span, row_rank, solve_accelerations
from lagrade.judge.sampling import Space, seed_for
from lagrade.judge.tolerances import RANK
from lagrade.mechanics import Domain
from lagrade.mechanics.lagrange import jet, t

x, y = sp.symbols("x y", real=True)
q = jet("q")
th = jet("theta")
m, g, l = (sp.Symbol(n, positive=True) for n in "mgl")


def space_of(jets=(), **params):
    return Space(
        tuple(jets), {sp.Symbol(n, positive=True): Domain.parse(d) for n, d in params.items()}
    )


@pytest.fixture(scope="module")
def pend():
    """A simple pendulum: L = ½ m l² θ̇² + m g l cos θ."""
    space = Space((th,), {s: Domain.parse("positive") for s in (m, g, l)})
    L = m * l**2 * th.dot**2 / 2 + m * g * l * sp.cos(th.q)
    points = space.draw(1, valid=finite_mask([Compiled.of(L)]))
    return space, L, points


@pytest.mark.parametrize(
    "expr",
    [
        sp.sin(x) * sp.cos(y) + sp.tan(x / 3),
        sp.exp(-x) * sp.log(y**2 + 1),
        sp.sqrt(x**2 + 1),
        sp.asin(x / 5) + sp.acos(y / 4) + sp.atan(x),
        sp.sinh(x) - sp.cosh(y) + sp.tanh(x * y),
        sp.sec(x) + sp.csc(y) + sp.cot(x + y),
        sp.Abs(x - y) + sp.pi * sp.E,
        (x**2 + 1) ** sp.Rational(3, 2),
        x**y if False else (x**2 + 1) ** (y**2),
    ],
)
def test_evaluator_agrees_with_sympy(expr):
    program = compile_program([expr])
    env = {x: np.array([0.7, -1.3]), y: np.array([1.1, 0.4])}
    got = run(program, env)[0]
    for i in range(2):
        want = float(expr.evalf(30, subs={x: env[x][i], y: env[y][i]}))
        assert got[i] == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize(
    "bad",
    [sp.Function("f")(x), sp.Derivative(sp.Function("f")(x), x), sp.gamma(x), sp.zoo],
)
def test_evaluator_rejects_what_it_does_not_know(bad):
    with pytest.raises(UnsupportedExpression):
        compile_program([bad])


def test_the_imaginary_unit_is_a_complex_constant():
    """Only a question that declares it lets the parser produce I (issue 12); the evaluator
    then computes with it, never dropping the imaginary part."""
    got = run(compile_program([sp.I * x]), {x: np.array([2.0])})[0]
    assert got[0] == 2j


def test_mp_backend_gives_50_digits():
    program = compile_program([sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1])
    with mpmath.workdps(50):
        value = run(program, {x: MP.array(np.array([0.3]))}, MP)[0][0]
    assert abs(value) < mpmath.mpf(10) ** -45


def test_cancellation_is_measured_against_the_terms():
    """(x + 10⁶)³ expanded and cancelled leaves small terms; the tolerance sees the big ones."""
    big = sp.Integer(10**6)
    a = Compiled.of((x + big) ** 3 - big**3 - 3 * big**2 * x)
    b = Compiled.of(x**3 + 3 * big * x**2)
    points = Space((), {x: Domain.parse("real")}).draw(3)
    assert expressions_equal(a, b, points).equal


def test_tiny_difference_is_decided_at_50_digits():
    a = Compiled.of(sp.sin(x) ** 2 + sp.Rational(1, 10**8) * x)
    b = Compiled.of(1 - sp.cos(x) ** 2)
    out = expressions_equal(a, b, Space((), {x: Domain.parse("real")}).draw(4))
    assert not out.equal and out.method == "numeric+mpmath50" and out.where is not None


def test_answer_undefined_where_reference_is_defined_is_wrong():
    """Wrong either way; the point quoted is one where both sides are defined when the answers
    differ at one (log q against q: q > 0), else an undefined one, said to be (issue 30)."""
    points = Space((q,), {}).draw(5)
    out = expressions_equal(Compiled.of(sp.log(q.q)), Compiled.of(q.q), points)
    assert not out.equal and out.reason == "" and points.env[q.q][out.where] > 0
    only_undefined = sp.sqrt(q.q**3) / sp.sqrt(q.q)  # q where q > 0, undefined where q < 0
    out = expressions_equal(Compiled.of(only_undefined), Compiled.of(q.q), points)
    assert not out.equal and out.reason == "undefined" and points.env[q.q][out.where] < 0


def test_points_where_the_reference_is_undefined_are_redrawn():
    ref = Compiled.of(sp.sqrt(q.q - 1))
    points = Space((q,), {}).draw(6, valid=finite_mask([ref]))
    assert np.all(points.env[q.q] > 1)
    assert expressions_equal(Compiled.of(sp.sqrt(q.q - 1)), ref, points).equal


def test_sqrt_of_a_square_is_not_the_function():
    points = Space((th,), {}).draw(7)
    out = expressions_equal(
        Compiled.of(sp.sqrt(1 - sp.cos(th.q) ** 2)), Compiled.of(sp.sin(th.q)), points
    )
    assert not out.equal


def test_euler_lagrange_values_match_the_symbolic_equations(pend):
    space, L, points = pend
    E, S = euler_lagrange_values(Compiled.of(L), (th,), points.env)
    symbolic = m * l**2 * th.ddot + m * g * l * sp.sin(th.q)
    want = Compiled.of(symbolic).values(points.env)[0]
    assert np.allclose(E[:, 0], want, rtol=1e-13)
    assert np.all(S[:, 0] >= np.abs(E[:, 0]))


@pytest.mark.parametrize(
    "factor, extra, equal",
    [
        (1, 0, True),
        (2, 0, True),
        (-1, 0, True),
        (1, 5 * m * g, True),
        (1, sp.cos(th.q) * th.dot * m, True),  # d/dt(m sin θ): a total derivative
        (1, th.q * th.dot**2 * m, False),
    ],
)
def test_lagrangians_match_up_to_factor_constant_and_total_derivative(pend, factor, extra, equal):
    space, L, points = pend
    match = lagrangians_match(Compiled.of(factor * L + extra), Compiled.of(L), (th,), points)
    assert match.outcome.equal is equal
    if equal:
        assert match.factor == pytest.approx(factor)


@pytest.mark.parametrize(
    "factor, extra, shifted",
    [(1, 0, False), (3, 0, False), (sp.Rational(1, 2), 7, True), (1, -m * g * l, True)],
)
def test_affine_match_settles_a_positive_multiple_plus_a_constant(pend, factor, extra, shifted):
    space, L, points = pend
    answer = Compiled.of(factor * sp.expand(L) + extra).values(points.env)
    found = affine_match(answer, Compiled.of(L).values(points.env), points)
    assert found is not None and found.factor == pytest.approx(float(factor))
    assert found.shifted is shifted and found.worst < 1e-12


@pytest.mark.parametrize(
    "other",
    [
        lambda L: -L,  # V − T: same motion, wrong convention — for the full test to say so
        lambda L: L + sp.cos(th.q) * th.dot * m,  # + dF/dt: same motion, values differ
        lambda L: L + th.q * th.dot**2 * m,  # different motion
        lambda L: sp.sin(th.q) ** 2 + sp.cos(th.q) ** 2,  # a constant with rounding noise
        lambda L: L * (1 + 1e-7),  # close, but not within the tolerance of the terms
        lambda L: L + 1e-6 * m * th.q,
    ],
)
def test_affine_match_says_yes_or_nothing(pend, other):
    """The fast path only ever accepts; every other case goes to the Euler–Lagrange test."""
    space, L, points = pend
    answer = Compiled.of(other(L)).values(points.env)
    found = affine_match(answer, Compiled.of(L).values(points.env), points)
    if found is not None:  # only L·(1 + 1e-7) may be a true multiple, and it is one
        assert other(L) == L * (1 + 1e-7)
        assert lagrangians_match(Compiled.of(other(L)), Compiled.of(L), (th,), points).outcome.equal


def test_factor_depending_on_parameters_is_per_group(pend):
    space, L, points = pend
    match = lagrangians_match(Compiled.of(L / m), Compiled.of(L), (th,), points)
    assert match.outcome.equal and match.factor is None


def test_rows_span_and_accelerations():
    wedge = get_scene("wedge").default
    problem_space = Space(
        wedge.jets, {wedge.parameter_symbols[n]: d for n, d in wedge.domains.items()}
    )
    E = [Compiled.of(e) for e in wedge.euler_lagrange]
    points = problem_space.draw(seed_for("test"))
    ref = equation_rows(E, wedge.jets, points.env)
    acc = solve_accelerations(ref)
    exact = [Compiled.of(a).values(points.env)[0] for a in wedge.system.accelerations]
    assert np.allclose(acc[:, 0], exact[0]) and np.allclose(acc[:, 1], exact[1])
    combos = [
        Compiled.of(sp.expand(3 * wedge.euler_lagrange[0] - wedge.euler_lagrange[1])),
        Compiled.of(wedge.euler_lagrange[1] + 1),
    ]
    rows = equation_rows(combos, wedge.jets, points.env)
    assert decide(lambda b: in_span(rows, ref, 0)).equal
    assert not decide(lambda b: in_span(rows, ref, 1)).equal
    assert row_rank(ref.coef, [0, 1]) == 2


def test_time_derivative_on_shell_of_energy(pend):
    space, L, points = pend
    ref = equation_rows(
        [Compiled.of(m * l**2 * th.ddot + m * g * l * sp.sin(th.q))], (th,), points.env
    )
    acc = solve_accelerations(ref)
    h = Compiled.of(m * l**2 * th.dot**2 / 2 - m * g * l * sp.cos(th.q))
    total, size, grad = time_derivative_on_shell(h, (th,), points.env, acc)
    assert np.all(np.abs(total) <= 1e-12 * size)
    assert np.all(grad[:, 0] == 0)  # no explicit t


def test_same_request_same_points():
    s = Space((q,), {m: Domain.parse("positive")})
    a, b = s.draw(seed_for("p", "lagrangian")), s.draw(seed_for("p", "lagrangian"))
    assert all(np.array_equal(a.env[k], b.env[k]) for k in a.env)
    assert t in a.env


def _rank_point_by_point(coef: np.ndarray, rows: list[int]) -> int:
    """row_rank's definition, one point at a time: the unit rows of the point, zero rows left
    out, counted by their singular values; the most common rank wins."""
    ranks = []
    for p in range(coef.shape[0]):
        M = np.array(coef[p, rows], dtype=float)
        norms = np.linalg.norm(M, axis=1)
        M = M[norms > 0] / norms[norms > 0, None]
        sv = np.linalg.svd(M, compute_uv=False) if M.size else np.zeros(0)
        ranks.append(int((sv > RANK * sv[0]).sum()) if sv.size else 0)
    return int(np.bincount(ranks).argmax())


@settings(max_examples=300, deadline=None)
@given(
    st.integers(1, 12),
    st.integers(1, 4),
    st.integers(1, 5),
    st.integers(0, 2**32 - 1),
    st.sampled_from(["plain", "dependent", "zero rows", "all zero"]),
)
def test_the_rank_of_stacked_points_is_the_rank_point_by_point(points, m, columns, seed, shape):
    """The points whose zero rows fall alike share one SVD: the rank found is the one found
    point by point, with rows that vanish at some points only and rows in proportion."""
    rng = np.random.default_rng(seed)
    coef = rng.normal(size=(points, m, columns)) * rng.choice([1.0, 1e-9, 1e6], (points, m, 1))
    if shape == "dependent" and m > 1:
        coef[:, -1] = rng.normal() * coef[:, 0]
    elif shape == "zero rows":
        coef[rng.random(points) < 0.5, rng.integers(m)] = 0.0
    elif shape == "all zero":
        coef[:] = 0.0
    rows = sorted({int(r) for r in rng.integers(0, m, rng.integers(1, m + 1))})
    assert row_rank(coef, rows) == _rank_point_by_point(coef, rows)
