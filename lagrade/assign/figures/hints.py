"""What a scene's geometry cannot tell the figure (the wedge is a triangle, the hoop has no rod,
the oscillators hang between walls on springs), given per scene in `HINTS`.

Geometry draws what moves; a hint declares what does not show in the positions: springs, ropes,
pulleys, walls, surfaces, supports and bars. `FIXTURE_KINDS` is the list, and the figure test
holds every scene to it: what a scene's statement names (a spring, a wall, a pulley) must be
declared here and drawn.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

import sympy as sp

Point = tuple[Any, ...]
#: A fixture's point: coordinates in the scene's symbols, or the name of a body (its position).
Anchor = Point | str

#: What a fixture can be. A wall and a surface are hatched on their `side`; a bar stands for a
#: rigid body (the ladder) and replaces its disc; a support is a fixed, hatched pivot.
FIXTURE_KINDS = ("spring", "rope", "pulley", "wall", "surface", "support", "bar")


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
    sweep.
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


def _tilt(s: SimpleNamespace) -> Any:
    """The ladder's tilt from the wall, whichever angle the variant names."""
    return s.theta if s.opt["angle_from"] == "wall" else sp.pi / 2 - s.theta


def _ladder_ends(s: SimpleNamespace) -> tuple[Point, Point]:
    """(foot, top) of the ladder: on the floor y = 0 and against the wall x = 0."""
    return (s.l * sp.sin(_tilt(s)), 0), (0, s.l * sp.cos(_tilt(s)))


def _ladder_angle(s: SimpleNamespace) -> tuple[Point, Point, Point]:
    """θ at the top, from the wall down to the ladder; or at the foot, from the floor up."""
    foot, top = _ladder_ends(s)
    if s.opt["angle_from"] == "wall":
        return top, (0, 0), foot
    return foot, (0, 0), top


def _along_incline(s: SimpleNamespace, d: Any) -> Point:
    """The point a distance d down the rolling cylinder's incline (it descends towards +x)."""
    return (d * sp.cos(s.alpha), -d * sp.sin(s.alpha))


def _oscillator(s: SimpleNamespace) -> Sequence[Fixture]:
    """A horizontal spring from a wall on a table, or a vertical one from the ceiling."""
    if s.opt["orientation"] == "horizontal":
        return (
            Fixture("wall", lambda s: [(-1.2, -0.1), (-1.2, 0.35)], side=1),
            Fixture("surface", lambda s: [(-1.2, -0.1), (1.0, -0.1)], side=-1),
            Fixture("spring", lambda s: [(-1.2, 0), "mass"], label="k"),
        )
    return (
        Fixture("surface", lambda s: [(-0.3, 1.2), (0.3, 1.2)], side=1),
        Fixture("spring", lambda s: [(0, 1.2), "mass"], label="k"),
    )


def _cone(s: SimpleNamespace) -> Sequence[Fixture]:
    """The cone's outline in the x-z plane: two generatrices from the vertex, hatched outside."""
    reach, height = 1.5 * s.r, 1.5 * s.r / sp.tan(s.alpha)
    return (
        Fixture("surface", lambda s: [(0, 0, 0), (reach, 0, height)], side=-1),
        Fixture("surface", lambda s: [(0, 0, 0), (-reach, 0, height)], side=1),
    )


HINTS: dict[str, FigureHint] = {
    # r is the distance from the axis, measured level with the particle, not along the cone
    "cone_particle": FigureHint(
        fixtures=_cone,
        sweeps={"r": "none"},
        spans={"r": lambda s: ((0, 0, s.r / sp.tan(s.alpha)), "particle")},
    ),
    "wedge": FigureHint(
        ranges={
            "q": lambda s: (0, s.h / sp.sin(s.alpha)),
            "x_M": lambda s: (-0.4 * s.h, s.x_M + s.h / sp.tan(s.alpha) + 0.6 * s.h),
        },
        shapes={"wedge": lambda s: [(s.x_M, 0), (s.x_M, s.h), (s.x_M + s.h / sp.tan(s.alpha), 0)]},
        dimensions=(("h", lambda s: ((s.x_M, 0), (s.x_M, s.h))),),
    ),
    "hoop": FigureHint(solid=frozenset({"theta"}), rods=False),
    # the pucks well apart, away from the origin, so that X, Y, r and θ each have room
    "two_body_spring": FigureHint(
        poses={
            "X": lambda s: 4 * s.l_0,
            "Y": lambda s: 2.5 * s.l_0,
            "r": lambda s: 3 * s.l_0,
            "theta": lambda s: 0.5,
        },
        fixtures=lambda s: (Fixture("spring", lambda s: ["mass1", "mass2"], label="k"),),
        spans={"r": lambda s: ("mass1", "mass2")},
    ),
    "sliding_ladder": FigureHint(
        fixtures=lambda s: (
            Fixture("wall", lambda s: [(0, 0), (0, 1.15 * s.l)], side=1),
            Fixture("surface", lambda s: [(0, 0), (1.15 * s.l, 0)], side=-1),
            Fixture("bar", _ladder_ends, body="ladder", label="l"),
        ),
        angles={"theta": _ladder_angle},
    ),
    "rolling_cylinder": FigureHint(
        fixtures=lambda s: (
            Fixture(
                "surface",
                lambda s: [_along_incline(s, -3 * s.R), _along_incline(s, s.s + 4 * s.R)],
                side=-1,
                angle="alpha",
            ),
        ),
        poses={"s": lambda s: 1.5 * s.R},
        sweeps={"s": "none"},
        radii={"cylinder": lambda s: s.R},
    ),
    "atwood": FigureHint(
        fixtures=lambda s: (
            Fixture("pulley", lambda s: [(0, 0)], radius=lambda s: s.R),
            Fixture("rope", lambda s: [(-s.R, 0), "mass1"]),
            Fixture("rope", lambda s: [(s.R, 0), "mass2"]),
        ),
        poses={"x": lambda s: 1.5 * s.R},
        sweeps={"x": "none"},
        offsets={"mass1": lambda s: (0, -5 * s.R), "mass2": lambda s: (0, -5 * s.R)},
        radii={"pulley": lambda s: s.R},
    ),
    "coupled_oscillators": FigureHint(
        fixtures=lambda s: (
            Fixture("wall", lambda s: [(-s.a, -0.17 * s.a), (-s.a, 0.2 * s.a)], side=1),
            Fixture("wall", lambda s: [(2 * s.a, -0.17 * s.a), (2 * s.a, 0.2 * s.a)], side=-1),
            Fixture("surface", lambda s: [(-s.a, -0.17 * s.a), (2 * s.a, -0.17 * s.a)], side=-1),
            Fixture("spring", lambda s: [(-s.a, 0), "block1"], label="k"),
            Fixture("spring", lambda s: ["block1", "block2"], label="k_c"),
            Fixture("spring", lambda s: ["block2", (2 * s.a, 0)], label="k"),
        ),
        poses={"x_1": lambda s: 0.2 * s.a, "x_2": lambda s: 0.25 * s.a},
        sweeps={"x_1": "none", "x_2": "none"},
    ),
    "harmonic_oscillator": FigureHint(fixtures=_oscillator, sweeps={"x": "none"}),
    "spring_pendulum": FigureHint(
        fixtures=lambda s: (
            Fixture("support", lambda s: [(0, 0)]),
            Fixture("spring", lambda s: [(0, 0), "bob"], label="k"),
        ),
        poses={"r": lambda s: 1.6 * s.l_0},
        rods=False,
        spokes=False,
    ),
}
