"""What a scene's geometry cannot tell its figure (the wedge is a triangle, the hoop has no rod,
the oscillators hang between walls on springs): the `FigureHint` a scene declares beside its
bodies (a scene file's `[figure]` table), read by `lagrade.assign.figures`.

Geometry draws what moves; a hint declares what does not show in the positions: springs, ropes,
pulleys, walls, surfaces, supports, bars and dashpots. `FIXTURE_KINDS` is the list, and the
figure test holds every scene to it: what a scene's statement names (a spring, a wall, a
pulley) must be declared and drawn. The hint's expressions are the scene's own, in its
canonical names, given as functions of the variant's namespace `s` (as a scene's bodies are).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

Point = tuple[Any, ...]
#: A fixture's point: coordinates in the scene's symbols, or the name of a body (its position).
Anchor = Point | str

#: What a fixture can be. A wall and a surface are hatched on their `side`; a bar stands for a
#: rigid body (the ladder) and replaces its disc; a support is a fixed, hatched pivot; a
#: dashpot (a damper: a cylinder and its piston) draws a Rayleigh function's damping.
FIXTURE_KINDS = ("spring", "rope", "pulley", "wall", "surface", "support", "bar", "dashpot")
#: Where a body's mass label can be placed, beside the body; without a place the layout puts
#: it up and to the right, and moves it off whatever is there.
LABEL_PLACES = ("above", "below", "left", "right")


@dataclass(frozen=True)
class Fixture:
    """One thing that is not a moving body. `points(s)` gives its anchors in the scene's canonical
    names: the two ends of a spring, wall, surface or bar, a rope's polyline, a pulley's or a
    support's centre. `radius(s)` sizes a pulley; `label` is a parameter drawn beside it (a
    spring's k); `side` (+1/−1) is the side of a→b that a wall or surface is hatched on;
    `body` is the rigid body a bar stands for; `angle` a parameter marked where a surface meets
    the horizontal (an incline's α)."""

    kind: str
    points: Callable[[SimpleNamespace], Sequence[Anchor]]
    radius: Callable[[SimpleNamespace], Any] | None = None
    label: str = ""
    side: int = 1
    body: str = ""
    angle: str = ""

    def __post_init__(self) -> None:
        assert self.kind in FIXTURE_KINDS, f"unknown fixture kind {self.kind!r}"


@dataclass(frozen=True)
class FigureHint:
    """What a scene's geometry does not say, in the scene's canonical names (`s.x_M`, `s.h`).

    poses: coordinate → value to draw it at; ranges: coordinate → (low, high) of its sweep;
    shapes: body → polygon drawn instead of a disc; dimensions: (parameter, (A, B)) dimension
    lines; solid: coordinates whose angle sweeps are surfaces (the hoop), not paths; rods: whether
    circular paths hang from rods; spokes: whether, without a rod, a thin radius is drawn to the
    body; t: the time drawn. fixtures: springs, ropes, walls and the like; sweeps: coordinate →
    "none" when its sweep is not drawn (a fixture shows the track); offsets: body → a shift of
    its drawing (the Atwood masses hang below their pulley, where the scene's reference level,
    at the axle, would put them beside it; V changes only by a constant); angles: coordinate →
    (vertex, A, B), an angle marked at the vertex from ray A to ray B instead of the automatic
    mark; radii: rigid body → its drawn radius (a cylinder's R); spans: coordinate → (A, B), a
    length measured between two anchors (the distance between the pucks), not along one body's
    sweep; labels: body → where its mass label sits (one of LABEL_PLACES), kept there by the
    layout.
    """

    poses: Mapping[str, Callable[[SimpleNamespace], Any]] = field(default_factory=dict)
    ranges: Mapping[str, Callable[[SimpleNamespace], tuple[Any, Any]]] = field(default_factory=dict)
    shapes: Mapping[str, Callable[[SimpleNamespace], Sequence[Point]]] = field(default_factory=dict)
    dimensions: Sequence[tuple[str, Callable[[SimpleNamespace], tuple[Point, Point]]]] = ()
    solid: frozenset[str] = frozenset()
    rods: bool = True
    spokes: bool = True
    t: float = 0.0
    fixtures: Callable[[SimpleNamespace], Sequence[Fixture]] = lambda s: ()
    sweeps: Mapping[str, str] = field(default_factory=dict)
    offsets: Mapping[str, Callable[[SimpleNamespace], Point]] = field(default_factory=dict)
    angles: Mapping[str, Callable[[SimpleNamespace], tuple[Point, Point, Point]]] = field(
        default_factory=dict
    )
    radii: Mapping[str, Callable[[SimpleNamespace], Any]] = field(default_factory=dict)
    spans: Mapping[str, Callable[[SimpleNamespace], tuple[Anchor, Anchor]]] = field(
        default_factory=dict
    )
    labels: Mapping[str, str] = field(default_factory=dict)
