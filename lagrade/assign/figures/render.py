"""The public entry of the figures: `draw` lays a scene variant out, scales it to its extent and
renders it to SVG and PDF bytes, the same bytes on every run."""

from __future__ import annotations

import io
from dataclasses import dataclass

import numpy as np

from lagrade.assign.figures.geometry import Geometry
from lagrade.assign.figures.hints import HINTS, FigureHint
from lagrade.assign.figures.plan import plan
from lagrade.assign.figures.style import RC, TRACE_STYLE
from lagrade.errors import LagradeError
from lagrade.mechanics.scene import SceneVariant


class FigureError(LagradeError):
    """A scene whose figure cannot be drawn (its positions do not evaluate to numbers)."""


@dataclass(frozen=True)
class Figure:
    """A drawn figure in both formats."""

    svg: bytes
    pdf: bytes


def draw(variant: SceneVariant) -> Figure:
    """The figure of `variant`, as SVG and PDF bytes (deterministic)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure as MplFigure

    hint = HINTS.get(variant.scene.id, FigureHint())
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
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_aspect("equal")
        ax.axis("off")
        for pts, style in drawing.traces:
            ax.plot(*pts.T, **TRACE_STYLE[style])
        for op in drawing.ops:
            op(ax, unit)
        margin = 0.2 * unit
        ax.set_xlim(lo[0] - margin, hi[0] + margin)
        ax.set_ylim(lo[1] - margin, hi[1] + margin)
        svg, pdf = io.BytesIO(), io.BytesIO()
        fig.savefig(svg, format="svg", metadata={"Date": None})
        fig.savefig(pdf, format="pdf", metadata={"CreationDate": None, "ModDate": None})
    return Figure(svg.getvalue(), pdf.getvalue())
