"""A point where a wrong answer shows, told as a physical situation a student can picture:
"at θ = 0.3 rad with the system at rest", "at θ = −2.22 rad, moving with θ̇ = 1.56 rad/s" —
coordinates, velocities (and on phase space the momenta) rounded to three significant figures,
in rad where a coordinate is an angle. Parameter values are sampled over their whole domain,
not the handout's numbers, so they are quoted only when the point has nothing else (a formula
in the parameters alone)."""

from __future__ import annotations

import math
from collections.abc import Mapping

import sympy as sp

from lagrade.judge.dimensions import NONE, dimensions_of
from lagrade.judge.dimensions import unit_text as unit_text_of
from lagrade.judge.problem import Problem
from lagrade.mechanics import momentum_name
from lagrade.notation import GREEK

_LETTER = {name: letter for letter, name in GREEK.items() if name != "sigma" or letter == "σ"}
_DOT, _DDOT = "\u0307", "\u0308"
_POWERS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def rounded(value: float) -> str:
    """`value` to three significant figures, with a real minus sign and no exponent between
    10⁻³ and 10⁴, trailing zeros dropped (0.839378 → 0.839; 0.300 → 0.3; 1234.5 → 1230;
    2.5e-07 → 2.5×10⁻⁷)."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    exponent = math.floor(math.log10(abs(value)))
    if -3 <= exponent < 4:
        text = f"{round(value, 2 - exponent):.{max(0, 2 - exponent)}f}"
        text = text.rstrip("0").rstrip(".") if "." in text else text  # 0.300 → 0.3
    else:
        mantissa = f"{value / 10**exponent:.3g}"
        text = f"{mantissa}×10{str(exponent).translate(_POWERS)}"
    return text.replace("-", "−", 1)


def symbol_text(name: str, dots: int = 0) -> str:
    """A name as a student reads it in print: theta → θ, theta_dot → θ̇, x_M_ddot → ẍ_M."""
    head, sep, tail = name.partition("_")
    head = _LETTER.get(head, head)
    head += (_DOT, _DDOT)[dots - 1] if dots else ""
    return head + sep + tail


def unit_text(unit: str) -> str:
    """An SI unit string as plain text: m/s^2 → m/s²."""
    return unit.replace("^", "").translate(_POWERS) if "^" in unit else unit


def situation(witness: Mapping[str, float], problem: Problem | None = None) -> str:
    """The situation of a witness point, e.g. "at θ = 0.3 rad with the system at rest"."""
    if problem is None:
        return "at " + _listing(witness.items(), {})
    units = coordinate_units(problem)
    where, moving, speeding = [], [], []
    for j in problem.jets:
        name = j.name
        unit, rate, acceleration = units.get(name, ("", "", ""))
        if name in witness:
            where.append(_quantity(symbol_text(name), witness[name], unit))
        if f"{name}_dot" in witness:
            moving.append((symbol_text(name, 1), witness[f"{name}_dot"], rate))
        if f"{name}_ddot" in witness:
            shown = symbol_text(name, 2)
            speeding.append(_quantity(shown, witness[f"{name}_ddot"], acceleration))
    for j in problem.jets:  # a point of phase space (H, Hamilton's equations) has momenta
        momentum = momentum_name(j.name)
        if momentum in witness:
            shown = momentum_name(symbol_text(j.name))  # p_θ
            where.append(_quantity(shown, witness[momentum], ""))
    if "t" in witness and _explicit_time(problem):
        where.append(_quantity("t", witness["t"], "s"))
    if not (where or moving or speeding):  # a formula in the parameters alone: quote them
        return "with " + _listing(witness.items(), _units(problem))
    text = "at " + _join(where) if where else ""
    if moving and all(abs(v) == 0 for _, v, _ in moving):
        text += " with the system at rest"
    elif moving:
        shown = [_quantity(n, v, u) for n, v, u in moving]
        text += (", moving with " if text else "when moving with ") + _join(shown)
    if speeding:
        text += (", accelerating with " if text else "when accelerating with ") + _join(speeding)
    return text.strip()


def _quantity(shown: str, value: float, unit: str) -> str:
    return f"{shown} = {rounded(value)}" + (f" {unit}" if unit else "")


def _listing(items, units: Mapping[str, str]) -> str:
    return _join([_quantity(symbol_text(k), v, units.get(k, "")) for k, v in items])


def _join(parts: list[str]) -> str:
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]


def angles(problem: Problem) -> frozenset[str]:
    """Coordinates that are angles. Where the scene tells a coordinate's dimension (from where
    it stands in the positions: `dimensions.symbol_dimensions`), an angle has no units (Kepler's
    r is a length whether it is called r or ρ); and it is one the reference puts inside a
    trigonometric function (θ in sin θ; a length never appears there) or one named by a Greek
    letter (Kepler's polar angle φ, which L holds only as φ̇).

    Found once per question (kept with it, as `dimensions_of` keeps its dimensions): every wrong
    answer's witness is told in these units, and finding them walks the whole reference."""
    cache = problem.__dict__
    if "_angles" not in cache:
        cache["_angles"] = _angles(problem)
    return cache["_angles"]


def _angles(problem: Problem) -> frozenset[str]:
    known = dimensions_of(problem)
    greek = {j.name for j in problem.jets if j.name.partition("_")[0] in _LETTER}
    reference = problem.lagrangian if problem.lagrangian is not None else problem.expression
    inside = set()
    for f in reference.atoms(sp.sin, sp.cos, sp.tan) if reference is not None else ():
        inside |= f.args[0].free_symbols
    guessed = {j.name for j in problem.jets if j.q in inside} | greek
    return frozenset(
        j.name
        for j in problem.jets
        if j.name in guessed and (j.q not in known or known[j.q] == NONE)
    )


def coordinate_units(problem: Problem) -> dict[str, tuple[str, str, str]]:
    """The units a coordinate, its velocity and its acceleration are quoted in: rad, rad/s and
    rad/s² for an angle; the SI units of its dimension where the scene tells one (m, m/s, m/s²);
    none otherwise (an ad-hoc question declares no units). Found once per question, like
    `angles`; a copy for the caller's own."""
    cache = problem.__dict__
    if "_coordinate_units" not in cache:
        cache["_coordinate_units"] = _coordinate_units(problem)
    return dict(cache["_coordinate_units"])


def _coordinate_units(problem: Problem) -> dict[str, tuple[str, str, str]]:
    known = dimensions_of(problem)
    angular = angles(problem)
    units = {}
    for j in problem.jets:
        if j.name in angular:
            units[j.name] = ("rad", "rad/s", "rad/s²")
        elif j.q in known and known[j.q] != NONE:
            units[j.name] = tuple(unit_text_of(known[s]) for s in (j.q, j.dot, j.ddot))
        else:
            units[j.name] = ("", "", "")
    return units


def _explicit_time(problem: Problem) -> bool:
    """Whether t is a variable of the reference (a driven system), so worth naming."""
    reference = problem.lagrangian if problem.lagrangian is not None else problem.expression
    return reference is not None and any(s.name == "t" for s in reference.free_symbols)


def _units(problem: Problem) -> dict[str, str]:
    if problem.variant is None:
        return {}
    return {p.name: unit_text(p.unit) for p in problem.variant.scene.parameters if p.unit}
