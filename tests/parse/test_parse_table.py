"""Realistic student answers, plain and LaTeX, and the exact sympy expression each must become.

Rows include the silent misreads of stock parsers (issue 3): `thetadot^2` (split_symbols),
`sin theta cos theta`, `x(t)^2`, `exp(-gamma t)`, `I`/`E` as constants, `\\dot{x}` as dot·x.
"""

from __future__ import annotations

from types import SimpleNamespace

import pytest
import sympy as sp
from sympy import (
    Abs,
    Rational,
    acos,
    asin,
    atan,
    cos,
    cosh,
    cot,
    csc,
    exp,
    log,
    pi,
    sec,
    sin,
    sinh,
    sqrt,
    tan,
    tanh,
)

from lagrade.mechanics.domains import Domain
from lagrade.mechanics.lagrange import jet, t
from lagrade.notation.parse import (
    Vocabulary,
    parse_answer,
    parse_equation,
    parse_equations,
    parse_expression,
)

COORDINATES = ("theta", "phi", "x_M", "q", "r", "x", "theta_1", "theta2")
PARAMETERS = {
    "m": "positive", "M": "positive", "g": "positive", "R": "positive", "l": "positive",
    "k": "positive", "omega": "positive", "alpha": "(0, pi/2)", "m_1": "positive",
    "m2": "positive", "gamma": "positive", "b": "real", "lambda": "positive",
}  # fmt: skip
LABELS = ("p_theta", "L", "h")
VOCAB = Vocabulary.from_names(COORDINATES, PARAMETERS, LABELS)
PRIMED = Vocabulary.from_names(COORDINATES, PARAMETERS, LABELS, allow_primes=True)
CONSTANTS = Vocabulary.from_names(["theta"], ["I", "E", "e", "omega", "m"], ["T", "V"])


def _namespace() -> SimpleNamespace:
    ns: dict[str, sp.Expr] = {}
    for c in COORDINATES:
        j = jet(c)
        ns[c], ns[c + "_dot"], ns[c + "_ddot"] = j.q, j.dot, j.ddot
    for name, domain in PARAMETERS.items():
        ns[name] = Domain.parse(domain).symbol(name)
    for name in LABELS + ("T", "V"):
        ns[name] = sp.Symbol(name, real=True)
    for name in ("I", "E", "e"):
        ns[name] = sp.Symbol(name, positive=True)
    ns["lam"] = ns["lambda"]
    ns["t"] = t
    return SimpleNamespace(**ns)


s = _namespace()
half = Rational(1, 2)

# (text, expected); expected is an expression, or (lhs, rhs) for an equation.
PLAIN = [
    ("m g l", s.m * s.g * s.l),
    ("2 m g", 2 * s.m * s.g),
    ("2m g", 2 * s.m * s.g),
    ("m*g*l", s.m * s.g * s.l),
    ("1/2 m R^2 thetadot^2", half * s.m * s.R**2 * s.theta_dot**2),
    ("1/2*m*R**2*theta_dot**2", half * s.m * s.R**2 * s.theta_dot**2),
    ("(1/2) m R^2 theta_dot^2", half * s.m * s.R**2 * s.theta_dot**2),
    ("0.5 m R^2 theta_dot^2", half * s.m * s.R**2 * s.theta_dot**2),
    (
        "m R^2 theta_ddot + m g R sin(theta)",
        s.m * s.R**2 * s.theta_ddot + s.m * s.g * s.R * sin(s.theta),
    ),
    (
        "m R^2 thetaddot + m g R sin theta",
        s.m * s.R**2 * s.theta_ddot + s.m * s.g * s.R * sin(s.theta),
    ),
    ("sin theta cos theta", sin(s.theta) * cos(s.theta)),
    ("sin(theta)cos(theta)", sin(s.theta) * cos(s.theta)),
    ("sin theta * cos theta", sin(s.theta) * cos(s.theta)),
    ("sin^2(theta)", sin(s.theta) ** 2),
    ("sin^2 theta", sin(s.theta) ** 2),
    ("sin(theta)^2", sin(s.theta) ** 2),
    ("sin(theta)**2", sin(s.theta) ** 2),
    ("cos^2(theta) + sin^2(theta)", cos(s.theta) ** 2 + sin(s.theta) ** 2),
    ("l(1-cos(theta))", s.l * (1 - cos(s.theta))),
    ("m g l (1 - cos theta)", s.m * s.g * s.l * (1 - cos(s.theta))),
    ("(m+M) x_Mddot", (s.m + s.M) * s.x_M_ddot),
    ("m g (h - q sin(alpha))", s.m * s.g * (s.h - s.q * sin(s.alpha))),
    ("x_{M}", s.x_M),
    ("x_Mdot", s.x_M_dot),
    ("x_M_dot", s.x_M_dot),
    ("x_{M}dot", s.x_M_dot),
    ("x_M_ddot", s.x_M_ddot),
    ("x_Mddot", s.x_M_ddot),
    ("ẋ_M", s.x_M_dot),
    ("\u1e8b_M", s.x_M_dot),
    ("x\u0307_M", s.x_M_dot),
    ("θ\u0307", s.theta_dot),
    ("θ\u0308", s.theta_ddot),
    ("\u1e8d", s.x_ddot),
    ("r\u0307^2", s.r_dot**2),
    ("diff(theta, t)", s.theta_dot),
    ("diff(theta, t, 2)", s.theta_ddot),
    ("diff(theta_dot, t)", s.theta_ddot),
    ("diff(x_M, t)", s.x_M_dot),
    ("diff(theta(t), t)", s.theta_dot),
    ("thetadot", s.theta_dot),
    ("theta_dot", s.theta_dot),
    ("theta1", s.theta_1),
    ("theta_1", s.theta_1),
    ("theta_1dot", s.theta_1_dot),
    ("theta1dot", s.theta_1_dot),
    ("theta1_ddot", s.theta_1_ddot),
    ("theta_2", s.theta2),
    ("theta2", s.theta2),
    ("theta_2_dot", s.theta2_dot),
    ("m1 m_2", s.m_1 * s.m2),
    ("ω", s.omega),
    ("ωt", s.omega * s.t),
    ("sin(ωt)", sin(s.omega * s.t)),
    ("mω²", s.m * s.omega**2),
    ("φ", s.phi),
    ("ϕ", s.phi),
    ("ϑ", s.theta),
    ("α", s.alpha),
    ("λ", s.lam),
    ("lambda", s.lam),
    ("gamma", s.gamma),
    ("2^3^2", sp.Integer(512)),
    ("x^-1", 1 / s.x),
    ("x^-2 m", s.m / s.x**2),
    ("-x^2", -(s.x**2)),
    ("(-x)^2", s.x**2),
    ("2^-1", half),
    ("6.674e-11", Rational(6674, 10**14)),
    ("0.5", half),
    ("1.25", Rational(5, 4)),
    (".5", half),
    ("3E2", sp.Integer(300)),
    ("2.5e3 m", 2500 * s.m),
    ("exp(-gamma t)", exp(-s.gamma * s.t)),
    ("exp(-gamma*t) cos(omega t)", exp(-s.gamma * s.t) * cos(s.omega * s.t)),
    ("sqrt(g/l)", sqrt(s.g / s.l)),
    ("sqrt(2 g h)", sqrt(2 * s.g * s.h)),
    ("abs(x)", Abs(s.x)),
    ("ln(r)", log(s.r)),
    ("log(r)", log(s.r)),
    (
        "tan(alpha) + sec(alpha) + cot(alpha) + csc(alpha)",
        tan(s.alpha) + sec(s.alpha) + cot(s.alpha) + csc(s.alpha),
    ),
    ("sinh(x) cosh(x) tanh(x)", sinh(s.x) * cosh(s.x) * tanh(s.x)),
    ("asin(x) + arcsin(x)", 2 * asin(s.x)),
    ("acos(x) + arccos(x)", 2 * acos(s.x)),
    ("atan(x) + arctan(x)", 2 * atan(s.x)),
    ("pi", pi),
    ("2 pi R", 2 * pi * s.R),
    ("π R^2", pi * s.R**2),
    ("t", s.t),
    ("cos(omega t)", cos(s.omega * s.t)),
    ("R omega^2 sin(theta) cos(theta)", s.R * s.omega**2 * sin(s.theta) * cos(s.theta)),
    (
        "1/2 m (R^2 thetadot^2 + R^2 omega^2 sin(theta)^2) + m g R cos(theta)",
        half * s.m * (s.R**2 * s.theta_dot**2 + s.R**2 * s.omega**2 * sin(s.theta) ** 2)
        + s.m * s.g * s.R * cos(s.theta),
    ),
    (
        "m R^2 thetaddot - m R^2 omega^2 sin theta cos theta + m g R sin theta = 0",
        (
            s.m * s.R**2 * s.theta_ddot
            - s.m * s.R**2 * s.omega**2 * sin(s.theta) * cos(s.theta)
            + s.m * s.g * s.R * sin(s.theta),
            0,
        ),
    ),
    ("p_theta = m R^2 theta_dot", (s.p_theta, s.m * s.R**2 * s.theta_dot)),
    ("L = 1/2 m x_dot^2 - 1/2 k x^2", (s.L, half * s.m * s.x_dot**2 - half * s.k * s.x**2)),
    (
        "1/2 m (rdot^2 + r^2 thetadot^2) + m g r cos theta - 1/2 k (r - l)^2",
        half * s.m * (s.r_dot**2 + s.r**2 * s.theta_dot**2)
        + s.m * s.g * s.r * cos(s.theta)
        - half * s.k * (s.r - s.l) ** 2,
    ),
    (
        "m rddot - m r thetadot^2 - m g cos theta + k (r - l) = 0",
        (
            s.m * s.r_ddot
            - s.m * s.r * s.theta_dot**2
            - s.m * s.g * cos(s.theta)
            + s.k * (s.r - s.l),
            0,
        ),
    ),
    (
        "m r^2 thetaddot + 2 m r rdot thetadot + m g r sin theta = 0",
        (
            s.m * s.r**2 * s.theta_ddot
            + 2 * s.m * s.r * s.r_dot * s.theta_dot
            + s.m * s.g * s.r * sin(s.theta),
            0,
        ),
    ),
    (
        "(m_1 + m2) l^2 theta_1ddot + m2 l^2 theta2ddot cos(theta_1 - theta2)",
        (s.m_1 + s.m2) * s.l**2 * s.theta_1_ddot
        + s.m2 * s.l**2 * s.theta2_ddot * cos(s.theta_1 - s.theta2),
    ),
    ("theta(t)", s.theta),
    ("x(t)^2", s.x**2),
    ("thetadot^2", s.theta_dot**2),
    ("1/2 m x_dot^2", half * s.m * s.x_dot**2),
    ("3/2 m g", Rational(3, 2) * s.m * s.g),
    ("1/2(m+M) x_Mdot^2", half * (s.m + s.M) * s.x_M_dot**2),
    ("m g/l", s.m * s.g / s.l),
    ("m g / (2 l)", s.m * s.g / (2 * s.l)),
    ("-1/2 k x^2", -half * s.k * s.x**2),
    ("k x^2/2", s.k * s.x**2 / 2),
    ("m - -g", s.m + s.g),
    ("+m g", s.m * s.g),
    ("(m)(g)", s.m * s.g),
    ("2(m+M)", 2 * (s.m + s.M)),
    ("m(x)", s.m * s.x),
    ("cos(theta)^2 - sin(theta)^2", cos(s.theta) ** 2 - sin(s.theta) ** 2),
    ("q cos alpha", s.q * cos(s.alpha)),
    ("2 sin(theta) cos(theta)", 2 * sin(s.theta) * cos(s.theta)),
    ("sin(2 theta)", sin(2 * s.theta)),
    ("sin(2theta)", sin(2 * s.theta)),
    ("b x_dot", s.b * s.x_dot),
    (
        "M x_Mddot + m (x_Mddot + qddot cos alpha) = 0",
        (s.M * s.x_M_ddot + s.m * (s.x_M_ddot + s.q_ddot * cos(s.alpha)), 0),
    ),
    (
        "m qddot + m x_Mddot cos(alpha) - m g sin(alpha) = 0",
        (s.m * s.q_ddot + s.m * s.x_M_ddot * cos(s.alpha) - s.m * s.g * sin(s.alpha), 0),
    ),
    (
        "x_M_ddot = -m g sin(alpha) cos(alpha) / (M + m sin(alpha)^2)",
        (s.x_M_ddot, -s.m * s.g * sin(s.alpha) * cos(s.alpha) / (s.M + s.m * sin(s.alpha) ** 2)),
    ),
    ("k (r - l)^2/2", s.k * (s.r - s.l) ** 2 / 2),
    # Unicode operators and forms
    ("m·g·l", s.m * s.g * s.l),
    ("m⋅g", s.m * s.g),
    ("m×g", s.m * s.g),
    ("m − g", s.m - s.g),
    ("m – g", s.m - s.g),
    ("x²", s.x**2),
    ("x³ + x⁻¹", s.x**3 + 1 / s.x),
    ("½ m ẋ²", half * s.m * s.x_dot**2),
    ("m g l (1 − cos θ)", s.m * s.g * s.l * (1 - cos(s.theta))),
    ("ｍ ｇ", s.m * s.g),
    ("m\u00a0g", s.m * s.g),
    ("m\tg\n", s.m * s.g),
    # total time derivatives: D_t on the jets (issue 25)
    (
        "d/dt(m r^2 theta_dot) = 0",
        (2 * s.m * s.r * s.r_dot * s.theta_dot + s.m * s.r**2 * s.theta_ddot, 0),
    ),
    (
        "diff(m r^2 theta_dot, t) = 0",
        (2 * s.m * s.r * s.r_dot * s.theta_dot + s.m * s.r**2 * s.theta_ddot, 0),
    ),
    ("d/dt (m x_dot) + k x", s.m * s.x_ddot + s.k * s.x),
    ("m d/dt(theta)", s.m * s.theta_dot),
    ("d/dt(theta)", s.theta_dot),
    ("d/dt(d/dt(x))", s.x_ddot),
    ("d^2/dt^2(r^2)", 2 * s.r * s.r_ddot + 2 * s.r_dot**2),
    (
        "d²/dt²(l sin(theta))",
        s.l * cos(s.theta) * s.theta_ddot - s.l * sin(s.theta) * s.theta_dot**2,
    ),
    ("diff(x^2, t, 2)", 2 * s.x * s.x_ddot + 2 * s.x_dot**2),
    ("diff(theta(t)^2, t)", 2 * s.theta * s.theta_dot),
    ("diff(sin(t), t)", cos(s.t)),  # a function of t, not a coordinate written theta(t)
    (
        "d/dt(1/2 m x_dot^2 + 1/2 k x^2)",
        s.m * s.x_dot * s.x_ddot + s.k * s.x * s.x_dot,
    ),
    ("d/dt(t^2 + m)", 2 * s.t),
    ("d/dt(abs(x))", sp.sign(s.x) * s.x_dot),
    # Max and Min, any number of arguments from two
    ("Max(m, g)", sp.Max(s.m, s.g)),
    ("max(m, g, l)", sp.Max(s.m, s.g, s.l)),
    ("Min(x, q) + min(theta, 0)", sp.Min(s.x, s.q) + sp.Min(s.theta, 0)),
    ("2 Max(x^2, b)", 2 * sp.Max(s.x**2, s.b)),
    # mixed numbers: 2¾ is 2 + 3/4, never 2·3/4
    ("2¾ m", Rational(11, 4) * s.m),
    ("1½", Rational(3, 2)),
    ("m 2 ½", Rational(5, 2) * s.m),
]

LATEX = [
    (r"\dot{x}", s.x_dot),
    (r"\frac{1}{2} m \dot{x}^2", half * s.m * s.x_dot**2),
    (r"\frac12 m R^2 \dot\theta^2", half * s.m * s.R**2 * s.theta_dot**2),
    (r"\ddot{x}_M", s.x_M_ddot),
    (r"\ddot{x_M}", s.x_M_ddot),
    (r"\dot{x}_{M}", s.x_M_dot),
    (r"\sin\theta\cos\theta", sin(s.theta) * cos(s.theta)),
    (r"\sin^2\theta", sin(s.theta) ** 2),
    (r"\sin^{2}(\theta)", sin(s.theta) ** 2),
    (r"m g l \left(1 - \cos\theta\right)", s.m * s.g * s.l * (1 - cos(s.theta))),
    (r"\frac{g}{R}\sin\theta", s.g / s.R * sin(s.theta)),
    (r"\ddot{\theta} + \frac{g}{l}\sin\theta = 0", (s.theta_ddot + s.g / s.l * sin(s.theta), 0)),
    (r"m \cdot g \cdot l", s.m * s.g * s.l),
    (r"m \times g", s.m * s.g),
    (r"\sqrt{\frac{g}{l}}", sqrt(s.g / s.l)),
    (r"e^{-\gamma t}", exp(-s.gamma * s.t)),
    (r"\omega^2", s.omega**2),
    (r"\varphi", s.phi),
    (r"\vartheta", s.theta),
    (r"\dot{\varphi}", s.phi_dot),
    (
        r"\frac{1}{2} m \left( \dot{r}^2 + r^2 \dot{\theta}^2 \right)",
        half * s.m * (s.r_dot**2 + s.r**2 * s.theta_dot**2),
    ),
    (r"p_{\theta} = m R^2 \dot{\theta}", (s.p_theta, s.m * s.R**2 * s.theta_dot)),
    (r"x_{M}", s.x_M),
    (r"\theta_1", s.theta_1),
    (r"\dot{\theta}_1", s.theta_1_dot),
    (r"\dot\theta_2", s.theta2_dot),
    (r"m\,g\,l", s.m * s.g * s.l),
    (r"\pi R^2", pi * s.R**2),
    (r"2^{10}", sp.Integer(1024)),
    (r"x^{-1}", 1 / s.x),
    (r"\ln(r) + \exp(x) + \tan\alpha", log(s.r) + exp(s.x) + tan(s.alpha)),
    (r"\sqrt[3]{x}", s.x ** Rational(1, 3)),
    ("$m g l$", s.m * s.g * s.l),
    (r"\tfrac{1}{2} k x^2 + \dfrac{m}{2} \dot{x}^2", half * s.k * s.x**2 + s.m / 2 * s.x_dot**2),
    (
        r"(M+m)\ddot{x}_M + m\ddot{q}\cos\alpha = 0",
        ((s.M + s.m) * s.x_M_ddot + s.m * s.q_ddot * cos(s.alpha), 0),
    ),
    (
        r"\frac{1}{2}(M+m)\dot{x}_M^2 + m \dot{x}_M \dot{q} \cos\alpha"
        r" + \frac{1}{2} m \dot{q}^2 + m g q \sin\alpha",
        half * (s.M + s.m) * s.x_M_dot**2
        + s.m * s.x_M_dot * s.q_dot * cos(s.alpha)
        + half * s.m * s.q_dot**2
        + s.m * s.g * s.q * sin(s.alpha),
    ),
    (r"\dot{\theta}^{2}", s.theta_dot**2),
    (r"\left(m + M\right) g", (s.m + s.M) * s.g),
    (r"m g \sin{\alpha}", s.m * s.g * sin(s.alpha)),
    (r"\frac{m g \sin\alpha}{M + m}", s.m * s.g * sin(s.alpha) / (s.M + s.m)),
    # total time derivatives
    (
        r"\frac{d}{dt}\left(m r^2 \dot\theta\right) = 0",
        (2 * s.m * s.r * s.r_dot * s.theta_dot + s.m * s.r**2 * s.theta_ddot, 0),
    ),
    (r"\frac{d}{dt}(m \dot{x}) = -k x", (s.m * s.x_ddot, -s.k * s.x)),
    (r"\dfrac{d}{dt}\left(\frac{1}{2} m \dot{x}^2\right)", s.m * s.x_dot * s.x_ddot),
    (
        r"\dot{\left(m r^2 \dot\theta\right)}",
        2 * s.m * s.r * s.r_dot * s.theta_dot + s.m * s.r**2 * s.theta_ddot,
    ),
    (r"\ddot{(r^2)}", 2 * s.r * s.r_ddot + 2 * s.r_dot**2),
    (r"\frac{d^2}{dt^2}(r^2)", 2 * s.r * s.r_ddot + 2 * s.r_dot**2),
    # adjacent single letters multiply in LaTeX when every one is a declared name
    (r"\frac{gMm}{R}", s.g * s.M * s.m / s.R),
    (r"mgl\cos\theta", s.m * s.g * s.l * cos(s.theta)),
    (r"\frac{1}{2}mR^2\dot\theta^2", half * s.m * s.R**2 * s.theta_dot**2),
    (r"$mgm_1$", s.m * s.g * s.m_1),
    (r"\max(m, g) + \min(x, q)", sp.Max(s.m, s.g) + sp.Min(s.x, s.q)),
]


def _check(parsed, expected) -> None:
    if isinstance(expected, tuple):
        lhs, rhs = expected
        assert parsed.rhs is not None, "expected an equation"
        assert parsed.lhs == lhs or sp.expand(parsed.lhs - lhs) == 0, (parsed.lhs, lhs)
        assert parsed.rhs == rhs or sp.expand(parsed.rhs - rhs) == 0, (parsed.rhs, rhs)
    else:
        expected = sp.sympify(expected)  # our own test value, never student text
        assert parsed.rhs is None
        assert parsed.lhs == expected or sp.expand(parsed.lhs - expected) == 0, (
            parsed.lhs,
            expected,
        )


def test_table_is_large_enough() -> None:
    assert len(PLAIN) + len(LATEX) >= 120


@pytest.mark.parametrize(("text", "expected"), PLAIN, ids=[r[0] for r in PLAIN])
def test_plain(text: str, expected) -> None:
    _check(parse_answer(text, VOCAB), expected)


@pytest.mark.parametrize(("text", "expected"), LATEX, ids=[r[0] for r in LATEX])
def test_latex(text: str, expected) -> None:
    _check(parse_answer(text, VOCAB), expected)
    _check(parse_answer(text, VOCAB, latex=True), expected)


def test_most_rows_are_structurally_identical() -> None:
    """The expand() fallback is for sympy's own regrouping (2*(m+M) x…); most rows match exactly."""
    exact = 0
    for text, expected in PLAIN + LATEX:
        parsed = parse_answer(text, VOCAB)
        if isinstance(expected, tuple):
            exact += parsed.lhs == expected[0] and parsed.rhs == sp.sympify(expected[1])
        else:
            exact += parsed.lhs == sp.sympify(expected)
    assert exact >= 0.9 * len(PLAIN + LATEX)


# --- silent misreads of stock parsers, pinned one by one ----------------------------------------


def test_thetadot_squared_is_not_split_into_letters() -> None:
    assert parse_expression("thetadot^2", VOCAB).lhs == s.theta_dot**2


def test_sin_theta_cos_theta_is_a_product_of_two_functions() -> None:
    assert parse_expression("sin theta cos theta", VOCAB).lhs == sin(s.theta) * cos(s.theta)


def test_exp_gamma_is_a_symbol_not_the_gamma_function() -> None:
    expr = parse_expression("exp(-gamma t)", VOCAB).lhs
    assert expr == exp(-s.gamma * s.t) and not expr.has(sp.gamma)


def test_declared_I_and_E_are_plain_symbols() -> None:
    parsed = parse_expression("I omega^2/2 + E + e", CONSTANTS)
    names = {x.name for x in parsed.lhs.free_symbols}
    assert names == {"I", "E", "e", "omega"} and not parsed.lhs.has(sp.I, sp.E)


def test_declared_e_with_latex_power_is_the_symbol() -> None:
    parsed = parse_expression(r"e^{2}", CONSTANTS)
    assert parsed.lhs == sp.Symbol("e", positive=True) ** 2


def test_latex_dot_is_a_velocity_not_dot_times_x() -> None:
    assert parse_expression(r"\dot{x}", VOCAB).lhs == s.x_dot


def test_x_of_t_squared_is_x_squared() -> None:
    parsed = parse_expression("x(t)^2", VOCAB)
    assert parsed.lhs == s.x**2
    assert parsed.warnings == ("x(t) is read as x.",)


def test_x_space_bracket_t_is_a_product() -> None:
    assert parse_expression("x (t)", VOCAB).lhs == s.x * s.t


def test_power_is_right_associative() -> None:
    assert parse_expression("2^3^2", VOCAB).lhs == 2**9
    assert parse_expression("2**3**2", VOCAB).lhs == 2**9


def test_decimals_are_exact() -> None:
    value = parse_expression("6.674e-11", VOCAB).lhs
    assert isinstance(value, sp.Rational) and value == Rational(6674, 10**14)
    assert parse_expression("0.1 + 0.2", VOCAB).lhs == Rational(3, 10)


def test_log_is_natural_with_a_warning() -> None:
    parsed = parse_expression("log(r)", VOCAB)
    assert parsed.lhs == log(s.r)
    assert parsed.warnings == ("log is read as the natural logarithm ln.",)


def test_pi_declared_as_a_parameter_is_the_parameter() -> None:
    vocab = Vocabulary.from_names(["x"], ["pi"])
    assert parse_expression("pi x", vocab).lhs == sp.Symbol("pi", positive=True) * jet("x").q


def test_parameters_are_the_very_symbols_of_the_reference() -> None:
    from lagrade import bank

    variant = bank.get_scene("wedge").default
    vocab = Vocabulary.from_variant(variant)
    reference = variant.lagrangian
    parsed = parse_expression(str(reference), vocab)
    assert parsed.lhs == reference
    assert parsed.symbols == {"M", "g", "h", "m", "q", "alpha", "q_dot", "x_M_dot"}


# --- primes, when a question allows them ---------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("x'", s.x_dot),
        ("x''", s.x_ddot),
        ("θ'", s.theta_dot),
        ("x_M'", s.x_M_dot),
        ("r'^2 + r''", s.r_dot**2 + s.r_ddot),
    ],
)
def test_primes_when_allowed(text: str, expected) -> None:
    assert parse_expression(text, PRIMED).lhs == expected


# --- the four entry points ---------------------------------------------------------------------


def test_parse_equation_reads_a_bare_expression_as_equal_to_zero() -> None:
    parsed = parse_equation("m x_ddot + k x", VOCAB)
    assert parsed.rhs == 0 and parsed.is_equation
    assert parsed.expr == s.m * s.x_ddot + s.k * s.x
    assert parsed.plain() == "m*x_ddot + k*x = 0"


def test_parse_answer_keeps_an_expression_an_expression() -> None:
    parsed = parse_answer("m x_ddot + k x", VOCAB)
    assert parsed.rhs is None and not parsed.is_equation


def test_parse_equations_by_lines_and_semicolons() -> None:
    parsed = parse_equations("m x_ddot = -k x\n\n M x_Mddot = 0 ; q_ddot = g sin(alpha)", VOCAB)
    assert [p.expr for p in parsed] == [
        s.m * s.x_ddot + s.k * s.x,
        s.M * s.x_M_ddot,
        s.q_ddot - s.g * sin(s.alpha),
    ]


def test_parse_equations_from_a_list_and_latex_lines() -> None:
    parsed = parse_equations(
        ["x_ddot = 0", r"\ddot{\theta} = 0 \\ \ddot{q} + \omega^2 q = 0"], VOCAB
    )
    assert [p.lhs for p in parsed] == [s.x_ddot, s.theta_ddot, s.q_ddot + s.omega**2 * s.q]


def test_latex_spacing_semicolon_is_not_a_separator() -> None:
    parsed = parse_equations(r"m\;\ddot{x} = 0", VOCAB)
    assert len(parsed) == 1 and parsed[0].lhs == s.m * s.x_ddot


def test_symbols_found() -> None:
    parsed = parse_answer("m R^2 thetaddot = -m g R sin(theta) + 0 t", VOCAB)
    assert parsed.symbols == {"m", "R", "theta_ddot", "g", "theta", "t"}


# --- preview -----------------------------------------------------------------------------------


def test_plain_echo_has_explicit_operators() -> None:
    parsed = parse_equation("m R^2 thetaddot - m g R sin theta = 0", VOCAB)
    assert parsed.plain() == "m*R^2*theta_ddot - m*g*R*sin(theta) = 0"


@pytest.mark.parametrize(
    ("text", "echo"),
    [
        ("1/2 m x_dot^2", "1/2*m*x_dot^2"),  # an integer fraction, then the factors it multiplies
        ("(g/R) sin θ", "(g/R)*sin(theta)"),  # the grouping the student chose stays visible
        (r"\frac{1}{2} m \dot{\theta}^2", "(1/2)*m*theta_dot^2"),
        ("x^-1 + sin^2(theta)", "x^(-1) + sin(theta)^2"),
        ("2^3^2", "2^(3^2)"),  # right-associative, shown
        ("m*-g - -(m + M) g", "m*(-g) - (-(m + M))*g"),
        ("9.81e-3 m / (R g) / R^2", "9.81e-3*m/(R*g)/R^2"),  # numbers as written
        ("1E100 m + (2) g", "1E100*m + 2*g"),  # not 10^100 spelled out (too long to read back)
        ("diff(theta, t) + theta'' ", "theta_dot + theta_ddot"),
    ],
)
def test_plain_echo_shows_the_reading_in_the_students_order(text: str, echo: str) -> None:
    vocabulary = VOCAB if "'" not in text else PRIMED
    assert parse_answer(text, vocabulary).plain() == echo


def test_latex_echo_has_dots_and_cdots() -> None:
    parsed = parse_expression("1/2 m x_Mdot^2 + x_M_ddot + thetadot", VOCAB)
    text = parsed.latex()
    assert r"\dot{x}_{M}^{2}" in text and r"\ddot{x}_{M}" in text and r"\dot{\theta}" in text
    assert r"m \cdot" in text


def test_a_mixed_number_is_a_sum_and_the_reading_is_said() -> None:
    """2¾ on paper is 2 + 3/4; reading it as the product 2·¾ (what a juxtaposition would give)
    would be a silent misread. The warning says how it was read."""
    read = parse_answer("2¾ m g", VOCAB)
    assert read.lhs == Rational(11, 4) * s.m * s.g
    assert read.warnings == ("2¾ is read as the mixed number 2 + 3/4.",)
    assert parse_answer("x½", VOCAB).lhs == s.x / 2  # after a name, ½ is still a factor


def test_time_derivative_echo_reads_back_to_the_same_expression() -> None:
    for text in ("d/dt(m r^2 theta_dot)", r"\dot{\left(m r^2 \dot\theta\right)}", "d^2/dt^2(x^2)"):
        read = parse_answer(text, VOCAB)
        assert read.echo.startswith("d")
        assert parse_answer(read.echo, VOCAB).lhs == read.lhs


def test_max_and_min_are_left_as_written_not_compared_by_sympy() -> None:
    """sympy compares every pair of Max's arguments when it builds one (seconds for a dozen);
    the parser leaves them unevaluated and the judge evaluates them itself."""
    read = parse_answer("Max(m g l, k x^2, M)", VOCAB)
    assert isinstance(read.lhs, sp.Max) and len(read.lhs.args) == 3


def test_a_coordinate_named_vartheta_is_read_in_every_spelling() -> None:
    """A handout that names its coordinate vartheta prints ϑ; a student types ϑ, θ, theta,
    \\vartheta or \\theta — one letter in two shapes. Only a question that declares both keeps
    them apart."""
    only = Vocabulary.from_names(["vartheta"], {})
    q = jet("vartheta")
    for text in ("vartheta", "theta", "ϑ", "θ", r"\vartheta", r"\theta"):
        assert parse_answer(text, only).lhs == q.q, text
    assert parse_answer("ϑ̇ + thetaddot", only).lhs == q.dot + q.ddot
    both = Vocabulary.from_names(["theta", "vartheta"], {})
    assert parse_answer("ϑ - θ", both).lhs == jet("vartheta").q - jet("theta").q
    assert parse_answer(r"\vartheta - \theta", both).lhs == jet("vartheta").q - jet("theta").q
