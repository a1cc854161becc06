"""The bodies a scene is made of, and their kinetic energy: point masses, rigid bodies turning in
the x-y plane, and rigid bodies turning freely in space (Euler angles). Each declares its
position, mass and, for a rigid body, its inertia and orientation as expressions in the
coordinates and t; `kinetic_energy(jets)` is T = ½ m |ṙ|² plus the body's rotation."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.simplify.fu import TR10i

import lagrade.mechanics.lagrange as mech

AXES = ("x", "y", "z")


def as_expr(value: object) -> sp.Expr:
    """A scene declaration's value as a sympy expression, without evaluating text.

    A scene file's expressions arrive already read by the notation layer (`lagrade.bank`), so
    what comes here is a sympy object or a plain number (the 0 of a fixed axle); a string is
    refused rather than parsed, so nothing here can turn text into code.
    """
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise TypeError(f"a scene declares sympy expressions or numbers, not {value!r}")
    return sp.Integer(value) if isinstance(value, int) else sp.Float(value)


@dataclass(frozen=True)
class PointMass:
    """A point mass at `position` (2 components: motion in the x–y plane, so z = 0 is a
    constraint; or 3 components), each a function of the coordinates and t. y (or z for 3-D
    positions) points up."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, ...]

    freedoms = 3

    @property
    def planar(self) -> bool:
        return len(self.position) == 2

    def kinetic_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """T = ½ m |ṙ|²."""
        return sp.Rational(1, 2) * self.mass * mech.speed_squared(self.position, jets)


@dataclass(frozen=True)
class RigidBody:
    """A rigid body moving in the x–y plane: its centre of mass at `position`, turned by `angle`
    about the z axis, with moment of inertia `inertia` about its centre of mass. In space it has
    6 freedoms; staying in the plane costs 3 (z = 0 and the two tilts)."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, sp.Expr]
    inertia: sp.Expr
    angle: sp.Expr

    freedoms = 6
    planar = True

    def kinetic_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """T = ½ m |ṙ_cm|² + ½ I φ̇² (König's theorem for plane motion)."""
        translation = sp.Rational(1, 2) * self.mass * mech.speed_squared(self.position, jets)
        return translation + self.rotational_energy(jets)

    def rotational_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """½ I φ̇²: the term a wrong moment of inertia changes."""
        omega = mech.total_derivative(self.angle, jets)
        return sp.Rational(1, 2) * self.inertia * omega**2


@dataclass(frozen=True)
class SpatialRigidBody:
    """A rigid body turning freely in space: its centre of mass at `position` (x, y, z; z up),
    its orientation given by Z-X-Z Euler `angles` (φ about z, then the tilt θ about the new x,
    then the spin ψ about the body's symmetry axis 3), and its principal moments of inertia
    `inertia` = (I₁, I₂, I₃) about its centre of mass. It has 6 freedoms and no implied
    constraint."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, sp.Expr, sp.Expr]
    inertia: tuple[sp.Expr, sp.Expr, sp.Expr]
    angles: tuple[sp.Expr, sp.Expr, sp.Expr]

    freedoms = 6
    planar = False
    #: How the transformation part names its angles: `phi_top`, `theta_top`, `psi_top`.
    ANGLES = ("phi", "theta", "psi")

    def angular_velocity(self, jets: Sequence[mech.Jet]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """ω in the body's principal axes, from the Z-X-Z Euler angles (Goldstein §4.9):
        ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ, ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ, ω₃ = φ̇ cos θ + ψ̇."""
        phi, theta, psi = self.angles
        d_phi, d_theta, d_psi = (mech.total_derivative(a, jets) for a in self.angles)
        return (
            d_phi * sp.sin(theta) * sp.sin(psi) + d_theta * sp.cos(psi),
            d_phi * sp.sin(theta) * sp.cos(psi) - d_theta * sp.sin(psi),
            d_phi * sp.cos(theta) + d_psi,
        )

    def kinetic_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """T = ½ m |ṙ_cm|² + ½ (I₁ ω₁² + I₂ ω₂² + I₃ ω₃²) (König's theorem, Euler's axes)."""
        omega = self.angular_velocity(jets)
        rotation = sum((i * w**2 for i, w in zip(self.inertia, omega, strict=True)), sp.S.Zero)
        translation = self.mass * mech.speed_squared(self.position, jets)
        return sp.Rational(1, 2) * (translation + rotation)


Body = PointMass | RigidBody | SpatialRigidBody


def gravity(g: sp.Expr, bodies: Sequence[Body], axis: str = "y") -> sp.Expr:
    """V = Σ m g h for uniform gravity along −axis (h is the `axis` component of each position)."""
    index = AXES.index(axis)
    return sum((b.mass * g * b.position[index] for b in bodies), sp.S.Zero)


def body_fields(body: Body) -> list[tuple[str, tuple]]:
    """A body's declared expressions by field: position, mass, and a rigid body's inertia and
    angle."""
    fields = [("position", tuple(body.position)), ("mass", (body.mass,))]
    if isinstance(body, RigidBody):
        fields += [("inertia", (body.inertia,)), ("angle", (body.angle,))]
    if isinstance(body, SpatialRigidBody):
        fields += [("inertia", tuple(body.inertia)), ("angles", tuple(body.angles))]
    return fields


def _normalized(body: Body) -> Body:
    """A declared body with every field a sympy expression (positions, mass, inertia, angle)."""
    fields = {**body.__dict__, "position": tuple(as_expr(x) for x in body.position)}
    fields["mass"] = as_expr(body.mass)
    if isinstance(body, RigidBody):
        fields["inertia"], fields["angle"] = as_expr(body.inertia), as_expr(body.angle)
    if isinstance(body, SpatialRigidBody):
        fields["inertia"] = tuple(as_expr(x) for x in body.inertia)
        fields["angles"] = tuple(as_expr(x) for x in body.angles)
    return type(body)(**fields)


def collapse_trig(expr: sp.Expr) -> sp.Expr:
    """T as the lecture writes it: sin² + cos² collapsed, cos a cos b + sin a sin b → cos(a − b).

    A targeted rewrite (Pythagoras both ways, keep the shorter; then fu's TR10i) instead of
    `trigsimp`, which is ~20× slower and dominated the derivation time of every scene.
    """
    expanded = sp.expand(expr)
    angles = {f.args[0] for f in expanded.atoms(sp.sin, sp.cos)}
    if not angles:
        return expanded
    via_sin = sp.expand(expanded.xreplace({sp.cos(u) ** 2: 1 - sp.sin(u) ** 2 for u in angles}))
    via_cos = sp.expand(expanded.xreplace({sp.sin(u) ** 2: 1 - sp.cos(u) ** 2 for u in angles}))
    shortest = min((expanded, via_sin, via_cos), key=sp.count_ops)
    combined = sp.expand(TR10i(shortest))
    return combined if sp.count_ops(combined) <= sp.count_ops(shortest) else shortest
