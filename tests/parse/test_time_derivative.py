"""d/dt(…) of an expression is D_t on the jets (D_t = ∂_t + Σ q̇ ∂_q + Σ q̈ ∂_q̇), cross-checked
against an independent derivation: sympy.physics.mechanics' dynamicsymbols, where q is a function
of time and sympy's own chain rule differentiates it. Random expressions in two coordinates, their
velocities, a parameter and t, printed in the student grammar, read back as `d/dt(…)` and
`diff(…, t)`, must give the same derivative."""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

from lagrade.mechanics.lagrange import jet, t
from lagrade.notation.parse import Vocabulary, parse_expression
from lagrade.notation.printer import answer_latex, plain

Q, R = jet("q"), jet("r")
M = sp.Symbol("m", positive=True)
VOCAB = Vocabulary.from_names(["q", "r"], ["m"])
LEAVES = [Q.q, R.q, Q.dot, R.dot, M, t, sp.Integer(2), sp.Rational(1, 3)]


def _expressions():
    leaf = st.sampled_from(LEAVES)

    def grow(children):
        unary = st.sampled_from([sp.sin, sp.cos, sp.exp, lambda x: x**2, lambda x: x**3])
        return st.one_of(
            st.tuples(children, children).map(lambda p: p[0] + p[1]),
            st.tuples(children, children).map(lambda p: p[0] * p[1]),
            st.tuples(unary, children).map(lambda p: p[0](p[1])),
        )

    return st.recursive(leaf, grow, max_leaves=8)


def _by_dynamicsymbols(expr: sp.Expr, order: int = 1) -> sp.Expr:
    """The order-th time derivative of expr with q and r functions of time
    (sympy.physics.mechanics' dynamicsymbols, differentiated by sympy), back in jet symbols."""
    time = dynamicsymbols._t
    q, r = dynamicsymbols("q r")
    timed = expr.xreplace({Q.q: q, R.q: r, Q.dot: q.diff(time), R.dot: r.diff(time), t: time})
    derived = sp.diff(timed, time, order)
    back = {q.diff(time, 2): Q.ddot, r.diff(time, 2): R.ddot}
    derived = derived.subs(back).subs({q.diff(time): Q.dot, r.diff(time): R.dot})
    return derived.subs({q: Q.q, r: R.q, time: t})


@settings(max_examples=60, deadline=None)
@given(_expressions())
def test_d_dt_of_an_expression_is_the_chain_rule_of_functions_of_time(expr) -> None:
    if expr.is_Symbol and expr not in (Q.q, R.q, Q.dot, R.dot):
        expr = expr * R.q  # diff(m, t), diff(t, t): a name alone must be a coordinate
    text, latex = plain(expr), answer_latex(expr)
    expected = _by_dynamicsymbols(expr)
    for written in (f"d/dt({text})", f"diff({text}, t)", rf"\frac{{d}}{{dt}}\left({latex}\right)"):
        got = parse_expression(written, VOCAB).lhs
        assert sp.expand(got - expected) == 0, (written, got, expected)


@settings(max_examples=30, deadline=None)
@given(_expressions())
def test_the_second_derivative_is_the_second_time_derivative(expr) -> None:
    """d^2/dt^2(f) of a function of the coordinates alone (no velocity: a third derivative)."""
    expr = expr.xreplace({Q.dot: Q.q, R.dot: sp.Integer(1)})
    if expr.is_Symbol and expr not in (Q.q, R.q):
        expr = expr * R.q  # a name alone must be a coordinate
    got = parse_expression(f"d^2/dt^2({plain(expr)})", VOCAB).lhs
    assert sp.expand(got - _by_dynamicsymbols(expr, 2)) == 0


def test_the_plain_printer_writes_eulers_number_as_the_grammar_reads_it() -> None:
    """`E` is a plain symbol to the grammar, so Euler's number alone prints as exp(1) (the
    second-derivative property found d^2/dt^2(E) for exp(r_dot) with r_dot set to 1)."""
    r = R.q
    for expr in (sp.E, sp.E * r, sp.exp(r) + sp.E):
        assert parse_expression(plain(expr), VOCAB).lhs == expr, plain(expr)
