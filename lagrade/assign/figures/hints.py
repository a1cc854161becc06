"""What a scene's geometry cannot tell the figure (the wedge is a triangle, the hoop has no rod),
given per scene in `HINTS`."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

import sympy as sp

Point = tuple[Any, ...]


@dataclass(frozen=True)
class FigureHint:
    """What a scene's geometry does not say, in the scene's canonical names (`s.x_M`, `s.h`).

    poses: coordinate → value to draw it at; ranges: coordinate → (low, high) of its sweep;
    shapes: body → polygon drawn instead of a disc; dimensions: (parameter, (A, B)) dimension
    lines; solid: coordinates whose angle sweeps are surfaces (the hoop), not paths; rods: whether
    circular paths hang from rods; t: the time drawn.
    """

    poses: Mapping[str, Callable[[SimpleNamespace], Any]] = field(default_factory=dict)
    ranges: Mapping[str, Callable[[SimpleNamespace], tuple[Any, Any]]] = field(default_factory=dict)
    shapes: Mapping[str, Callable[[SimpleNamespace], Sequence[Point]]] = field(default_factory=dict)
    dimensions: Sequence[tuple[str, Callable[[SimpleNamespace], tuple[Point, Point]]]] = ()
    solid: frozenset[str] = frozenset()
    rods: bool = True
    t: float = 0.0


HINTS: dict[str, FigureHint] = {
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
            "X": lambda s: 3 * s.l_0,
            "Y": lambda s: 2 * s.l_0,
            "r": lambda s: 2 * s.l_0,
            "theta": lambda s: 0.5,
        }
    ),
}
