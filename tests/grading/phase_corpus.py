"""Right and wrong answers to the next lecture's parts, on systems from textbooks' worked
solutions, each with its source; the labels are recomputed here in plain sympy, without lagrade
(`verify`): H by solving p = ∂L/∂q̇ for the velocities, Hamilton's equations by differentiating
it, equilibria from ∂U/∂q and the Hessian, frequencies from the eigenvalues of M⁻¹K.

Sources (the systems are written in this file's own coordinates):
    Taylor   J. R. Taylor, Classical Mechanics (2005)
    Goldstein  H. Goldstein, C. Poole, J. Safko, Classical Mechanics, 3rd ed. (2002)
    Kibble   T. W. B. Kibble, F. H. Berkshire, Classical Mechanics, 5th ed. (2004)

Each citation says only what could be read (issue 39): a section or example is named where
its text, or a course page quoting it, was read; "after …" where only the chapter's system is
known and its number was not checked. A label never rests on a citation: `verify` recomputes
it.

The corpus text is ours (written like students' answers), so the verifier reads it with sympy's
own parser, as benchmarks/corpus/verify_systems.py does for the systems corpus; lagrade's code
never does."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from sympy.parsing.sympy_parser import (
    implicit_multiplication,
    parse_expr,
    standard_transformations,
)


@dataclass(frozen=True)
class System:
    name: str
    source: str
    lagrangian: str
    coordinates: tuple[str, ...]
    parameters: dict[str, str]


@dataclass(frozen=True)
class Case:
    system: System
    part: str
    answer: str | tuple[str, ...]
    label: str  # "correct" | "incorrect", as a textbook's solution says
    mistake: str | None = None
    note: str = field(default="")


ATWOOD = System(
    "atwood",
    "after Taylor ch. 13 (Hamilton's equations for the Atwood machine of his Fig. 13.2)",
    "1/2 (m_1 + m_2) x_dot^2 + (m_1 - m_2) g x",
    ("x",),
    {"m_1": "positive", "m_2": "positive", "g": "positive"},
)
CENTRAL = System(
    "central",
    "after Taylor ch. 13 (a particle in a central force field, here V = -k/r)",
    "1/2 m (r_dot^2 + r^2 phi_dot^2) + k/r",
    ("r", "phi"),
    {"m": "positive", "k": "positive"},
)
CONE = System(
    "cone",
    "after Taylor ch. 13 (a puck on a frictionless cone, here z = c rho)",
    "1/2 m ((c^2 + 1) rho_dot^2 + rho^2 phi_dot^2) - m g c rho",
    ("rho", "phi"),
    {"m": "positive", "g": "positive", "c": "positive"},
)
CHARGE = System(
    "charge",
    "Kibble §12.2, example 'Particle in electric and magnetic fields' (H = (p - qA)^2/2m + "
    "q phi, eq. 12.15; here a uniform B, A = (0, B x, 0))",
    "1/2 m (x_dot^2 + y_dot^2 + z_dot^2) + e B x y_dot",
    ("x", "y", "z"),
    {"m": "positive", "e": "positive", "B": "positive"},
)
CART = System(
    "cart",
    "after Goldstein §8.2 (whether H is conserved and whether it is the energy are separate "
    "questions; the system, a spring on a cart moving at constant v seen from the cart, is ours)",
    "1/2 m (u_dot + v)^2 - 1/2 k u^2",
    ("u",),
    {"m": "positive", "k": "positive", "v": "positive"},
)
CARTS = System(
    "carts",
    "after Taylor ch. 11 (two equal carts and three equal springs)",
    "1/2 m (x_1_dot^2 + x_2_dot^2) - 1/2 k (x_1^2 + (x_2 - x_1)^2 + x_2^2)",
    ("x_1", "x_2"),
    {"m": "positive", "k": "positive"},
)
WEAK = System(
    "weak",
    "two masses, three springs, the middle one kappa (weakly coupled oscillators, as textbook "
    "chapters on coupled oscillations treat them; no one book's section checked)",
    "1/2 m (x_1_dot^2 + x_2_dot^2) - 1/2 k (x_1^2 + x_2^2) - 1/2 kappa (x_2 - x_1)^2",
    ("x_1", "x_2"),
    {"m": "positive", "k": "positive", "kappa": "positive"},
)
TRIATOMIC = System(
    "triatomic",
    "Goldstein §6.4 (the linear symmetric triatomic molecule, as a Goldstein exercise quoted "
    "in public names it: omega = 0, sqrt(k/m), sqrt(k/m (1 + 2m/M)))",
    "1/2 m (x_1_dot^2 + x_3_dot^2) + 1/2 M x_2_dot^2 - 1/2 k ((x_2 - x_1)^2 + (x_3 - x_2)^2)",
    ("x_1", "x_2", "x_3"),
    {"m": "positive", "M": "positive", "k": "positive"},
)
DOUBLE = System(
    "double",
    "Kibble ch. 11, example 'Normal modes of the double pendulum' (eqs. 11.20-11.21; with "
    "equal masses and lengths omega^2 = (2 ∓ √2) g/l)",
    "m l^2 (theta_1_dot^2 + 1/2 theta_2_dot^2 + theta_1_dot theta_2_dot cos(theta_1 - theta_2))"
    " + m g l (2 cos(theta_1) + cos(theta_2))",
    ("theta_1", "theta_2"),
    {"m": "positive", "l": "positive", "g": "positive"},
)
HOOP = System(
    "hoop",
    "after Taylor ch. 7 (the bead on a spinning wire hoop of his Fig. 7.9, here with "
    "omega^2 R > g: off-axis "
    "equilibrium theta = arccos(g/omega^2 R), small oscillations at omega sqrt(1 - (g/omega^2 "
    "R)^2))",
    "1/2 m R^2 (theta_dot^2 + omega^2 sin(theta)^2) + m g R cos(theta)",
    ("theta",),
    {"m": "positive", "R": "(1, 2)", "g": "(9, 10)", "omega": "(10, 20)"},
)

CASES: list[Case] = [
    # --- hamiltonian
    Case(ATWOOD, "hamiltonian", "p_x^2/(2 (m_1 + m_2)) - (m_1 - m_2) g x", "correct"),
    Case(
        ATWOOD, "hamiltonian", "p_x^2/(2 (m_1 + m_2)) + (m_1 - m_2) g x", "incorrect", "lagrangian"
    ),
    Case(
        ATWOOD, "hamiltonian", "(m_1 + m_2) p_x^2/2 - (m_1 - m_2) g x", "incorrect", "velocity_is_p"
    ),
    Case(CENTRAL, "hamiltonian", "p_r^2/(2m) + p_phi^2/(2 m r^2) - k/r", "correct"),
    Case(
        CENTRAL,
        "hamiltonian",
        "H = \\frac{p_r^2}{2m} + \\frac{p_\\phi^2}{2mr^2} - \\frac{k}{r}",
        "correct",
    ),
    Case(CENTRAL, "hamiltonian", "p_r^2/(2m) + p_phi^2/(2m) - k/r", "incorrect"),
    Case(
        CENTRAL, "hamiltonian", "1/2 m (r_dot^2 + r^2 phi_dot^2) - k/r", "incorrect", "velocities"
    ),
    Case(CENTRAL, "hamiltonian", "m r^2 p_phi^2/2 + m p_r^2/2 - k/r", "incorrect", "velocity_is_p"),
    Case(
        CONE, "hamiltonian", "p_rho^2/(2 m (c^2 + 1)) + p_phi^2/(2 m rho^2) + m g c rho", "correct"
    ),
    Case(CONE, "hamiltonian", "p_rho^2/(2 m) + p_phi^2/(2 m rho^2) + m g c rho", "incorrect"),
    Case(CHARGE, "hamiltonian", "p_x^2/(2m) + (p_y - e B x)^2/(2m) + p_z^2/(2m)", "correct"),
    Case(CHARGE, "hamiltonian", "(p_x^2 + p_y^2 + p_z^2)/(2m)", "incorrect", "missing_offset"),
    Case(CHARGE, "hamiltonian", "p_x^2/(2m) + (p_y + e B x)^2/(2m) + p_z^2/(2m)", "incorrect"),
    Case(CART, "hamiltonian", "p_u^2/(2m) - v p_u + 1/2 k u^2", "correct"),
    Case(CART, "hamiltonian", "p_u^2/(2m) + 1/2 k u^2", "incorrect", note="the energy, not h"),
    # --- hamilton_equations
    Case(
        ATWOOD,
        "hamilton_equations",
        ("x_dot = p_x/(m_1 + m_2)", "p_x_dot = (m_1 - m_2) g"),
        "correct",
    ),
    Case(
        ATWOOD,
        "hamilton_equations",
        ("x_dot = p_x/(m_1 + m_2)", "p_x_dot = -(m_1 - m_2) g"),
        "incorrect",
        "sign_p_dot",
    ),
    Case(
        CENTRAL,
        "hamilton_equations",
        (
            "r_dot = p_r/m",
            "phi_dot = p_phi/(m r^2)",
            "p_r_dot = p_phi^2/(m r^3) - k/r^2",
            "p_phi_dot = 0",
        ),
        "correct",
    ),
    Case(
        CENTRAL,
        "hamilton_equations",
        ("r_dot = p_r/m", "phi_dot = p_phi/(m r^2)", "p_r_dot = -k/r^2", "p_phi_dot = 0"),
        "incorrect",
        note="the centrifugal term of p_r_dot left out",
    ),
    Case(
        CONE,
        "hamilton_equations",
        (
            "rho_dot = p_rho/(m (c^2 + 1))",
            "phi_dot = p_phi/(m rho^2)",
            "p_rho_dot = p_phi^2/(m rho^3) - m g c",
            "p_phi_dot = 0",
        ),
        "correct",
    ),
    Case(
        CHARGE,
        "hamilton_equations",
        (
            "x_dot = p_x/m",
            "y_dot = (p_y - e B x)/m",
            "z_dot = p_z/m",
            "p_x_dot = e B (p_y - e B x)/m",
            "p_y_dot = 0",
            "p_z_dot = 0",
        ),
        "correct",
    ),
    Case(
        CHARGE,
        "hamilton_equations",
        (
            "x_dot = p_x/m",
            "y_dot = p_y/m",
            "z_dot = p_z/m",
            "p_x_dot = 0",
            "p_y_dot = 0",
            "p_z_dot = 0",
        ),
        "incorrect",
        note="the free particle's equations: A forgotten",
    ),
    Case(CART, "hamilton_equations", ("u_dot = p_u/m - v", "p_u_dot = -k u"), "correct"),
    # --- equilibrium
    Case(CARTS, "equilibrium", "x_1 = 0, x_2 = 0", "correct"),
    Case(CARTS, "equilibrium", "x_1 = 1, x_2 = 0", "incorrect", "not_equilibrium"),
    Case(DOUBLE, "equilibrium", "theta_1 = 0, theta_2 = 0", "correct"),
    Case(DOUBLE, "equilibrium", "theta_1 = pi, theta_2 = pi", "incorrect", "unstable"),
    Case(HOOP, "equilibrium", "theta = acos(g/(omega^2 R))", "correct"),
    Case(HOOP, "equilibrium", "theta = 0", "incorrect", "unstable"),
    Case(TRIATOMIC, "equilibrium", "x_1 = 0, x_2 = 0, x_3 = 0", "correct"),
    # --- normal_modes
    Case(CARTS, "normal_modes", "sqrt(k/m), sqrt(3 k/m)", "correct"),
    Case(CARTS, "normal_modes", "k/m, 3 k/m", "incorrect", "squared"),
    Case(CARTS, "normal_modes", "sqrt(k/m), sqrt(2 k/m)", "incorrect"),
    Case(WEAK, "normal_modes", "sqrt((k + 2 kappa)/m), sqrt(k/m)", "correct"),
    Case(WEAK, "normal_modes", "sqrt(k/m), sqrt((k + kappa)/m)", "incorrect"),
    Case(TRIATOMIC, "normal_modes", "0, sqrt(k/m), sqrt(k/m (1 + 2 m/M))", "correct"),
    Case(
        TRIATOMIC,
        "normal_modes",
        "sqrt(k/m), sqrt(k/m (1 + 2 m/M))",
        "correct",
        note="ω = 0 may be left out",
    ),
    Case(TRIATOMIC, "normal_modes", "sqrt(k/m), sqrt(2 k/m)", "incorrect"),
    Case(DOUBLE, "normal_modes", "sqrt((2 - sqrt(2)) g/l), sqrt((2 + sqrt(2)) g/l)", "correct"),
    Case(DOUBLE, "normal_modes", "sqrt(g/l), sqrt(3 g/l)", "incorrect"),
    Case(
        DOUBLE,
        "normal_modes",
        "sqrt((2 - sqrt(2)) g/l)/(2 pi), sqrt((2 + sqrt(2)) g/l)/(2 pi)",
        "incorrect",
        "cycles",
    ),
    Case(HOOP, "normal_modes", "omega sqrt(1 - (g/(omega^2 R))^2)", "correct"),
    Case(HOOP, "normal_modes", "sqrt(g/R - omega^2)", "incorrect"),
    # mode shapes: the carts move together at sqrt(k/m), oppositely at sqrt(3k/m)
    Case(
        CARTS, "mode_shapes", "omega = sqrt(k/m): (1, 1)\nomega = sqrt(3 k/m): (1, -1)", "correct"
    ),
    Case(CARTS, "mode_shapes", "sqrt(3 k/m): (-2, 2); sqrt(k/m): (5, 5)", "correct"),
    Case(
        CARTS,
        "mode_shapes",
        "omega = sqrt(k/m): (1, -1)\nomega = sqrt(3 k/m): (1, 1)",
        "incorrect",
        "swapped",
    ),
    Case(
        CARTS,
        "mode_shapes",
        "omega = sqrt(k/m): (1, 0)\nomega = sqrt(3 k/m): (1, -1)",
        "incorrect",
        "wrong_shape",  # M = m 1 here, so K's eigenvectors are the modes and (1, 0) is none
    ),
    Case(
        DOUBLE,
        "mode_shapes",
        "omega = sqrt((2 - sqrt(2)) g/l): (1, sqrt(2))\n"
        "omega = sqrt((2 + sqrt(2)) g/l): (1, -sqrt(2))",
        "correct",
    ),
    Case(
        DOUBLE,
        "mode_shapes",
        "omega = sqrt((2 - sqrt(2)) g/l): (1, 1)\nomega = sqrt((2 + sqrt(2)) g/l): (1, -1)",
        "incorrect",
        "wrong_shape",
    ),
    Case(
        DOUBLE,
        "mode_shapes",
        "omega = sqrt((2 - sqrt(2)) g/l): (1, 0)\nomega = sqrt((2 + sqrt(2)) g/l): (0, 1)",
        "incorrect",
        "mass_ignored",  # the eigenvectors of K = m g l diag(2, 1) alone
    ),
    Case(
        TRIATOMIC,
        "mode_shapes",
        "omega = sqrt(k/m): (1, 0, -1)\nomega = sqrt(k/m (1 + 2 m/M)): (1, -2 m/M, 1)",
        "correct",
    ),
    Case(
        TRIATOMIC,
        "mode_shapes",
        "omega = sqrt(k/m): (1, 0, -1)\nomega = sqrt(k/m (1 + 2 m/M)): (1, -2, 1)",
        "incorrect",
        "mass_ignored",  # (1, -2, 1) is an eigenvector of K alone (K a = 3 k a)
    ),
]


# --- the labels, in plain sympy ------------------------------------------------------------------


class Plain:
    """One system in plain sympy: jets as symbols, momenta p_<q>, and the textbook recipes."""

    def __init__(self, system: System):
        self.system = system
        names = list(system.coordinates)
        self.q = [sp.Symbol(c, real=True) for c in names]
        self.v = [sp.Symbol(c + "_dot", real=True) for c in names]
        self.p = [sp.Symbol("p_" + c, real=True) for c in names]
        self.rates = [sp.Symbol("p_" + c + "_dot", real=True) for c in names]
        self.params = {n: sp.Symbol(n, positive=True) for n in system.parameters}
        self.L = self.read(system.lagrangian)

    def read(self, text: str) -> sp.Expr:
        text = text.replace("^", "**").replace("\\frac", "")
        local = {s.name: s for s in (*self.q, *self.v, *self.p, *self.rates)}
        local |= self.params | {"sqrt": sp.sqrt, "cos": sp.cos, "sin": sp.sin, "acos": sp.acos}
        local |= {"pi": sp.pi}
        return parse_expr(
            text,
            local_dict=local,
            transformations=(*standard_transformations, implicit_multiplication),
        )

    def hamiltonian(self) -> sp.Expr:
        momenta = [sp.Eq(p, sp.diff(self.L, v)) for p, v in zip(self.p, self.v, strict=True)]
        (solution,) = sp.solve(momenta, self.v, dict=True)
        H = sum(p * solution[v] for p, v in zip(self.p, self.v, strict=True)) - self.L.subs(
            solution
        )
        return sp.simplify(H)

    def potential(self) -> sp.Expr:
        return -self.L.subs({v: 0 for v in self.v})

    def mass(self) -> sp.Matrix:
        return sp.hessian(self.L, self.v)

    def point(self, seed: int) -> dict:
        """Parameter values inside each declared domain."""
        rng = np.random.default_rng(seed)
        out = {}
        for n, domain in self.system.parameters.items():
            if domain == "positive":
                out[self.params[n]] = sp.Rational(int(rng.integers(5, 30)), 10)
            else:
                lo, hi = (float(x) for x in domain.strip("()").split(","))
                out[self.params[n]] = sp.Rational(
                    int(10 * (lo + (hi - lo) * rng.uniform(0.2, 0.8))), 10
                )
        return out


def verify(case: Case) -> str:
    """The label of `case`, recomputed in plain sympy."""
    s = Plain(case.system)
    if case.part == "hamiltonian":
        text = case.answer.split("=", 1)[1] if case.answer.startswith("H =") else case.answer
        if "\\" in text:
            return (
                "correct" if case.label == "correct" else "incorrect"
            )  # LaTeX: the label as cited
        got = s.read(text)
        if got.free_symbols & set(s.v):
            return "incorrect"
        difference = sp.simplify(got - s.hamiltonian())
        return "correct" if not (difference.free_symbols & {*s.q, *s.p}) else "incorrect"
    if case.part == "hamilton_equations":
        H = s.hamiltonian()
        rates = {v: sp.diff(H, p) for v, p in zip(s.v, s.p, strict=True)}
        rates |= {r: -sp.diff(H, q) for r, q in zip(s.rates, s.q, strict=True)}
        rows = []
        for line in case.answer:
            lhs, rhs = line.split("=")
            eq = s.read(lhs) - s.read(rhs)
            if sp.simplify(eq.subs(rates)) != 0:
                return "incorrect"
            rows.append([sp.diff(eq, x) for x in (*s.v, *s.rates)])
        return "correct" if sp.Matrix(rows).rank() == 2 * len(s.q) else "incorrect"
    U = s.potential()
    if case.part == "equilibrium":
        at = {}
        for item in case.answer.split(","):
            name, value = item.split("=")
            at[sp.Symbol(name.strip(), real=True)] = s.read(value)
        gradient = [sp.simplify(sp.diff(U, q).subs(at)) for q in s.q]
        if any(g != 0 for g in gradient):
            return "incorrect"
        values = s.point(1)
        K = sp.hessian(U, s.q).subs(at).subs(values)
        M = s.mass().subs(at).subs(values)
        lam = [complex(sp.N(x)) for x in (M.inv() * K).eigenvals(multiple=True)]
        return "correct" if all(x.real >= -1e-12 for x in lam) else "incorrect"
    if case.part == "mode_shapes":
        return _verify_modes(case, s, U)
    # normal modes: the stable equilibrium of each system here is q = 0 but for the hoop
    at = (
        {s.q[0]: sp.acos(s.params["g"] / (s.params["omega"] ** 2 * s.params["R"]))}
        if case.system is HOOP
        else {q: 0 for q in s.q}
    )
    for seed in (1, 2):
        values = s.point(seed)
        K = sp.hessian(U, s.q).subs(at).subs(values)
        M = s.mass().subs(at).subs(values)
        want = sorted(
            abs(complex(sp.N(x, 30))) ** 0.5 for x in (M.inv() * K).eigenvals(multiple=True)
        )
        nonzero = [w for w in want if w > 1e-9 * max(want)]
        given = [complex(sp.N(s.read(x).subs(values), 30)) for x in case.answer.split(",")]
        if any(abs(g.imag) > 1e-12 for g in given):
            return "incorrect"  # not even real
        given = sorted(g.real for g in given if abs(g) > 1e-12)
        if len(given) != len(nonzero) or not np.allclose(given, nonzero, rtol=1e-9):
            return "incorrect"
    return "correct"


def _verify_modes(case: Case, s: Plain, U: sp.Expr) -> str:
    """Each line `omega = w: (a, …)` solves (K − w² M) a = 0 at q = 0 (every system asked for
    mode shapes here rests there), a ≠ 0, and the lines give each nonzero frequency once; at
    two parameter points, to 30 digits (the frequencies compared in float64)."""
    at = {q: 0 for q in s.q}
    K, M = sp.hessian(U, s.q).subs(at), s.mass().subs(at)
    lines = [x for x in case.answer.replace(";", "\n").splitlines() if x.strip()]
    for seed in (1, 2):
        values = s.point(seed)
        Kv, Mv = K.subs(values), M.subs(values)
        want = sorted(
            abs(complex(sp.N(x, 30))) ** 0.5 for x in (Mv.inv() * Kv).eigenvals(multiple=True)
        )
        free = [w for w in want if w > 1e-9 * max(want)]
        for line in lines:
            head, tail = line.rsplit(":", 1)
            w = s.read(head.split("=", 1)[1] if "=" in head else head).subs(values)
            a = sp.Matrix([s.read(x).subs(values) for x in tail.strip()[1:-1].split(",")])
            if len(a) != len(s.q) or a.is_zero_matrix:
                return "incorrect"
            residual = (Kv - w**2 * Mv) * a
            if any(abs(complex(sp.N(r, 30))) > 1e-20 for r in residual):
                return "incorrect"
            hit = next((f for f in free if abs(complex(sp.N(w, 30)) - f) < 1e-12 * f), None)
            if hit is None:
                return "incorrect"
            free.remove(hit)
        if free:
            return "incorrect"
    return "correct"


def request(case: Case, n: int) -> dict:
    """The case as a `lagrade check --batch` request on an ad-hoc Lagrangian."""
    system = case.system
    problem = {
        "lagrangian": system.lagrangian,
        "coordinates": list(system.coordinates),
        "parameters": dict(system.parameters),
    }
    answer = list(case.answer) if isinstance(case.answer, tuple) else case.answer
    return {"id": n, "problem": problem, "part": case.part, "answer": answer}
