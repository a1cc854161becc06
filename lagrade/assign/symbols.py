"""The names an answer to each part may use, as the handout lists them: the grader reads only
the question's coordinates (with `_dot` and `_ddot`), its parameters, t, and per part the
left-hand names it expects (`x_bob` for a transformation equation, `p_theta` for a momentum).
Built from the same variant the grader builds its question from, so the list and the grader
agree."""

from __future__ import annotations

from typing import Any

from lagrade.mechanics import SceneVariant, momentum_name
from lagrade.mechanics import lagrange as mech

#: Parts whose answers are formulas in the coordinates: which time derivatives they may contain.
_ORDERS = {
    "transformation": 0,
    "T": 1,
    "V": 1,
    "lagrangian": 1,
    "momenta": 1,
    "conserved": 1,
    "eom": 2,
}


def _time_dependent(variant: SceneVariant) -> bool:
    if variant.scene.given_by_lagrangian:
        return variant.lagrangian.has(mech.t)
    exprs = [x for b in variant.bodies for x in b.position] + [variant.potential_energy]
    return any(getattr(x, "has", lambda _: False)(mech.t) for x in exprs)


def part_symbols(variant: SceneVariant, part: str) -> list[dict[str, Any]]:
    """For one part, groups of names: each {"what": …, "names": […]} as the handout prints it
    ("left-hand sides: x_bob, y_bob"; "may use: theta, theta_dot, l, m, g")."""
    coordinates = list(variant.coordinates)
    parameters = list(variant.used_parameters)
    if part in ("coordinates", "cyclic"):
        return [{"what": "coordinate names", "names": coordinates}]
    if part == "dof":
        return []
    if part == "expression":
        return [{"what": "may use", "names": parameters}]
    if part in ("hamiltonian", "hamilton_equations"):
        return _phase_symbols(variant, part, coordinates, parameters)
    if part == "equilibrium":
        return [
            {"what": "left-hand sides", "names": coordinates},
            {"what": "may use", "names": parameters},
        ]
    if part == "mode_shapes":  # `omega = …: (1, -1)`, one mode a line
        return [
            {"what": "left-hand sides", "names": ["omega"]},
            {"what": "may use", "names": parameters},
        ]
    if part == "normal_modes":
        return [{"what": "may use", "names": parameters}]
    groups = []
    if part == "transformation":
        groups.append({"what": "left-hand sides", "names": list(variant.transformation)})
    if part == "momenta":
        groups.append({"what": "left-hand sides", "names": [f"p_{c}" for c in coordinates]})
    order = _ORDERS.get(part, 1)
    names = list(coordinates)
    if order >= 1:
        names += [c + mech.DOT for c in coordinates]
    if order >= 2:
        names += [c + mech.DDOT for c in coordinates]
    names += parameters
    if _time_dependent(variant):
        names.append("t")
    groups.append({"what": "may use", "names": names})
    return groups


def _phase_symbols(
    variant: SceneVariant, part: str, coordinates: list[str], parameters: list[str]
) -> list[dict[str, Any]]:
    """H and Hamilton's equations are written in the coordinates and the momenta p_q; the
    equations' left-hand sides are the rates q_dot and p_q_dot."""
    momenta = [momentum_name(c) for c in coordinates]
    groups = []
    if part == "hamilton_equations":
        rates = [c + mech.DOT for c in coordinates] + [p + mech.DOT for p in momenta]
        groups.append({"what": "left-hand sides", "names": rates})
    names = coordinates + momenta + parameters
    if variant.lagrangian.has(mech.t):
        names.append("t")
    groups.append({"what": "may use", "names": names})
    return groups
