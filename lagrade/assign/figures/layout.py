"""The last step of a figure, done on the rendered artists rather than guessed from scene units:
move each label off the labels, bodies, lines and arrows around it, then widen the limits until
every artist is inside the frame, and repeat until nothing moves (a label is 12 pt whatever the
scene's size, so only the renderer knows where it ends)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

#: Pixels a label keeps from what it must not touch, and the rings it is tried on when moved.
_GAP = 2.0
_RINGS = tuple(range(4, 96, 4))
_DIRECTIONS = tuple((math.cos(a), math.sin(a)) for a in np.linspace(0, 2 * math.pi, 16, False))


def labels(ax: Any) -> list[Any]:
    """The texts that show something (arrow annotations carry an empty text)."""
    return [t for t in ax.texts if t.get_visible() and t.get_text().strip()]


def extent(artist: Any, renderer: Any) -> Any:
    """An artist's box on the canvas, unclipped; an annotation's is its arrow's."""
    patch = getattr(artist, "arrow_patch", None)
    if patch is not None and not artist.get_text().strip():
        artist.update_positions(renderer)  # the arrow's path is laid out only when drawn
        return patch.get_window_extent(renderer)
    return artist.get_window_extent(renderer)


def drawn(ax: Any) -> list[Any]:
    """Every artist on the axes that puts ink on the page."""
    return [a for a in (*ax.lines, *ax.patches, *ax.texts, *ax.collections) if a.get_visible()]


def ink_segments(ax: Any, renderer: Any) -> np.ndarray:
    """Every straight piece of ink that is not a label, as rows (x0, y0, x1, y1) in pixels:
    lines, the outlines of patches (curves flattened) and the arrows of annotations."""
    pieces = []
    for artist in drawn(ax):
        if hasattr(artist, "get_text"):
            patch = getattr(artist, "arrow_patch", None)
            if patch is None:
                continue  # a label: kept apart by its box
            artist.update_positions(renderer)
            artist = patch
        if hasattr(artist, "get_xydata"):  # Line2D
            polylines = [artist.get_transform().transform(artist.get_xydata())]
        elif hasattr(artist, "get_path"):  # a patch or an arrow
            path = artist.get_transform().transform_path(artist.get_path())
            polylines = path.to_polygons(closed_only=False)
        else:
            continue
        for pts in polylines:
            pts = np.asarray(pts, dtype=float)
            if len(pts) >= 2:
                pieces.append(np.hstack([pts[:-1], pts[1:]]))
    rows = np.vstack(pieces) if pieces else np.zeros((0, 4))
    return rows[np.all(np.isfinite(rows), axis=1)]


def crosses(box: Any, segments: np.ndarray) -> bool:
    """Whether any segment (rows x0, y0, x1, y1) passes through `box` (Liang–Barsky clipping)."""
    if not len(segments):
        return False
    start, step = segments[:, :2], segments[:, 2:] - segments[:, :2]
    t0, t1 = np.zeros(len(segments)), np.ones(len(segments))
    for k, (lo, hi) in enumerate(((box.x0, box.x1), (box.y0, box.y1))):
        p, d = start[:, k], step[:, k]
        with np.errstate(divide="ignore", invalid="ignore"):
            a, b = (lo - p) / d, (hi - p) / d
        flat = d == 0
        inside = (p >= lo) & (p <= hi)
        t0 = np.maximum(t0, np.where(flat, np.where(inside, -np.inf, np.inf), np.minimum(a, b)))
        t1 = np.minimum(t1, np.where(flat, np.where(inside, np.inf, -np.inf), np.maximum(a, b)))
    return bool(np.any(t0 <= t1))


def _free(box: Any, taken: Iterable[Any], frame: Any, ink: np.ndarray) -> bool:
    inside = box.x0 >= frame.x0 and box.y0 >= frame.y0 and box.x1 <= frame.x1 and box.y1 <= frame.y1
    return inside and not any(box.overlaps(t) for t in taken) and not crosses(box, ink)


def _toward(way: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    """The directions within 45° of `way`, straight on first: a placed label that moves stays
    on the side of its body it was put."""
    near = [d for d in _DIRECTIONS if d[0] * way[0] + d[1] * way[1] > math.cos(math.radians(46))]
    return tuple(sorted(near, key=lambda d: -(d[0] * way[0] + d[1] * way[1])))


def _declutter(
    ax: Any, renderer: Any, obstacles: Sequence[Any], placed: Mapping[Any, tuple[float, float]]
) -> bool:
    """Move each label to the nearest place clear of the labels settled before it, the bodies
    and every drawn line and arrow; True when one moved. The labels the scene file placed go
    first, and move only away from their body (within 45° of straight on, so still on the side
    asked for); the others follow in drawing order, in any direction."""
    frame = ax.get_window_extent(renderer)
    taken = [o.get_window_extent(renderer).padded(_GAP) for o in obstacles]
    ink = ink_segments(ax, renderer)
    moved = False
    first = [t for t in labels(ax) if t in placed]
    for text in (*first, *(t for t in labels(ax) if t not in placed)):
        directions = _toward(placed[text]) if text in placed else _DIRECTIONS
        box = text.get_window_extent(renderer).padded(_GAP)
        if not _free(box, taken, frame, ink):
            for ring in _RINGS:
                shift = next(
                    (
                        (ring * dx, ring * dy)
                        for dx, dy in directions
                        if _free(box.translated(ring * dx, ring * dy), taken, frame, ink)
                    ),
                    None,
                )
                if shift is not None:
                    x, y = ax.transData.transform(text.get_position())
                    text.set_position(
                        ax.transData.inverted().transform((x + shift[0], y + shift[1]))
                    )
                    box = box.translated(*shift)
                    moved = True
                    break
        taken.append(box)
    return moved


def _fit(ax: Any, renderer: Any) -> bool:
    """Widen the limits so that every artist is inside the axes' box; True when they grew."""
    ax.apply_aspect()
    frame = ax.get_window_extent(renderer).padded(-3)
    boxes = [extent(a, renderer) for a in drawn(ax)]
    boxes = [b for b in boxes if np.all(np.isfinite(b.get_points())) and b.width + b.height > 0]
    x0 = min(b.x0 for b in boxes)
    y0 = min(b.y0 for b in boxes)
    x1 = max(b.x1 for b in boxes)
    y1 = max(b.y1 for b in boxes)
    if x0 >= frame.x0 and y0 >= frame.y0 and x1 <= frame.x1 and y1 <= frame.y1:
        return False
    to_data = ax.transData.inverted()
    (dx0, dy0), (dx1, dy1) = to_data.transform([(x0, y0), (x1, y1)])
    (lx0, lx1), (ly0, ly1) = ax.get_xlim(), ax.get_ylim()
    pad = 0.04 * max(lx1 - lx0, ly1 - ly0)
    ax.set_xlim(min(lx0, dx0 - pad), max(lx1, dx1 + pad))
    ax.set_ylim(min(ly0, dy0 - pad), max(ly1, dy1 + pad))
    ax.apply_aspect()
    return True


def settle(
    fig: Any,
    ax: Any,
    obstacles: Sequence[Any],
    placed: Mapping[Any, tuple[float, float]] | None = None,
    rounds: int = 8,
) -> None:
    """Declutter and fit in turns until neither changes anything. `placed` maps each label the
    scene file placed to its direction from its body, the one way it may move."""
    placed = placed or {}
    renderer = fig.canvas.get_renderer()
    ax.apply_aspect()
    for _ in range(rounds):
        moved = _declutter(ax, renderer, obstacles, placed)
        grew = _fit(ax, renderer)
        if not moved and not grew:
            return
