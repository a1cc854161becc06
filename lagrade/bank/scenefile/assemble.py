"""A checked declaration and its read expressions, assembled into a `Scene`: the scene's bodies,
potential, constraints, quantities and L as functions of a variant's namespace, each one the
file's expression with the variant's coordinate names and the chosen options' `let` names put in.

The expressions are read once, in the scene's own (canonical) names; a variant renames them by
substitution, which sympy re-evaluates node by node, so a renamed variant is what reading it under
the new names would give.
"""

from __future__ import annotations

import string
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

import sympy as sp

from lagrade.bank.scenefile.claims import Claim, read_claim
from lagrade.bank.scenefile.declaration import BodyDecl, Declaration
from lagrade.bank.scenefile.fields import Problems
from lagrade.bank.scenefile.figure import FigureReader
from lagrade.bank.scenefile.reading import Reader
from lagrade.errors import SceneError
from lagrade.mechanics import Parameter, PointMass, Quantity, RigidBody, Scene, SpatialRigidBody
from lagrade.mechanics import lagrange as mech


@dataclass
class _Body:
    """A body's fields read: expressions in the scene's canonical names."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, ...]
    inertia: sp.Expr | None = None
    angle: sp.Expr | None = None
    moments: tuple[sp.Expr, ...] | None = None
    angles: tuple[sp.Expr, ...] | None = None

    def make(self, put: Callable[[sp.Expr], sp.Expr]) -> PointMass | RigidBody | SpatialRigidBody:
        position = tuple(put(x) for x in self.position)
        if self.moments is not None and self.angles is not None:
            return SpatialRigidBody(
                self.name,
                put(self.mass),
                position,  # type: ignore[arg-type]
                tuple(put(x) for x in self.moments),  # type: ignore[arg-type]
                tuple(put(x) for x in self.angles),  # type: ignore[arg-type]
            )
        if self.inertia is None or self.angle is None:
            return PointMass(self.name, put(self.mass), position)
        return RigidBody(self.name, put(self.mass), position, put(self.inertia), put(self.angle))  # type: ignore[arg-type]


@dataclass
class _Choice:
    lets: dict[sp.Symbol, sp.Expr] = field(default_factory=dict)
    bodies: list[_Body] = field(default_factory=list)
    constraints: list[sp.Expr] = field(default_factory=list)


class Substitution:
    """What a variant puts in place of the file's names: its own coordinate symbols for the
    canonical ones, and the chosen options' `let` expressions (themselves renamed)."""

    def __init__(self, jets: Mapping[str, mech.Jet], choices: Mapping[str, Mapping[str, _Choice]]):
        self.jets = jets
        self.choices = choices

    def __call__(self, s: SimpleNamespace) -> dict[sp.Symbol, sp.Expr]:
        subs: dict[sp.Symbol, sp.Expr] = {}
        for name, j in self.jets.items():
            subs[j.q], subs[j.dot] = getattr(s, name), getattr(s, name + mech.DOT)
        renamed = {k: v for k, v in subs.items() if k is not v and k != v}
        for option, choices in self.choices.items():
            for let, expr in choices[s.opt[option]].lets.items():
                subs[let] = expr.xreplace(renamed) if renamed else expr
        return subs

    def chosen(self, s: SimpleNamespace) -> list[_Choice]:
        """The chosen choice of each option, in the order the options are declared."""
        return [choices[s.opt[option]] for option, choices in self.choices.items()]


def _put(subs: Mapping[sp.Symbol, sp.Expr]) -> Callable[[sp.Expr], sp.Expr]:
    return lambda e: e.xreplace(subs) if subs else e


def assemble(scene_id: str, d: Declaration, source: str, problems: Problems) -> Scene | None:
    """The Scene a declaration describes, or None with every problem in `problems`."""
    reader = Reader(d, problems)
    scene_bodies = [b.name for b in d.bodies]
    bodies = [_read_body(b, reader) for b in d.bodies]
    choices: dict[str, dict[str, _Choice]] = {}
    for option, decls in d.options.items():
        choices[option] = {}
        for c in decls:
            choice = _Choice()
            for name, text in c.lets.items():
                value = reader.read(text, "let")
                if value is not None:
                    choice.lets[sp.Symbol(name, real=True)] = value
            choice.bodies = [_read_body(b, reader) for b in c.bodies]
            present = scene_bodies + [b.name for b in c.bodies]
            choice.constraints = [reader.read(x, "constraint", present) for x in c.constraints]  # type: ignore[misc]
            choices[option][c.name] = choice
        _same_lets(option, decls, problems)
    _lets_in_one_option(d, problems)
    _body_names(d, problems)
    potential = reader.read(d.potential, "potential", scene_bodies)
    lagrangian = reader.read(d.lagrangian, "lagrangian")
    relations = [
        (reader.read(small, "relation"), reader.read(large, "relation"))
        for small, large in d.relations
    ]
    dissipation = reader.read(d.dissipation, "dissipation")
    forces = {c: reader.read(x, "dissipation") for c, x in d.forces.items()}
    constraints = [reader.read(x, "constraint", scene_bodies) for x in d.constraints]
    quantities = {q.name: reader.read(q.value, "quantity") for q in d.quantities}
    claims = {q.name: read_claim(q, d, reader, problems) for q in d.quantities if q.check}
    figure = FigureReader(d, reader, problems)
    parameters = tuple(
        Parameter(p.name, p.domain, p.unit, p.values, p.description) for p in d.parameters
    )
    if potential is not None and potential.has(sp.Symbol("gravity", real=True)):
        if "g" not in reader.parameters:
            problems.add("potential", "gravity needs a parameter g (gravitational acceleration)")
    _statement_fields(d, problems)
    if problems.blocking or None in bodies or None in constraints or None in quantities.values():
        return None
    if (d.dissipation is not None and dissipation is None) or None in forces.values():
        return None
    if any(None in pair for pair in relations):
        return None
    if any(
        None in c.constraints or None in c.bodies for cs in choices.values() for c in cs.values()
    ):
        return None
    sub = Substitution(reader.jets, choices)
    g = reader.parameters.get("g")
    scene_kwargs: dict[str, Any] = {}
    if d.lagrangian is not None:
        if lagrangian is None:
            return None
        scene_kwargs["lagrangian"] = lambda s: _put(sub(s))(lagrangian)
    else:
        scene_kwargs["bodies"] = lambda s: _bodies(s, sub, bodies)  # type: ignore[arg-type]
        scene_kwargs["potential"] = lambda s, made: _potential(s, sub, potential, made, g)
        scene_kwargs["constraints"] = lambda s, c: _constraints(s, sub, constraints)  # type: ignore[arg-type]
    if dissipation is not None:
        scene_kwargs["dissipation"] = lambda s: _put(sub(s))(dissipation)
    if forces:
        scene_kwargs["forces"] = lambda s: {c: _put(sub(s))(q) for c, q in forces.items()}
    wording = {
        o: {c.name: c.wording or c.name for c in decls}
        for o, decls in d.options.items()
        if any(c.wording is not None for c in decls)
    }
    try:
        scene = Scene(
            id=scene_id,
            title=d.title,
            statement=d.statement,
            coordinates=tuple(d.coordinates),
            coordinate_domains=dict(d.domains),
            relations=tuple(large - small for small, large in relations),  # type: ignore[operator]
            parameters=parameters,
            renames=dict(d.renames),
            rename_sets=tuple(d.rename_sets),
            options={o: tuple(c.name for c in decls) for o, decls in d.options.items()},
            quantities=tuple(
                Quantity(
                    q.name,
                    q.description,
                    _quantity(sub, quantities[q.name]),
                    q.unit,
                    _claim(sub, claims.get(q.name), quantities),
                )
                for q in d.quantities
            ),
            tags=d.tags,
            wording=wording,
            figure=figure.hint_for(sub),
            source=source,
            **scene_kwargs,
        )
    except SceneError as error:
        for p in error.problems:
            problems.add("", p)
        return None
    return scene


def _read_body(b: BodyDecl, reader: Reader) -> _Body | None:
    if b.moments is not None and b.angles is not None:
        read = [reader.read(x, "body") for x in [b.mass, *b.position, *b.moments, *b.angles]]
        if any(x is None for x in read):
            return None
        return _Body(
            b.name, read[0], tuple(read[1:4]), moments=tuple(read[4:7]), angles=tuple(read[7:10])
        )  # type: ignore[arg-type]
    fields = [b.mass, *b.position] + ([b.inertia, b.angle] if b.inertia is not None else [])
    read = [reader.read(x, "body") for x in fields]
    if any(x is None for x in read):
        return None
    n = len(b.position)
    mass, position = read[0], tuple(read[1 : 1 + n])
    if b.inertia is not None:
        return _Body(b.name, mass, position, read[1 + n], read[2 + n])  # type: ignore[arg-type]
    return _Body(b.name, mass, position)  # type: ignore[arg-type]


def _bodies(s: SimpleNamespace, sub: Substitution, bodies: list[_Body]) -> tuple:
    put = _put(sub(s))
    made = [b.make(put) for b in bodies]
    for choice in sub.chosen(s):
        made += [b.make(put) for b in choice.bodies]
    return tuple(made)


def _potential(
    s: SimpleNamespace,
    sub: Substitution,
    potential: sp.Expr | None,
    bodies: tuple,
    g: sp.Symbol | None,
) -> sp.Expr:
    """V with the bodies' Cartesian coordinates put in, and `gravity` as Σ m g h (h the last
    component: y of a plane position, z of a position in space)."""
    if potential is None:
        return sp.S.Zero
    V = _put(sub(s))(potential)
    cartesian: dict[sp.Symbol, sp.Expr] = {}
    for b in bodies:
        position = tuple(b.position) + (sp.S.Zero,) * (3 - len(b.position))
        for axis, value in zip("xyz", position, strict=True):
            cartesian[sp.Symbol(f"{axis}_{b.name}", real=True)] = value
        if isinstance(b, RigidBody):
            cartesian[sp.Symbol(f"phi_{b.name}", real=True)] = b.angle
        if isinstance(b, SpatialRigidBody):
            for a, e in zip(b.ANGLES, b.angles, strict=True):
                cartesian[sp.Symbol(f"{a}_{b.name}", real=True)] = e
    gravity = sp.Symbol("gravity", real=True)
    if V.has(gravity):
        cartesian[gravity] = sum((b.mass * g * b.position[-1] for b in bodies), sp.S.Zero)
    return V.xreplace(cartesian)


def _constraints(s: SimpleNamespace, sub: Substitution, constraints: list[sp.Expr]) -> tuple:
    put = _put(sub(s))
    found = [put(f) for f in constraints]
    for choice in sub.chosen(s):
        found += [put(f) for f in choice.constraints]
    return tuple(found)


def _quantity(sub: Substitution, expr: sp.Expr | None) -> Callable[[SimpleNamespace], sp.Expr]:
    return lambda s: _put(sub(s))(expr)  # type: ignore[arg-type]


def _claim(
    sub: Substitution, claim: Claim | None, quantities: Mapping[str, sp.Expr | None]
) -> Callable[[SimpleNamespace], Claim] | None:
    """The quantity's claim about the motion in a variant's names (its state may name any of
    the scene's quantities, by their values)."""
    if claim is None:
        return None

    def resolved(s: SimpleNamespace) -> Claim:
        subs = sub(s)
        values = {
            sp.Symbol(n, real=True): _put(subs)(q) for n, q in quantities.items() if q is not None
        }
        return claim.resolved(lambda e: _put(subs)(e).xreplace(values), subs)

    return resolved


def _same_lets(option: str, decls: list, problems: Problems) -> None:
    """Every choice of an option binds the same names, so each means something in every variant."""
    names = [set(c.lets) for c in decls]
    if any(n != names[0] for n in names):
        listing = "; ".join(f"{c.name}: {', '.join(sorted(c.lets)) or 'none'}" for c in decls)
        problems.add(f"options.{option}", f"every choice must bind the same names ({listing})")


def _lets_in_one_option(d: Declaration, problems: Problems) -> None:
    owner: dict[str, str] = {}
    for option, decls in d.options.items():
        for name in {n for c in decls for n in c.lets}:
            if name in owner:
                problems.add(
                    f"options.{option}", f"{name!r} is bound by option {owner[name]!r} too"
                )
            owner.setdefault(name, option)


def _body_names(d: Declaration, problems: Problems) -> None:
    """A body name is the scene's or one option's: two choices of one option may share it."""
    owner = {b.name: "the scene" for b in d.bodies}
    for option, decls in d.options.items():
        mine = {b.name for c in decls for b in c.bodies}
        for name in sorted(mine):
            if name in owner:
                problems.add(f"options.{option}", f"body {name!r} is declared by {owner[name]} too")
            owner.setdefault(name, f"option {option!r}")


def _statement_fields(d: Declaration, problems: Problems) -> None:
    """Each `{field}` of the statement names a coordinate, an option or a parameter."""
    allowed = set(d.coordinates) | set(d.options) | {p.name for p in d.parameters}
    try:
        fields = list(string.Formatter().parse(d.statement))
    except ValueError as error:
        problems.add("statement", f"{error}; write {{{{ and }}}} for a brace itself")
        return
    for _, name, spec, conversion in fields:
        if name is None:
            continue
        if spec or conversion or name not in allowed:
            problems.add(
                "statement",
                f"{{{name}{'!' + conversion if conversion else ''}{':' + spec if spec else ''}}} "
                "is not a field; a field names a coordinate, an option or a parameter "
                f"({', '.join(sorted(allowed))})",
                blocking=False,
            )
