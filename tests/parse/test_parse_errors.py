"""Malformed and ambiguous answers: the exact message each gives, and where its caret points.

The messages are part of the contract (notation.md's Reject table): they show the student how
to write what they meant, so they are checked word for word.
"""

from __future__ import annotations

import pickle

import pytest

from lagrade.errors import GraderError, ParseError
from lagrade.notation.parse import (
    Vocabulary,
    parse_answer,
    parse_equation,
    parse_equations,
    parse_expression,
)

VOCAB = Vocabulary.from_names(
    ["theta", "x_M", "q", "x"],
    {
        "m": "positive",
        "M": "positive",
        "g": "positive",
        "l": "positive",
        "k": "positive",
        "omega": "positive",
        "alpha": "(0, pi/2)",
    },
    ["L"],
)
ALLOWED = (
    "m, M, g, l, k, omega, alpha, theta, theta_dot, theta_ddot, x_M, x_M_dot, x_M_ddot, "
    "q, q_dot, q_ddot, x, x_dot, x_ddot, L, t"
)
NOT_COORDINATE = "is not a coordinate of this problem (coordinates: theta, x_M, q, x)."

# (text, message, span in the text)
ERRORS = [
    # names
    (  # a run of single letters is read as their product (issue 38); with a longer name
        "mthetal",  # inside, the message still asks
        "Unknown symbol 'mthetal'. Did you mean m*theta*l? Separate variables with * or a space.",
        (0, 7),
    ),
    (
        "2 mthetadot",
        "Unknown symbol 'mthetadot'. Did you mean m*thetadot? "
        "Separate variables with * or a space.",
        (2, 11),
    ),
    ("ydot", f"'y' {NOT_COORDINATE}", (0, 4)),
    ("m omegadot", f"'omega' {NOT_COORDINATE}", (2, 10)),
    ("theta dot", f"Unknown symbol 'dot'. Allowed: {ALLOWED}.", (6, 9)),
    ("vel", f"Unknown symbol 'vel'. Allowed: {ALLOWED}.", (0, 3)),
    ("e^x", f"Unknown symbol 'e'. Allowed: {ALLOWED}.", (0, 1)),
    ("I omega", f"Unknown symbol 'I'. Allowed: {ALLOWED}.", (0, 1)),
    ("E", f"Unknown symbol 'E'. Allowed: {ALLOWED}.", (0, 1)),
    ("sintheta", "Unknown symbol 'sintheta'. Did you mean sin(theta)?", (0, 8)),
    ("__import__", f"Unknown symbol '__import__'. Allowed: {ALLOWED}.", (0, 10)),
    (
        "l(t)",
        "'l(t)' reads as a function of time, but l is not a coordinate; write l*t for a product.",
        (0, 4),
    ),
    ("diff(m, t)", f"'m' {NOT_COORDINATE}", (5, 6)),
    ("d/dt(m) = 0", f"'m' {NOT_COORDINATE}", (4, 7)),
    # derivatives
    ("dx/dt", "Leibniz notation is not supported; write xdot, diff(x, t) or d/dt(x).", (0, 5)),
    (
        "dtheta/dt",
        "Leibniz notation is not supported; write thetadot, diff(theta, t) or d/dt(theta).",
        (0, 9),
    ),
    (
        "d theta/d t",
        "Leibniz notation is not supported; write thetadot, diff(theta, t) or d/dt(theta).",
        (2, 9),
    ),
    (
        "m d/dt theta^2",
        "Write what d/dt differentiates in brackets, as in d/dt(m*r^2*theta_dot).",
        (2, 6),
    ),
    (
        "d/dt(m theta_ddot)",
        "This time derivative would be a third derivative: what it differentiates holds an "
        "acceleration (theta_ddot), and only velocities and accelerations exist here.",
        (0, 18),
    ),
    (
        "d^2/dt^2(x_dot) = 0",
        "This time derivative would be a third derivative: what it differentiates holds an "
        "acceleration (x_ddot), and only velocities and accelerations exist here.",
        (0, 15),
    ),
    (
        "diff(diff(theta_dot, t), t)",
        "This time derivative would be a third derivative: what it differentiates holds an "
        "acceleration (theta_ddot), and only velocities and accelerations exist here.",
        (0, 27),
    ),
    (
        "d/dt(Max(x, q))",
        "This time derivative cannot be worked out: sign, Max and Min have no derivative where "
        "they jump or bend; write the derivative itself.",
        (0, 15),
    ),
    (
        "d/dt(" + "*".join(f"sin(theta + {k})" for k in range(40)) + ")",
        "This time derivative is too large to work out (the product rule would write more than "
        "2,000 terms and factors); differentiate it by hand, or a smaller expression.",
        (0, 5 + 40 * 14 + 39 * 1 + 1 + 30),
    ),
    ("diff(L, thetadot)", "diff(...) is only allowed with respect to t.", (8, 16)),
    ("diff(theta^2)", "diff(...) needs the variable t: write diff(x, t).", (0, 13)),
    ("Max(m)", "Max compares two values or more: Max(a, b).", (0, 6)),
    (
        "Max(m, g, l, k, omega) + Min(x, q, theta, M)",
        "Too many values to compare: at most 8 in all the Max and Min of one answer.",
        (25, 44),
    ),
    (
        "2.5½ m",
        "A fraction sign right after a decimal number: write ½ as a sum or a product "
        "with brackets, as in 2.5 + 1/2 or 2.5*(1/2).",
        (0, 4),
    ),
    (
        "2 3/4 m",
        "Two numbers side by side: for the mixed number write 2 + 3/4, for a product 2*3/4.",
        (0, 5),
    ),
    ("diff(theta, t, 3)", "The order in diff(x, t, n) must be 1 or 2.", (15, 16)),
    (
        "diff(theta_dot, t, 2)",
        "Only velocities and accelerations exist here: that is a derivative of order 3 of theta.",
        (0, 21),
    ),
    ("diff(theta)", "diff(...) needs the variable t: write diff(theta, t).", (0, 11)),
    # primes are time derivatives with a note (issue 38: tests/parse/test_round_trip_notation.py)
    (
        "x'''",
        "Only velocities and accelerations exist here: that is a derivative of order 3 of x.",
        (0, 4),
    ),
    ("m'", "'m' is not a coordinate of this problem (coordinates: theta, x_M, q, x).", (0, 2)),
    # bracket-less functions
    (
        "sin omega t",
        "Ambiguous 'sin' without brackets: write sin(omega*t) or sin(omega)*t.",
        (0, 11),
    ),
    (
        "sin 2 theta",
        "Ambiguous 'sin' without brackets: write sin(2*theta) or sin(2)*theta.",
        (0, 11),
    ),
    (
        "sin 2theta",
        "Ambiguous 'sin' without brackets: write sin(2*theta) or sin(2)*theta.",
        (0, 10),
    ),
    (
        "cos theta^2",
        "Ambiguous 'cos' without brackets: write cos(theta^2) or cos(theta)^2.",
        (0, 11),
    ),
    (
        "m g sin theta/2",
        "Ambiguous 'sin' without brackets: write sin(theta/2) or sin(theta)/2.",
        (4, 15),
    ),
    (
        "sin^2 theta t",
        "Ambiguous 'sin' without brackets: write sin^2(theta*t) or sin^2(theta)*t.",
        (0, 13),
    ),
    ("sin^-1(x)", "sin^-1 is ambiguous; write asin(x) or 1/sin(x).", (0, 5)),
    ("tan^(-1) x", "tan^-1 is ambiguous; write atan(x) or 1/tan(x).", (0, 5)),
    (
        "sin^x(theta)",
        "After 'sin^' write a whole number, as in sin^2(x), "
        "or put the power after the argument: sin(x)^n.",
        (3, 5),
    ),
    ("sin", "Expected '(' after 'sin' but the answer ended.", (0, 3)),
    ("sin cos theta", "Write the argument of 'sin' in brackets, as in sin(x).", (0, 7)),
    # division and numbers
    ("1 000 g", "Two numbers side by side; write 1000 or 1*000.", (0, 5)),
    ("1.2.3", "Cannot read the number '1.2.3'.", (0, 5)),
    ("12345678901234567890123456789012", "Number too long: at most 30 digits.", (0, 32)),
    ("1e101", "Exponent of a number too large: at most e±100.", (0, 5)),
    ("x^10000000", "Exponent too large: at most 1,000,000 in absolute value.", (2, 10)),
    ("2^(10^7)", "Exponent too large: at most 1,000,000 in absolute value.", (0, 8)),
    ("2^20000", "This power gives a number too large to work with.", (0, 7)),
    (
        "(m+g+theta+x+q)^1000",
        "This power of a sum is too large to work with (multiplied out it would have more "
        "than 1,000,000 terms).",
        (0, 20),
    ),
    ("(2^100)^100", "This power gives a number too large to work with.", (0, 11)),
    # equations and operators
    ("m == g", "Use a single '=' for an equation.", (2, 4)),
    ("m = g = l", "Use a single '=' for an equation.", (6, 7)),
    ("m < g", "Use a single '=' for an equation.", (2, 3)),
    ("m >= g", "Use a single '=' for an equation.", (2, 4)),
    ("m ≠ g", "Use a single '=' for an equation.", (2, 3)),
    ("m g +", "The answer ends with '+'; something is missing after it.", (4, 5)),
    ("m**", "The answer ends with '**'; something is missing after it.", (1, 3)),
    ("m =", "The answer ends with '='; write what it equals (0 if nothing).", (2, 3)),
    ("=m", "Something is missing before '='.", (0, 1)),
    ("*m", "The answer starts with '*'; something is missing before it.", (0, 1)),
    ("m + * g", "Expected a term after '+' but found '*'.", (2, 5)),
    ("m!", "Factorials are not supported.", (1, 2)),
    ("x # rest", "Unexpected character '#': comments are not part of an answer.", (2, 3)),
    ("m @ g", "Unexpected character '@'.", (2, 3)),
    ("m,g", "Unexpected ','.", (1, 2)),
    ("m; g", "Only one answer is expected here; put each equation on its own line.", (1, 2)),
    ("", "The answer is empty.", (0, 0)),
    ("   ", "The answer is empty.", (0, 3)),
    # brackets
    ("(m + M", "Missing ')': the '(' at position 1 is never closed.", (0, 1)),
    ("m (g (l)", "Missing ')': the '(' at position 3 is never closed.", (2, 3)),
    ("m + M)", "Unmatched ')'.", (5, 6)),
    ("()", "Empty brackets '()'.", (0, 2)),
    ("[x]", "Use round brackets ( ) only.", (0, 1)),
    ("{m+M} g", "Use round brackets ( ) only.", (0, 1)),
    # not finite or not real
    ("1/0", "The answer is not a finite real expression.", (0, 3)),
    ("m + 1/(x - x)", "The answer is not a finite real expression.", (0, 13)),
    ("log(0)", "The answer is not a finite real expression.", (0, 6)),
    ("sqrt(-1)", "The answer is not a finite real expression.", (0, 8)),
    ("(-8)^(1/3)", "The answer is not a finite real expression.", (0, 10)),
    # characters
    ("m\u200bg", "Invisible or look-alike character U+200B at position 2.", (1, 2)),
    (
        "ab\u200bc".replace("ab", "mg"),
        "Invisible or look-alike character U+200B at position 3.",
        (2, 3),
    ),
    ("m\u202eg", "Invisible or look-alike character U+202E at position 2.", (1, 2)),
    ("m\x00g", "Invisible or look-alike character U+0000 at position 2.", (1, 2)),
    ("m\u0430g", "Invisible or look-alike character U+0430 at position 2.", (1, 2)),
    ("m \u03bfmega", "Invisible or look-alike character U+03BF at position 3.", (2, 3)),
    ("θ\u200dx", "Invisible or look-alike character U+200D at position 2.", (1, 2)),
    ("é", "Unexpected character 'é' (U+00E9) at position 1.", (0, 1)),
    ("\u0307x", "A combining dot must follow a coordinate's name, as in θ̇.", (0, 1)),
    # LaTeX
    (
        r"\frac{dx}{dt}",
        "Leibniz notation is not supported; write \\dot{x}, diff(x, t) or \\frac{d}{dt}(x).",
        (0, 13),
    ),
    (
        r"\frac{d\theta}{dt}",
        "Leibniz notation is not supported; write \\dot{\\theta}, diff(\\theta, t) or "
        "\\frac{d}{dt}(\\theta).",
        (0, 18),
    ),
    (
        r"\frac{d}{dt}\theta^2",
        "Write what \\frac{d}{dt} differentiates in round brackets, as in "
        "\\frac{d}{dt}\\left(m r^2 \\dot{\\theta}\\right).",
        (0, 12),
    ),
    (
        r"\frac{d}{dt}\frac{1}{2} m \dot{x}^2",
        "Write what \\frac{d}{dt} differentiates in round brackets, as in "
        "\\frac{d}{dt}\\left(m r^2 \\dot{\\theta}\\right).",
        (0, 12),
    ),
    (
        r"\partial L",
        "Partial derivatives are not supported; "
        "write the expression itself, with \\dot{x} for a velocity.",
        (0, 8),
    ),
    (r"\foo x", "Unknown LaTeX command '\\foo'.", (0, 4)),
    (r"\mathrm{d}x", "Unknown LaTeX command '\\mathrm'.", (0, 7)),
    (r"\dot{x+y}", "\\dot{...} must hold a single coordinate, as in \\dot{x}.", (0, 8)),
    (r"\dot{m}", f"'m' {NOT_COORDINATE}", (0, 6)),
    (r"\left[ x \right]", "Use round brackets ( ) only.", (0, 6)),
    (r"\frac{1}{2", "Missing '}': this '{' is never closed.", (8, 9)),
    (r"\sqrt", "'\\sqrt' needs an argument, as in \\sqrt{x}.", (0, 5)),
    (
        r"\sin \omega t",
        "Ambiguous 'sin' without brackets: write sin(omega*t) or sin(omega)*t.",
        (0, 13),
    ),
    (r"\frac{g}{2 l} + \frac{g}{2}l x^{", "Missing '}': this '{' is never closed.", (31, 32)),
    (
        r"\ddot{\theta}'",
        "Only velocities and accelerations exist here: that is a derivative of order 3 of theta.",
        (0, 14),
    ),
]


def test_there_are_enough_error_rows() -> None:
    assert len(ERRORS) >= 40


@pytest.mark.parametrize(("text", "message", "span"), ERRORS, ids=[repr(r[0]) for r in ERRORS])
def test_error_message_and_caret(text: str, message: str, span: tuple[int, int]) -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer(text, VOCAB)
    assert caught.value.message == message
    assert caught.value.span == span
    assert caught.value.source == text


def test_hints_for_e_and_constants() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("e^x", VOCAB)
    assert caught.value.hint == "e is not Euler's number here; write exp(x) for the exponential."
    with pytest.raises(ParseError) as caught:
        parse_answer("I", VOCAB)
    assert caught.value.hint.startswith("I is not one of this question's names")
    assert "declares" not in caught.value.hint  # words a student knows (issue 30)
    with pytest.raises(ParseError) as caught:
        parse_answer("1/2 m x_dot^2 = E", VOCAB)
    assert caught.value.hint.startswith("E is not one of this question's names: write the energy")


def test_str_shows_message_line_and_caret() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("m + sin 2 theta", VOCAB)
    assert str(caught.value) == (
        "Ambiguous 'sin' without brackets: write sin(2*theta) or sin(2)*theta.\n"
        "  m + sin 2 theta\n      ^^^^^^^^^^^"
    )


def test_str_shows_only_the_offending_line_of_a_list() -> None:
    with pytest.raises(ParseError) as caught:
        parse_equations("m x_ddot = -k x\nM x_Mddot = sin 2 theta\nq_ddot = 0", VOCAB)
    error = caught.value
    assert error.span == (28, 39)
    assert str(error) == (
        "Ambiguous 'sin' without brackets: write sin(2*theta) or sin(2)*theta.\n"
        "  M x_Mddot = sin 2 theta\n              ^^^^^^^^^^^"
    )


def test_str_never_echoes_invisible_characters() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("m\u202eg", VOCAB)
    assert "\u202e" not in str(caught.value)
    assert str(caught.value).splitlines()[1:] == ["  m?g", "   ^"]


def test_caret_at_the_end_when_the_answer_ended() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("(m", VOCAB)
    assert str(caught.value).splitlines()[2] == "  ^"
    with pytest.raises(ParseError) as caught:
        parse_answer("sin", VOCAB)
    assert caught.value.span == (0, 3)


def test_a_long_answer_is_cut_around_the_caret() -> None:
    text = "m + " * 300 + "mthetal"
    with pytest.raises(ParseError) as caught:
        parse_answer(text, VOCAB)
    line, caret = str(caught.value).splitlines()[1:3]
    assert line.startswith("  …") and len(line) < 90
    assert line[caret.index("^") : caret.index("^") + 7] == "mthetal"


def test_expression_refuses_an_equals_sign() -> None:
    with pytest.raises(ParseError) as caught:
        parse_expression("L = m g", VOCAB)
    assert caught.value.message == (
        "Expected an expression, not an equation; write only the expression, without '='."
    )
    assert caught.value.span == (2, 3)


def test_equation_and_list_errors() -> None:
    with pytest.raises(ParseError, match="The answer is empty."):
        parse_equations("\n ; \n", VOCAB)
    with pytest.raises(ParseError, match="Use a single '='"):
        parse_equation("m == g", VOCAB)


def test_non_text_is_a_parse_error() -> None:
    with pytest.raises(ParseError, match="The answer must be text, not bytes."):
        parse_answer(b"m g", VOCAB)  # type: ignore[arg-type]
    with pytest.raises(ParseError, match="The answer must be text, not NoneType."):
        parse_equations([None], VOCAB)  # type: ignore[list-item]


def test_too_long() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("m" * 2001, VOCAB)
    assert caught.value.message == "The answer is too long (2001 characters; the limit is 2000)."


def test_too_deep() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("(" * 60 + "m" + ")" * 60, VOCAB)
    assert caught.value.message == "The answer is nested too deeply (more than 50 levels)."
    with pytest.raises(ParseError, match="nested too deeply"):
        parse_answer("-" * 60 + "m", VOCAB)
    with pytest.raises(ParseError, match="nested too deeply"):
        parse_answer("x^" * 60 + "2", VOCAB)


def test_parse_error_pickles_and_is_a_grader_error() -> None:
    with pytest.raises(ParseError) as caught:
        parse_answer("m + sin 2 theta", VOCAB)
    error = caught.value
    clone = pickle.loads(pickle.dumps(error))
    assert isinstance(clone, ParseError) and isinstance(clone, GraderError)
    assert (clone.message, clone.span, clone.source, clone.hint) == (
        error.message,
        error.span,
        error.source,
        error.hint,
    )
    assert str(clone) == str(error)


def test_primes_with_a_non_coordinate_when_allowed() -> None:
    primed = Vocabulary.from_names(["x"], ["m"], allow_primes=True)
    with pytest.raises(ParseError) as caught:
        parse_answer("m'", primed)
    assert caught.value.message == "'m' is not a coordinate of this problem (coordinates: x)."
