"""Issue 15: for a system of several coordinates, a wrong equation of motion is answered as for
one coordinate — "your equation gives q̈ = … and the reference q̈ = …" — with the other
accelerations taken as Lagrange's equations give them, and said so. The numbers are checked
here against sympy's own Euler–Lagrange equations of the wedge, solved at the handout values."""

from __future__ import annotations

import re
import unicodedata

import sympy as sp

from lagrade.bank.registry import get_scene
from lagrade.judge.check import check

NUMBER = r"(−?[\d.]+(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)"


def _value(text: str) -> float:
    return float(text.replace("−", "-"))


def test_the_wrong_equation_of_a_wedge_gets_its_numbers():
    variant = get_scene("wedge").variant(3)
    answer = ["(M + m) X_ddot + m q_ddot cos(alpha) = 0", "q_ddot + 3 X_ddot = g q"]
    verdict = check({"scene": "wedge", "seed": 3}, "eom", answer, time_limit=None)
    assert verdict.status == "incorrect" and verdict.score == 0.5
    (sentence, units) = [f for f in verdict.feedback if f.startswith("Equation 2")]
    # g q is no acceleration: the dimension hint says so (issue 25), after the numbers
    assert "g*q has units of m²/s²; the other terms m/s², an acceleration." in units
    sentence = unicodedata.normalize("NFD", sentence)  # dots as combining marks
    state = dict(re.findall("([Xq]\u0307?) = " + NUMBER, sentence))
    unit = r"(?: m/s²)?"  # the wedge's X and q are lengths: their accelerations in m/s²
    gives = re.search(
        "your equation gives q\u0308 = " + NUMBER + unit + " and the reference q\u0308 = " + NUMBER,
        sentence,
    )
    other = re.search(
        "with X\u0308 = " + NUMBER + unit + r" as Lagrange's equations give it", sentence
    )
    assert gives and other, sentence

    # sympy, independently: Euler–Lagrange equations of the variant's L at the handout values
    t = sp.Symbol("t")
    X, q = sp.Function("X")(t), sp.Function("q")(t)
    syms = {s.name: s for s in variant.lagrangian.free_symbols}
    L = variant.lagrangian.subs({syms["X_dot"]: X.diff(t), syms["q_dot"]: q.diff(t)})
    L = L.subs({syms["q"]: q}).subs({syms[n]: v for n, v in variant.values.items()})
    eqs = [sp.diff(L.diff(c.diff(t)), t) - L.diff(c) for c in (X, q)]
    at = {
        X.diff(t): _value(state["X\u0307"]),
        q.diff(t): _value(state["q\u0307"]),
        X: _value(state["X"]),
        q: _value(state["q"]),
    }
    aX, aq = sp.symbols("aX aq")
    eqs = [e.subs({X.diff(t, 2): aX, q.diff(t, 2): aq}).subs(at) for e in eqs]
    solved = sp.solve(eqs, [aX, aq])
    # computed at the state as quoted (issue 36): equal to the quoted three significant figures
    close = lambda a, b: abs(a - b) <= 0.006 * abs(a) + 1e-9  # noqa: E731
    assert close(float(solved[aq]), _value(gives.group(2)))
    assert close(float(solved[aX]), _value(other.group(1)))
    # the student's equation 2, with Ẍ from Lagrange's equations, solved for q̈
    g, qv = variant.values["g"], _value(state["q"])
    mine = g * qv - 3 * float(solved[aX])
    assert close(mine, _value(gives.group(1)))
