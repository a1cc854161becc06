"""Drawing the fixtures a hint declares (springs, dashpots, ropes, pulleys, walls, surfaces,
supports and bars), in scene units: each function gets its anchors already as numbers, and
`unit`, the figure's extent, sizes the zigzags and hatches."""

from __future__ import annotations

import math
from collections.abc import Callable
from types import SimpleNamespace
from typing import Any

import numpy as np
import sympy as sp

from lagrade.assign.figures.geometry import Geometry
from lagrade.assign.figures.primitives import (
    arc_arrow,
    beside,
    incline_angle,
    label_id,
    pivot,
    put_text,
)
from lagrade.assign.figures.style import ACCENT, GREY, INK
from lagrade.mechanics import Anchor, Fixture, as_expr
from lagrade.mechanics import lagrange as mech
from lagrade.notation import name_latex

_FILL = "#e4e4e4"


def _normal(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The unit normal to the left of a → b."""
    v = b - a
    n = np.array([-v[1], v[0]])
    return n / (np.hypot(*n) or 1.0)


def hatched(ax: Any, unit: float, a: np.ndarray, b: np.ndarray, side: int) -> None:
    """A fixed line a → b with short hatches on `side` (+1: left of a → b, −1: right)."""
    ax.plot(*np.array([a, b]).T, color=INK, linewidth=1.4, zorder=2, solid_capstyle="butt")
    n = side * _normal(a, b)
    along = (b - a) / (np.hypot(*(b - a)) or 1.0)
    step = 0.035 * unit
    count = max(2, int(np.hypot(*(b - a)) / step))
    for k in range(count + 1):
        p = a + (b - a) * k / count
        tick = np.array([p, p + 0.03 * unit * (n - 0.8 * along)])
        ax.plot(*tick.T, color=INK, linewidth=0.7, zorder=2)


def spring(ax: Any, unit: float, a: np.ndarray, b: np.ndarray, label: str) -> None:
    """A zigzag spring from a to b: straight leads at both ends, the coils in between."""
    length = float(np.hypot(*(b - a)))
    if length < 1e-12:
        return
    along, n = (b - a) / length, _normal(a, b)
    lead = min(0.2 * length, 0.05 * unit)
    coils = 10
    amplitude = 0.022 * unit
    pts = [a, a + lead * along]
    for k in range(coils):
        s = lead + (length - 2 * lead) * (k + 0.5) / coils
        pts.append(a + s * along + (amplitude if k % 2 == 0 else -amplitude) * n)
    pts += [b - lead * along, b]
    ax.plot(*np.array(pts).T, color=INK, linewidth=1.0, zorder=3, solid_joinstyle="miter")
    if label:
        put_text(ax, (a + b) / 2 + 0.075 * unit * (n if n[1] >= 0 else -n), label)


def dashpot(ax: Any, unit: float, a: np.ndarray, b: np.ndarray, label: str) -> None:
    """A dashpot (a damper) from a to b: a cylinder, open toward b, on a lead from a, and a
    piston in it on a rod from b; the cylinder stays fixed to a as the rod slides."""
    length = float(np.hypot(*(b - a)))
    if length < 1e-12:
        return
    along, n = (b - a) / length, _normal(a, b)
    cylinder = min(0.4 * length, 0.16 * unit)
    start = a + 0.5 * (length - cylinder) * along  # centred between its ends
    end = start + cylinder * along
    half = 0.028 * unit
    outline = [end + half * n, start + half * n, start - half * n, end - half * n]
    piston = start + 0.6 * cylinder * along
    line = dict(color=INK, linewidth=1.0, zorder=3, solid_capstyle="butt")
    ax.plot(*np.array([a, start]).T, **line)
    ax.plot(*np.array(outline).T, color=INK, linewidth=1.2, zorder=3, solid_joinstyle="miter")
    ax.plot(
        *np.array([piston + 0.75 * half * n, piston - 0.75 * half * n]).T,
        **{**line, "linewidth": 2.0},
    )
    ax.plot(*np.array([piston, b]).T, **line)
    if label:
        put_text(ax, (start + end) / 2 + (half + 0.05 * unit) * (n if n[1] >= 0 else -n), label)


def rope(ax: Any, unit: float, pts: np.ndarray) -> None:
    ax.plot(*pts.T, color=INK, linewidth=1.0, zorder=2)


def pulley(ax: Any, unit: float, centre: np.ndarray, radius: float, fixed: bool = True) -> None:
    """A pulley on its axle: a fixed one hung from a hatched ceiling by a strut, a moving one
    (centred on a body, or where a coordinate puts it) on its own, held by its rope."""
    from matplotlib.patches import Circle

    if fixed:
        top = centre + np.array([0.0, radius + 0.12 * unit])
        ax.plot(*np.array([centre, top]).T, color=INK, linewidth=1.4, zorder=2)
        half = np.array([max(radius, 0.06 * unit), 0.0])
        hatched(ax, unit, top - half, top + half, side=1)
    ax.add_patch(Circle(tuple(centre), radius, facecolor=_FILL, edgecolor=INK, lw=1.2, zorder=3))
    ax.plot(*centre, marker="o", markersize=3, color=INK, zorder=4)


def surface(ax: Any, unit: float, a: np.ndarray, b: np.ndarray, side: int, angle: str) -> None:
    """A fixed surface: a hatched line, or, with an angle to mark, a solid incline whose angle
    is marked where it meets the horizontal."""
    if not angle:
        hatched(ax, unit, a, b, side)
        return
    high, low = (a, b) if a[1] >= b[1] else (b, a)
    corner = np.array([high[0], low[1]])
    ax.fill(*np.array([high, low, corner]).T, facecolor=_FILL, edgecolor=INK, lw=1.2, zorder=1)
    incline_angle(ax, unit, np.array([high, low]), angle)


def support(ax: Any, unit: float, at: np.ndarray) -> None:
    pivot(ax, at, unit)
    ax.plot(*at, marker="o", markersize=3, color=INK, zorder=4)


def bar(
    ax: Any,
    unit: float,
    a: np.ndarray,
    b: np.ndarray,
    mass: str,
    length: str,
    body: str,
    place: str,
) -> None:
    """A rigid bar (a ladder) from a to b, with its mass at the middle (or on the side of the bar
    the scene file places it) and its length beside."""
    ax.plot(*np.array([a, b]).T, color=GREY, linewidth=5.0, zorder=3, solid_capstyle="round")
    ax.plot(*np.array([a, b]).T, color=INK, linewidth=0.8, zorder=3)
    n = _normal(a, b)
    n = n if n[0] + n[1] >= 0 else -n
    middle = (a + b) / 2
    ax.plot(*middle, marker="o", markersize=4, color=INK, zorder=4)
    if place:
        beside(ax, unit, middle, np.abs(b - a) / 2, place, mass, label_id(body))
    else:
        put_text(ax, middle + 0.07 * unit * n, mass, gid=label_id(body))
    if length:
        quarter = a + 0.25 * (b - a)
        put_text(ax, quarter + 0.07 * unit * n, length)


def angle_mark(
    ax: Any, unit: float, vertex: np.ndarray, a: np.ndarray, b: np.ndarray, label: str
) -> None:
    """An angle at `vertex` from ray → a to ray → b, the arc labelled."""
    start = math.atan2(*(a - vertex)[::-1])
    end = math.atan2(*(b - vertex)[::-1])
    sweep = (end - start + math.pi) % (2 * math.pi) - math.pi  # the shorter way round
    r = 0.14 * unit
    angles = np.linspace(start, start + sweep, 30)
    pts = vertex + r * np.column_stack([np.cos(angles), np.sin(angles)])
    arc_arrow(ax, pts, label)
    mid = start + sweep / 2
    put_text(ax, vertex + 1.4 * r * np.array([math.cos(mid), math.sin(mid)]), label, color=ACCENT)


def anchor(g: Geometry, anchor: Anchor) -> np.ndarray:
    """A fixture's anchor as a drawn point: a body's name stands for where it is drawn."""
    if isinstance(anchor, str):
        index = next(k for k, b in enumerate(g.bodies) if b.name == anchor)
        return g.at(index)[0]
    return np.array([g.number(c) for c in g.project(anchor)])


def moves(g: Geometry, anchor: Anchor) -> bool:
    """The anchor moves with the system: a body's name, or a point a coordinate or t places."""
    if isinstance(anchor, str):
        return True
    moving = [j.q for j in g.jets] + [mech.t]
    return any(as_expr(c).has(s) for c in anchor for s in moving)


def _draw(
    g: Geometry, f: Fixture, pts: np.ndarray, ns: SimpleNamespace, fixed: bool = True
) -> Callable:
    """The drawing operation of one fixture, its anchors already numbers."""
    label = f"${name_latex(f.label)}$" if f.label else ""
    if f.kind == "spring":
        return lambda ax, u: spring(ax, u, pts[0], pts[-1], label)
    if f.kind == "dashpot":
        return lambda ax, u: dashpot(ax, u, pts[0], pts[-1], label)
    if f.kind == "rope":
        return lambda ax, u: rope(ax, u, pts)
    if f.kind == "pulley":
        radius = g.number(f.radius(ns)) if f.radius else 0.05 * g.scale
        return lambda ax, u: pulley(ax, u, pts[0], radius, fixed)
    if f.kind == "wall":
        return lambda ax, u: hatched(ax, u, pts[0], pts[-1], f.side)
    if f.kind == "surface":
        angle = name_latex(f.angle) if f.angle else ""
        return lambda ax, u: surface(ax, u, pts[0], pts[-1], f.side, angle)
    if f.kind == "support":
        return lambda ax, u: support(ax, u, pts[0])
    body = next(b for b in g.bodies if b.name == f.body)
    mass = f"${sp.latex(body.mass)}$"
    place = g.hint.labels.get(f.body, "")
    return lambda ax, u: bar(ax, u, pts[0], pts[-1], mass, label, f.body, place)


def plan_fixtures(
    g: Geometry,
    ns: SimpleNamespace,
    add: Callable[[str, str, Callable], None],
    add_points: Callable[[np.ndarray], None],
) -> None:
    """Every fixture the hint declares, as a drawing operation of its kind; its anchors count
    toward the figure's extent."""
    for k, f in enumerate(g.hint.fixtures(ns)):
        anchors = f.points(ns)
        pts = np.array([anchor(g, a) for a in anchors])
        add_points(pts)
        fixed = not moves(g, anchors[0])
        add(f.kind, f.body or f.label or f"{f.kind}{k + 1}", _draw(g, f, pts, ns, fixed))
