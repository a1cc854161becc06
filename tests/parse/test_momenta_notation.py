"""Momenta and their rates as students write them in the parts on phase space (docs/notation.md):
`p_theta`, `p_\\theta`, `p_{\\theta}`, and `p_theta_dot`, `\\dot{p}_\\theta`; declared only when
the vocabulary asks for them, so every other part reads them as before."""

import pytest
import sympy as sp

from lagrade.errors import ParseError
from lagrade.mechanics import momentum_jet
from lagrade.notation import Vocabulary, parse_equation, parse_expression

PLAIN = Vocabulary.from_names(["theta", "r"], ["m", "g", "l"])
PHASE = Vocabulary(PLAIN.coordinates, PLAIN.parameters, momenta=True)
m, g, l = (PLAIN.parameters[n] for n in "mgl")
p_theta, p_r = momentum_jet("theta"), momentum_jet("r")
theta = sp.Symbol("theta", real=True)


@pytest.mark.parametrize(
    ("text", "latex", "want"),
    [
        ("p_theta", False, p_theta.q),
        (
            "p_theta^2/(2 m l^2) - m g l cos(theta)",
            False,
            p_theta.q**2 / (2 * m * l**2) - m * g * l * sp.cos(theta),
        ),
        ("p_r_dot", False, p_r.dot),
        ("p_rdot", False, p_r.dot),
        ("ṗ_r", False, p_r.dot),
        ("diff(p_r, t)", False, p_r.dot),
        ("d/dt(p_theta)", False, p_theta.dot),
        (r"p_\theta", True, p_theta.q),
        (r"p_{\theta}", True, p_theta.q),
        (r"\frac{p_\theta^2}{2ml^2}", True, p_theta.q**2 / (2 * m * l**2)),
        (r"\dot{p}_r", True, p_r.dot),
        (r"\dot{p}_{\theta}", True, p_theta.dot),
        (r"\dot{p_r}", True, p_r.dot),
    ],
)
def test_momenta_read_in_every_spelling(text, latex, want):
    assert sp.simplify(parse_expression(text, PHASE, latex=latex).expr - want) == 0


def test_a_hamilton_equation_in_latex():
    got = parse_equation(r"\dot{p}_\theta = -mgl\sin\theta", PHASE, latex=True)
    assert sp.simplify(got.lhs - p_theta.dot) == 0
    assert sp.simplify(got.rhs + m * g * l * sp.sin(theta)) == 0


def test_the_greek_shape_follows_the_coordinate():
    vocab = Vocabulary(("vartheta",), {}, momenta=True)
    assert parse_expression("p_theta", vocab).expr == momentum_jet("vartheta").q
    assert (
        parse_expression(r"\dot{p}_\theta", vocab, latex=True).expr == momentum_jet("vartheta").dot
    )


@pytest.mark.parametrize("text", ["p_theta", "p_r_dot", "p_q"])
def test_momenta_are_unknown_unless_declared(text):
    with pytest.raises(ParseError):
        parse_expression(text, PLAIN)


def test_a_momentum_of_no_coordinate_is_unknown_and_the_message_lists_the_momenta():
    with pytest.raises(ParseError, match="p_theta, p_theta_dot"):
        parse_expression("p_q", PHASE)


def test_a_parameter_named_like_a_momentum_is_a_clash():
    with pytest.raises(Exception, match="declared twice"):
        Vocabulary(("x",), {"p_x": sp.Symbol("p_x", positive=True)}, momenta=True)
