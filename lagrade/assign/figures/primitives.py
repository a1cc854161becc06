"""Drawing primitives on a matplotlib axes, in scene units: labels, dimension lines, arrows along
a path, pivots, angle marks and the gravity arrow. They know nothing of scenes or coordinates;
`unit` is the figure's extent, so sizes scale with the drawing."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from lagrade.assign.figures.style import ACCENT, GREY, INK


def put_text(
    ax: Any,
    at: np.ndarray,
    text: str,
    color: str = INK,
    zorder: int = 7,
    align: tuple[str, str] = ("center", "center"),
    gid: str | None = None,
) -> Any:
    return ax.text(
        float(at[0]),
        float(at[1]),
        text,
        ha=align[0],
        va=align[1],
        color=color,
        fontsize=12,
        zorder=zorder,
        gid=gid,
    )


#: A placed label's direction from what it labels, and the alignment that puts its near edge
#: there (so a long label grows away from the body, not over it).
PLACES = {
    "above": ((0.0, 1.0), ("center", "bottom")),
    "below": ((0.0, -1.0), ("center", "top")),
    "left": ((-1.0, 0.0), ("right", "center")),
    "right": ((1.0, 0.0), ("left", "center")),
}


def label_id(body: str) -> str:
    """The SVG id of a body's mass label (the layout keeps a placed one where it was put)."""
    return f"label-{body}"


def beside(
    ax: Any, unit: float, centre: np.ndarray, reach: np.ndarray, place: str, text: str, gid: str
) -> Any:
    """A label on the `place` side of something centred at `centre` that reaches `reach`
    (half its width, half its height) from there, a small gap beyond its edge."""
    (dx, dy), align = PLACES[place]
    gap = 0.03 * unit
    at = centre + np.array([dx * (reach[0] + gap), dy * (reach[1] + gap)])
    return put_text(ax, at, text, align=align, gid=gid)


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


def dimension(
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
            color=ACCENT,
            linewidth=1.0,
            shrinkA=0,
            shrinkB=0,
            mutation_scale=9,
        ),
        zorder=5,
    )
    ax.plot(*pts.T, color=ACCENT, linewidth=1.0, zorder=5)
    for end in (a, b):
        tick = np.array([end + 0.03 * unit * n, end + 0.11 * unit * n])
        ax.plot(*tick.T, color=ACCENT, linewidth=0.8, zorder=5)
    put_text(ax, (a + b) / 2 + 0.16 * unit * n, label, color=ACCENT)


def along_label(
    ax: Any, a: np.ndarray, b: np.ndarray, label: str, unit: float, centre_of: np.ndarray | None
) -> None:
    n = _unit_normal(a, b)
    if n[1] < 0 or (abs(n[1]) < 1e-9 and n[0] < 0):
        n = -n
    put_text(ax, (a + b) / 2 + 0.07 * unit * n, label)


def arc_arrow(ax: Any, pts: np.ndarray, label: str) -> None:
    if len(pts) < 2 or np.hypot(*(pts[-1] - pts[0])) < 1e-12:
        return
    ax.plot(*pts.T, color=ACCENT, linewidth=1.0, zorder=5)
    ax.annotate(
        "",
        xy=pts[-1],
        xytext=pts[-2],
        arrowprops=dict(
            arrowstyle="-|>", color=ACCENT, linewidth=1.0, shrinkA=0, shrinkB=0, mutation_scale=9
        ),
        zorder=5,
    )


def arrow_along(ax: Any, pts: np.ndarray, label: str, unit: float) -> None:
    arc_arrow(ax, pts, label)
    put_text(ax, pts[len(pts) // 2] + np.array([0.0, 0.08 * unit]), label, color=ACCENT)


def pivot(ax: Any, at: np.ndarray, unit: float) -> None:
    w = 0.07 * unit
    ax.plot([at[0] - w, at[0] + w], [at[1], at[1]], color=INK, linewidth=1.4, zorder=3)
    for x in np.linspace(at[0] - w, at[0] + w, 5):
        ax.plot([x, x + 0.35 * w], [at[1], at[1] + 0.35 * w], color=INK, linewidth=0.7, zorder=3)


def incline_angle(ax: Any, unit: float, trace: np.ndarray, name: str) -> None:
    finite = trace[np.all(np.isfinite(trace), axis=1)]
    low = finite[np.argmin(finite[:, 1])]
    high = finite[np.argmax(finite[:, 1])]
    up = math.atan2(high[1] - low[1], high[0] - low[0])
    base = 0.0 if high[0] >= low[0] else math.pi
    r = 0.16 * unit
    angles = np.linspace(base, up, 30)
    pts = low + r * np.column_stack([np.cos(angles), np.sin(angles)])
    ax.plot(*pts.T, color=ACCENT, linewidth=1.0, zorder=5)
    mid = (base + up) / 2
    put_text(
        ax, low + 1.35 * r * np.array([math.cos(mid), math.sin(mid)]), f"${name}$", color=ACCENT
    )


def time_mark(
    ax: Any, unit: float, pts: np.ndarray, label: str, axis: tuple[np.ndarray, np.ndarray] | None
) -> None:
    k = 3 * len(pts) // 8
    ax.annotate(
        "",
        xy=pts[k + 4],
        xytext=pts[k],
        arrowprops=dict(
            arrowstyle="-|>", color=ACCENT, linewidth=1.0, shrinkA=0, shrinkB=0, mutation_scale=10
        ),
        zorder=5,
    )
    centre = pts.mean(axis=0)
    out = pts[k + 2] - centre
    out = out / (np.hypot(*out) or 1.0)
    put_text(ax, pts[k + 2] + 0.09 * unit * out, label, color=ACCENT)
    if axis is not None:
        c, n = axis
        ends = np.array([c - 0.55 * unit * n, c + 0.55 * unit * n])
        ax.plot(*ends.T, color=GREY, linewidth=0.8, linestyle=(0, (8, 3, 2, 3)), zorder=1)


def field_arrow(
    ax: Any, unit: float, points: list[np.ndarray], direction: np.ndarray, label: str
) -> None:
    """A uniform field beside the figure, on its left: an arrow along its direction on the
    page (a unit vector there), labelled with its name."""
    allpts = np.vstack(points)
    base = np.array([allpts[:, 0].min() - 0.2 * unit, allpts[:, 1].mean()])
    tip = base + 0.25 * unit * direction
    ax.annotate(
        "",
        xy=tip,
        xytext=base,
        arrowprops=dict(
            arrowstyle="-|>", color=INK, linewidth=1.2, shrinkA=0, shrinkB=0, mutation_scale=10
        ),
    )
    put_text(ax, (base + tip) / 2 + np.array([-0.08 * unit, 0.0]), label)


def gravity_arrow(ax: Any, unit: float, points: list[np.ndarray]) -> None:
    allpts = np.vstack(points)
    top = np.array([allpts[:, 0].max() + 0.12 * unit, allpts[:, 1].max()])
    ax.annotate(
        "",
        xy=top - np.array([0, 0.2 * unit]),
        xytext=top,
        arrowprops=dict(
            arrowstyle="-|>", color=INK, linewidth=1.2, shrinkA=0, shrinkB=0, mutation_scale=10
        ),
    )
    put_text(ax, top - np.array([-0.06 * unit, 0.1 * unit]), "$g$")
