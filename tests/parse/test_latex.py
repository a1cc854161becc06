"""The LaTeX translator: our own subset, mapped back to the student's characters."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.errors import ParseError
from lagrade.mechanics.lagrange import jet
from lagrade.notation.latex import translate
from lagrade.notation.lexer import Source
from lagrade.notation.parse import Vocabulary, parse_answer, parse_expression

VOCAB = Vocabulary.from_names(["x_M", "q", "theta"], ["m", "M", "g", "alpha"])


def _plain(latex: str) -> str:
    return translate(Source(latex, latex)).text


@pytest.mark.parametrize(
    ("latex", "plain"),
    [
        (r"\frac{1}{2} m", "(1/2) m"),
        (r"\dot{x}_M", "x_M\u0307"),
        (r"\dot{x_M}", "x_M\u0307"),
        (r"\ddot\theta", "theta\u0308"),
        (r"\sin^2\theta", "sin^2 theta"),
        (r"\omega t", "omega t"),
        (r"m\cdot g", "m* g"),
        (r"e^{-\gamma t}", "exp(-gamma t)"),
        (r"\left( m \right)", "( m )"),
        (r"x^{2}", "x^2"),
        (r"x^{a+b}", "x^(a+b)"),
        (r"\sqrt{g}", "sqrt(g)"),
    ],
)
def test_translation(latex: str, plain: str) -> None:
    assert _plain(latex) == plain


def test_both_dot_placements_are_the_same_symbol() -> None:
    a = parse_expression(r"\dot{x}_M", VOCAB).lhs
    b = parse_expression(r"\dot{x_M}", VOCAB).lhs
    c = parse_expression(r"\dot{x}_{M}", VOCAB).lhs
    assert a == b == c == jet("x_M").dot


def test_errors_point_into_the_latex_source() -> None:
    text = r"\frac{1}{2} m \dot{x}_M^2 + \frac{g}{2} mq"
    with pytest.raises(ParseError) as caught:
        parse_answer(text, VOCAB)
    assert (
        caught.value.message
        == "Unknown symbol 'mq'. Did you mean m*q? Separate variables with * or a space."
    )
    assert text[slice(*caught.value.span)] == "mq"


def test_auto_detection_and_forcing() -> None:
    assert parse_answer(r"\theta", VOCAB).lhs == jet("theta").q
    with pytest.raises(ParseError, match="Unexpected backslash"):
        parse_answer(r"\theta", VOCAB, latex=False)
    assert parse_answer("m g", VOCAB, latex=True).lhs == sp.Symbol("m", positive=True) * sp.Symbol(
        "g", positive=True
    )


def test_latex_greek_in_unicode_and_commands_agree() -> None:
    assert (
        parse_answer(r"\dot{\theta}^2", VOCAB).lhs
        == parse_answer("θ̇²", VOCAB).lhs
        == jet("theta").dot ** 2
    )
