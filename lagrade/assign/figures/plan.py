"""The layout of a figure: from a scene's geometry, what to draw and in which order (shapes,
each coordinate's sweep with its rod, arc or dimension line, motions in time, dimensions, bodies,
gravity), collected as traces and drawing operations before the figure's extent is known."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np
import sympy as sp

from lagrade.assign.figures.bodies import axes3d, body_disc, body_radius
from lagrade.assign.figures.fixtures import anchor, angle_mark, plan_fixtures
from lagrade.assign.figures.geometry import (
    TRIG,
    Geometry,
    circle,
    label_for_length,
    rotation_axis,
)
from lagrade.assign.figures.primitives import (
    along_label,
    arc_arrow,
    arrow_along,
    beside,
    dimension,
    field_arrow,
    gravity_arrow,
    incline_angle,
    label_id,
    pivot,
    put_text,
    time_mark,
)
from lagrade.assign.figures.style import ACCENT, GREY, INK, TRACE_STYLE
from lagrade.mechanics import RigidBody, as_expr
from lagrade.mechanics import lagrange as mech
from lagrade.notation import name_latex

#: What a traced path is, by its style: a constraint surface is a track the body runs on.
TRACE_KIND = {"solid": "track", "path": "path", "time": "time"}


@dataclass(frozen=True)
class Op:
    """One element of the figure: what it is (`body`, `rod`, `spring`, `mark`, …), whose it is
    (a body's or coordinate's name), and how to draw it on axes scaled by `unit`. The kinds let
    the figure test ask whether everything the scene declares was drawn."""

    kind: str
    name: str
    draw: Callable[[Any, float], None]


class Drawing:
    """Collects what to draw, then draws it scaled to the figure's extent."""

    def __init__(self, geometry: Geometry):
        self.g = geometry
        self.traces: list[Op] = []  # drawn first, under everything
        self.ops: list[Op] = []
        self.points: list[np.ndarray] = []

    def add(self, kind: str, name: str, draw: Callable[[Any, float], None]) -> None:
        self.ops.append(Op(kind, name, draw))

    def trace(self, pts: np.ndarray, style: str, name: str) -> None:
        self.traces.append(
            Op(TRACE_KIND[style], name, lambda ax, u: ax.plot(*pts.T, **TRACE_STYLE[style]))
        )

    def add_points(self, pts: np.ndarray) -> None:
        finite = pts[np.all(np.isfinite(pts), axis=1)]
        if len(finite):
            self.points.append(finite)


def plan(geometry: Geometry) -> Drawing:
    """Everything to draw for `geometry`, in drawing order."""
    d = Drawing(geometry)
    ns = geometry.variant.namespace
    _plan_shapes(d, ns)
    plan_fixtures(d.g, ns, d.add, d.add_points)
    centre_of = np.mean(np.vstack(d.points), axis=0)
    for k, j in enumerate(geometry.jets):
        _plan_coordinate(d, k, j, ns, centre_of)
    _plan_time(d)
    _plan_dimensions_and_bodies(d, ns, centre_of)
    return d


def _plan_shapes(d: Drawing, ns: SimpleNamespace) -> None:
    """Every body's position counts toward the extent; a body given a shape (the wedge) is drawn
    as that polygon, with its mass at the centroid."""
    g = d.g
    for i in range(len(g.bodies)):
        d.add_points(g.at(i))
    for body_name, shape in g.hint.shapes.items():
        vertices = np.array([[g.number(c) for c in g.project(v)] for v in shape(ns)])
        d.add_points(vertices)
        d.add(
            "body",
            body_name,
            lambda ax, u, v=vertices, n=body_name: ax.fill(
                *v.T, facecolor="#e4e4e4", edgecolor=INK, linewidth=1.2, zorder=2, gid=f"body-{n}"
            ),
        )
        index = next((k for k, b in enumerate(g.bodies) if b.name == body_name), None)
        if index is not None:
            d.add("label", body_name, _shape_label(g, index, vertices))


def _shape_label(g: Geometry, index: int, vertices: np.ndarray) -> Callable:
    """A shaped body's mass label: at its centroid, or beside its outline where the scene file
    places it."""
    b = g.bodies[index]
    mass, place = f"${sp.latex(b.mass)}$", g.hint.labels.get(b.name)
    if place:
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        return lambda ax, u: beside(
            ax, u, (lo + hi) / 2, (hi - lo) / 2, place, mass, label_id(b.name)
        )
    centroid = vertices.mean(axis=0)
    return lambda ax, u: put_text(ax, centroid, mass, zorder=6, gid=label_id(b.name))


def _plan_coordinate(
    d: Drawing, k: int, j: mech.Jet, ns: SimpleNamespace, centre_of: np.ndarray
) -> None:
    """The k-th coordinate: the paths it sweeps its bodies along, and one label for it."""
    g = d.g
    canonical = g.variant.scene.coordinates[k]
    label = f"${name_latex(j.name)}$"
    carriers = g.carriers(j.q)
    if canonical in g.hint.angles:
        _plan_marked_angle(d, canonical, label, ns)
        return
    if canonical in g.hint.spans:
        a, b = (anchor(g, x) for x in g.hint.spans[canonical](ns))
        d.add("mark", j.name, lambda ax, u: dimension(ax, u, a, b, label, centre_of, both=True))
        return
    if not carriers:
        _plan_rotation(d, j, label)
        return
    lo, hi = _sweep_range(g, canonical, j.q, ns)
    sweep = np.linspace(lo, hi, 181)
    shown = g.hint.sweeps.get(canonical) != "none"
    for n, i in enumerate(carriers):
        pts = g.at(i, {j.q: sweep})
        if shown:
            d.add_points(pts)
        if g.is_angle(j.q):
            style = "solid" if canonical in g.hint.solid else "path"
            if shown:
                d.trace(pts, style, j.name)
            if n == 0:  # one label per coordinate, however many bodies it moves
                _plan_angle(d, i, j, label, canonical)
        else:
            if g.constrained and shown:  # the sweep traces a track; a free body has none
                d.trace(pts, "solid", j.name)
            if n == 0:
                _plan_length(d, i, j, label, pts if shown else None, centre_of)


def _sweep_range(
    g: Geometry, canonical: str, q: sp.Symbol, ns: SimpleNamespace
) -> tuple[float, float]:
    """The hint's range, else a full turn for an angle, else a length scale either side of the
    pose (starting at zero or below)."""
    if canonical in g.hint.ranges:
        lo, hi = (g.number(x) for x in g.hint.ranges[canonical](ns))
        return lo, hi
    if g.is_angle(q):
        return 0.0, 2 * math.pi
    pose = g.pose[q]
    return min(0.0, pose - g.scale), pose + g.scale


def _plan_dimensions_and_bodies(d: Drawing, ns: SimpleNamespace, centre_of: np.ndarray) -> None:
    """The hint's dimension lines, then the bodies on top, gravity, and the axes of a 3-D view."""
    g = d.g
    shaped = set(g.hint.shapes)
    for name, ends in g.hint.dimensions:
        a, b = (np.array([g.number(c) for c in g.project(p)]) for p in ends(ns))
        d.add(
            "dimension",
            name,
            lambda ax, u, a=a, b=b, n=name: dimension(
                ax, u, a, b, f"${name_latex(n)}$", centre_of, both=True
            ),
        )
    barred = {f.body for f in g.hint.fixtures(ns) if f.kind == "bar"}
    for i, b in enumerate(g.bodies):
        if b.name in shaped or b.name in barred:
            continue
        d.add("body", b.name, lambda ax, u, i=i, b=b: body_disc(ax, u, g, i, b))
    if any(s.name == "g" for s in g.variant.potential_energy.free_symbols):
        d.add("gravity", "g", lambda ax, u: gravity_arrow(ax, u, d.points))
    _plan_field(d)
    if g.three_d:
        d.add("axes", "xyz", lambda ax, u: axes3d(ax, u, g))


def _plan_field(d: Drawing) -> None:
    """A magnetic field (a parameter in tesla) shown as an arrow along it: its direction is
    curl A, with the vector potential A read off the velocity-dependent potential of the one
    body that the coordinates place in space, U = −e v·A (so A ∝ −J⁻ᵀ ∂U/∂q̇, J = ∂r/∂q)."""
    g = d.g
    fields = g.parameters_with_unit("T")
    if not fields or len(g.bodies) != 1 or len(g.jets) != 3:
        return
    position = sp.Matrix([as_expr(c) for c in g.bodies[0].position])
    q = [j.q for j in g.jets]
    U = g.variant.potential_energy
    J = position.jacobian(q)
    if position.shape != (3, 1) or g.identically_zero(J.det()):
        return
    A = -(J.T).inv() * sp.Matrix([sp.diff(U, j.dot) for j in g.jets])
    D = A.jacobian(q) * J.inv()  # ∂A_i/∂x_k
    curl = [D[2, 1] - D[1, 2], D[0, 2] - D[2, 0], D[1, 0] - D[0, 1]]
    B = np.array([g.number(c) for c in curl])
    if not np.all(np.isfinite(B)) or np.hypot.reduce(B) == 0:
        return
    on_page = np.array([g.number(c) for c in g.project(tuple(B / np.hypot.reduce(B)))])
    if np.hypot(*on_page) < 0.3:  # along the line of sight: an arrow would be a dot
        return
    on_page = on_page / np.hypot(*on_page)
    label = f"${name_latex(fields[0].name)}$"
    d.add("field", fields[0].name, lambda ax, u: field_arrow(ax, u, d.points, on_page, label))


def _plan_angle(d: Drawing, body: int, j: mech.Jet, label: str, canonical: str) -> None:
    """An angle whose body moves on a circle: a rod (or a radius) from the circle's centre, a
    dashed line to where the angle is zero and an arc from there to the pose. On any other path,
    an arrow along it."""
    g = d.g
    found = circle(g, body, j.q)
    pose = g.pose[j.q]
    if found is None:
        pts = g.at(body, {j.q: np.linspace(pose - 0.3, pose, 20)})
        d.add("mark", j.name, lambda ax, u: arrow_along(ax, pts, label, u))
        return
    centre, radius = found
    position = g.at(body)[0]
    pivot_body = _body_at(g, body, centre, radius)
    length = _rod_length(g, body, j.q)
    zero = g.at(body, {j.q: np.array([0.0])})[0]
    arc = g.at(body, {j.q: np.linspace(0.0, pose, 40)})
    # a free orbit (Kepler) hangs from nothing, and neither does a circle whose centre other
    # coordinates move with no body there (the spherical pendulum's φ circle: its centre is
    # on the axis below the pivot, not a second pivot)
    rods = g.hint.rods and g.constrained and (pivot_body is not None or _fixed_centre(g, body, j.q))
    spokes = g.hint.spokes

    def draw(ax: Any, unit: float) -> None:
        ax.plot(
            *np.array([centre, zero]).T, color=GREY, linewidth=0.8, linestyle=(0, (4, 3)), zorder=1
        )
        if rods:
            ax.plot(
                *np.array([centre, position]).T,
                color=INK,
                linewidth=2.2,
                zorder=3,
                solid_capstyle="round",
            )
            if pivot_body is None:
                pivot(ax, centre, unit)
        elif spokes:
            ax.plot(*np.array([centre, position]).T, color=INK, linewidth=0.9, zorder=3)
            ax.plot(*centre, marker="o", markersize=3, color=INK, zorder=4)
        if length:
            along_label(ax, centre, position, f"${length}$", unit, centre_of=None)
        r = min(0.35, 0.3 * unit / max(radius, 1e-9))
        pts = centre + r * (arc - centre)
        arc_arrow(ax, pts, label)
        mid = centre + 1.45 * r * (g.at(body, {j.q: np.array([pose / 2])})[0] - centre)
        put_text(ax, mid, label, color=ACCENT)

    d.add("rod" if rods else "mark", j.name, draw)


def _plan_marked_angle(d: Drawing, canonical: str, label: str, ns: SimpleNamespace) -> None:
    """An angle the hint places (the ladder's, at its top or foot, between it and the wall or
    the floor), where no circular path of a body would show it."""
    g = d.g
    vertex, a, b = (
        np.array([g.number(c) for c in g.project(p)]) for p in g.hint.angles[canonical](ns)
    )
    d.add("mark", canonical, lambda ax, u: angle_mark(ax, u, vertex, a, b, label))


def _fixed_centre(g: Geometry, body: int, q: sp.Symbol) -> bool:
    """Whether the centre of the circle `q` moves `body` on stays put as the other coordinates
    change (a pivot), judged in space, before the projection."""
    thirds = (0, 2 * sp.pi / 3, 4 * sp.pi / 3)
    centre = [sum(as_expr(x).subs(q, a) for a in thirds) / 3 for x in g.bodies[body].position]
    others = [j.q for j in g.jets if j.q != q]
    return all(g.identically_zero(sp.diff(c, o)) for c in centre for o in others)


def _body_at(g: Geometry, body: int, centre: np.ndarray, radius: float) -> int | None:
    """Another body sitting at the circle's centre (the rod hangs from it: no pivot is drawn)."""
    return next(
        (
            k
            for k in range(len(g.bodies))
            if k != body and np.allclose(g.at(k)[0], centre, atol=1e-6 * max(radius, 1))
        ),
        None,
    )


def _rod_length(g: Geometry, body: int, q: sp.Symbol) -> str | None:
    """The length parameter the rod equals, as LaTeX, if any."""
    # the rod's length, symbolically: |P - C|² with C the mean of three points on the circle
    thirds = (0, 2 * sp.pi / 3, 4 * sp.pi / 3)
    if g.three_d:  # measured in space, before the projection
        raw = g.bodies[body].position
        c3 = [sum(as_expr(p).subs(q, a) for a in thirds) / 3 for p in raw]
        return label_for_length(g, sum((as_expr(p) - c) ** 2 for p, c in zip(raw, c3, strict=True)))
    p_sym = [g.project(g.bodies[body].position)[k] for k in range(2)]
    c_sym = [sum(as_expr(p).subs(q, a) for a in thirds) / 3 for p in p_sym]
    return label_for_length(g, sum((p - c) ** 2 for p, c in zip(p_sym, c_sym, strict=True)))


def _plan_length(
    d: Drawing, body: int, j: mech.Jet, label: str, trace: np.ndarray | None, centre_of: np.ndarray
) -> None:
    """A length coordinate: a dimension arrow from where it is zero to the pose; on a straight
    track inclined at an angle parameter, that angle marked at the track's lower end (unless the
    track is not drawn: a declared surface marks its own angle)."""
    g = d.g
    pose = g.pose[j.q]
    # several lengths placing one body (Cartesian x, y, z): measured as a chain from the origin,
    # each from where the one before ends (x along the x axis, then y, then z up to the body),
    # so that no two dimension lines cross
    k = next(n for n, jet in enumerate(g.jets) if jet.q == j.q)
    later = {
        jet.q: 0.0 for jet in g.jets[k + 1 :] if not g.is_angle(jet.q) and g.moves(body, jet.q)
    }
    pts = g.at(body, {**later, j.q: np.linspace(0.0, pose, 30)})
    if np.hypot(*(pts[-1] - pts[0])) < 1e-9:
        return
    d.add(
        "mark", j.name, lambda ax, u: dimension(ax, u, pts[0], pts[-1], label, centre_of, path=pts)
    )
    if g.three_d or trace is None:
        return
    # a straight track inclined at an angle parameter: mark that angle at its lower end
    position = g.project(g.bodies[body].position)
    direction = [sp.diff(as_expr(c), j.q) for c in position]
    for a in g.parameters_with_unit("rad"):
        for sign in (1, -1):
            if g.identically_zero(
                direction[1] * sp.cos(a) - sign * direction[0] * sp.sin(a)
            ) and not g.identically_zero(direction[0]):
                d.add(
                    "mark",
                    a.name,
                    lambda ax, u, a=a: incline_angle(ax, u, trace, name_latex(a.name)),
                )
                return


def _plan_rotation(d: Drawing, j: mech.Jet, label: str) -> None:
    """A coordinate that only turns a rigid body: the angle of its mark from where the mark
    is at zero, which a dashed reference line shows, with an arc between them (an arc alone
    measures from nothing)."""
    g = d.g
    for i, b in enumerate(g.bodies):
        if isinstance(b, RigidBody) and as_expr(b.angle).has(j.q):
            start = g.number(as_expr(b.angle).subs(j.q, 0))
            end = g.number(b.angle)

            def draw(
                ax: Any, unit: float, i: int = i, start: float = start, end: float = end
            ) -> None:
                centre = g.at(i)[0]
                r = body_radius(g, i, unit)
                # the reference ray and the mark, both carried past the rim, the arc outside
                for angle, colour in ((start, GREY), (end, INK)):
                    ray = np.array([math.cos(angle), math.sin(angle)])
                    inner = centre if colour == GREY else centre + r * ray
                    ax.plot(
                        *np.array([inner, centre + 1.6 * r * ray]).T,
                        color=colour,
                        linewidth=0.8,
                        linestyle=(0, (4, 3)),
                        zorder=5,
                    )
                angles = np.linspace(start, end, 40)
                pts = centre + 1.4 * r * np.column_stack([np.cos(angles), np.sin(angles)])
                arc_arrow(ax, pts, label)
                middle = (start + end) / 2
                put_text(
                    ax,
                    centre + 1.75 * r * np.array([math.cos(middle), math.sin(middle)]),
                    label,
                    color=ACCENT,
                )

            d.add("mark", j.name, draw)
            return


def _plan_time(d: Drawing) -> None:
    """Bodies moved by t (a turning hoop, a driven support): trace them over one period."""
    g = d.g
    for i, b in enumerate(g.bodies):
        if not g.moves(i, mech.t):
            continue
        rates = set()
        for f in as_expr(sp.Tuple(*b.position)).atoms(*TRIG):
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
        d.trace(pts, "time", b.name)
        axis = rotation_axis(g, i, times) if label != "$t$" else None
        d.add(
            "mark",
            "t",
            lambda ax, u, pts=pts, label=label, axis=axis: time_mark(ax, u, pts, label, axis),
        )
