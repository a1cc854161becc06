"""A scene file's `[figure]` table (and each option choice's own `figure` table): what the geometry
cannot tell the figure, read into a `FigureHint` for each presentation.

    [figure]
    poses = { r = "1.6 l_0" }                       # coordinate → where it is drawn
    ranges = { q = ["0", "h/sin(alpha)"] }          # coordinate → its sweep
    sweeps = { x = "none" }                         # coordinate → its sweep not drawn
    solid = ["theta"]                               # angle sweeps drawn as surfaces (a hoop)
    rods = false                                    # circular paths not hung from rods
    spokes = false                                  # …nor a thin radius drawn to the body
    shapes = { wedge = [["x_M", 0], ["x_M", "h"], ["x_M + h/tan(alpha)", 0]] }
    dimensions = { h = [["x_M", 0], ["x_M", "h"]] } # parameter → a dimension line
    offsets = { mass1 = [0, "-5 R"] }               # body → a shift of its drawing
    radii = { pulley = "R" }                        # rigid body → its drawn radius
    angles = { theta = [vertex, from, to] }         # coordinate → an angle marked there
    spans = { r = ["mass1", "mass2"] }              # coordinate → a length between two anchors
    labels = { bob = "left" }                       # body → where its mass label sits
    fixtures = [{ kind = "spring", points = [[-1.2, 0], "mass"], label = "k" }]

A point is a list of 2 (or, in a 3-D scene, 3) expressions; an anchor is a point or a body's
name (where the body is drawn). A choice's figure table adds to the scene's: its tables' entries
replace the scene's, its lists (fixtures, solid) follow the scene's, its rods/spokes/t replace.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import sympy as sp

from lagrade.bank.scenefile.declaration import Declaration
from lagrade.bank.scenefile.fields import Problems, expression
from lagrade.bank.scenefile.reading import Reader
from lagrade.mechanics import FIXTURE_KINDS, LABEL_PLACES, FigureHint, Fixture

FIGURE_KEYS = (
    "poses",
    "ranges",
    "sweeps",
    "solid",
    "rods",
    "spokes",
    "t",
    "shapes",
    "dimensions",
    "offsets",
    "radii",
    "angles",
    "spans",
    "labels",
    "fixtures",
)
FIXTURE_KEYS = ("kind", "points", "radius", "label", "side", "body", "angle")
_TABLES = (
    "poses",
    "ranges",
    "sweeps",
    "shapes",
    "dimensions",
    "offsets",
    "radii",
    "angles",
    "spans",
    "labels",
)
#: How many anchors each fixture kind takes (a rope is a polyline: two or more).
_ANCHORS = {
    "spring": 2, "dashpot": 2, "wall": 2, "surface": 2, "bar": 2, "pulley": 1, "support": 1,
}  # fmt: skip
MAX_FIXTURES = 64
MAX_POINTS = 64

Expr = sp.Expr
Point = tuple[Expr, ...]
Anchor = Point | str


@dataclass(frozen=True)
class _Fixture:
    kind: str
    anchors: tuple[Anchor, ...]
    radius: Expr | None
    label: str
    side: int
    body: str
    angle: str


class FigureReader:
    """Reads the scene's figure table and every choice's, reporting problems by key; `hint_for`
    gives the FigureHint of each presentation."""

    def __init__(self, d: Declaration, reader: Reader, problems: Problems):
        self.reader, self.problems = reader, problems
        self.coordinates = set(d.coordinates)
        self.parameters = {p.name for p in d.parameters}
        self.three_d = any(len(b.position) == 3 for b in d.bodies) or any(
            len(b.position) == 3 for cs in d.options.values() for c in cs for b in c.bodies
        )
        scene_bodies = {b.name for b in d.bodies}
        self.scene = self._read(d.figure, "figure", scene_bodies)
        self.choices = {
            option: {
                c.name: self._read(
                    c.figure, f"{c.key}.figure", scene_bodies | {b.name for b in c.bodies}
                )
                for c in choices
            }
            for option, choices in d.options.items()
        }

    # --- reading ------------------------------------------------------------------------------
    def _read(self, table: Mapping[str, Any], key: str, bodies: set[str]) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for name in table:
            if name not in FIGURE_KEYS:
                self.problems.add(f"{key}.{name}", f"unknown key (known: {', '.join(FIGURE_KEYS)})")
        self.bodies = bodies
        for name in _TABLES:
            if name in table:
                out[name] = self._entries(table[name], f"{key}.{name}", name)
        for name in ("rods", "spokes"):
            if name in table:
                if isinstance(table[name], bool):
                    out[name] = table[name]
                else:
                    self.problems.add(f"{key}.{name}", "is not true or false")
        if "t" in table:
            value = table["t"]
            if isinstance(value, int | float) and not isinstance(value, bool):
                out["t"] = float(value)
            else:
                self.problems.add(f"{key}.t", "is not a number (the time drawn)")
        if "solid" in table:
            solid = table["solid"]
            if not isinstance(solid, list) or not all(c in self.coordinates for c in solid):
                self.problems.add(f"{key}.solid", "is not a list of coordinates")
            else:
                out["solid"] = list(solid)
        if "fixtures" in table:
            out["fixtures"] = self._fixtures(table["fixtures"], f"{key}.fixtures")
        return out

    def _entries(self, raw: Any, key: str, kind: str) -> dict[str, Any]:
        if not isinstance(raw, dict):
            self.problems.add(key, "is not a table")
            return {}
        owners = {
            "poses": "coordinate", "ranges": "coordinate", "sweeps": "coordinate",
            "angles": "coordinate", "spans": "coordinate", "shapes": "body", "offsets": "body",
            "radii": "body", "labels": "body", "dimensions": "parameter",
        }  # fmt: skip
        names = {
            "coordinate": self.coordinates,
            "body": self.bodies,
            "parameter": self.parameters,
        }[owners[kind]]
        found = {}
        for name, value in raw.items():
            at = f"{key}.{name}"
            if name not in names:
                self.problems.add(at, f"{name!r} is not a {owners[kind]} of the scene")
                continue
            read = self._entry(kind, value, at)
            if read is not None:
                found[name] = read
        return found

    def _entry(self, kind: str, value: Any, at: str) -> Any:
        if kind in ("poses", "radii"):
            return self._expr(value, at)
        if kind == "sweeps":
            if value != "none":
                self.problems.add(at, 'the only sweep setting is "none" (not drawn)')
                return None
            return value
        if kind == "ranges":
            return self._each(value, at, 2, 2, self._expr)
        if kind == "labels":
            if value not in LABEL_PLACES:
                places = ", ".join(LABEL_PLACES[:-1]) + f" or {LABEL_PLACES[-1]}"
                self.problems.add(at, f"{value!r} is not a place for a label ({places})")
                return None
            return value
        if kind in ("offsets",):
            return self._point(value, at)
        if kind == "shapes":
            return self._each(value, at, 3, MAX_POINTS, self._point)
        if kind == "dimensions":
            return self._each(value, at, 2, 2, self._point)
        if kind == "angles":
            return self._each(value, at, 3, 3, self._point)
        if kind == "spans":
            return self._each(value, at, 2, 2, self._anchor)
        raise AssertionError(kind)

    def _fixtures(self, raw: Any, key: str) -> list[_Fixture]:
        items = self._list(raw, key, 0, MAX_FIXTURES)
        found = []
        for i, item in enumerate(items or [], 1):
            at = f"{key}[{i}]"
            if not isinstance(item, dict):
                self.problems.add(at, 'is not a table such as { kind = "spring", points = [...] }')
                continue
            for name in item:
                if name not in FIXTURE_KEYS:
                    self.problems.add(
                        f"{at}.{name}", f"unknown key (known: {', '.join(FIXTURE_KEYS)})"
                    )
            kind = item.get("kind")
            if kind not in FIXTURE_KINDS:
                self.problems.add(
                    f"{at}.kind", f"{kind!r} is not one of {', '.join(FIXTURE_KINDS)}"
                )
                continue
            count = _ANCHORS.get(kind)
            anchors = self._list(
                item.get("points"), f"{at}.points", count or 2, count or MAX_POINTS
            )
            if anchors is None:
                continue
            read = [self._anchor(a, f"{at}.points[{j}]") for j, a in enumerate(anchors, 1)]
            radius = self._expr(item["radius"], f"{at}.radius") if "radius" in item else None
            label, angle = (self._parameter(item, name, at) for name in ("label", "angle"))
            side = item.get("side", 1)
            if side not in (1, -1) or isinstance(side, bool):
                self.problems.add(
                    f"{at}.side", "is 1 (left of the first point to the second) or -1"
                )
                continue
            body = item.get("body", "")
            if kind == "bar" and body not in self.bodies:
                self.problems.add(f"{at}.body", "a bar names the rigid body it stands for")
                continue
            if (
                None in read
                or label is None
                or angle is None
                or ("radius" in item and radius is None)
            ):
                continue
            found.append(_Fixture(kind, tuple(read), radius, label, side, body, angle))
        return found

    def _parameter(self, item: Mapping[str, Any], name: str, at: str) -> str | None:
        value = item.get(name, "")
        if value and value not in self.parameters:
            self.problems.add(f"{at}.{name}", f"{value!r} is not a parameter of the scene")
            return None
        return value

    def _list(self, raw: Any, at: str, low: int, high: int) -> list | None:
        if not isinstance(raw, list) or not low <= len(raw) <= high:
            count = f"{low}" if low == high else f"{low} to {high}"
            self.problems.add(at, f"is not a list of {count} entries")
            return None
        return raw

    def _expr(self, value: Any, at: str) -> Expr | None:
        return self.reader.read(expression(value, at, self.problems), "figure")

    def _each(self, value: Any, at: str, low: int, high: int, read: Any) -> tuple | None:
        """A list of `low` to `high` entries, each read by `read` at `at[i]`; None (the
        problems noted) when the list or any entry is wrong."""
        entries = self._list(value, at, low, high)
        if entries is None:
            return None
        return self._all([read(x, f"{at}[{i}]") for i, x in enumerate(entries, 1)])

    def _point(self, value: Any, at: str) -> Point | None:
        size = 3 if self.three_d else 2
        if not isinstance(value, list) or len(value) != size:
            self.problems.add(at, f"is not a point: a list of {size} expressions")
            return None
        return self._all([self._expr(x, f"{at}[{i}]") for i, x in enumerate(value, 1)])

    def _anchor(self, value: Any, at: str) -> Anchor | None:
        if isinstance(value, str):
            if value not in self.bodies:
                self.problems.add(
                    at, f"{value!r} is not a body here (an anchor is a body or a point)"
                )
                return None
            return value
        return self._point(value, at)

    @staticmethod
    def _all(items: list) -> tuple | None:
        return None if any(x is None for x in items) else tuple(items)

    # --- one presentation's hint ----------------------------------------------------------------
    def hint_for(self, sub: Callable) -> Callable[[Mapping[str, str]], FigureHint]:
        """The function from a presentation's options to its FigureHint (built once each)."""

        @lru_cache(maxsize=64)
        def build(options: tuple[tuple[str, str], ...]) -> FigureHint:
            chosen = dict(options)
            merged = _merge(
                [self.scene, *(c[chosen[o]] for o, c in self.choices.items() if o in chosen)]
            )
            return _hint(merged, sub)

        return lambda options: build(tuple(sorted(options.items())))


def _merge(tables: list[dict[str, Any]]) -> dict[str, Any]:
    merged: dict[str, Any] = {}
    for table in tables:
        for key, value in table.items():
            if key in _TABLES:
                merged[key] = {**merged.get(key, {}), **value}
            elif key in ("fixtures", "solid"):
                merged[key] = [*merged.get(key, []), *value]
            else:
                merged[key] = value
    return merged


def _hint(m: Mapping[str, Any], sub: Callable) -> FigureHint:
    """The FigureHint of a merged table: every expression put into the variant's names."""

    def at(expr: Expr) -> Callable:
        return lambda s: expr.xreplace(sub(s))

    def point(p: Point, s: Any) -> tuple:
        subs = sub(s)
        return tuple(x.xreplace(subs) for x in p)

    def anchor(a: Anchor, s: Any) -> Any:
        return a if isinstance(a, str) else point(a, s)

    def fixture(f: _Fixture) -> Fixture:
        return Fixture(
            f.kind,
            lambda s: [anchor(a, s) for a in f.anchors],
            radius=at(f.radius) if f.radius is not None else None,
            label=f.label,
            side=f.side,
            body=f.body,
            angle=f.angle,
        )

    fixtures = [fixture(f) for f in m.get("fixtures", [])]
    return FigureHint(
        poses={c: at(e) for c, e in m.get("poses", {}).items()},
        ranges={
            c: (lambda s, r=r: (r[0].xreplace(sub(s)), r[1].xreplace(sub(s))))
            for c, r in m.get("ranges", {}).items()
        },
        shapes={
            b: (lambda s, ps=ps: [point(p, s) for p in ps]) for b, ps in m.get("shapes", {}).items()
        },
        dimensions=tuple(
            (n, lambda s, ps=ps: (point(ps[0], s), point(ps[1], s)))
            for n, ps in m.get("dimensions", {}).items()
        ),
        solid=frozenset(m.get("solid", ())),
        rods=m.get("rods", True),
        spokes=m.get("spokes", True),
        t=m.get("t", 0.0),
        fixtures=lambda s: tuple(fixtures),
        sweeps=dict(m.get("sweeps", {})),
        offsets={b: (lambda s, p=p: point(p, s)) for b, p in m.get("offsets", {}).items()},
        angles={
            c: (lambda s, ps=ps: tuple(point(p, s) for p in ps))
            for c, ps in m.get("angles", {}).items()
        },
        radii={b: at(e) for b, e in m.get("radii", {}).items()},
        spans={
            c: (lambda s, ps=ps: tuple(anchor(a, s) for a in ps))
            for c, ps in m.get("spans", {}).items()
        },
        labels=dict(m.get("labels", {})),
    )
