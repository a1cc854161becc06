"""Right answers a class typed on a real round trip and the parser refused (issue 38), each read
as the student meant, with a note where the reading is a choice. Every case below was a
`ParseError` before; the forms come from the textbooks and LaTeX habits named beside them.

The notes travel like the `g/2 l` warning: in the preview (`Parsed.warnings`) and, on a wrong
answer, in the feedback (tests/grading/test_round_trip_answers.py)."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.errors import ParseError
from lagrade.mechanics.lagrange import jet
from lagrade.notation.parse import Vocabulary, parse_answer, parse_equation

VOCAB = Vocabulary.from_names(["x", "theta", "x_M"], ["m", "k", "g", "l", "G", "M", "omega"])
x, theta, x_M = jet("x"), jet("theta"), jet("x_M")
m, k, g, l, G, M, omega = (
    sp.Symbol(n, positive=True) for n in ("m", "k", "g", "l", "G", "M", "omega")
)


def _read(text: str, vocab: Vocabulary = VOCAB):
    return parse_answer(text, vocab)


# --- 1. a LaTeX line that uses the question's own plain names --------------------------------
# The sheet's notation comment names velocities `x_dot`; LaTeX habit adds \frac{1}{2} (Taylor,
# Classical Mechanics, sec. 7.1: L = ½mẋ² − ½kx², typed with the sheet's names).


@pytest.mark.parametrize(
    ("latex", "value"),
    [
        (r"\frac{1}{2} m x_dot^2 - \frac{1}{2} k x^2", m * x.dot**2 / 2 - k * x.q**2 / 2),
        (r"\frac{1}{2} m l^2 theta_dot^2", m * l**2 * theta.dot**2 / 2),
        (r"m x_ddot + k \cdot x", m * x.ddot + k * x.q),
        (r"\theta_dot \cos\theta", theta.dot * sp.cos(theta.q)),  # \theta then the sheet's _dot
        (r"\frac{1}{2} M x_M_dot^2", M * x_M.dot**2 / 2),
        (r"\frac{1}{2} M x_Mdot^2", M * x_M.dot**2 / 2),
        (r"mx_dot", m * x.dot),  # LaTeX's product of letters, the last one the sheet's name
    ],
)
def test_a_latex_line_reads_the_questions_plain_names(latex: str, value) -> None:
    assert _read(latex).lhs == value


def test_a_latex_subscript_that_spells_no_declared_name_stays_a_subscript() -> None:
    """x_dot reads whole only because the question declares it: an undeclared `v_dot` is still
    v with the subscript d (unknown), and `x_d` alone is not stretched."""
    with pytest.raises(ParseError, match="Unknown symbol 'v_d'"):
        _read(r"\frac{1}{2} m v_dot^2")
    with pytest.raises(ParseError, match="Unknown symbol 'x_d'"):
        _read(r"m x_d")


# --- 2. a run of declared one-letter names typed together -------------------------------------
# Goldstein (3rd ed., sec. 3.7) and Taylor (sec. 8.2) print the Kepler potential as −GMm/r; a
# student types `GM m/r` or `GMm/r` in plain text.


@pytest.mark.parametrize(
    ("text", "value", "note"),
    [
        ("GM m/theta", G * M * m / theta.q, "GM is read as G*M: separate names with * or a space."),
        ("GMm", G * M * m, "GMm is read as G*M*m: separate names with * or a space."),
        ("mgl cos(theta)", m * g * l * sp.cos(theta.q), "mgl is read as m*g*l: separate names"),
        ("kx^2/2", k * x.q**2 / 2, "kx is read as k*x: separate names with * or a space."),
    ],
)
def test_a_run_of_declared_single_letters_is_their_product_with_a_note(text, value, note) -> None:
    read = _read(text)
    assert read.lhs == value
    assert any(w.startswith(note) for w in read.warnings), read.warnings
    assert "*" in read.echo  # the echo shows the split


def test_a_run_with_a_longer_declared_name_inside_still_asks() -> None:
    """With k, m and km declared, `kmm` could be km·m or k·m·m: the message asks, as before."""
    vocab = Vocabulary.from_names(["x"], ["k", "m", "km"])
    with pytest.raises(ParseError, match=r"Unknown symbol 'kmm'\. Did you mean km\*m\?"):
        parse_answer("kmm", vocab)
    with pytest.raises(ParseError, match="Unknown symbol 'Gm'"):  # G undeclared: no split
        parse_answer("Gm", Vocabulary.from_names(["x"], ["m"]))


# --- 4. primes as time derivatives -------------------------------------------------------------
# Boas, Mathematical Methods in the Physical Sciences (ch. 8), writes y'' for d²y/dt²; students
# carry the habit into mechanics: θ'' + (g/l) sin θ = 0.


@pytest.mark.parametrize(
    ("text", "value", "note"),
    [
        ("θ'' + g/l sin(θ)", theta.ddot + g / l * sp.sin(theta.q), "theta'' is read as theta_ddot"),
        ("m l^2 theta'", m * l**2 * theta.dot, "theta' is read as theta_dot"),
        ("M x_M''", M * x_M.ddot, "x_M'' is read as x_M_ddot"),
        ("m θ′", m * theta.dot, "theta' is read as theta_dot"),  # U+2032, the prime sign
        (r"\dot{\theta}'", theta.ddot, "theta_dot' is read as theta_ddot"),
        (r"\ddot{x} + \omega^2 x'", x.ddot + omega**2 * x.dot, "x' is read as x_dot"),
    ],
)
def test_primes_on_a_coordinate_are_time_derivatives_with_a_note(text, value, note) -> None:
    read = _read(text)
    assert sp.simplify(read.lhs - value) == 0
    assert any(w.startswith(note) and "(a prime as d/dt)" in w for w in read.warnings)


def test_primes_keep_their_refusals_where_they_are_not_time_derivatives() -> None:
    """A prime on a parameter, a third derivative, and a question where t is not time (an
    `expression` problem that declares t as a variable: d/dt is not the only derivative)."""
    with pytest.raises(ParseError, match="'m' is not a coordinate"):
        _read("m'")
    with pytest.raises(ParseError, match="derivative of order 3"):
        _read("x'''")
    t_is_a_variable = Vocabulary.from_names(["x"], ["t", "m"])
    with pytest.raises(ParseError, match="Primes are ambiguous in mechanics"):
        parse_answer("x'", t_is_a_variable)


def test_primes_allowed_by_the_question_read_without_a_note() -> None:
    primed = Vocabulary.from_names(["x"], ["m"], allow_primes=True)
    read = parse_answer("m x''", primed)
    assert read.lhs == sp.Symbol("m", positive=True) * x.ddot and read.warnings == ()


# --- 6. a LaTeX function ended by a spacing command -------------------------------------------
# The TeXbook (ch. 18) sets a thin space `\,` after a function's argument, as in
# $\sin\theta\,d\theta$; Wikipedia's "Lagrangian mechanics" writes ml\cos\theta\,\dot\theta.


@pytest.mark.parametrize(
    ("latex", "value"),
    [
        (r"\cos\theta \, \dot{\theta}", sp.cos(theta.q) * theta.dot),
        (r"m l \cos\theta\,\dot\theta \dot x", m * l * sp.cos(theta.q) * theta.dot * x.dot),
        (r"\sin \omega t \; x", None),
        (r"\cos^2\theta \, \dot x^2", sp.cos(theta.q) ** 2 * x.dot**2),
        (r"\sin\theta \quad k", sp.sin(theta.q) * k),
    ],
)
def test_a_spacing_command_ends_a_bracketless_functions_argument(latex, value) -> None:
    read = _read(latex)
    if value is not None:
        assert read.lhs == value
    else:  # sin(ω t)·x: the argument runs to the spacing command
        assert read.plain() == "sin(omega*t)*x"


@pytest.mark.parametrize(
    "latex",
    [r"\cos\theta^2 \, x", r"\sin \omega t x", r"\cos \theta + x \, k"],
)
def test_without_the_spacing_command_the_ambiguity_still_asks(latex) -> None:
    """The spacing command is what ends the argument: a power inside it, or no spacing at all,
    leaves the grammar's rule (an ambiguity with a hint); `\\cos \\theta + x \\, k` is
    cos(θ) + x·k, read by the ordinary rule, and must not swallow the sum."""
    if "+" in latex:
        assert _read(latex).lhs == sp.cos(theta.q) + x.q * k
        return
    with pytest.raises(ParseError, match="Ambiguous"):
        _read(latex)


def test_an_equation_with_every_habit_at_once() -> None:
    """The pendulum on a cart (Goldstein's problem 1.21 family): the sheet's names, a prime,
    a thin space and a run of letters, in one equation."""
    eq = parse_equation(r"(M + m) x'' + ml \cos\theta \, theta_ddot = 0", VOCAB)
    assert sp.expand(eq.lhs - ((M + m) * x.ddot + m * l * sp.cos(theta.q) * theta.ddot)) == 0
