"""A variant's answer key as a student would type it, one answer per part: what the handout's key
prints under "as a student would type them", what `generate` checks the grader accepts before it
writes a handout, and what the demo's model students send. It lives in notation, under both judge
and assign, so that the key printed and the key checked are the same text."""

from __future__ import annotations

import sympy as sp

from lagrade.mechanics import SceneVariant, phase_space, variant_oscillations
from lagrade.notation.printer import plain


def key_answer(variant: SceneVariant, part: str, quantity: str | None = None) -> str | list[str]:
    """The reference answer to `part` in student notation (lists for multi-item parts)."""
    system = variant.system
    if part == "dof":
        return str(variant.dof)
    if part == "coordinates":
        return ", ".join(variant.coordinates)
    if part == "transformation":
        return [f"{name} = {plain(value)}" for name, value in variant.transformation.items()]
    if part == "T":
        return plain(variant.kinetic_energy)
    if part == "V":
        return plain(variant.potential_energy)
    if part == "lagrangian":
        return plain(variant.lagrangian)
    if part == "eom":
        return [plain(sp.Eq(e, 0, evaluate=False)) for e in system.euler_lagrange]
    if part == "momenta":
        return [
            f"p_{q} = {plain(p)}"
            for q, p in zip(variant.coordinates, system.generalized_momenta, strict=True)
        ]
    if part == "cyclic":
        return ", ".join(system.cyclic_coordinates) or "none"
    if part == "conserved":
        return [plain(q) for q in system.conserved_quantities.values()] or ["none"]
    if part == "hamiltonian":
        return plain(phase_space(system).hamiltonian)
    if part == "hamilton_equations":
        return [plain(e) for e in phase_space(system).hamilton_equations]
    if part in ("equilibrium", "normal_modes", "mode_shapes"):
        return _oscillation_key(variant, part)
    if part == "expression":
        if quantity is None or quantity not in variant.quantities:
            raise KeyError(f"scene {variant.scene.id!r} has no quantity {quantity!r}")
        return plain(variant.quantities[quantity])
    raise KeyError(f"no key for part {part!r}")


def mode_shape_lines(osc) -> list[str]:
    """`omega = ω: (a_1, …)` for each oscillating mode about the stable equilibrium: closed
    forms where sympy gives them, else scipy's `eigh` at the handout's values (each vector
    scaled so that its largest entry is 1)."""
    if osc.mode_shapes is not None:
        return [
            f"omega = {plain(w)}: ({', '.join(plain(x) for x in a)})" for w, a in osc.mode_shapes
        ]
    return [
        f"omega = {w:.12g}: ({', '.join(f'{x:.12g}' for x in a)})"
        for w, a in osc.numeric_mode_shapes()
    ]


def _oscillation_key(variant: SceneVariant, part: str) -> str:
    """The stable equilibrium (its fixed coordinates) or the nonzero normal-mode frequencies:
    closed forms where sympy gives them, else the numbers at the handout's values."""
    osc = variant_oscillations(variant)
    if osc.why_not is not None:
        raise KeyError(f"no key for part {part!r}: {osc.why_not}")
    if part == "equilibrium":
        return ", ".join(f"{q.name} = {plain(v)}" for q, v in osc.stable.at.items())
    if part == "mode_shapes":
        return mode_shape_lines(osc) or ["none"]
    closed = osc.frequencies
    if closed is not None:
        shown = [plain(w) for w in closed if w != 0]
    else:
        numbers = osc.numeric_frequencies()
        top = max(float(numbers.max()), 1e-300)
        shown = [f"{w:.12g}" for w in numbers if w > 1e-9 * top]
    return ", ".join(shown) or "none"  # only zero modes: nothing oscillates
