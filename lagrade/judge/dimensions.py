"""Dimensions, as a hint: the terms of a Lagrangian, an equation of motion or a momentum must
share one dimension, so a wrong answer whose terms disagree is told which term has which
("m*l*theta_dot^2 has units of kg·m/s², a force; the other terms kg·m²/s², an energy").

Parameters carry SI units in the scene (`Parameter.unit`: "kg", "m/s^2", "N/m", "rad"); each
coordinate gets its dimension from where it stands in the positions (in `l sin(phi)` phi is an
angle, `x_M` in a position is a length), t is a time, and a velocity or acceleration divides by
one or two. Correctness is decided by the physics, never here: this only explains a wrong
answer, and says nothing when a dimension is unknown (an ad-hoc problem, a unit it cannot read).
Units are read by a small parser of our own, never evaluated.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping
from fractions import Fraction

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.rows import equation_rows, in_span
from lagrade.judge.tolerances import SAME_VALUE
from lagrade.mechanics import LagrangianSystem, RigidBody, SceneVariant, SpatialRigidBody, t
from lagrade.notation import plain

#: A dimension: exponents of metre, kilogram, second and ampere, in twelfths (whole numbers,
#: so that comparing and adding them is cheap; a square or cube root of a unit is whole too).
Dim = tuple[int, int, int, int]
_PARTS = 12

NONE: Dim = (0, 0, 0, 0)


def _dim(m: int = 0, kg: int = 0, s: int = 0, a: int = 0) -> Dim:
    return (_PARTS * m, _PARTS * kg, _PARTS * s, _PARTS * a)


LENGTH, MASS, TIME = _dim(m=1), _dim(kg=1), _dim(s=1)
ENERGY = _dim(m=2, kg=1, s=-2)

#: SI units a scene may use, by symbol.
UNITS: dict[str, Dim] = {
    "m": LENGTH, "cm": LENGTH, "mm": LENGTH, "km": LENGTH, "kg": MASS, "g": MASS,
    "s": TIME, "ms": TIME, "min": TIME, "h": TIME, "A": _dim(a=1), "rad": NONE, "sr": NONE,
    "1": NONE, "N": _dim(m=1, kg=1, s=-2), "J": ENERGY, "W": _dim(m=2, kg=1, s=-3),
    "Hz": _dim(s=-1), "C": _dim(s=1, a=1), "T": _dim(kg=1, s=-2, a=-1),
    "V": _dim(m=2, kg=1, s=-3, a=-1), "Pa": _dim(m=-1, kg=1, s=-2),
}  # fmt: skip

#: Names of the dimensions a student meets, for the message.
NAMES: dict[Dim, str] = {
    ENERGY: "an energy", _dim(m=1, kg=1, s=-2): "a force", _dim(m=1, kg=1, s=-1): "a momentum",
    _dim(m=2, kg=1, s=-1): "an angular momentum", LENGTH: "a length",
    _dim(m=1, s=-1): "a velocity", _dim(m=1, s=-2): "an acceleration", MASS: "a mass",
    TIME: "a time",
}  # fmt: skip


def _add(a: Dim, b: Dim, k: int = 1) -> Dim:
    return (a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2], a[3] + k * b[3])


def _scale(a: Dim, k: Fraction) -> Dim | None:
    """a·k, or None when that is no whole number of twelfths (an unusual root: unknown)."""
    scaled = [x * k for x in a]
    if any(x.denominator != 1 for x in scaled):
        return None
    return tuple(int(x) for x in scaled)  # type: ignore[return-value]


# --- reading a unit ---------------------------------------------------------------------------

_TOKEN = re.compile(r"\s*(?:([-+]?\d+(?:/\d+)?)|([A-Za-z]+)|(\^|\*\*)|([*·/()]))")


def read_unit(text: str) -> Dim | None:
    """ "m^3/(kg s^2)" → (3, −1, −2, 0); None for a unit it cannot read (no hint then)."""
    tokens, pos = [], 0
    text = text.strip()
    if not text:
        return None
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if match is None or match.end() == pos:
            return None
        tokens.append(match.group(0).strip())
        pos = match.end()
    try:
        dim, rest = _product(tokens)
    except (KeyError, ValueError, IndexError, ZeroDivisionError):
        return None
    return dim if not rest else None


def _product(tokens: list[str]) -> tuple[Dim, list[str]]:
    """factor ( [*·/] factor | factor )*, '/' dividing by the next factor only."""
    dim, tokens = _factor(tokens)
    while tokens and tokens[0] != ")":
        sign = 1
        if tokens[0] in ("*", "·", "/"):
            sign = -1 if tokens[0] == "/" else sign
            tokens = tokens[1:]
        factor, tokens = _factor(tokens)
        dim = _add(dim, factor, sign)
    return dim, tokens


def _factor(tokens: list[str]) -> tuple[Dim, list[str]]:
    head, tokens = tokens[0], tokens[1:]
    if head == "(":
        dim, tokens = _product(tokens)
        if not tokens or tokens[0] != ")":
            raise ValueError("unclosed bracket")
        tokens = tokens[1:]
    else:
        dim = UNITS[head]
    if tokens and tokens[0] in ("^", "**"):
        if tokens[1] == "(":  # kg^(1/2)
            if tokens[3] != ")":
                raise ValueError("an exponent in brackets is one number")
            tokens = [tokens[0], tokens[2], *tokens[4:]]
        dim, tokens = _scale(dim, Fraction(tokens[1].replace("+", ""))), tokens[2:]
        if dim is None:
            raise ValueError("a power that is no whole number of twelfths")
    return dim, tokens


def unit_text(dim: Dim) -> str:
    """(2, 1, −2, 0) → "kg·m²/s²"; "no units" for a pure number."""
    names = ("m", "kg", "s", "A")
    order = (1, 0, 2, 3)  # kg before m, as units are usually written
    up = [_power(names[i], Fraction(dim[i], _PARTS)) for i in order if dim[i] > 0]
    down = [_power(names[i], Fraction(-dim[i], _PARTS)) for i in order if dim[i] < 0]
    if not up and not down:
        return "no units"
    below = "·".join(down)
    below = f"({below})" if len(down) > 1 else below
    return "·".join(up or ["1"]) + ("/" + below if down else "")


_SUPERSCRIPT = str.maketrans("0123456789-/", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻ᐟ")


def _power(name: str, k: Fraction) -> str:
    return name if k == 1 else name + str(k).translate(_SUPERSCRIPT)


# --- dimensions of the symbols of a scene -------------------------------------------------------

#: What a term's dimension is when its parts disagree (a sum of a length and a time inside it).
MIXED = "mixed"


def symbol_dimensions(variant: SceneVariant) -> dict[sp.Symbol, Dim]:
    """The dimension of every symbol whose dimension the scene tells: parameters from their
    units, t, and each coordinate (with its velocity and acceleration) from where it stands in
    the positions, the bodies' angles and the potential (in L, for a scene given by its
    Lagrangian)."""
    known: dict[sp.Symbol, Dim] = {t: TIME}
    symbols = variant.parameter_symbols
    for parameter in variant.scene.parameters:
        dim = read_unit(parameter.unit)
        if dim is not None:
            known[symbols[parameter.name]] = dim
    wanted: list[tuple[sp.Expr, Dim]] = []
    for body in variant.bodies:
        wanted += [(x, LENGTH) for x in body.position]
        wanted.append((body.mass, MASS))
        if isinstance(body, RigidBody):
            wanted += [(body.angle, NONE), (body.inertia, _dim(m=2, kg=1))]
        if isinstance(body, SpatialRigidBody):
            wanted += [(a, NONE) for a in body.angles]
            wanted += [(i, _dim(m=2, kg=1)) for i in body.inertia]
    # a scene given by its Lagrangian has no bodies and no V: its L is the energy it tells
    energy = variant.lagrangian if variant.scene.given_by_lagrangian else variant.potential_energy
    wanted.append((energy, ENERGY))
    coordinates = [j.q for j in variant.jets]
    for _ in range(len(coordinates) + 1):  # each pass settles at least one coordinate, or none
        before = len(known)
        for expr, dim in wanted:
            _infer(sp.expand(expr), dim, known, coordinates)
        if len(known) == before:
            break
    for j in variant.jets:
        if j.q in known:
            known[j.dot] = _add(known[j.q], TIME, -1)
            known[j.ddot] = _add(known[j.q], TIME, -2)
    return known


def _infer(expr: sp.Expr, dim: Dim, known: dict, unknowns: list[sp.Symbol]) -> None:
    """Learn the dimension of an unknown coordinate from `expr` having dimension `dim`: each
    term with one unknown factor, the arguments of functions (dimensionless)."""
    for term in sp.Add.make_args(expr):
        for f in term.atoms(sp.Function):
            for arg in f.args:
                _infer(sp.expand(arg), NONE, known, unknowns)
        rest, unknown = NONE, []
        for factor in sp.Mul.make_args(term):
            base, exponent = factor.as_base_exp() if factor.is_Pow else (factor, sp.S.One)
            if base in unknowns and base not in known and exponent.is_Rational:
                unknown.append((base, Fraction(int(exponent.p), int(exponent.q))))
                continue
            d = dimension(factor, known)
            if d is None or d == MIXED:
                break
            rest = _add(rest, d)
        else:
            if len(unknown) == 1:
                base, k = unknown[0]
                found = _scale(_add(dim, rest, -1), 1 / k)
                if found is not None:
                    known[base] = found


def dimension(expr: sp.Expr, known: Mapping[sp.Symbol, Dim]) -> Dim | str | None:
    """The dimension of expr; `MIXED` when its parts disagree (a sum of a length and a time, a
    function of a length); None when some symbol's dimension is unknown."""
    if expr.is_Symbol:
        return known.get(expr)
    if expr.is_Number or expr is sp.pi or expr is sp.E or expr is sp.I:  # `is`: sympy's == is slow
        return NONE
    if expr.is_Mul:
        total = NONE
        for factor in expr.args:
            d = dimension(factor, known)
            if d is None or d == MIXED:
                return d
            total = _add(total, d)
        return total
    if expr.is_Pow:
        base, exponent = expr.args
        d = dimension(base, known)
        if d is None or d == MIXED:
            return d
        if exponent.is_Rational:
            return _scale(d, Fraction(int(exponent.p), int(exponent.q)))  # None: unknown
        e = dimension(exponent, known)
        return NONE if d == NONE and e == NONE else (None if e is None else MIXED)
    if expr.is_Add:
        dims = {dimension(a, known) for a in expr.args}
        if None in dims:
            return None
        return dims.pop() if len(dims) == 1 else MIXED
    if isinstance(expr, sp.Abs):
        return dimension(expr.args[0], known)
    if isinstance(expr, sp.sign):  # the sign of a length is a number
        d = dimension(expr.args[0], known)
        return d if d is None or d == MIXED else NONE
    if isinstance(expr, (sp.Max, sp.Min)):  # of quantities of one dimension, that dimension
        dims = {dimension(a, known) for a in expr.args}
        return None if None in dims else (dims.pop() if len(dims) == 1 else MIXED)
    if isinstance(expr, sp.Function):  # sin, exp, log, atan2 …: of pure numbers, a number
        dims = [dimension(a, known) for a in expr.args]
        if None in dims:
            return None
        if isinstance(expr, sp.atan2) and dims[0] == dims[1]:
            return NONE
        return NONE if all(d == NONE for d in dims) else MIXED
    return None


# --- the hint -------------------------------------------------------------------------------------


def disagreement(
    terms: Iterable[sp.Expr],
    known: Mapping[sp.Symbol, Dim],
    expected: Iterable[Dim] = (),
    harmless: Callable[[list[sp.Expr]], bool] = lambda odd: False,
) -> str:
    """The sentence naming which term has which dimension when the terms of an answer do not
    share one, or "" when they do, or when a dimension is unknown (say nothing unsure).

    The terms of the dimension the answer should have (`expected`: an energy for L; a force or
    a torque for an equation of motion) are "the other terms"; without one of those, the
    largest group of terms sharing a dimension; with no largest group, every group is named.
    `harmless(odd terms)`: those terms change nothing the part judges (a total time derivative
    added to L), so their dimension is no mistake."""
    groups: dict[Dim, list[sp.Expr]] = {}
    for term in terms:
        d = dimension(term, known)
        if d is None:
            return ""
        if d == MIXED:
            return _mixed_sentence(term, known)
        groups.setdefault(d, []).append(term)  # type: ignore[arg-type]
    if len(groups) < 2:
        return ""
    ranked = sorted(groups.items(), key=lambda item: -len(item[1]))
    right = [item for item in ranked if item[0] in set(expected)]
    main = right[0] if len(right) == 1 else ranked[0]
    if harmless([x for d, ts in ranked if d != main[0] for x in ts]):
        return ""
    if len(right) != 1 and len(ranked[0][1]) == len(ranked[1][1]):
        parts = [_has_units(ts, d) for d, ts in ranked]  # no majority: every group by itself
        return "The terms do not share one dimension: " + "; ".join(parts) + "."
    odd = [_has_units(ts, d) for d, ts in ranked if d != main[0]]
    rest = "the other term" if len(main[1]) == 1 else "the other terms"
    return f"{'; '.join(odd)}; {rest} {_with_name(main[0])}."


def _mixed_sentence(term: sp.Expr, known: Mapping[sp.Symbol, Dim]) -> str:
    """A term whose own parts disagree: the first sum or function inside it that mixes them."""
    for sub in sp.preorder_traversal(term):
        if isinstance(sub, sp.Add) and dimension(sub, known) == MIXED:
            parts = [
                f"{plain(a)} ({unit_text(d)})"
                for a in sub.args
                if isinstance(d := dimension(a, known), tuple)
            ]
            return f"In {plain(term)}, {' and '.join(parts)} are added but have different units."
        if isinstance(sub, sp.Function) and not isinstance(sub, (sp.Abs, sp.sign, sp.Max, sp.Min)):
            args = [dimension(a, known) for a in sub.args]
            if all(isinstance(d, tuple) for d in args) and any(d != NONE for d in args):
                shown = ", ".join(
                    f"{plain(a)} ({unit_text(d)})" for a, d in zip(sub.args, args, strict=True)
                )
                return f"In {plain(term)}, {type(sub).__name__} takes a pure number, not {shown}."
    return ""


def _has_units(terms: list[sp.Expr], dim: Dim) -> str:
    return f"{_listed(terms)} {_verb(terms)} units of {_with_name(dim)}"


def _listed(terms: list[sp.Expr]) -> str:
    shown = [plain(x) for x in terms]
    return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1]


def _verb(terms: list) -> str:
    return "has" if len(terms) == 1 else "have"


def _with_name(dim: Dim) -> str:
    name = NAMES.get(dim)
    return unit_text(dim) + (f", {name}" if name else "")


def hint_for(problem, answer, expected: str = "") -> str:
    """The dimension hint for an answer to `problem` (a `Problem`), a sympy expression or a read
    answer (whose sympy form is built only when the question has units): its terms are the
    top-level terms of the expression (lhs − rhs for an equation), `expected` what it is —
    "energy" (L, V), "kinetic" (T), "equation" (a force or torque per coordinate),
    "momentum:k" (of coordinate k); "" without a hint. In L and V, what changes no motion
    is no term to check: a constant, and terms that add up to a total time derivative dF/dt
    (whatever F's dimension): a right answer may add either."""
    known = dimensions_of(problem)
    if not known:
        return ""
    expr = answer if isinstance(answer, sp.Basic) else answer.expr  # a Read: built only now
    terms = list(sp.Add.make_args(expr))
    values = [abs(float(v)) for v in getattr(problem, "values", {}).values() if v]
    if any(_typed_number(term, values) for term in terms):
        return ""  # a number typed for a parameter has that parameter's units, unseen here
    harmless: Callable[[list[sp.Expr]], bool] = lambda odd: False  # noqa: E731
    if expected == "energy":
        motion = {s for j in problem.jets for s in (j.q, j.dot)} | {t}
        terms = [x for x in terms if x.free_symbols & motion]
        harmless = lambda odd: _total_derivative(sp.Add(*odd), problem.jets)  # noqa: E731
    elif expected == "equation":  # rows of different dimensions combined: a right equation
        harmless = lambda odd: _right_equation(problem, sp.Add(*odd))  # noqa: E731
    return disagreement(terms, known, _expected(problem, known, expected), harmless)


#: The numbers formulas carry (½, 2, ⅓, 3/2, 1/12): a coefficient beyond them was typed for a
#: quantity (9.81 for g), and its units cannot be told.
_FORMULA_NUMBER = 12
_FORMULA_NUMBERS = frozenset(
    sp.Rational(p, q) for p, q in ((2, 1), (3, 1), (4, 1), (1, 2), (1, 3), (1, 4), (3, 2), (2, 3))
)


def _typed_number(term: sp.Expr, handout: list[float]) -> bool:
    """Whether the term's number stands for a quantity: a decimal-born fraction (981/100), a
    large whole number, or a handout value or its square, perhaps times a formula's number
    (k = 5 typed as `5 q^2`, ½k as `2.5 q^2`). Such a
    number carries units the hint cannot see, so "981*q/100 has units of m" would be false."""
    coefficient = abs(term.as_coeff_Mul()[0])
    if not isinstance(coefficient, sp.Rational) or coefficient in (0, 1):
        return not isinstance(coefficient, sp.Rational)
    if coefficient.p > _FORMULA_NUMBER or coefficient.q > _FORMULA_NUMBER:
        return True
    if coefficient in _FORMULA_NUMBERS:  # ½ m v² is ½, even where some length is 0.5 m
        return False
    c = float(coefficient)
    factors = [1.0, *(float(f) for f in _FORMULA_NUMBERS)]  # ½k typed as 2.5 for k = 5
    return any(
        abs(c - f * w) <= SAME_VALUE * c for v in handout for w in (v, v * v) for f in factors
    )


def _right_equation(problem, expr: sp.Expr) -> bool:
    """Whether expr = 0 is a right equation (in the span of the reference rows at the points
    of the eom part): E_r + 3 E_θ mixes a force and a torque and is right all the same."""
    points = problem.points("eom")
    try:
        with np.errstate(all="ignore"):
            student = equation_rows([Compiled.of(expr)], problem.jets, points.env)
            r, size = in_span(student, problem.reference_rows(points), 0)
    except (UnsupportedExpression, ValueError, ZeroDivisionError):
        return False
    return bool(np.all(np.isfinite(r)) and np.all(np.abs(r) <= SAME_VALUE * size))


def _total_derivative(expr: sp.Expr, jets) -> bool:
    """Whether expr is dF/dt: its Euler–Lagrange expressions vanish identically."""
    try:
        rows = LagrangianSystem(expr, jets).euler_lagrange
    except Exception:  # noqa: BLE001 - a term sympy cannot differentiate: not known to be
        return False
    return all(_vanishes(sp.expand(e)) for e in rows)


def _vanishes(e: sp.Expr) -> bool:
    return e == 0 or (e.has(sp.sin, sp.cos) and sp.expand(sp.trigsimp(e)) == 0)


def _expected(problem, known: Mapping[sp.Symbol, Dim], what: str) -> list[Dim]:
    """ENERGY/[q] per coordinate for an equation, ENERGY·s/[q] for a momentum."""
    dims = [known.get(j.q) for j in problem.jets]
    if what in ("energy", "kinetic"):
        return [ENERGY]
    if what == "equation":
        return [_add(ENERGY, d, -1) for d in dims if d is not None]
    if what.startswith("momentum:"):
        d = dims[int(what.split(":")[1])]
        return [] if d is None else [_add(_add(ENERGY, TIME), d, -1)]
    return []


def tells(mutant) -> bool:
    """Whether a dimension hint can add to a named mistake: none named, or a term that lacks a
    parameter factor (its units differ from the others'); a sign, a factor 2 or ½, a missing or
    swapped term keeps every term's units, so the hint would say nothing (and is not sought)."""
    return mutant is None or mutant.kind == "missing_factor"


def dimensions_of(problem) -> dict[sp.Symbol, Dim]:
    """The symbol dimensions of a bank variant's question, computed once; {} for an ad-hoc
    problem (no units are declared)."""
    cache = problem.__dict__
    if "_dimensions" not in cache:
        variant = getattr(problem, "variant", None)
        cache["_dimensions"] = symbol_dimensions(variant) if variant is not None else {}
    return cache["_dimensions"]
