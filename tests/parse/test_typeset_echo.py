"""The typeset "read as" echo (`lagrade.notation.typeset`): the student's terms in the student's
order, every product shown with a centred dot, in LaTeX and in MathML; well-formed whatever the
answer, read back by our own LaTeX reader as the same value, and the same whether it is typeset
from the answer or from its plain echo typed back in (which is what the answer page does)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.errors import ParseError
from lagrade.notation.limits import MAX_LENGTH
from lagrade.notation.parse import Vocabulary, parse_answer, parse_equation

VOCAB = Vocabulary.from_names(["q", "x", "theta"], ["M", "m", "g", "l", "alpha"])
COORDINATES = ("q", "x", "theta")
NS = "{http://www.w3.org/1998/Math/MathML}"
DOT = "<mo>&#183;</mo>"


def test_the_issue_example_keeps_the_students_order_and_shows_every_product():
    """Issue 29: `1/2 (M+m) ẋ² + … + m g q sin α` was shown as `gmq sin(α) + m q̇²/2 + …`."""
    parsed = parse_answer("1/2 (M+m) x_dot^2 + 1/2 m q_dot^2 + m g q sin alpha", VOCAB)
    assert parsed.latex() == (
        r"\frac{1}{2} \cdot \left(M + m\right) \cdot \dot{x}^{2}"
        r" + \frac{1}{2} \cdot m \cdot \dot{q}^{2}"
        r" + m \cdot g \cdot q \cdot \sin\left(\alpha\right)"
    )
    shown = str(parsed.mathml(COORDINATES))
    assert f"<mi>m</mi>{DOT}<mi>g</mi>{DOT}<mi>q</mi>{DOT}<mrow><mi>sin</mi>" in shown
    assert shown.index("<mi>M</mi>") < shown.index("<mi>g</mi>")  # first term first


@pytest.mark.parametrize(
    ("text", "latex"),
    [
        ("g/2 l", r"\frac{g}{2} \cdot l"),  # what the parser divided, made visible
        (
            "m g l (1 - cos theta)",
            r"m \cdot g \cdot l \cdot \left(1 - \cos\left(\theta\right)\right)",
        ),
        ("-(M+m) x_ddot = m g", r"-\left(M + m\right) \cdot \ddot{x} = m \cdot g"),
        ("1.6e-19 q + 2.5 x", r"1.6 \cdot 10^{-19} \cdot q + 2.5 \cdot x"),
        ("log(x) + asin(q)", r"\ln\left(x\right) + \arcsin\left(q\right)"),
        ("m + |x|", r"m + \left|x\right|"),
        ("sin^2(theta)", r"\sin^{2}\left(\theta\right)"),
        ("x^-2 (g/l)", r"x^{-2} \cdot \frac{g}{l}"),  # a fraction needs no brackets
    ],
)
def test_latex_examples(text, latex):
    assert parse_answer(text, VOCAB).latex() == latex


def test_a_bare_equation_reads_equal_to_zero():
    parsed = parse_equation("2.5 m x_ddot + m g", VOCAB)
    assert parsed.latex() == r"2.5 \cdot m \cdot \ddot{x} + m \cdot g = 0"
    shown = str(parsed.mathml(COORDINATES))
    assert shown.startswith("<math") and "<mn>2.5</mn>" in shown  # the decimal as typed
    assert shown.endswith("<mo>=</mo><mn>0</mn></mrow></math>")


def test_the_mathml_says_the_plain_echo_to_a_screen_reader():
    parsed = parse_answer("m g l (1 - cos theta)", VOCAB)
    root = ET.fromstring(str(parsed.mathml(COORDINATES)))
    assert root.get("aria-label") == parsed.plain() == "m*g*l*(1 - cos(theta))"


def test_the_imaginary_unit_as_spelled_is_escaped():
    vocab = Vocabulary.from_names(["x"], ["m"], imaginary_unit="j")
    try:
        parsed = parse_answer("m x + j - j", vocab)
    except ParseError:
        pytest.skip("the imaginary unit is refused outright here")
    ET.fromstring(str(parsed.mathml(["x"])))


# --- properties over generated answers -----------------------------------------------------------

NAMES = ["q", "q_dot", "x_ddot", "theta", "theta_dot", "M", "m", "g", "l", "pi", "t"]
CALLS = ["sin", "cos", "exp", "sqrt", "abs", "ln", "asin", "atan", "cbrt", "atan2", "max"]
leaf = st.one_of(
    st.sampled_from(NAMES),
    st.integers(1, 12).map(str),
    st.sampled_from(["0.5", "2.25", "1.5e2", "3E-2"]),
)


def _extend(children):
    return st.one_of(
        st.tuples(st.sampled_from(["+", "-", "*", "/", " "]), children, children).map(
            lambda t: f"({t[1]}){t[0]}({t[2]})" if t[0] != " " else f"({t[1]}) ({t[2]})"
        ),
        st.tuples(children, st.integers(-3, 4)).map(lambda t: f"({t[0]})^{t[1]}"),
        children.map(lambda c: f"-({c})"),
        st.tuples(st.sampled_from(CALLS), children, children).map(
            lambda t: f"{t[0]}({t[1]}, {t[2]})" if t[0] in ("atan2", "max") else f"{t[0]}({t[1]})"
        ),
        children.map(lambda c: f"|{c}|"),
    )


answers = st.recursive(leaf, _extend, max_leaves=8)
PROPERTY = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _read(text: str):
    try:
        return parse_answer(text, VOCAB)
    except ParseError:  # not finite, too costly: nothing to typeset
        return None


def _check_mathml(markup: str) -> None:
    root = ET.fromstring(markup)  # well-formed XML
    assert root.tag == f"{NS}math"
    arity = {"mfrac": 2, "msup": 2, "msub": 2, "mroot": 2, "mover": 2}
    for element in root.iter():
        tag = element.tag.removeprefix(NS)
        assert tag in {"math", "mrow", "mi", "mn", "mo", "msqrt", *arity}, tag
        if tag in arity:
            assert len(element) == arity[tag], ET.tostring(element)


def _check_latex(latex: str) -> None:
    depth = 0
    for c in latex.replace(r"\{", "").replace(r"\}", ""):
        depth += {"{": 1, "}": -1}.get(c, 0)
        assert depth >= 0, latex
    assert depth == 0, latex
    assert latex.count(r"\left") == latex.count(r"\right"), latex


POINTS = [
    {"q": 0.3, "x": -0.7, "theta": 1.1, "M": 2.0, "m": 0.5, "g": 9.8, "l": 1.3, "t": 0.4},
    {"q": -1.2, "x": 0.9, "theta": -0.4, "M": 1.5, "m": 3.0, "g": 1.6, "l": 0.7, "t": 2.0},
]


def _values(expr: sp.Expr) -> list[complex | None]:
    values = []
    for point in POINTS:
        subs = {
            s: point.get(s.name.split("_")[0], 0.5) + 0.1 * s.name.count("d")
            for s in expr.free_symbols
        }
        try:
            value = complex(expr.xreplace(subs).evalf(30))
        except (TypeError, ValueError, ZeroDivisionError, OverflowError):
            value = None  # no value there: exp(exp(exp(150 q))) has more digits than mpmath holds
        values.append(value)
    return values


def _same_value(a: sp.Expr, b: sp.Expr) -> bool:
    if a == b:
        return True
    for u, v in zip(_values(a), _values(b), strict=True):
        if u is None or v is None or not (math.isfinite(abs(u)) and math.isfinite(abs(v))):
            continue
        if abs(u - v) > 1e-9 * max(1.0, abs(u)):
            return False
    return True


@PROPERTY
@given(answers)
def test_typeset_echo_is_well_formed(text):
    parsed = _read(text)
    if parsed is None:
        return
    markup = str(parsed.mathml(COORDINATES))
    _check_mathml(markup)
    assert ET.fromstring(markup).get("aria-label") == parsed.plain()
    _check_latex(parsed.latex())


@PROPERTY
@given(answers)
def test_the_plain_echo_reads_back_to_the_same_value_and_typesets_the_same(text):
    """The answer page typesets the grader's plain echo typed back in: it must read as the same
    value and show what the answer itself would show."""
    parsed = _read(text)
    if parsed is None or len(parsed.plain()) > MAX_LENGTH:
        return
    again = parse_answer(parsed.plain(), VOCAB)
    assert again.expr == parsed.expr, (text, parsed.plain())
    assert again.latex() == parsed.latex(), text
    assert _seen(again.mathml(COORDINATES)) == _seen(parsed.mathml(COORDINATES)), text


def _seen(markup: str) -> str:
    """MathML as it looks: <mrow> only groups, and draws nothing."""
    return markup.replace("<mrow>", "").replace("</mrow>", "")


@PROPERTY
@given(answers)
def test_typeset_latex_reads_back_to_the_same_value(text):
    """Our own LaTeX reader (never sympy's) reads the typeset echo as the same value, wherever
    it knows every command (it has no \\operatorname: cbrt, atan2) and reads bars without doubt
    (inside bars a '|' after an operator is taken to close them: | -|q| | is refused)."""
    parsed = _read(text)
    if parsed is None:
        return
    latex = parsed.latex()
    if r"\operatorname" in latex or latex.count(r"\left|") > 1 or len(latex) > MAX_LENGTH:
        return
    again = parse_answer(latex, VOCAB, latex=True)
    assert _same_value(again.expr, parsed.expr), (text, latex, again.plain())
