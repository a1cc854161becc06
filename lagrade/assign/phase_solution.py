"""The key's solution of the next lecture's parts (`hamiltonian`, `hamilton_equations`,
`equilibrium`, `normal_modes`, `mode_shapes`) for one student's variant: H, Hamilton's equations,
the stable equilibrium, the normal-mode frequencies and their mode vectors set as math in every
format, or the reason there are none, and the answers as a student types them
(`lagrade.notation.keys`, the text the grader checks). Derived only for a problem that asks one of
them: most handouts never pay for it. The equilibrium that is stable can depend on the values (a
hoop turning fast or slowly), so this is computed per variant, not per presentation."""

from __future__ import annotations

import itertools
from functools import lru_cache
from typing import Any

import sympy as sp

from lagrade.mechanics import (
    NotQuadratic,
    Scene,
    SceneVariant,
    momentum_name,
    phase_space,
    variant_oscillations,
)
from lagrade.notation import key_answer
from lagrade.notation import printer as rm

#: The parts on phase space and about small oscillations, in the order a handout asks them.
PHASE_PARTS = ("hamiltonian", "hamilton_equations", "equilibrium", "normal_modes", "mode_shapes")
#: Their prompts on the handout.
PHASE_PROMPTS = {
    "hamiltonian": "Write the Hamiltonian H in the coordinates and the momenta p_q "
    "(e.g. p_theta), with no velocities.",
    "hamilton_equations": "Write Hamilton's equations, one per line: the rate of each coordinate "
    "and of each momentum (e.g. theta_dot = ..., p_theta_dot = ...).",
    "equilibrium": "Give a stable equilibrium at rest: the value of each coordinate, as "
    "coordinate = value (a coordinate that may take any value can be left out).",
    "normal_modes": "Give the angular frequencies of small oscillations about it, separated by "
    "commas, in any order (a zero frequency may be left out).",
    "mode_shapes": "For each normal-mode frequency give its mode vector, one mode per line, as "
    "omega = frequency: (amplitudes of the coordinates in their order), e.g. "
    "omega = sqrt(k/m): (1, -1); any scale, any order of modes.",
}


def can_ask(variant: SceneVariant, part: str) -> str | None:
    """Why `part` cannot be asked of this variant (no stable equilibrium, H without a closed
    form), or None."""
    try:
        phase_space(variant.system).velocity_matrix  # noqa: B018 - raises NotQuadratic
    except NotQuadratic as error:
        return str(error)
    if part in ("equilibrium", "normal_modes", "mode_shapes"):
        return variant_oscillations(variant).why_not
    return None


def can_ask_scene(scene: Scene, part: str) -> str | None:
    """Why `part` cannot be asked of some presentation of `scene` (each combination of its
    options: a particle in a trap has an equilibrium, the same particle under gravity none),
    naming the options; None when every presentation can be asked it."""
    names = sorted(scene.options)
    for choice in itertools.product(*(scene.options[n] for n in names)):
        options = dict(zip(names, choice, strict=True))
        why = can_ask(SceneVariant(scene, options=options), part)
        if why is not None:
            shown = ", ".join(f"{k} = {v}" for k, v in options.items())
            return why + (f" (with {shown})" if shown else "")
    return None


def phase_solution(scene: Scene, names: tuple, options: tuple, values: tuple) -> dict[str, Any]:
    """The solution of the four parts for one variant (names, options, values as sorted
    tuples): entries `hamiltonian`, `hamilton_equations`, `equilibrium`, `normal_modes` and
    `key_answers` for the parts it can ask."""
    return _phase_solution(scene, names, options, values)


@lru_cache(maxsize=256)
def _phase_solution(scene: Scene, names: tuple, options: tuple, values: tuple) -> dict[str, Any]:
    v = SceneVariant(scene, names=dict(names), options=dict(options), values=dict(values))
    coords = tuple(v.coordinates)
    phase_names = coords + tuple(momentum_name(c) for c in coords)
    out: dict[str, Any] = {"key_answers": {}}
    why = can_ask(v, "hamiltonian")
    if why is not None:
        return out | {"phase_why_not": why}
    hs = phase_space(v.system)
    out["hamiltonian"] = rm.equation(sp.Symbol("H"), hs.hamiltonian, phase_names)
    out["hamilton_equations"] = [
        rm.equation(e.lhs, e.rhs, phase_names) for e in hs.hamilton_equations
    ]
    out["key_answers"] |= {p: key_answer(v, p) for p in ("hamiltonian", "hamilton_equations")}
    osc = variant_oscillations(v)
    if osc.why_not is not None:
        return out | {"oscillation_why_not": osc.why_not}
    eq = osc.stable
    out["equilibrium"] = [rm.equation(q, value, coords) for q, value in eq.at.items()]
    out["free"] = [rm.render(sp.Symbol(name), coords) for name in eq.free]
    if osc.frequencies is not None:
        out["normal_modes"] = [rm.render(w, coords) for w in osc.frequencies]
    else:
        out["normal_modes"] = [rm.render(sp.Float(w, 6), coords) for w in osc.numeric_frequencies()]
    out["mode_shapes"] = [
        {"frequency": rm.render(w, coords), "vector": rm.render(_vector(a), coords)}
        for w, a in _mode_shapes(osc)
    ]
    out["key_answers"] |= {
        p: key_answer(v, p) for p in ("equilibrium", "normal_modes", "mode_shapes")
    }
    return out


def _mode_shapes(osc) -> list[tuple[sp.Expr, tuple[sp.Expr, ...]]]:
    """(ω, a) of each oscillating mode: closed forms where sympy gives them, else scipy's
    `eigh` at the handout's values to six figures (the largest entry 1)."""
    if osc.mode_shapes is not None:
        return list(osc.mode_shapes)
    return [
        (sp.Float(w, 6), tuple(sp.Float(x, 6) for x in a)) for w, a in osc.numeric_mode_shapes()
    ]


def phase_data(variant: SceneVariant) -> dict[str, Any]:
    """H, Hamilton's equations, every equilibrium at rest found (with whether it is stable at
    the deciding values), the normal-mode frequencies about the stable one and each oscillating
    mode's shape, as text for
    `lagrade bank show` and `lagrade scene check`; each missing piece says why."""
    text = rm.plain
    why = can_ask(variant, "hamiltonian")
    if why is not None:
        return {"hamiltonian": None, "why_not": why}
    hs = phase_space(variant.system)
    osc = variant_oscillations(variant)
    data: dict[str, Any] = {
        "hamiltonian": text(hs.hamiltonian),
        "hamilton_equations": [text(e) for e in hs.hamilton_equations],
        "equilibria": [
            {
                "at": {q.name: text(v) for q, v in eq.at.items()},
                "free": list(eq.free),
                "stable": osc.is_stable(eq),
            }
            for eq in osc.equilibria
        ],
    }
    if osc.why_not is not None:
        return data | {"normal_modes": None, "why_not": osc.why_not}
    closed = osc.frequencies
    data["normal_modes"] = (
        [text(w) for w in closed]
        if closed is not None
        else [f"{w:.6g}" for w in osc.numeric_frequencies()]
    )
    data["mode_shapes"] = [
        {"frequency": text(w), "vector": text(_vector(a))} for w, a in _mode_shapes(osc)
    ]
    zero = [w for w in osc.numeric_frequencies() if w == 0]
    if zero:
        data["zero_modes"] = (
            f"{len(zero)} zero mode{'s' * (len(zero) != 1)}: "
            f"{', '.join(osc.stable.free)} may take any value (a free direction)"
        )
    return data


def phase_lines(variant: SceneVariant) -> list[str]:
    """`phase_data` as lines of a terminal summary."""
    d = phase_data(variant)
    if d["hamiltonian"] is None:
        return [f"H: none ({d['why_not']})"]
    lines = [f"H = {d['hamiltonian']}", "Hamilton's equations:"]
    lines += [f"  {e}" for e in d["hamilton_equations"]]
    for eq in d["equilibria"]:
        at = ", ".join(f"{k} = {v}" for k, v in eq["at"].items()) or "anywhere"
        free = f" ({', '.join(eq['free'])} free)" if eq["free"] else ""
        lines.append(f"equilibrium: {at}{free}, {'stable' if eq['stable'] else 'unstable'}")
    if d["normal_modes"] is None:
        lines.append(f"normal modes: none ({d['why_not']})")
    else:
        lines.append("normal-mode angular frequencies: " + ", ".join(d["normal_modes"]))
        if "zero_modes" in d:
            lines.append(f"  {d['zero_modes']}")
        if d["mode_shapes"]:
            coordinates = ", ".join(j.name for j in variant.jets)
            lines.append(f"mode shapes (amplitudes of {coordinates}):")
            lines += [f"  omega = {m['frequency']}: {m['vector']}" for m in d["mode_shapes"]]
        else:
            lines.append("mode shapes: none (no mode oscillates)")
    return lines


__all__ = [
    "PHASE_PARTS",
    "PHASE_PROMPTS",
    "can_ask",
    "can_ask_scene",
    "phase_data",
    "phase_lines",
    "phase_solution",
]


def _vector(amplitudes) -> sp.Expr:
    """A mode's amplitudes as shown: (1, −1); one amplitude alone is (1), not a tuple's (1,)."""
    if len(amplitudes) == 1:
        return sp.Tuple(*amplitudes)[0]
    return sp.Tuple(*amplitudes)
