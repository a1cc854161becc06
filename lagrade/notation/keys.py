"""A variant's answer key as a student would type it, one answer per part: what the handout's key
prints under "as a student would type them", what `generate` checks the grader accepts before it
writes a handout, and what the demo's model students send. It lives in notation, under both judge
and assign, so that the key printed and the key checked are the same text."""

from __future__ import annotations

import sympy as sp

from lagrade.mechanics.scene import SceneVariant
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
    if part == "expression":
        if quantity is None or quantity not in variant.quantities:
            raise KeyError(f"scene {variant.scene.id!r} has no quantity {quantity!r}")
        return plain(variant.quantities[quantity])
    raise KeyError(f"no key for part {part!r}")
