"""A scene variant checked against itself (`SceneVariant.validate`): every problem of its
declaration found and raised at once, in one SceneError that names each field — symbols without
a declared parameter, coordinates that appear nowhere, constraints the transformation equations
do not satisfy, a DOF count that differs from the coordinates', a transformation without full
rank, and for a scene given by its Lagrangian what that L may not hold."""

from __future__ import annotations

import random
from typing import Any

import numpy as np
import sympy as sp

import lagrade.mechanics.lagrange as mech
from lagrade.errors import SceneError
from lagrade.mechanics.bodies import body_fields
from lagrade.mechanics.domains import branched

#: A `lagrade.mechanics.scene.SceneVariant` (which calls in here: not imported, to keep the
#: import graph one way).
Variant = Any


def validate_variant(variant: Variant) -> None:
    """Check the declaration against itself and raise one SceneError listing every problem:
    symbols without a declared parameter, coordinates that appear nowhere, constraints that
    the transformation equations do not satisfy identically, a DOF count that differs from
    the number of coordinates, and a transformation without full rank."""
    problems: list[str] = []
    known = set(variant.parameter_symbols.values()) | {mech.t}
    for j in variant.jets:
        known |= {j.q, j.dot}
    if variant.scene.given_by_lagrangian:
        _validate_lagrangian(variant, known)
        return
    used: set[sp.Symbol] = set()
    for b in variant.bodies:
        for label, expr in body_fields(b):
            for x in expr:
                free = x.free_symbols
                used |= free
                for s in sorted(free - known, key=str):
                    problems.append(
                        f"bodies: {b.name}.{label} uses {s}, which is not a declared parameter"
                    )
    V = variant._declared_potential
    used |= V.free_symbols
    for s in sorted(V.free_symbols - known, key=str):
        problems.append(f"potential: uses {s}, which is not a declared parameter")
    for j in variant.jets:
        if j.q not in used and j.dot not in used:
            problems.append(
                f"coordinates: {j.name!r} appears in no position and not in the potential"
            )
    subs = variant._cartesian_substitution()
    for i, (label, f) in enumerate(variant.constraints):
        if label != "declared":
            continue
        residual = variant.within_domains(
            f.xreplace(subs), lambda e: sp.simplify(sp.expand_trig(e))
        )
        if residual != 0 and not variant.vanishes_in_domains(residual):
            hint = (
                ""
                if variant.coordinate_domains or not branched(residual)
                else (
                    " (if it holds where the coordinates live, declare their domains: "
                    'domains = { r = "positive" })'
                )
            )
            problems.append(
                f"constraints: constraint {i + 1} ({f} = 0) is not satisfied by the "
                f"transformation equations; it leaves {residual}{hint}"
            )
    if variant.dof != len(variant.jets):
        problems.append(
            f"constraints: 3N - k gives {variant.dof} degrees of freedom but the scene declares "
            f"{len(variant.jets)} coordinates {list(variant.coordinates)}"
        )
    rank = _jacobian_rank(variant)
    if rank < len(variant.jets):
        problems.append(
            f"bodies: the transformation has rank {rank} < {len(variant.jets)}; some coordinate "
            "does not move any body independently"
        )
    if problems:
        raise SceneError(variant.scene.id, problems)


def _validate_lagrangian(variant: Variant, known: set[sp.Symbol]) -> None:
    """A given L: declared symbols only, no acceleration, every coordinate in it."""
    problems = []
    L = variant.lagrangian
    for s in sorted(L.free_symbols - known, key=str):
        problems.append(f"lagrangian: uses {s}, which is not declared")
    for j in variant.jets:
        if L.has(j.ddot):
            problems.append(f"lagrangian: contains the acceleration {j.ddot}")
        if not L.has(j.q) and not L.has(j.dot):
            problems.append(f"coordinates: {j.name!r} appears nowhere in the Lagrangian")
    if problems:
        raise SceneError(variant.scene.id, problems)


def _jacobian_rank(variant: Variant) -> int:
    """Rank of ∂(positions, angles)/∂q at a seeded generic point (numerically)."""
    rows = list(variant.transformation.values())
    J = sp.Matrix([[sp.diff(r, j.q) for j in variant.jets] for r in rows])
    rng = random.Random(0)
    point = {
        s: rng.uniform(*variant.domains[str(s)].sample_range())
        for s in variant.parameter_symbols.values()
    }
    point |= {
        j.q: rng.uniform(*variant.coordinate_domains[j.name].sample_range())
        if j.name in variant.coordinate_domains
        else rng.uniform(0.2, 1.2)
        for j in variant.jets
    } | {mech.t: 0.7}
    numeric = J.xreplace(point).evalf()
    return int(np.linalg.matrix_rank(np.array(numeric.tolist(), dtype=float), tol=1e-9))
