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


FRACTIONS = Vocabulary.from_names(["x_M", "q", "theta"], ["m", "M", "g", "l", "alpha"])


@pytest.mark.parametrize(
    ("latex", "expected"),
    [
        (r"\frac{mg}{2l}", "m*g/(2*l)"),  # was (m*g/2)*l: the denominator 2l unbracketed
        (r"\frac{g}{Mm}", "g/(M*m)"),
        (r"\frac{1}{2m} q", "q/(2*m)"),
        (r"\frac{x_M}{2}", "x_M/2"),
        (r"\frac{\theta}{\alpha}", "theta/alpha"),
    ],
)
def test_a_fraction_is_read_with_its_numerator_and_denominator_whole(latex, expected) -> None:
    """A systems-corpus case (coupled pendula, `\\frac{mg}{2l}`) was read as (mg/2)·l: every
    numerator and denominator longer than one number or one letter is bracketed. The expected
    reading is the plain grammar's, which does not go through the LaTeX translator."""
    got = parse_expression(latex, FRACTIONS).lhs
    assert got == parse_expression(expected, FRACTIONS).lhs, (latex, got)


def test_both_dot_placements_are_the_same_symbol() -> None:
    a = parse_expression(r"\dot{x}_M", VOCAB).lhs
    b = parse_expression(r"\dot{x_M}", VOCAB).lhs
    c = parse_expression(r"\dot{x}_{M}", VOCAB).lhs
    assert a == b == c == jet("x_M").dot


def test_errors_point_into_the_latex_source() -> None:
    text = r"\frac{1}{2} m \dot{x}_M^2 + \frac{g}{2} mtheta"
    with pytest.raises(ParseError) as caught:
        parse_answer(text, VOCAB)
    assert (
        caught.value.message
        == "Unknown symbol 'mtheta'. Did you mean m*theta? Separate variables with * or a space."
    )
    assert text[slice(*caught.value.span)] == "mtheta"


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


def test_adjacent_declared_letters_multiply_in_latex_and_the_echo_shows_it() -> None:
    """LaTeX sets G·M·m as `GMm`: a run of single letters, every one a declared name, is their
    product there, and the echo and a warning show the split; plain text reads the run the same
    way with its own note (issue 38, tests/parse/test_letter_runs.py)."""
    vocab = Vocabulary.from_names(["r"], ["G", "M", "m"])
    read = parse_answer(r"\frac{GMm}{r}", vocab)
    G, M, m = (sp.Symbol(n, positive=True) for n in "GMm")
    assert read.lhs == G * M * m / jet("r").q
    assert read.echo == "(G*M*m)/r"  # a fraction's numerator is bracketed whole
    assert read.warnings == ("GMm is read as G*M*m: in LaTeX adjacent letters multiply.",)
    assert parse_answer("GMm/r", vocab).warnings == (
        "GMm is read as G*M*m: separate names with * or a space.",
    )


def test_a_run_with_an_undeclared_letter_is_not_split() -> None:
    vocab = Vocabulary.from_names(["r"], ["G", "M", "m"])
    with pytest.raises(ParseError, match="Unknown symbol 'GMmx'"):
        parse_answer(r"\frac{GMmx}{r}", vocab)
    assert parse_answer(r"\frac{d}{dt}\left(r\right)", vocab).lhs == jet("r").dot  # d, t: no run
