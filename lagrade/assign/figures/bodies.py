"""The bodies of a scene as drawn: point masses as discs sized by mass, rigid bodies as wheels
with a mark that shows their angle, each labelled with its mass; and the axes of a 3-D view."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import sympy as sp

from lagrade.assign.figures.geometry import Geometry
from lagrade.assign.figures.primitives import arc_arrow, beside, label_id, put_text
from lagrade.assign.figures.style import ACCENT, GREY, GREY_TEXT, INK
from lagrade.mechanics import RigidBody, SpatialRigidBody, as_expr
from lagrade.notation import name_latex


def body_radius(g: Geometry, i: int, unit: float) -> float:
    b = g.bodies[i]
    if b.name in g.hint.radii:
        return g.number(g.hint.radii[b.name](g.variant.namespace))
    if isinstance(b, SpatialRigidBody):  # its radius of gyration about the axis 3
        try:
            gyration = math.sqrt(g.number(b.inertia[2] / b.mass))
            return min(max(gyration, 0.15 * unit), 0.35 * unit)
        except (TypeError, ValueError):
            return 0.25 * unit
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


def body_disc(ax: Any, unit: float, g: Geometry, i: int, b: Any) -> None:
    from matplotlib.patches import Circle

    at = g.at(i)[0]
    r = body_radius(g, i, unit)
    gid = f"body-{b.name}"
    if b.mass == 0:  # a massless helper (a moving pulley's axle): a small ring, no label
        ax.add_patch(
            Circle(tuple(at), 0.02 * unit, facecolor="white", edgecolor=INK, zorder=4, gid=gid)
        )
        return
    if isinstance(b, SpatialRigidBody):
        spinning_disc(ax, g, b, at, r)
    elif isinstance(b, RigidBody):
        ax.add_patch(
            Circle(
                tuple(at), r, facecolor="#f2f2f2", edgecolor=INK, linewidth=1.4, zorder=4, gid=gid
            )
        )
        phi = g.number(b.angle)
        tip = at + r * np.array([math.cos(phi), math.sin(phi)])
        ax.plot(*np.array([at, tip]).T, color=INK, linewidth=1.2, zorder=5)
        ax.plot(*at, marker="o", markersize=2.5, color=INK, zorder=5)
    else:
        ax.add_patch(Circle(tuple(at), r, facecolor=INK, edgecolor=INK, zorder=4, gid=gid))
    mass = f"${sp.latex(b.mass)}$"
    place = g.hint.labels.get(b.name)
    if place:  # where the scene file puts it; the layout leaves it there
        beside(ax, unit, at, np.array([r, r]), place, mass, label_id(b.name))
        return
    # beside the disc, up and to the right; the layout moves it if something else is there
    put_text(ax, at + (r + 0.05 * unit) * np.array([0.8, 0.8]), mass, gid=label_id(b.name))


def euler_axes(g: Geometry, b: SpatialRigidBody, spin: bool = True) -> np.ndarray:
    """The body's principal axes 1, 2, 3 in space (columns) at the pose: R = R_z(φ) R_x(θ) R_z(ψ),
    the Z-X-Z convention the body's T is derived in (without the spin ψ: the line of nodes,
    where ψ is measured from, is axis 1)."""
    phi, theta, psi = (g.number(a) for a in b.angles)
    psi = psi if spin else 0.0

    def about_z(a: float) -> np.ndarray:
        return np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])

    c, s = math.cos(theta), math.sin(theta)
    about_x = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    return about_z(phi) @ about_x @ about_z(psi)


def spinning_disc(ax: Any, g: Geometry, b: SpatialRigidBody, at: np.ndarray, r: float) -> None:
    """A rigid body in space as a disc about its axis 3 (a top's or a gyroscope's wheel), drawn
    in perspective around its centre of mass, with the axis through it and a radius along its
    axis 1, which turns with the spin angle ψ."""
    from matplotlib.patches import Polygon

    axes = euler_axes(g, b)

    def projected(vec: np.ndarray) -> np.ndarray:  # the view is linear: project differences
        return np.array([float(c) for c in g.project([float(v) for v in vec])])

    rim = [
        at + projected(r * (math.cos(a) * axes[:, 0] + math.sin(a) * axes[:, 1]))
        for a in np.linspace(0, 2 * math.pi, 73)
    ]
    ax.add_patch(
        Polygon(rim, closed=True, facecolor="#f2f2f2", edgecolor=INK, linewidth=1.4, zorder=4)
    )
    axis = projected(1.25 * r * axes[:, 2])
    ax.plot(*np.array([at - axis, at + axis]).T, color=INK, linewidth=1.0, zorder=5)
    mark = at + projected(r * axes[:, 0])
    ax.plot(*np.array([at, mark]).T, color=INK, linewidth=1.2, zorder=5)
    ax.plot(*at, marker="o", markersize=2.5, color=INK, zorder=5)
    # the spin: an arc in the disc from the line of nodes to the mark, named like its coordinate
    spin = as_expr(b.angles[2])
    if spin.is_Symbol and any(j.q == spin for j in g.jets):
        nodes = euler_axes(g, b, spin=False)
        psi = g.number(spin)
        arc = [
            at + projected(0.6 * r * (math.cos(a) * nodes[:, 0] + math.sin(a) * nodes[:, 1]))
            for a in np.linspace(0.0, psi, 24)
        ]
        line = np.array([at, at + projected(r * nodes[:, 0])])
        ax.plot(*line.T, color=ACCENT, linewidth=0.8, linestyle="--", zorder=5)
        arc_arrow(ax, np.array(arc), "")
        middle = at + projected(
            0.8 * r * (math.cos(psi / 2) * nodes[:, 0] + math.sin(psi / 2) * nodes[:, 1])
        )
        put_text(ax, middle, f"${name_latex(spin.name)}$", color=ACCENT)


def axes3d(ax: Any, unit: float, g: Geometry) -> None:
    origin = np.zeros(2)
    for name, vec in (("x", (1, 0, 0)), ("y", (0, 1, 0)), ("z", (0, 0, 1))):
        tip = np.array([float(c) for c in g.project(vec)]) * 0.25 * unit
        ax.annotate(
            "",
            xy=tip,
            xytext=origin,
            arrowprops=dict(
                arrowstyle="-|>", color=GREY, linewidth=0.8, shrinkA=0, shrinkB=0, mutation_scale=8
            ),
        )
        put_text(ax, tip * 1.18, f"${name}$", color=GREY_TEXT)
