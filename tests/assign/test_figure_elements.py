"""Figures hold up for every scene and every presentation: each body, and each spring, rope,
pulley, wall, surface, rod or bar the statement names, is drawn; everything is inside the frame;
no label sits on another label or on a body. Measured on the laid-out matplotlib artists."""

from __future__ import annotations

import itertools
import re

import numpy as np
import pytest

from lagrade.assign.figures import compose
from lagrade.assign.figures.layout import drawn, extent, labels
from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics.bodies import RigidBody
from lagrade.mechanics.scene import SceneVariant

#: What a statement's noun obliges the figure to draw (any of these element kinds). A table
#: seen from above (the two pucks, the rotating frame) is the page itself, so it is not here.
NOUNS = {
    "spring": {"spring"},
    "dashpot": {"dashpot"},
    "string": {"rope"},
    "rope": {"rope"},
    "pulley": {"pulley"},
    "wall": {"wall"},
    "floor": {"surface", "track"},
    "incline": {"surface", "track"},
    "track": {"track", "surface"},
    "hoop": {"track"},
    "cone": {"track", "surface"},
    "rod": {"rod", "track"},
    "ladder": {"bar"},
}


def presentations(scene_id: str) -> list[SceneVariant]:
    """Every option combination, and every name a coordinate can take (cycled alongside)."""
    scene = get_scene(scene_id)
    keys = sorted(scene.options)
    combos = list(itertools.product(*(scene.options[k] for k in keys))) or [()]
    longest = max((len(c) for c in scene.renames.values()), default=1)
    out = []
    for i in range(max(len(combos), longest)):
        names = {c: choices[i % len(choices)] for c, choices in scene.renames.items()}
        options = dict(zip(keys, combos[i % len(combos)], strict=True))
        out.append(SceneVariant(scene, names=names, options=options))
    return out


CASES = [
    pytest.param(v, id=f"{sid}-{i}")
    for sid in scene_ids()
    for i, v in enumerate(presentations(sid))
]


@pytest.fixture(scope="module")
def composed():
    cache: dict = {}

    def get(variant: SceneVariant):
        key = id(variant)
        if key not in cache:
            cache[key] = compose(variant)
        return cache[key]

    yield get
    for c in cache.values():
        c.figure.clear()


@pytest.mark.parametrize("variant", CASES)
def test_every_body_and_named_fixture_is_drawn(variant: SceneVariant, composed) -> None:
    figure = composed(variant)
    drawn_kinds = {e.kind for e in figure.elements if e.artists}
    bodies = {e.name for e in figure.elements if e.kind in ("body", "bar") and e.artists}
    assert {b.name for b in variant.bodies} <= bodies
    words = set(re.findall(r"[a-z]+", variant.statement().lower()))
    missing = {
        noun: kinds for noun, kinds in NOUNS.items() if noun in words and not kinds & drawn_kinds
    }
    assert missing == {}, f"the statement names {sorted(missing)} but the figure draws none"
    declared = variant.figure.fixtures(variant.namespace)
    for f in declared:
        assert any(e.kind == f.kind and e.artists for e in figure.elements), f.kind
    marked = {e.name for e in figure.elements if e.kind in ("mark", "rod") and e.artists}
    canonical = dict(zip(variant.coordinates, variant.scene.coordinates, strict=True))
    for name in variant.coordinates:
        assert name in marked or canonical[name] in marked, f"coordinate {name} is not marked"


@pytest.mark.parametrize("variant", CASES)
def test_everything_is_inside_the_frame(variant: SceneVariant, composed) -> None:
    figure = composed(variant)
    renderer = figure.figure.canvas.get_renderer()
    frame = figure.figure.bbox
    outside = []
    for artist in drawn(figure.axes):
        box = extent(artist, renderer)
        if box.width + box.height == 0:
            continue
        if (
            box.x0 < frame.x0 - 1
            or box.y0 < frame.y0 - 1
            or box.x1 > frame.x1 + 1
            or box.y1 > frame.y1 + 1
        ):
            outside.append(
                (type(artist).__name__, getattr(artist, "get_text", lambda: "")(), box.bounds)
            )
    assert outside == []


@pytest.mark.parametrize("variant", CASES)
def test_no_label_overlaps_a_label_or_a_body(variant: SceneVariant, composed) -> None:
    from matplotlib.patches import Circle

    figure = composed(variant)
    renderer = figure.figure.canvas.get_renderer()
    texts = [(t.get_text(), t.get_window_extent(renderer)) for t in labels(figure.axes)]
    clashes = [
        (a, b)
        for (a, box_a), (b, box_b) in itertools.combinations(texts, 2)
        if box_a.overlaps(box_b)
    ]
    discs = [
        a.get_window_extent(renderer)
        for e in figure.elements
        if e.kind == "body"
        for a in e.artists
        if isinstance(a, Circle)
    ]
    clashes += [(t, "a body") for t, box in texts for d in discs if box.overlaps(d)]
    assert clashes == []


def _distance(point, a, b) -> float:
    ab, ap = b - a, point - a
    t = min(1.0, max(0.0, float(ab @ ap) / float(ab @ ab or 1.0)))
    return float(np.hypot(*(ap - t * ab)))


@pytest.mark.parametrize("variant", CASES)
def test_no_wall_or_surface_cuts_through_a_body(variant: SceneVariant, composed) -> None:
    """A body rests on a surface or against a wall; it never lies across one (the old rolling
    cylinder's incline, traced through its centre, ran through its middle). A point mass may ride
    a track drawn through it, as a bead on a wire; a rigid body has a size and may not."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon

    figure = composed(variant)
    rigid = {b.name for b in variant.bodies if isinstance(b, RigidBody)}
    discs = [
        (np.array(a.center), a.radius, e.name in rigid)
        for e in figure.elements
        if e.kind == "body"
        for a in e.artists
        if isinstance(a, Circle)
    ]
    cuts = []
    for e in figure.elements:
        if e.kind not in ("surface", "wall", "track"):
            continue
        for artist in e.artists:
            if isinstance(artist, Line2D):
                pts = np.asarray(artist.get_xydata(), dtype=float)
            elif isinstance(artist, Polygon):
                pts = np.asarray(artist.get_xy(), dtype=float)
            else:
                continue
            for centre, radius, sized in discs:
                if e.kind == "track" and not sized:
                    continue
                for a, b in zip(pts[:-1], pts[1:], strict=True):
                    if _distance(centre, a, b) < 0.97 * radius:
                        cuts.append((e.kind, e.name))
    assert cuts == []


def _segments(artist) -> list[tuple[np.ndarray, np.ndarray]]:
    pts = np.asarray(artist.get_xydata(), dtype=float)
    return list(zip(pts[:-1], pts[1:], strict=True))


def _straight(artist) -> bool:
    pts = np.asarray(artist.get_xydata(), dtype=float)
    if len(pts) <= 2:
        return True
    d = pts[-1] - pts[0]
    normal = np.array([-d[1], d[0]]) / max(float(np.hypot(*d)), 1e-12)
    return bool(np.all(np.abs((pts - pts[0]) @ normal) <= 1e-6 * max(np.ptp(pts), 1e-12)))


def _cross(p, q, r, s) -> bool:
    """Whether segments pq and rs cross properly (not merely touch at an end)."""

    def orient(a, b, c) -> float:
        return float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

    d1, d2, d3, d4 = orient(r, s, p), orient(r, s, q), orient(p, q, r), orient(p, q, s)
    scale = max(np.ptp(np.array([p, q, r, s]), axis=0).max(), 1e-12) ** 2
    eps = 1e-6 * scale
    return (d1 > eps and d2 < -eps or d1 < -eps and d2 > eps) and (
        d3 > eps and d4 < -eps or d3 < -eps and d4 > eps
    )


@pytest.mark.parametrize("variant", CASES)
def test_no_two_dimension_lines_cross(variant: SceneVariant, composed) -> None:
    """Length marks (x, y, z of a free particle; a hint's h) never cross one another: the old
    3-D figures measured x, y and z each up to the particle, three lines through one point."""
    from matplotlib.colors import to_hex
    from matplotlib.lines import Line2D

    from lagrade.assign.figures.style import ACCENT

    figure = composed(variant)
    lines = [
        (e.name, seg)
        for e in figure.elements
        if e.kind in ("mark", "dimension")
        for a in e.artists
        if isinstance(a, Line2D)
        and to_hex(a.get_color()) == to_hex(ACCENT)
        and a.get_linewidth() in (0.8, 1.0)  # a dimension line and its end ticks
        and _straight(a)  # not an angle's arc
        for seg in _segments(a)
    ]
    crossings = {
        (n1, n2)
        for (n1, s1), (n2, s2) in itertools.combinations(lines, 2)
        if n1 != n2 and _cross(*s1, *s2)
    }
    assert crossings == set()


@pytest.mark.parametrize("variant", CASES)
def test_at_most_one_pivot(variant: SceneVariant, composed) -> None:
    """A rod hangs from a pivot only where a fixed point holds it: the spherical pendulum's
    azimuth circle is centred on the axis below the pivot, and once drew a second pivot there."""
    from matplotlib.lines import Line2D

    figure = composed(variant)
    pivots = [
        a
        for e in figure.elements
        if e.kind == "rod"
        for a in e.artists
        if isinstance(a, Line2D)
        and a.get_linewidth() == 1.4
        and len(a.get_xydata()) == 2
        and a.get_xydata()[0][1] == a.get_xydata()[1][1]
    ]
    assert len(pivots) <= 1, [tuple(p.get_xydata()[0]) for p in pivots]


def _ink(figure, renderer) -> list[tuple[str, np.ndarray]]:
    """Every line, outline and arrow of the figure as (what, polyline in pixels): measured here
    from the artists themselves (not the layout's own list)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    out = []
    for e in figure.elements:
        for a in e.artists:
            arrow = getattr(a, "arrow_patch", None)
            if arrow is not None:
                a.update_positions(renderer)
                path = arrow.get_transform().transform_path(arrow.get_path())
                out += [
                    (f"{e.kind} {e.name} arrow", p) for p in path.to_polygons(closed_only=False)
                ]
            elif isinstance(a, Line2D):
                out.append((f"{e.kind} {e.name} line", a.get_transform().transform(a.get_xydata())))
            elif isinstance(a, Patch):
                path = a.get_transform().transform_path(a.get_path())
                out += [
                    (f"{e.kind} {e.name} outline", p) for p in path.to_polygons(closed_only=False)
                ]
    return out


def _through(box, polyline: np.ndarray) -> bool:
    """Whether the polyline enters the box: a vertex inside, or a piece crossing an edge."""
    pts = np.asarray(polyline, dtype=float)
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    x0, y0, x1, y1 = box.x0, box.y0, box.x1, box.y1
    if np.any((pts[:, 0] > x0) & (pts[:, 0] < x1) & (pts[:, 1] > y0) & (pts[:, 1] < y1)):
        return True
    corners = [np.array(c) for c in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    edges = list(zip(corners, corners[1:] + corners[:1], strict=True))
    return any(_cross(p, q, r, s) for p, q in zip(pts[:-1], pts[1:], strict=True) for r, s in edges)


@pytest.mark.parametrize("variant", CASES)
def test_no_label_sits_on_a_line_or_an_arrow(variant: SceneVariant, composed) -> None:
    """A label is clear of every drawn line, outline and arrow: not a bead's m on the hoop's
    circle, not x_M struck through by its own dimension line, not M on an arrow's end."""
    figure = composed(variant)
    renderer = figure.figure.canvas.get_renderer()
    ink = _ink(figure, renderer)
    struck = [
        (t.get_text(), what)
        for t in labels(figure.axes)
        for what, line in ink
        if _through(t.get_window_extent(renderer), line)
    ]
    assert struck == []


@pytest.mark.parametrize("variant", presentations("wheel"), ids=lambda v: v.coordinates[0])
def test_a_turning_bodys_angle_is_measured_from_a_drawn_reference(variant, composed) -> None:
    """The wheel's angle: an arc from a dashed reference ray through the wheel's centre to its
    mark, not an arc measured from nothing."""
    from matplotlib.lines import Line2D

    figure = composed(variant)
    (mark,) = [e for e in figure.elements if e.kind == "mark" and e.name in variant.coordinates]
    centre = np.asarray([float(c) for c in variant.bodies[0].position[:2]])
    dashed = [
        a
        for a in mark.artists
        if isinstance(a, Line2D) and a.get_linestyle() != "-" and _straight(a)
    ]
    assert any(np.allclose(a.get_xydata()[0], centre, atol=1e-9) for a in dashed), [
        a.get_xydata()[0] for a in dashed
    ]


@pytest.mark.parametrize(
    "variant", presentations("charged_particle"), ids=lambda v: v.options["gauge"]
)
def test_a_magnetic_field_is_drawn_along_its_direction(variant, composed) -> None:
    """B along z: an arrow pointing up the page (z is drawn up), labelled B, in every gauge."""
    figure = composed(variant)
    (field,) = [e for e in figure.elements if e.kind == "field"]
    arrows = [a for a in field.artists if getattr(a, "arrow_patch", None) is not None]
    texts = [a.get_text() for a in field.artists if hasattr(a, "get_text") and a.get_text()]
    assert texts == ["$B$"] and len(arrows) == 1
    (x0, y0), (x1, y1) = np.asarray(arrows[0].xyann), np.asarray(arrows[0].xy)
    assert y1 - y0 > 0 and abs(x1 - x0) < 1e-9 * abs(y1 - y0) + 1e-12
