"""A scene in other generalized coordinates: the same bodies, masses, T and V, with the bodies'
positions given by other (valid) transformation equations — a student's own choice of
coordinates.

T and V are functions of the bodies' Cartesian positions (scene files declare them so: V in
`x_bob`, `y_bob`, … or `gravity`), so L in other coordinates is T and V evaluated on the other
transformation, with no inverse map:

    T' = Σ ½ m |D_t r'(q')|² (+ ½ I (D_t φ'(q'))²),   V'(q') = V(r'(q'))

Only where the scene writes its potential in its own generalized coordinates (a spring
`k (r - l_0)^2/2` in the length r, a charge's e v·A with A in x) must those coordinates be
carried over: each by an expression of the student's coordinates (`pullback`, q ↦ g(q'), and
q̇ ↦ D_t g). `coordinates_through_positions` offers such expressions when the scene's own
transformation can be inverted in closed form for them (a coordinate that a position component
holds linearly, or a distance between two bodies or from the origin); the judge verifies them.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from functools import cached_property

import sympy as sp

import lagrade.mechanics.lagrange as mech
from lagrade.mechanics.bodies import (
    AXES,
    Body,
    PointMass,
    RigidBody,
    SpatialRigidBody,
    as_expr,
    collapse_trig,
)
from lagrade.mechanics.scene import SceneVariant


def cartesian_symbols(variant: SceneVariant) -> dict[str, sp.Symbol]:
    """Every body's Cartesian coordinates (and a rigid body's angle) as symbols, keyed as the
    transformation part names them: `x_bob`, `y_bob`, `phi_wheel` (the 2-D bodies' z is 0)."""
    return {name: sp.Symbol(name, real=True) for name in variant.transformation}


def cartesian_bodies(variant: SceneVariant) -> tuple[Body, ...]:
    """The variant's bodies with their positions (and angles) left as the Cartesian symbols."""
    symbols = cartesian_symbols(variant)
    made: list[Body] = []
    for b in variant.bodies:
        position = tuple(symbols[f"{axis}_{b.name}"] for axis in AXES[: len(b.position)])
        if isinstance(b, RigidBody):
            made.append(RigidBody(b.name, b.mass, position, b.inertia, symbols[f"phi_{b.name}"]))  # type: ignore[arg-type]
        elif isinstance(b, SpatialRigidBody):
            angles = tuple(symbols[f"{a}_{b.name}"] for a in b.ANGLES)
            made.append(SpatialRigidBody(b.name, b.mass, position, b.inertia, angles))  # type: ignore[arg-type]
        else:
            made.append(PointMass(b.name, b.mass, position))
    return tuple(made)


def cartesian_potential(variant: SceneVariant) -> sp.Expr:
    """V as the scene declares it, in the bodies' Cartesian symbols: `gravity` becomes
    Σ m g y_b (z_b in space); what the scene wrote in its generalized coordinates stays in them."""
    return sp.expand(as_expr(variant.scene.potential(variant.namespace, cartesian_bodies(variant))))


def coordinates_to_carry(variant: SceneVariant) -> tuple[mech.Jet, ...]:
    """The coordinates that V, a mass or an inertia names itself (besides the positions): each
    must be carried over to other coordinates by a pullback."""
    exprs = [cartesian_potential(variant)]
    for b in variant.bodies:
        exprs.append(b.mass)
        if isinstance(b, RigidBody):
            exprs.append(b.inertia)
        if isinstance(b, SpatialRigidBody):
            exprs += list(b.inertia)
    return tuple(j for j in variant.jets if any(e.has(j.q) or e.has(j.dot) for e in exprs))


def coordinates_through_positions(
    variant: SceneVariant, wanted: Collection[sp.Symbol] | None = None
) -> dict[sp.Symbol, sp.Expr]:
    """Closed forms of the scene's coordinates (those `wanted`, default all) in the Cartesian
    symbols (and the parameters and t), where its transformation can be inverted simply: a
    position component that is linear in the coordinate, with the rest known
    (x_block = x_M + q cos α gives q = (x_block − x_wedge)/cos α once x_M = x_wedge), or a
    distance (the spring's length r from √(x² + y²), two bodies' separation). Candidates only:
    a caller checks each at sample points (a square root holds for r > 0 alone)."""
    transformation = variant.transformation
    symbols = cartesian_symbols(variant)
    coordinates = [j.q for j in variant.jets]
    wanted = set(coordinates if wanted is None else wanted)
    found: dict[sp.Symbol, sp.Expr] = {}
    for _round in range(len(coordinates)):  # each round may use what the last one found
        progress = False
        for q in coordinates:
            if q not in found:
                candidate = _linear_inverse(q, transformation, symbols, found, coordinates)
                if candidate is not None:
                    found[q] = candidate
                    progress = True
        if not progress:
            break
    missing = [q for q in coordinates if q in wanted and q not in found]
    if missing:
        found |= _distance_inverses(missing, variant, symbols)
    return {q: e for q, e in found.items() if q in wanted}


def _linear_inverse(
    q: sp.Symbol,
    transformation: Mapping[str, sp.Expr],
    symbols: Mapping[str, sp.Symbol],
    known: Mapping[sp.Symbol, sp.Expr],
    coordinates: list[sp.Symbol],
) -> sp.Expr | None:
    """q from a component a q + b with a and b free of unknown coordinates (a ≠ 0)."""
    for name, e in transformation.items():
        if not e.has(q):
            continue
        a = sp.diff(e, q)
        if a.has(*coordinates) or a == 0:
            continue
        b = sp.expand(e - a * q)
        if any(b.has(c) for c in coordinates if c not in known):
            continue
        return sp.cancel((symbols[name] - b.xreplace(dict(known))) / a)
    return None


def _distance_inverses(
    missing: list[sp.Symbol], variant: SceneVariant, symbols: Mapping[str, sp.Symbol]
) -> dict[sp.Symbol, sp.Expr]:
    """Each of `missing` from a squared distance k q² (a body from the origin, or two bodies
    apart), k free of the coordinates and t."""
    coordinates = [j.q for j in variant.jets]
    bodies = variant.bodies
    pairs: list[tuple[Body, Body | None]] = [(b, None) for b in bodies]
    pairs += [(a, b) for i, a in enumerate(bodies) for b in bodies[i + 1 :]]
    found: dict[sp.Symbol, sp.Expr] = {}
    for first, second in pairs:
        n = len(first.position)
        if second is not None and len(second.position) != n:
            continue
        squared, through = sp.S.Zero, sp.S.Zero
        for k, axis in enumerate(AXES[:n]):
            there = second.position[k] if second is not None else sp.S.Zero
            squared += (first.position[k] - there) ** 2
            mine = symbols[f"{axis}_{first.name}"]
            other = symbols[f"{axis}_{second.name}"] if second is not None else sp.S.Zero
            through += (mine - other) ** 2
        held = [q for q in missing if q not in found and squared.has(q)]
        if not held:
            continue
        tidied = collapse_trig(squared)
        for q in held:
            k2 = sp.cancel(tidied / q**2)
            if k2 != 0 and not k2.has(*coordinates, mech.t):
                found[q] = sp.sqrt(through) / sp.sqrt(k2)
    return found


class Reparametrized(SceneVariant):
    """A variant's system in other coordinates of the same names: its bodies at `positions`
    (keyed like its transformation, `x_bob` …, each an expression in the coordinates and t),
    its potential carried over by `pullback` (the variant's coordinates in the new ones, for the
    coordinates the potential names itself). Everything else — T, L, the Euler–Lagrange
    equations, momenta, cyclic coordinates, conserved quantities — is derived from those as for
    any variant."""

    def __init__(
        self,
        base: SceneVariant,
        positions: Mapping[str, sp.Expr],
        pullback: Mapping[sp.Symbol, sp.Expr] | None = None,
    ):
        super().__init__(base.scene, base.seed, base.names, base.options, base.values)
        self.base = base
        self.positions = dict(positions)
        carried = dict(pullback or {})
        for j in base.jets:  # q̇ ↦ D_t g(q', t) for each carried q ↦ g
            if j.q in carried:
                carried[j.dot] = mech.total_derivative(carried[j.q], base.jets)
        self.pullback = carried

    def __repr__(self) -> str:
        return f"Reparametrized({self.scene.id!r}, seed={self.seed})"

    def _carry(self, expr: sp.Expr) -> sp.Expr:
        return expr.xreplace(self.pullback) if self.pullback else expr

    @cached_property
    def bodies(self) -> tuple[Body, ...]:
        made: list[Body] = []
        for b in self.base.bodies:
            position = tuple(self.positions[f"{axis}_{b.name}"] for axis in AXES[: len(b.position)])
            if isinstance(b, RigidBody):
                made.append(
                    RigidBody(
                        b.name,
                        self._carry(b.mass),
                        position,  # type: ignore[arg-type]
                        self._carry(b.inertia),
                        self.positions[f"phi_{b.name}"],
                    )
                )
            elif isinstance(b, SpatialRigidBody):
                made.append(
                    SpatialRigidBody(
                        b.name,
                        self._carry(b.mass),
                        position,  # type: ignore[arg-type]
                        tuple(self._carry(i) for i in b.inertia),  # type: ignore[arg-type]
                        tuple(self.positions[f"{a}_{b.name}"] for a in b.ANGLES),  # type: ignore[arg-type]
                    )
                )
            else:
                made.append(PointMass(b.name, self._carry(b.mass), position))
        return tuple(made)

    @cached_property
    def _declared_potential(self) -> sp.Expr:
        """V(r'(q')): the Cartesian potential on these positions, and each coordinate the scene's
        potential names itself carried over (simultaneously: the names are shared). What the
        variant's `potential_energy` and L are made from, as the declared V is for a variant."""
        symbols = cartesian_symbols(self.base)
        put = {symbols[name]: self.positions[name] for name in symbols}
        return sp.expand(cartesian_potential(self.base).xreplace({**self.pullback, **put}))
