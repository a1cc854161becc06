"""The numeric geometry of one scene variant: projected body positions as fast functions of the
coordinates and t at a representative pose, and the questions a figure asks of them (is this
path a circle, which length parameter is this distance, about which axis does a body turn)."""

from __future__ import annotations

import math
import random
from collections.abc import Mapping, Sequence
from functools import cached_property
from types import SimpleNamespace
from typing import Any

import numpy as np
import sympy as sp

from lagrade.mechanics import FigureHint, RigidBody, SceneVariant, as_expr
from lagrade.mechanics import lagrange as mech
from lagrade.notation import name_latex

_ANGLE_POSES = (0.6, 1.0, 0.35, 0.8)
_LENGTH_POSES = (0.5, 0.8, 0.35, 0.65)
_OBLIQUE = (0.5 * math.cos(math.radians(35)), 0.5 * math.sin(math.radians(35)))
TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def representative_values(variant: SceneVariant) -> dict[sp.Symbol, float]:
    """Parameters at the median of their value pool, else the middle of their sampling range."""
    values: dict[sp.Symbol, float] = {}
    for p in variant.scene.parameters:
        if p.values:
            pool = sorted(p.values)
            value = pool[len(pool) // 2]
        else:
            lo, hi = p.domain.sample_range()
            value = (lo + hi) / 2
        values[variant.parameter_symbols[p.name]] = float(value)
    return values


class Geometry:
    """Numeric geometry of one variant: projected positions as functions of (q…, t)."""

    def __init__(self, variant: SceneVariant, hint: FigureHint):
        self.variant, self.hint = variant, hint
        self.jets = variant.jets
        self.canonical = dict(zip(variant.coordinates, variant.scene.coordinates, strict=True))
        self.values = representative_values(variant)
        self.bodies = variant.bodies
        self.three_d = any(len(b.position) == 3 for b in self.bodies)
        self.args = [j.q for j in self.jets] + [mech.t]
        positions = [self.project(b.position) for b in self.bodies]
        self.symbolic = [tuple(as_expr(x).xreplace(self.values) for x in p) for p in positions]
        self.raw = positions
        # lambdify on the bank's own positions (never student text): fast sweeps for drawing
        self._funcs = [sp.lambdify(self.args, list(p), modules="numpy") for p in self.symbolic]
        ns = variant.namespace
        self.scale = self._length_scale()
        self.pose = self._pose(ns)
        self.offsets = {
            i: np.array([self.number(c) for c in self.project(hint.offsets[b.name](ns))])
            for i, b in enumerate(self.bodies)
            if b.name in hint.offsets
        }

    def project(self, position: Sequence[sp.Expr]) -> tuple[sp.Expr, sp.Expr]:
        """2-D positions as they are; 3-D ones (z up) in an oblique view with y going back."""
        if len(position) == 2:
            return (as_expr(position[0]), as_expr(position[1]))
        x, y, z = (as_expr(c) for c in position)
        return (x + _OBLIQUE[0] * y, z + _OBLIQUE[1] * y)

    def _length_scale(self) -> float:
        lengths = [
            v
            for p in self.variant.scene.parameters
            if p.unit == "m"
            for s, v in self.values.items()
            if s.name == p.name
        ]
        return float(np.median(lengths)) if lengths else 1.0

    def _pose(self, ns: SimpleNamespace) -> dict[sp.Symbol, float]:
        pose: dict[sp.Symbol, float] = {}
        for i, j in enumerate(self.jets):
            pose[j.q] = (_ANGLE_POSES if self.is_angle(j.q) else _LENGTH_POSES)[i % 4] * (
                1.0 if self.is_angle(j.q) else self.scale
            )
        for canonical, value in self.hint.poses.items():
            j = self.jets[self.variant.scene.coordinates.index(canonical)]
            pose[j.q] = self.number(value(ns), pose)
        return pose

    def number(self, expr: Any, pose: Mapping[sp.Symbol, float] | None = None) -> float:
        """A hint's expression as a number at the representative values and pose."""
        subs = (
            dict(self.values)
            | dict(pose if pose is not None else self.pose)
            | {mech.t: self.hint.t}
        )
        return float(as_expr(expr).xreplace(subs))

    def is_angle(self, q: sp.Symbol) -> bool:
        """q enters the positions only through trigonometric functions (a body's own angle may
        be q itself: the ladder's tilt, the wheel's turn)."""
        positions = [as_expr(x) for b in self.bodies for x in b.position]
        angles = [as_expr(b.angle) for b in self.bodies if isinstance(b, RigidBody)]
        hidden = [e.replace(lambda f: isinstance(f, TRIG), lambda f: sp.S.One) for e in positions]
        return any(e.has(q) for e in positions + angles) and not any(h.has(q) for h in hidden)

    @cached_property
    def constrained(self) -> bool:
        """The scene declares constraints (tracks, rods, surfaces), so coordinate sweeps trace
        something real; without any, bodies move freely and a sweep would look like a rail."""
        return any(label == "declared" for label, _ in self.variant.constraints)

    def moves(self, body_index: int, symbol: sp.Symbol) -> bool:
        return any(as_expr(x).has(symbol) for x in self.bodies[body_index].position)

    def depends(self, body_index: int) -> int:
        return sum(self.moves(body_index, j.q) for j in self.jets)

    def carriers(self, q: sp.Symbol) -> list[int]:
        """Bodies that q moves and that depend on the fewest coordinates (q's own body)."""
        moved = [i for i in range(len(self.bodies)) if self.moves(i, q)]
        if not moved:
            return []
        fewest = min(self.depends(i) for i in moved)
        return [i for i in moved if self.depends(i) == fewest]

    def at(self, body_index: int, changes: Mapping[sp.Symbol, Any] | None = None) -> np.ndarray:
        """Projected position(s); `changes` may hold arrays to sweep a coordinate or t."""
        point = dict(self.pose) | {mech.t: self.hint.t} | dict(changes or {})
        values = self._funcs[body_index](*[point[a] for a in self.args])
        size = max((np.size(v) for v in values), default=1)
        pts = np.array([np.broadcast_to(np.asarray(v, dtype=float), (size,)) for v in values]).T
        return pts + self.offsets[body_index] if body_index in self.offsets else pts

    @cached_property
    def rng_points(self) -> list[dict[sp.Symbol, float]]:
        """Random points over parameters, coordinates and t, for identity checks."""
        rng = random.Random(1)
        points = []
        for _ in range(3):
            point = {
                s: rng.uniform(*self.variant.domains[s.name].sample_range())
                for s in self.variant.parameter_symbols.values()
            }
            point |= {j.q: rng.uniform(0.3, 1.3) for j in self.jets} | {mech.t: rng.uniform(0, 1)}
            points.append(point)
        return points

    def identically_zero(self, expr: sp.Expr) -> bool:
        """expr vanishes at several random points (parameters, coordinates, t)."""
        try:
            return all(abs(complex(as_expr(expr).evalf(subs=p))) < 1e-9 for p in self.rng_points)
        except (TypeError, ValueError, ZeroDivisionError):
            return False

    def parameters_with_unit(self, unit: str) -> list[sp.Symbol]:
        return [
            self.variant.parameter_symbols[p.name]
            for p in self.variant.scene.parameters
            if p.unit == unit
        ]


def circle(geometry: Geometry, body: int, q: sp.Symbol) -> tuple[np.ndarray, float] | None:
    """(centre, radius) when the body's path as q turns is a circle at constant speed."""
    angles = np.array([0.0, 2 * math.pi / 3, 4 * math.pi / 3])
    pts = geometry.at(body, {q: angles})
    centre = pts.mean(axis=0)
    check = geometry.at(body, {q: np.array([0.3, 1.1, 2.0, 4.4])})
    radii = np.hypot(*(check - centre).T)
    if geometry.three_d:
        # the projection of a tilted circle is an ellipse; test the circle in 3-D instead
        raw = [
            sp.lambdify(  # the bank's own positions, never student text
                geometry.args,
                [as_expr(x).xreplace(geometry.values) for x in geometry.bodies[body].position],
                modules="numpy",
            )
        ]
        base = dict(geometry.pose) | {mech.t: geometry.hint.t}

        def point3(a: float) -> np.ndarray:
            return np.array(raw[0](*[a if s == q else base[s] for s in geometry.args]), dtype=float)

        c3 = np.mean([point3(a) for a in angles], axis=0)
        radii = np.array([np.linalg.norm(point3(a) - c3) for a in (0.3, 1.1, 2.0, 4.4)])
    radius = float(radii.mean())
    if radius < 1e-9 or not np.allclose(radii, radius, rtol=1e-6):
        return None
    return centre, radius


def label_for_length(geometry: Geometry, expr: sp.Expr) -> str | None:
    """The length parameter that `expr` (a distance) equals identically, as LaTeX."""
    for p in geometry.parameters_with_unit("m"):
        if geometry.identically_zero(sp.expand(expr - p**2)):
            return name_latex(p.name)
    return None


def rotation_axis(
    g: Geometry, body: int, times: np.ndarray
) -> tuple[np.ndarray, np.ndarray] | None:
    """(projected centre, projected unit direction) of the axis a body circles about in time."""
    position = [as_expr(x).xreplace(g.values) for x in g.bodies[body].position]
    f = sp.lambdify(g.args, position, modules="numpy")  # bank positions, never student text
    base = dict(g.pose)
    pts = np.array(
        [
            np.broadcast_to(np.asarray(v, dtype=float), times.shape)
            for v in f(*[times if s == mech.t else base[s] for s in g.args])
        ]
    ).T[:-1]
    if pts.shape[1] != 3:
        return None
    centre = pts.mean(axis=0)
    radii = np.linalg.norm(pts - centre, axis=1)
    if radii.mean() < 1e-9 or not np.allclose(radii, radii.mean(), rtol=1e-6):
        return None
    normal = np.cross(pts[0] - centre, pts[len(pts) // 4] - centre)
    normal /= np.linalg.norm(normal)
    c2 = np.array([float(v) for v in g.project([sp.Float(x) for x in centre])])
    tip = np.array([float(v) for v in g.project([sp.Float(x) for x in centre + normal])])
    direction = tip - c2
    return c2, direction / (np.hypot(*direction) or 1.0)
