"""A body's mass label where the scene file's `[figure]` table puts it (`labels = { bob =
"left" }`), read back from the drawn SVG: the body's outline (`<g id="body-bob">`) against the
label's origin (`<g id="label-bob">`, its left end on the baseline); the layout leaves a placed
label there and keeps the other labels off it. And the dashpot fixture the damped oscillator
draws for its Rayleigh function."""

from __future__ import annotations

import itertools
import pathlib
import re

import pytest

from lagrade.assign.figures import compose, draw
from lagrade.assign.figures.layout import crosses, ink_segments, labels, settle
from lagrade.bank.scenefile import scene_from_text
from lagrade.mechanics import LABEL_PLACES
from tests.scene_texts import PENDULUM

BLOCK = """\
title = "Block"
statement = "A block of mass M slides on a smooth floor. Use {x}."
coordinates = ["x"]
potential = "0"
constraints = ["y_block"]

[parameters]
M = { domain = "positive", unit = "kg", values = [1.0] }

[bodies.block]
mass = "M"
position = ["x", 0]

[figure]
shapes = { block = [["x - 0.2", 0], ["x + 0.2", 0], ["x + 0.2", 0.3], ["x - 0.2", 0.3]] }
"""

EXAMPLES = pathlib.Path(__file__).parents[2] / "examples" / "scenes"
#: The label is a 12 px letter: its width and its height above the baseline are below this.
GLYPH = 12.0


def _svg(text: str) -> str:
    return draw(scene_from_text(text, "placed").default).svg.decode()


def _body_box(svg: str, name: str) -> tuple[float, float, float, float]:
    """The body's outline in SVG pixels (x0, y0, x1, y1; y grows downward), from its path."""
    path = re.search(rf'<g id="body-{name}">\s*<path d="([^"]*)"', svg).group(1)
    numbers = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", path)]
    xs, ys = numbers[0::2], numbers[1::2]
    return min(xs), min(ys), max(xs), max(ys)


def _label_origin(svg: str, name: str) -> tuple[float, float]:
    """Where the label's text starts: its left end on its baseline."""
    found = re.search(rf'<g id="label-{name}">.*?translate\(([-\d.]+) ([-\d.]+)\)', svg, flags=re.S)
    return float(found.group(1)), float(found.group(2))


def _beside(place: str, box: tuple, origin: tuple) -> bool:
    """The whole label lies on `place`'s side of the box, and faces the box's middle."""
    x0, y0, x1, y1 = box
    x, y = origin
    middle_x, middle_y = (x0 + x1) / 2, (y0 + y1) / 2
    return {
        "above": y <= y0 and abs(x + GLYPH / 2 - middle_x) < GLYPH,
        "below": y - GLYPH >= y1 and abs(x + GLYPH / 2 - middle_x) < GLYPH,
        "left": x + GLYPH <= x0 and abs(y - GLYPH / 3 - middle_y) < GLYPH,
        "right": x >= x1 and abs(y - GLYPH / 3 - middle_y) < GLYPH,
    }[place]


@pytest.mark.parametrize("place", LABEL_PLACES)
def test_a_point_mass_label_is_drawn_where_the_file_places_it(place: str) -> None:
    svg = _svg(PENDULUM + f'\n[figure]\nlabels = {{ bob = "{place}" }}\n')
    box, origin = _body_box(svg, "bob"), _label_origin(svg, "bob")
    assert _beside(place, box, origin), (place, box, origin)
    others = [p for p in LABEL_PLACES if p != place]
    assert not any(_beside(p, box, origin) for p in others), (place, box, origin)


def test_the_default_label_is_up_and_to_the_right() -> None:
    svg = _svg(PENDULUM)
    (x0, y0, x1, _), (x, y) = _body_box(svg, "bob"), _label_origin(svg, "bob")
    assert x > (x0 + x1) / 2 and y <= y0


@pytest.mark.parametrize("place", LABEL_PLACES)
def test_a_shaped_body_label_is_placed_beside_its_outline(place: str) -> None:
    svg = _svg(BLOCK.replace("[figure]\n", f'[figure]\nlabels = {{ block = "{place}" }}\n'))
    box, origin = _body_box(svg, "block"), _label_origin(svg, "block")
    assert _beside(place, box, origin), (place, box, origin)


def test_a_shaped_body_label_is_inside_it_by_default() -> None:
    svg = _svg(BLOCK)
    (x0, y0, x1, y1), (x, y) = _body_box(svg, "block"), _label_origin(svg, "block")
    assert x0 < x < x1 and y0 < y < y1


def test_other_labels_keep_off_a_placed_label() -> None:
    """The damped oscillator's mass label put below the body, where the label of the dimension
    line x would be: it stays there, and x moves off it."""
    text = (EXAMPLES / "damped_oscillator.toml").read_text()
    text = text.replace('labels = { mass = "right" }', 'labels = { mass = "below" }')
    composed = compose(scene_from_text(text, "damped_oscillator").default)
    renderer = composed.figure.canvas.get_renderer()
    texts = {t.get_text(): t.get_window_extent(renderer) for t in labels(composed.axes)}
    assert {"$m$", "$x$"} <= set(texts)
    clashes = [
        (a, b) for (a, p), (b, q) in itertools.combinations(texts.items(), 2) if p.overlaps(q)
    ]
    assert clashes == []
    # put on the dimension line's end tick, it moved straight down, off every line
    assert not crosses(texts["$m$"], ink_segments(composed.axes, renderer))
    svg = draw(scene_from_text(text, "damped_oscillator").default).svg.decode()
    assert _beside("below", _body_box(svg, "mass"), _label_origin(svg, "mass"))


def test_the_damped_oscillator_draws_its_dashpot() -> None:
    text = (EXAMPLES / "damped_oscillator.toml").read_text()
    variant = scene_from_text(text, "damped_oscillator").default
    composed = compose(variant)
    kinds = {e.kind for e in composed.elements if e.artists}
    assert {"dashpot", "spring", "wall", "surface", "body"} <= kinds
    written = {t.get_text() for t in labels(composed.axes)}
    assert {"$b$", "$k$", "$m$"} <= written  # the dashpot's b beside it
    svg = draw(variant).svg.decode()
    assert _beside("right", _body_box(svg, "mass"), _label_origin(svg, "mass"))


def test_a_placed_label_moves_only_away_from_its_body() -> None:
    """A label put above a disc, under a stack of short lines: the nearest clear place is beside
    the stack, but a placed label moves only within 45° of straight up, so it goes over it."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle

    fig = Figure(figsize=(4, 4), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, 400)
    ax.set_ylim(0, 400)  # a data unit is a pixel
    ax.axis("off")
    disc = ax.add_patch(Circle((200, 150), 10))
    text = ax.text(200, 163, "$m$", ha="center", va="bottom", fontsize=12)
    for y in range(160, 200, 4):
        ax.plot([185, 215], [y, y], color="k")
    settle(fig, ax, [disc], {text: (0.0, 1.0)})
    x, y = text.get_position()
    assert y > 163 and abs(x - 200) <= y - 163, (x, y)
