"""The public entry of the figures: `compose` lays a scene variant out, scales it to its extent,
keeps its labels apart and inside the frame, and says which artists draw which element; `draw`
renders that to SVG and PDF bytes, the same bytes on every run."""

from __future__ import annotations

import io
from dataclasses import dataclass
from typing import Any

import numpy as np

from lagrade.assign.figures.geometry import Geometry
from lagrade.assign.figures.layout import drawn, settle
from lagrade.assign.figures.plan import plan
from lagrade.assign.figures.primitives import PLACES, label_id
from lagrade.assign.figures.style import RC
from lagrade.errors import LagradeError
from lagrade.mechanics import SceneVariant


class FigureError(LagradeError):
    """A scene whose figure cannot be drawn (its positions do not evaluate to numbers)."""


@dataclass(frozen=True)
class Figure:
    """A drawn figure in both formats, and the labels written on it (as matplotlib's mathtext:
    `$x_{M}$`, `$\\alpha$`), for its text alternative."""

    svg: bytes
    pdf: bytes
    labels: tuple[str, ...] = ()


@dataclass(frozen=True)
class Element:
    """What one planned element put on the page: its kind (`body`, `spring`, `mark`, …), whose
    it is, and its matplotlib artists."""

    kind: str
    name: str
    artists: tuple[Any, ...]


@dataclass(frozen=True)
class Composed:
    """A laid-out figure, before it is saved: the matplotlib figure, its axes, its elements."""

    figure: Any
    axes: Any
    elements: tuple[Element, ...]


def compose(variant: SceneVariant) -> Composed:
    """The figure of `variant` laid out on a matplotlib figure, with its elements."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure as MplFigure
    from matplotlib.patches import Circle

    hint = variant.figure
    try:
        geometry = Geometry(variant, hint)
        drawing = plan(geometry)
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        raise FigureError(f"scene {variant.scene.id!r}: cannot draw its figure ({exc})") from exc
    allpts = np.vstack(drawing.points)
    lo, hi = allpts.min(axis=0), allpts.max(axis=0)
    unit = float(max(hi - lo))
    if unit < 1e-6 * geometry.scale:  # nothing moves in space (a wheel turning in place)
        unit = geometry.scale
        lo, hi = lo - 0.5 * unit, hi + 0.5 * unit
    with matplotlib.rc_context(RC):
        fig = MplFigure(figsize=(4.6, 3.6))
        FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_aspect("equal")
        ax.axis("off")
        elements = []
        for op in (*drawing.traces, *drawing.ops):
            before = set(map(id, drawn(ax)))
            op.draw(ax, unit)
            new = tuple(a for a in drawn(ax) if id(a) not in before)
            elements.append(Element(op.kind, op.name, new))
        margin = 0.12 * unit
        ax.set_xlim(lo[0] - margin, hi[0] + margin)
        ax.set_ylim(lo[1] - margin, hi[1] + margin)
        discs = [
            a
            for e in elements
            if e.kind in ("body", "pulley")
            for a in e.artists
            if isinstance(a, Circle)
        ]
        ways = {label_id(name): PLACES[place][0] for name, place in hint.labels.items()}
        settle(fig, ax, discs, {t: ways[t.get_gid()] for t in ax.texts if t.get_gid() in ways})
    return Composed(fig, ax, tuple(elements))


def draw(variant: SceneVariant) -> Figure:
    """The figure of `variant`, as SVG and PDF bytes (deterministic)."""
    import matplotlib

    composed = compose(variant)
    svg, pdf = io.BytesIO(), io.BytesIO()
    with matplotlib.rc_context(RC):
        composed.figure.savefig(svg, format="svg", metadata={"Date": None})
        composed.figure.savefig(pdf, format="pdf", metadata={"CreationDate": None, "ModDate": None})
    labels = tuple(t.get_text() for t in composed.axes.texts if t.get_text().strip())
    return Figure(svg.getvalue(), pdf.getvalue(), labels)
