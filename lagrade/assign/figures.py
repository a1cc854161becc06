"""Figures drawn from a scene's own geometry, so that every scene of the bank (and any new one)
has a picture without drawing code of its own.

The bodies' positions are evaluated at a representative configuration (parameters at the middle
of their value pools or domains, coordinates at a generic pose), and each body's path is traced
as each coordinate sweeps a range: that draws the constraint surfaces (the hoop, the wedge's
face, the incline, a pendulum's arc). A body whose path under an angle is a circle gets a rod
from the circle's centre and an angle mark from where the angle is zero; a length coordinate
gets a dimension arrow from where it is zero. 3-D scenes are drawn in an oblique projection.
What geometry cannot tell (the wedge is a triangle, the hoop has no rod) comes from `HINTS`.

Output is SVG and PDF, byte-identical across runs (fixed hash salt, no dates).
"""

from __future__ import annotations

import io
import math
import random
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from types import SimpleNamespace
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import LagradeError
from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.scene import RigidBody, SceneVariant, as_expr
from lagrade.notation.printer import name_latex

Point = tuple[Any, ...]


@dataclass(frozen=True)
class FigureHint:
    """What a scene's geometry does not say, in the scene's canonical names (`s.x_M`, `s.h`).

    poses: coordinate → value to draw it at; ranges: coordinate → (low, high) of its sweep;
    shapes: body → polygon drawn instead of a disc; dimensions: (parameter, (A, B)) dimension
    lines; solid: coordinates whose angle sweeps are surfaces (the hoop), not paths; rods: whether
    circular paths hang from rods; t: the time drawn.
    """

    poses: Mapping[str, Callable[[SimpleNamespace], Any]] = field(default_factory=dict)
    ranges: Mapping[str, Callable[[SimpleNamespace], tuple[Any, Any]]] = field(default_factory=dict)
    shapes: Mapping[str, Callable[[SimpleNamespace], Sequence[Point]]] = field(default_factory=dict)
    dimensions: Sequence[tuple[str, Callable[[SimpleNamespace], tuple[Point, Point]]]] = ()
    solid: frozenset[str] = frozenset()
    rods: bool = True
    t: float = 0.0


HINTS: dict[str, FigureHint] = {
    "wedge": FigureHint(
        ranges={
            "q": lambda s: (0, s.h / sp.sin(s.alpha)),
            "x_M": lambda s: (-0.4 * s.h, s.x_M + s.h / sp.tan(s.alpha) + 0.6 * s.h),
        },
        shapes={"wedge": lambda s: [(s.x_M, 0), (s.x_M, s.h), (s.x_M + s.h / sp.tan(s.alpha), 0)]},
        dimensions=(("h", lambda s: ((s.x_M, 0), (s.x_M, s.h))),),
    ),
    "hoop": FigureHint(solid=frozenset({"theta"}), rods=False),
    # the pucks well apart, away from the origin, so that X, Y, r and θ each have room
    "two_body_spring": FigureHint(
        poses={
            "X": lambda s: 3 * s.l_0,
            "Y": lambda s: 2 * s.l_0,
            "r": lambda s: 2 * s.l_0,
            "theta": lambda s: 0.5,
        }
    ),
}

_ANGLE_POSES = (0.6, 1.0, 0.35, 0.8)
_LENGTH_POSES = (0.5, 0.8, 0.35, 0.65)
_OBLIQUE = (0.5 * math.cos(math.radians(35)), 0.5 * math.sin(math.radians(35)))
_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)
_INK, _GREY, _ACCENT = "#222222", "#8a8a8a", "#1f5fa8"
_RC = {
    "svg.hashsalt": "lagrade",
    "svg.fonttype": "none",
    "pdf.compression": 6,
    "font.size": 11,
    "mathtext.fontset": "dejavuserif",
    "path.simplify": False,
}


class FigureError(LagradeError):
    """A scene whose figure cannot be drawn (its positions do not evaluate to numbers)."""


@dataclass(frozen=True)
class Figure:
    """A drawn figure in both formats."""

    svg: bytes
    pdf: bytes


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


class _Geometry:
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
        """q enters the positions (and body angles) only through trigonometric functions."""
        exprs = [as_expr(x) for b in self.bodies for x in b.position]
        exprs += [as_expr(b.angle) for b in self.bodies if isinstance(b, RigidBody)]
        hidden = [e.replace(lambda f: isinstance(f, _TRIG), lambda f: sp.S.One) for e in exprs]
        return any(e.has(q) for e in exprs) and not any(h.has(q) for h in hidden)

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
        return np.array([np.broadcast_to(np.asarray(v, dtype=float), (size,)) for v in values]).T

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


class _Drawing:
    """Collects what to draw, then draws it scaled to the figure's extent."""

    def __init__(self, geometry: _Geometry):
        self.g = geometry
        self.traces: list[tuple[np.ndarray, str]] = []  # (points, style)
        self.ops: list[Callable[[Any, float], None]] = []
        self.points: list[np.ndarray] = []

    def add_points(self, pts: np.ndarray) -> None:
        finite = pts[np.all(np.isfinite(pts), axis=1)]
        if len(finite):
            self.points.append(finite)


def _circle(geometry: _Geometry, body: int, q: sp.Symbol) -> tuple[np.ndarray, float] | None:
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


def _label_for_length(geometry: _Geometry, expr: sp.Expr) -> str | None:
    """The length parameter that `expr` (a distance) equals identically, as LaTeX."""
    for p in geometry.parameters_with_unit("m"):
        if geometry.identically_zero(sp.expand(expr - p**2)):
            return name_latex(p.name)
    return None


def _plan(geometry: _Geometry) -> _Drawing:
    d = _Drawing(geometry)
    g = geometry
    ns = g.variant.namespace
    shaped = set(g.hint.shapes)
    for i in range(len(g.bodies)):
        d.add_points(g.at(i))
    for body_name, shape in g.hint.shapes.items():
        vertices = np.array([[g.number(c) for c in g.project(v)] for v in shape(ns)])
        d.add_points(vertices)
        d.ops.append(
            lambda ax, u, v=vertices: ax.fill(
                *v.T, facecolor="#e4e4e4", edgecolor=_INK, linewidth=1.2, zorder=2
            )
        )
        index = next((k for k, b in enumerate(g.bodies) if b.name == body_name), None)
        if index is not None:
            centroid = vertices.mean(axis=0)
            d.ops.append(
                lambda ax, u, c=centroid, b=g.bodies[index]: _text(
                    ax, c, f"${sp.latex(b.mass)}$", zorder=6
                )
            )
    centre_of = np.mean(np.vstack(d.points), axis=0)
    for k, j in enumerate(g.jets):
        canonical = g.variant.scene.coordinates[k]
        label = f"${name_latex(j.name)}$"
        carriers = g.carriers(j.q)
        if not carriers:
            _plan_rotation(d, j, label)
            continue
        if canonical in g.hint.ranges:
            lo, hi = (g.number(x) for x in g.hint.ranges[canonical](ns))
        elif g.is_angle(j.q):
            lo, hi = 0.0, 2 * math.pi
        else:
            pose = g.pose[j.q]
            lo, hi = min(0.0, pose - g.scale), pose + g.scale
        sweep = np.linspace(lo, hi, 181)
        for n, i in enumerate(carriers):
            pts = g.at(i, {j.q: sweep})
            d.add_points(pts)
            if g.is_angle(j.q):
                style = "solid" if canonical in g.hint.solid else "path"
                d.traces.append((pts, style))
                if n == 0:  # one label per coordinate, however many bodies it moves
                    _plan_angle(d, i, j, label, canonical)
            else:
                if g.constrained:  # the sweep traces a track; a free body has none
                    d.traces.append((pts, "solid"))
                if n == 0:
                    _plan_length(d, i, j, label, pts, centre_of)
    _plan_time(d)
    for name, ends in g.hint.dimensions:
        a, b = (np.array([g.number(c) for c in g.project(p)]) for p in ends(ns))
        d.ops.append(
            lambda ax, u, a=a, b=b, n=name: _dimension(
                ax, u, a, b, f"${name_latex(n)}$", centre_of, both=True
            )
        )
    for i, b in enumerate(g.bodies):
        if b.name in shaped:
            continue
        d.ops.append(lambda ax, u, i=i, b=b: _body(ax, u, g, i, b))
    if any(s.name == "g" for s in g.variant.potential_energy.free_symbols):
        d.ops.append(lambda ax, u: _gravity(ax, u, d))
    if g.three_d:
        d.ops.append(lambda ax, u: _axes3d(ax, u, g))
    return d


def _plan_angle(d: _Drawing, body: int, j: mech.Jet, label: str, canonical: str) -> None:
    g = d.g
    found = _circle(g, body, j.q)
    pose = g.pose[j.q]
    if found is None:
        pts = g.at(body, {j.q: np.linspace(pose - 0.3, pose, 20)})
        d.ops.append(lambda ax, u: _arrow_along(ax, pts, label, u))
        return
    centre, radius = found
    position = g.at(body)[0]
    pivot_body = next(
        (
            k
            for k in range(len(g.bodies))
            if k != body and np.allclose(g.at(k)[0], centre, atol=1e-6 * max(radius, 1))
        ),
        None,
    )
    # the rod's length, symbolically: |P - C|² with C the mean of three points on the circle
    p_sym = [g.project(g.bodies[body].position)[k] for k in range(2)]
    c_sym = [
        sum(as_expr(p).subs(j.q, a) for a in (0, 2 * sp.pi / 3, 4 * sp.pi / 3)) / 3 for p in p_sym
    ]
    length = (
        None
        if g.three_d
        else _label_for_length(g, sum((p - c) ** 2 for p, c in zip(p_sym, c_sym, strict=True)))
    )
    if g.three_d:
        raw = g.bodies[body].position
        c3 = [
            sum(as_expr(p).subs(j.q, a) for a in (0, 2 * sp.pi / 3, 4 * sp.pi / 3)) / 3 for p in raw
        ]
        length = _label_for_length(
            g, sum((as_expr(p) - c) ** 2 for p, c in zip(raw, c3, strict=True))
        )
    zero = g.at(body, {j.q: np.array([0.0])})[0]
    arc = g.at(body, {j.q: np.linspace(0.0, pose, 40)})
    rods = g.hint.rods and g.constrained  # a free orbit (Kepler) hangs from nothing

    def draw(ax: Any, unit: float) -> None:
        ax.plot(
            *np.array([centre, zero]).T, color=_GREY, linewidth=0.8, linestyle=(0, (4, 3)), zorder=1
        )
        if rods:
            ax.plot(
                *np.array([centre, position]).T,
                color=_INK,
                linewidth=2.2,
                zorder=3,
                solid_capstyle="round",
            )
            if pivot_body is None:
                _pivot(ax, centre, unit)
        else:
            ax.plot(*np.array([centre, position]).T, color=_INK, linewidth=0.9, zorder=3)
            ax.plot(*centre, marker="o", markersize=3, color=_INK, zorder=4)
        if length:
            _along_label(ax, centre, position, f"${length}$", unit, centre_of=None)
        r = min(0.35, 0.3 * unit / max(radius, 1e-9))
        pts = centre + r * (arc - centre)
        _arc_arrow(ax, pts, label)
        mid = centre + 1.45 * r * (g.at(body, {j.q: np.array([pose / 2])})[0] - centre)
        _text(ax, mid, label, color=_ACCENT)

    d.ops.append(draw)


def _plan_length(
    d: _Drawing, body: int, j: mech.Jet, label: str, trace: np.ndarray, centre_of: np.ndarray
) -> None:
    g = d.g
    pose = g.pose[j.q]
    pts = g.at(body, {j.q: np.linspace(0.0, pose, 30)})
    if np.hypot(*(pts[-1] - pts[0])) < 1e-9:
        return
    d.ops.append(lambda ax, u: _dimension(ax, u, pts[0], pts[-1], label, centre_of, path=pts))
    if g.three_d:
        return
    # a straight track inclined at an angle parameter: mark that angle at its lower end
    position = g.project(g.bodies[body].position)
    direction = [sp.diff(as_expr(c), j.q) for c in position]
    for a in g.parameters_with_unit("rad"):
        for sign in (1, -1):
            if g.identically_zero(
                direction[1] * sp.cos(a) - sign * direction[0] * sp.sin(a)
            ) and not g.identically_zero(direction[0]):
                d.ops.append(lambda ax, u, a=a: _incline_angle(ax, u, trace, name_latex(a.name)))
                return


def _plan_rotation(d: _Drawing, j: mech.Jet, label: str) -> None:
    """A coordinate that only turns a rigid body: a curved arrow around that body."""
    g = d.g
    for i, b in enumerate(g.bodies):
        if isinstance(b, RigidBody) and as_expr(b.angle).has(j.q):

            def draw(ax: Any, unit: float, i: int = i) -> None:
                centre = g.at(i)[0]
                r = 1.5 * _body_radius(g, i, unit)
                angles = np.linspace(0.3, 0.3 + g.pose[j.q] + 0.8, 40)
                pts = centre + r * np.column_stack([np.cos(angles), np.sin(angles)])
                _arc_arrow(ax, pts, label)
                _text(
                    ax,
                    centre + 1.3 * r * np.array([math.cos(0.2), math.sin(0.2)]),
                    label,
                    color=_ACCENT,
                )

            d.ops.append(draw)
            return


def _plan_time(d: _Drawing) -> None:
    """Bodies moved by t (a turning hoop, a driven support): trace them over one period."""
    g = d.g
    for i, b in enumerate(g.bodies):
        if not g.moves(i, mech.t):
            continue
        rates = set()
        for f in as_expr(sp.Tuple(*b.position)).atoms(*_TRIG):
            if f.args[0].has(mech.t):
                rate = sp.diff(f.args[0], mech.t)
                if not rate.has(mech.t):
                    rates.add(rate)
        if len(rates) == 1:
            rate = rates.pop()
            period = 2 * math.pi / g.number(rate)
            label = f"${sp.latex(rate)}$"
        else:
            period, label = 1.0, "$t$"
        times = g.hint.t + np.linspace(0, period, 121)
        pts = g.at(i, {mech.t: times})
        d.add_points(pts)
        d.traces.append((pts, "time"))
        axis = _rotation_axis(g, i, times) if label != "$t$" else None
        d.ops.append(
            lambda ax, u, pts=pts, label=label, axis=axis: _time_mark(ax, u, pts, label, axis)
        )


def _rotation_axis(
    g: _Geometry, body: int, times: np.ndarray
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


# --- drawing primitives ------------------------------------------------------------------------


def _text(ax: Any, at: np.ndarray, text: str, color: str = _INK, zorder: int = 7) -> None:
    ax.text(
        float(at[0]),
        float(at[1]),
        text,
        ha="center",
        va="center",
        color=color,
        fontsize=12,
        zorder=zorder,
    )


def _unit_normal(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    v = b - a
    n = np.array([-v[1], v[0]])
    return n / (np.hypot(*n) or 1.0)


def _away(a: np.ndarray, b: np.ndarray, centre_of: np.ndarray | None) -> np.ndarray:
    """The unit normal of segment ab pointing away from the figure's centre."""
    n = _unit_normal(a, b)
    if centre_of is not None and np.dot((a + b) / 2 - centre_of, n) < 0:
        n = -n
    return n


def _dimension(
    ax: Any,
    unit: float,
    a: np.ndarray,
    b: np.ndarray,
    label: str,
    centre_of: np.ndarray,
    both: bool = False,
    path: np.ndarray | None = None,
) -> None:
    n = _away(a, b, centre_of)
    off = 0.08 * unit * n
    pts = (path if path is not None else np.array([a, b])) + off
    style = "<|-|>" if both else "-|>"
    ax.annotate(
        "",
        xy=pts[-1],
        xytext=pts[-2] if len(pts) > 2 else pts[0],
        arrowprops=dict(
            arrowstyle=style if not both else "<|-|>",
            color=_ACCENT,
            linewidth=1.0,
            shrinkA=0,
            shrinkB=0,
            mutation_scale=9,
        ),
        zorder=5,
    )
    ax.plot(*pts.T, color=_ACCENT, linewidth=1.0, zorder=5)
    for end in (a, b):
        tick = np.array([end + 0.03 * unit * n, end + 0.11 * unit * n])
        ax.plot(*tick.T, color=_ACCENT, linewidth=0.8, zorder=5)
    _text(ax, (a + b) / 2 + 0.16 * unit * n, label, color=_ACCENT)


def _along_label(
    ax: Any, a: np.ndarray, b: np.ndarray, label: str, unit: float, centre_of: np.ndarray | None
) -> None:
    n = _unit_normal(a, b)
    if n[1] < 0 or (abs(n[1]) < 1e-9 and n[0] < 0):
        n = -n
    _text(ax, (a + b) / 2 + 0.07 * unit * n, label)


def _arc_arrow(ax: Any, pts: np.ndarray, label: str) -> None:
    if len(pts) < 2 or np.hypot(*(pts[-1] - pts[0])) < 1e-12:
        return
    ax.plot(*pts.T, color=_ACCENT, linewidth=1.0, zorder=5)
    ax.annotate(
        "",
        xy=pts[-1],
        xytext=pts[-2],
        arrowprops=dict(
            arrowstyle="-|>", color=_ACCENT, linewidth=1.0, shrinkA=0, shrinkB=0, mutation_scale=9
        ),
        zorder=5,
    )


def _arrow_along(ax: Any, pts: np.ndarray, label: str, unit: float) -> None:
    _arc_arrow(ax, pts, label)
    _text(ax, pts[len(pts) // 2] + np.array([0.0, 0.08 * unit]), label, color=_ACCENT)


def _pivot(ax: Any, at: np.ndarray, unit: float) -> None:
    w = 0.07 * unit
    ax.plot([at[0] - w, at[0] + w], [at[1], at[1]], color=_INK, linewidth=1.4, zorder=3)
    for x in np.linspace(at[0] - w, at[0] + w, 5):
        ax.plot([x, x + 0.35 * w], [at[1], at[1] + 0.35 * w], color=_INK, linewidth=0.7, zorder=3)


def _incline_angle(ax: Any, unit: float, trace: np.ndarray, name: str) -> None:
    finite = trace[np.all(np.isfinite(trace), axis=1)]
    low = finite[np.argmin(finite[:, 1])]
    high = finite[np.argmax(finite[:, 1])]
    up = math.atan2(high[1] - low[1], high[0] - low[0])
    base = 0.0 if high[0] >= low[0] else math.pi
    r = 0.16 * unit
    angles = np.linspace(base, up, 30)
    pts = low + r * np.column_stack([np.cos(angles), np.sin(angles)])
    ax.plot(*pts.T, color=_ACCENT, linewidth=1.0, zorder=5)
    mid = (base + up) / 2
    _text(ax, low + 1.35 * r * np.array([math.cos(mid), math.sin(mid)]), f"${name}$", color=_ACCENT)


def _time_mark(
    ax: Any, unit: float, pts: np.ndarray, label: str, axis: tuple[np.ndarray, np.ndarray] | None
) -> None:
    k = 3 * len(pts) // 8
    ax.annotate(
        "",
        xy=pts[k + 4],
        xytext=pts[k],
        arrowprops=dict(
            arrowstyle="-|>", color=_ACCENT, linewidth=1.0, shrinkA=0, shrinkB=0, mutation_scale=10
        ),
        zorder=5,
    )
    centre = pts.mean(axis=0)
    out = pts[k + 2] - centre
    out = out / (np.hypot(*out) or 1.0)
    _text(ax, pts[k + 2] + 0.09 * unit * out, label, color=_ACCENT)
    if axis is not None:
        c, n = axis
        ends = np.array([c - 0.55 * unit * n, c + 0.55 * unit * n])
        ax.plot(*ends.T, color=_GREY, linewidth=0.8, linestyle=(0, (8, 3, 2, 3)), zorder=1)


def _body_radius(g: _Geometry, i: int, unit: float) -> float:
    b = g.bodies[i]
    if isinstance(b, RigidBody):
        try:
            gyration = math.sqrt(g.number(b.inertia / b.mass))
            return min(max(gyration, 0.05 * unit), 0.3 * unit)
        except (TypeError, ValueError):
            return 0.1 * unit
    masses = []
    for other in g.bodies:
        try:
            masses.append(g.number(other.mass))
        except (TypeError, ValueError):
            masses.append(1.0)
    relative = g.number(b.mass) / max(masses) if masses and max(masses) > 0 else 1.0
    return 0.045 * unit * (0.7 + 0.3 * relative ** (1 / 3))


def _body(ax: Any, unit: float, g: _Geometry, i: int, b: Any) -> None:
    from matplotlib.patches import Circle

    at = g.at(i)[0]
    r = _body_radius(g, i, unit)
    if isinstance(b, RigidBody):
        ax.add_patch(
            Circle(tuple(at), r, facecolor="#f2f2f2", edgecolor=_INK, linewidth=1.4, zorder=4)
        )
        phi = g.number(b.angle)
        tip = at + r * np.array([math.cos(phi), math.sin(phi)])
        ax.plot(*np.array([at, tip]).T, color=_INK, linewidth=1.2, zorder=5)
        ax.plot(*at, marker="o", markersize=2.5, color=_INK, zorder=5)
    else:
        ax.add_patch(Circle(tuple(at), r, facecolor=_INK, edgecolor=_INK, zorder=4))
    _text(ax, at + np.array([1.6 * r + 0.04 * unit, 1.6 * r]), f"${sp.latex(b.mass)}$")


def _gravity(ax: Any, unit: float, d: _Drawing) -> None:
    allpts = np.vstack(d.points)
    top = np.array([allpts[:, 0].max() + 0.12 * unit, allpts[:, 1].max()])
    ax.annotate(
        "",
        xy=top - np.array([0, 0.2 * unit]),
        xytext=top,
        arrowprops=dict(
            arrowstyle="-|>", color=_INK, linewidth=1.2, shrinkA=0, shrinkB=0, mutation_scale=10
        ),
    )
    _text(ax, top - np.array([-0.06 * unit, 0.1 * unit]), "$g$")


def _axes3d(ax: Any, unit: float, g: _Geometry) -> None:
    origin = np.zeros(2)
    for name, vec in (("x", (1, 0, 0)), ("y", (0, 1, 0)), ("z", (0, 0, 1))):
        tip = np.array([float(c) for c in g.project(vec)]) * 0.25 * unit
        ax.annotate(
            "",
            xy=tip,
            xytext=origin,
            arrowprops=dict(
                arrowstyle="-|>", color=_GREY, linewidth=0.8, shrinkA=0, shrinkB=0, mutation_scale=8
            ),
        )
        _text(ax, tip * 1.18, f"${name}$", color=_GREY)


_TRACE_STYLE = {
    "solid": dict(color=_INK, linewidth=1.4, zorder=1),
    "path": dict(color=_GREY, linewidth=0.8, linestyle=(0, (2, 2)), zorder=1),
    "time": dict(color=_GREY, linewidth=0.8, linestyle=(0, (6, 3)), zorder=1),
}


def draw(variant: SceneVariant) -> Figure:
    """The figure of `variant`, as SVG and PDF bytes (deterministic)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure as MplFigure

    hint = HINTS.get(variant.scene.id, FigureHint())
    try:
        geometry = _Geometry(variant, hint)
        plan = _plan(geometry)
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        raise FigureError(f"scene {variant.scene.id!r}: cannot draw its figure ({exc})") from exc
    allpts = np.vstack(plan.points)
    lo, hi = allpts.min(axis=0), allpts.max(axis=0)
    unit = float(max(hi - lo))
    if unit < 1e-6 * geometry.scale:  # nothing moves in space (a wheel turning in place)
        unit = geometry.scale
        lo, hi = lo - 0.5 * unit, hi + 0.5 * unit
    with matplotlib.rc_context(_RC):
        fig = MplFigure(figsize=(4.6, 3.6))
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_aspect("equal")
        ax.axis("off")
        for pts, style in plan.traces:
            ax.plot(*pts.T, **_TRACE_STYLE[style])
        for op in plan.ops:
            op(ax, unit)
        margin = 0.2 * unit
        ax.set_xlim(lo[0] - margin, hi[0] + margin)
        ax.set_ylim(lo[1] - margin, hi[1] + margin)
        svg, pdf = io.BytesIO(), io.BytesIO()
        fig.savefig(svg, format="svg", metadata={"Date": None})
        fig.savefig(pdf, format="pdf", metadata={"CreationDate": None, "ModDate": None})
    return Figure(svg.getvalue(), pdf.getvalue())
