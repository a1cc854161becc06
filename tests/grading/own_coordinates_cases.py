"""Students who chose their own coordinates, and the answers that are right in them, computed
independently of lagrade's judge: plain sympy with each coordinate a function of time, the
bodies' Cartesian positions written here from the statement's words (not read from the scene
files), T = ½ Σ m |ṙ|² (+ ½ I φ̇²), V written from the physics (gravity m g y, a spring's
length from the two ends it joins, e v·A with the field at the body), then L = T − V, the
Euler–Lagrange equations d/dt ∂L/∂q̇ − ∂L/∂q = 0, the momenta ∂L/∂q̇, the cyclic coordinates
(∂L/∂q = 0) and the conserved quantities (their momenta, and h = Σ q̇ p − L when L has no t).

Each case is a bank scene, a convention a student might choose (an angle measured the other
way or from the other axis, a distance from the other end, a shifted origin, another choice of
coordinates altogether) and the same bodies in the statement's own coordinates, so that the
statement's answers can be put to the student's transformation too. The conventions are those
a class does choose: the incline pendulum's angle towards the bottom of the incline and the
wedge's block measured up from the floor are the cases of issue 27; Kepler's polar angle from
the y axis and the two-body problem in the first body's position are the textbook alternatives
(Goldstein, Classical Mechanics, 3rd ed., §3.1 and §3.2, which use the centre of mass).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

t = sp.Symbol("t", real=True)
P = {
    name: sp.Symbol(name, positive=True)
    for name in "m M g l h alpha k k_c a l_0 m_1 m_2 G e B R".split()
}
RADIAL = {"r"}


def functions(names: list[str]) -> dict[str, sp.Expr]:
    """Each coordinate as a function of time (a radius positive, as the physics has it)."""
    return {
        n: sp.Function(n, positive=True)(t) if n in RADIAL else sp.Function(n, real=True)(t)
        for n in names
    }


#: A body: (mass, position components, and for a rigid body (inertia, angle)).
Body = tuple


@dataclass(frozen=True, eq=False)
class Case:
    scene: str
    convention: str
    coordinates: list[str]
    student: Callable[[dict], dict[str, Body]]
    statement: Callable[[dict], dict[str, Body]]
    potential: Callable[[dict[str, Body], dict], sp.Expr]
    #: words the note must hold (how the student's coordinates differ)
    words: str
    #: the statement's answers differ from the student's (not so for a shift of a cyclic one)
    statement_differs: bool = True


def _gravity(bodies: dict[str, Body], q: dict) -> sp.Expr:
    return sum(b[0] * P["g"] * b[1][-1] for b in bodies.values())


def _distance(one, other) -> sp.Expr:
    """|one − other|, its square tidied first (r² cos²θ + r² sin²θ = r², so √ gives r)."""
    squared = sum((u - v) ** 2 for u, v in zip(one, other, strict=True))
    return sp.sqrt(sp.trigsimp(sp.factor(sp.expand(squared))))


def _spring(k, length, one, other) -> sp.Expr:
    return k * (_distance(one, other) - length) ** 2 / 2


m, M, g, l, h, alpha = (P[n] for n in "m M g l h alpha".split())
k, k_c, a, l_0, m_1, m_2 = (P[n] for n in "k k_c a l_0 m_1 m_2".split())


def _incline(q, sign):
    s, phi = q["s"], q["phi"]
    block = (-s * sp.cos(alpha), -s * sp.sin(alpha))
    bob = (block[0] + sign * l * sp.sin(phi), block[1] - l * sp.cos(phi))
    return {"block": (M, block), "bob": (m, bob)}


def _wedge_statement(q):
    x, s = q["x_M"], q["q"]
    return {
        "wedge": (M, (x, sp.S.Zero)),
        "block": (m, (x + s * sp.cos(alpha), h - s * sp.sin(alpha))),
    }


def _wedge_from_floor(q):
    """The block's distance up the face from the floor, where the face meets it at
    x_M + h/tan(alpha)."""
    x, s = q["x_M"], q["q"]
    return {
        "wedge": (M, (x, sp.S.Zero)),
        "block": (m, (x + h / sp.tan(alpha) - s * sp.cos(alpha), s * sp.sin(alpha))),
    }


def _coupled(q, shift):
    return {
        "block1": (m, (q["x_1"], sp.S.Zero)),
        "block2": (m, (q["x_2"] + (a if not shift else 0), sp.S.Zero)),
    }


def _coupled_potential(bodies, q):
    """The springs are relaxed with the blocks at 0 and a: the outer ones stretch by each
    block's displacement, the middle one by the change of the blocks' distance."""
    x1 = bodies["block1"][1][0]
    x2 = bodies["block2"][1][0]
    return k * x1**2 / 2 + k_c * (x2 - x1 - a) ** 2 / 2 + k * (x2 - a) ** 2 / 2


def _spring_pendulum(q, from_horizontal):
    r, th = q["r"], q["theta"]
    if from_horizontal:
        return {"bob": (m, (r * sp.cos(th), -r * sp.sin(th)))}
    return {"bob": (m, (r * sp.sin(th), -r * sp.cos(th)))}


def _spring_pendulum_potential(bodies, q):
    x, y = bodies["bob"][1]
    return m * g * y + _spring(k, l_0, (x, y), (0, 0))


def _two_body(q, centre):
    X, Y, r, th = q["X"], q["Y"], q["r"], q["theta"]
    if centre:
        f1, f2 = m_2 / (m_1 + m_2), m_1 / (m_1 + m_2)
        one = (X - f1 * r * sp.cos(th), Y - f1 * r * sp.sin(th))
        two = (X + f2 * r * sp.cos(th), Y + f2 * r * sp.sin(th))
    else:  # (X, Y) is the first puck itself
        one = (X, Y)
        two = (X + r * sp.cos(th), Y + r * sp.sin(th))
    return {"mass1": (m_1, one), "mass2": (m_2, two)}


def _two_body_potential(bodies, q):
    return _spring(k, l_0, bodies["mass1"][1], bodies["mass2"][1])


def _kepler(q, from_y):
    r, th = q["r"], q["theta"]
    if from_y:  # the polar angle from the y axis, counterclockwise
        return {"planet": (m, (-r * sp.sin(th), r * sp.cos(th)))}
    return {"planet": (m, (r * sp.cos(th), r * sp.sin(th)))}


def _kepler_potential(bodies, q):
    return -P["G"] * M * m / _distance(bodies["planet"][1], (0, 0))


def _charged(q, mirrored):
    x = -q["x"] if mirrored else q["x"]
    return {"particle": (m, (x, q["y"], q["z"]))}


def _charged_potential(bodies, q):
    """U = −e v·A with A = (0, B x, 0) at the particle (the Landau gauge of the default
    presentation)."""
    x, y, z = bodies["particle"][1]
    return -P["e"] * sp.diff(y, t) * P["B"] * x


def _ladder(q, from_floor):
    th = q["theta"]
    tilt = sp.pi / 2 - th if from_floor else th  # from the vertical wall
    return {
        "ladder": (m, (l * sp.sin(tilt) / 2, l * sp.cos(tilt) / 2), (m * l**2 / 12, tilt)),
    }


def _double(q, relative):
    t1, t2 = q["theta_1"], q["theta_2"]
    l_1, l_2 = sp.Symbol("l_1", positive=True), sp.Symbol("l_2", positive=True)
    second = t1 + t2 if relative else t2
    one = (l_1 * sp.sin(t1), -l_1 * sp.cos(t1))
    two = (one[0] + l_2 * sp.sin(second), one[1] - l_2 * sp.cos(second))
    return {"bob1": (m_1, one), "bob2": (m_2, two)}


CASES = [
    Case(
        "incline_pendulum",
        "angle towards the bottom of the incline",
        ["s", "phi"],
        lambda q: _incline(q, -1),
        lambda q: _incline(q, +1),
        _gravity,
        "measured the other way",
    ),
    Case(
        "wedge",
        "block measured up from the floor",
        ["x_M", "q"],
        _wedge_from_floor,
        _wedge_statement,
        _gravity,
        "from the other end",
    ),
    Case(
        "coupled_oscillators",
        "second block measured from the first one's rest position (a shifted origin)",
        ["x_1", "x_2"],
        lambda q: _coupled(q, shift=True),
        lambda q: _coupled(q, shift=False),
        _coupled_potential,
        "from another origin",
    ),
    Case(
        "spring_pendulum",
        "angle from the horizontal (the other axis)",
        ["r", "theta"],
        lambda q: _spring_pendulum(q, True),
        lambda q: _spring_pendulum(q, False),
        _spring_pendulum_potential,
        "from the other axis",
    ),
    Case(
        "two_body_spring",
        "the first puck's position instead of the centre of mass",
        ["X", "Y", "r", "theta"],
        lambda q: _two_body(q, centre=False),
        lambda q: _two_body(q, centre=True),
        _two_body_potential,
        "different choice of coordinates",
    ),
    Case(
        "kepler",
        "polar angle from the y axis",
        ["r", "theta"],
        lambda q: _kepler(q, True),
        lambda q: _kepler(q, False),
        _kepler_potential,
        "quarter turn",
        statement_differs=False,  # theta is cyclic: a turned zero leaves L as it was
    ),
    Case(
        "charged_particle",
        "x axis mirrored (a velocity-dependent potential)",
        ["x", "y", "z"],
        lambda q: _charged(q, True),
        lambda q: _charged(q, False),
        _charged_potential,
        "opposite direction",
    ),
    Case(
        "sliding_ladder",
        "angle from the floor, where the statement measures it from the wall (a rigid body)",
        ["theta"],
        lambda q: _ladder(q, True),
        lambda q: _ladder(q, False),
        _gravity,
        "from the other axis",
    ),
    Case(
        "double_pendulum",
        "second angle measured from the first rod",
        ["theta_1", "theta_2"],
        lambda q: _double(q, True),
        lambda q: _double(q, False),
        _gravity,
        "another quantity",
    ),
]


# --- the answers that are right, derived here --------------------------------------------------


def in_jets(expr: sp.Expr, q: dict[str, sp.Expr]) -> sp.Expr:
    """An expression in q(t), q̇, q̈ with plain symbols for them: theta, theta_dot, theta_ddot."""
    swap = {}
    for name, f in q.items():
        swap[sp.Derivative(f, (t, 2))] = sp.Symbol(f"{name}_ddot")
        swap[sp.Derivative(f, t)] = sp.Symbol(f"{name}_dot")
    return expr.subs(swap).subs({f: sp.Symbol(name) for name, f in q.items()})


def _jet_text(expr: sp.Expr, q: dict[str, sp.Expr]) -> str:
    """An expression in q(t), q̇, q̈ as a student types it: theta_dot, theta_ddot."""
    return sp.sstr(in_jets(expr, q))


@dataclass(frozen=True)
class Derivation:
    """The five steps in one set of coordinates, each coordinate a function of time."""

    q: dict
    transformation: list[str]
    T: sp.Expr
    V: sp.Expr
    L: sp.Expr
    momenta: dict
    equations: dict
    cyclic: list[str]
    h: sp.Expr


@functools.cache
def derivation(case: Case, which: str = "student") -> Derivation:
    """T, V, L, momenta, Euler–Lagrange expressions, cyclic coordinates and h in the student's
    (`which="student"`) or the statement's coordinates."""
    q = functions(case.coordinates)
    bodies = (case.student if which == "student" else case.statement)(q)
    T = sp.S.Zero
    lines = []
    for name, body in bodies.items():
        mass, position = body[0], body[1]
        T += mass * sum(sp.diff(x, t) ** 2 for x in position) / 2
        for axis, x in zip("xyz", position, strict=False):
            lines.append(f"{axis}_{name} = {_jet_text(x, q)}")
        if len(body) > 2:
            inertia, angle = body[2]
            T += inertia * sp.diff(angle, t) ** 2 / 2
            lines.append(f"phi_{name} = {_jet_text(angle, q)}")
    V = sp.expand(case.potential(bodies, q))
    T = sp.trigsimp(sp.expand(T))
    L = sp.expand(T - V)
    velocities = {n: sp.diff(f, t) for n, f in q.items()}
    p = {n: sp.expand(sp.diff(L, v)) for n, v in velocities.items()}
    el = {n: sp.expand(sp.diff(p[n], t) - sp.diff(L, q[n])) for n in q}
    cyclic = [n for n in q if sp.trigsimp(sp.expand(sp.diff(L, q[n]))) == 0]
    h = sp.expand(sum(velocities[n] * p[n] for n in q) - L)
    return Derivation(q, lines, T, V, L, p, el, cyclic, h)


@dataclass(frozen=True)
class Answers:
    transformation: list[str]
    T: str
    V: str
    lagrangian: str
    eom: list[str]
    momenta: list[str]
    cyclic: list[str]
    conserved: list[str]
    #: the same with a sign or factor error
    wrong: dict


@functools.cache
def answers(case: Case, which: str = "student") -> Answers:
    """The right answers of every part, as a student types them (and the same with errors)."""
    d = derivation(case, which)
    q, T, V, L, p, el, h = d.q, d.T, d.V, d.L, d.momenta, d.equations, d.h
    # none of these scenes depends on t explicitly: h is conserved besides the cyclic momenta
    conserved = [p[n] for n in d.cyclic] + [h]
    text = lambda e: _jet_text(e, q)  # noqa: E731
    first = case.coordinates[0]
    broken, flip = _sign_error(el, q)
    wrong = {
        "lagrangian": text(L + 2 * V),  # V's sign wrong: T + V
        "T": text(2 * T),
        "V": text(-V),
        "eom": [f"{text(el[n] + (flip if n == broken else 0))} = 0" for n in q],
        "momenta": [f"p_{n} = {text(2 * p[n] if n == first else p[n])}" for n in q],
        "conserved": [text(sp.expand(h + 2 * V))],
    }
    return Answers(
        d.transformation,
        text(T),
        text(V),
        text(L),
        [f"{text(el[n])} = 0" for n in q],
        [f"p_{n} = {text(p[n])}" for n in q],
        d.cyclic,
        [text(c) for c in conserved],
        wrong,
    )


def _sign_error(equations: dict, q: dict) -> tuple[str, sp.Expr]:
    """(coordinate, −2 × a term) that flips one term's sign so that the set of equations
    changes: a term free of accelerations, else the second acceleration's term (flipping the
    only acceleration of an equation would give the same equation)."""
    accelerations = [sp.Derivative(f, (t, 2)) for f in q.values()]
    for name, equation in equations.items():
        for term in sp.Add.make_args(equation):
            if not any(term.has(d) for d in accelerations):
                return name, -2 * term
    for name, equation in equations.items():
        held = [d for d in accelerations if equation.has(d)]
        if len(held) > 1:
            term = next(x for x in sp.Add.make_args(equation) if x.has(held[1]))
            return name, -2 * term
    raise AssertionError("no single sign error changes these equations of motion")
