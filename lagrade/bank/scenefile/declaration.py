"""The shape of a scene file: its TOML table checked key by key into a `Declaration` of names and
expression texts, every problem collected (with the key it sits under) rather than the first one
raised. Nothing here reads an expression; `reading` does, with the notation layer.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from lagrade.bank.scenefile.fields import (
    Problems,
    Text,
    expression,
    list_field,
    name_field,
    shown,
    table_field,
    text_field,
    unknown_keys,
)
from lagrade.errors import LagradeError
from lagrade.mechanics import Domain

TOP_KEYS = (
    "title",
    "statement",
    "tags",
    "coordinates",
    "domains",
    "renames",
    "parameters",
    "relations",
    "bodies",
    "potential",
    "lagrangian",
    "constraints",
    "dissipation",
    "forces",
    "options",
    "quantities",
    "figure",
)
PARAMETER_KEYS = ("domain", "unit", "values", "description")
BODY_KEYS = ("mass", "position", "inertia", "angle", "angles")
CHOICE_KEYS = ("wording", "let", "bodies", "constraints", "figure")
QUANTITY_KEYS = ("description", "value", "unit", "check")
CHECK_KEYS = ("at", "accelerations", "frequencies")

#: Bounds that no mechanics problem comes near, so that a hostile file costs little to refuse.
LIMITS = {
    "coordinates": 16,
    "parameters": 64,
    "bodies": 32,
    "constraints": 64,
    "options": 8,
    "choices": 16,
    "lets": 16,
    "quantities": 32,
    "tags": 16,
    "renames": 8,
    "relations": 16,
}
MAX_VALUES = 64  # numbers in a parameter's value pool


@dataclass
class BodyDecl:
    name: str
    key: str
    mass: Text
    position: list[Text]
    inertia: Text | None = None
    angle: Text | None = None
    #: A rigid body in space: its principal moments (I₁, I₂, I₃) and Z-X-Z Euler angles.
    moments: list[Text] | None = None
    angles: list[Text] | None = None


@dataclass
class ChoiceDecl:
    """One choice of a presentation option: its wording, the names it binds, what it adds."""

    name: str
    key: str
    wording: str | None = None
    lets: dict[str, Text] = field(default_factory=dict)
    bodies: list[BodyDecl] = field(default_factory=list)
    constraints: list[Text] = field(default_factory=list)
    figure: dict[str, Any] = field(default_factory=dict)


@dataclass
class ParameterDecl:
    name: str
    domain: Domain
    unit: str
    values: tuple[float, ...]
    description: str


@dataclass
class QuantityDecl:
    name: str
    key: str
    description: str
    value: Text
    unit: str
    check: dict[str, Any] | None = None


@dataclass
class Declaration:
    """Everything a scene file declares, names checked, expressions still text."""

    title: str = ""
    statement: str = ""
    tags: tuple[str, ...] = ()
    coordinates: list[str] = field(default_factory=list)
    #: Where each coordinate lives (`r = "positive"`): the coordinates without one are real.
    domains: dict[str, Domain] = field(default_factory=dict)
    renames: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: Renames as consistent sets (`[["x", "y"], ["q_1", "q_2"]]`): a variant takes one whole.
    rename_sets: list[tuple[str, ...]] = field(default_factory=list)
    parameters: list[ParameterDecl] = field(default_factory=list)
    #: Inequalities between parameters (`b < R`), each as (smaller side, larger side).
    relations: list[tuple[Text, Text]] = field(default_factory=list)
    bodies: list[BodyDecl] = field(default_factory=list)
    potential: Text | None = None
    lagrangian: Text | None = None
    constraints: list[Text] = field(default_factory=list)
    #: Rayleigh's dissipation function F(q, q̇, t), and given generalized forces Q_j by coordinate.
    dissipation: Text | None = None
    forces: dict[str, Text] = field(default_factory=dict)
    options: dict[str, list[ChoiceDecl]] = field(default_factory=dict)
    quantities: list[QuantityDecl] = field(default_factory=list)
    figure: dict[str, Any] = field(default_factory=dict)


def cartesian_axes(body: BodyDecl) -> tuple[str, ...]:
    """The Cartesian names a body brings (`x`, `y`, `z`, and `phi` for a rigid body), as the
    transformation part names them (`x_bead`, `phi_wheel`)."""
    if body.angles is not None:
        return ("x", "y", "z", "phi", "theta", "psi")
    return ("x", "y", "z", "phi") if body.inertia is not None else ("x", "y", "z")


def read_declaration(data: Mapping[str, Any], problems: Problems) -> Declaration:
    """The checked declaration of a scene file's table; what is wrong goes to `problems`."""
    d = Declaration()
    unknown_keys(data, TOP_KEYS, "", problems)
    d.title = text_field(data, "title", "", problems, required=True) or ""
    d.statement = text_field(data, "statement", "", problems, required=True, lines=True) or ""
    tags = list_field(data.get("tags", []), "tags", problems, LIMITS["tags"]) or []
    d.tags = tuple(
        t for i, t in enumerate(tags) if name_field(t, f"tags[{i + 1}]", "tag", problems)
    )
    _coordinates(data, d, problems)
    _domains(data, d, problems)
    _parameters(data, d, problems)
    _relations(data, d, problems)
    _renames(data, d, problems)
    raw_bodies = data.get("bodies", {})
    if (table := table_field(raw_bodies, "bodies", problems)) is not None:
        d.bodies = _bodies(table, "bodies", problems)
    for key in ("potential", "lagrangian"):
        if key in data:
            setattr(d, key, expression(data[key], key, problems))
    d.constraints = _expressions(data.get("constraints", []), "constraints", problems)
    _dissipation(data, d, problems)
    if d.lagrangian is not None:
        for key in ("bodies", "potential", "constraints"):
            if key in data:
                problems.add(
                    key,
                    "a scene given by its Lagrangian declares no bodies, potential "
                    "or constraints (drop one or the other)",
                )
    elif not d.bodies and not _any_choice_bodies(data):
        problems.add("bodies", "missing: declare the bodies (or give the scene's lagrangian)")
    _options(data, d, problems)
    _quantities(data, d, problems)
    if "figure" in data and (figure := table_field(data["figure"], "figure", problems)) is not None:
        d.figure = figure
    return d


def _any_choice_bodies(data: Mapping[str, Any]) -> bool:
    options = data.get("options")
    if not isinstance(options, dict):
        return False
    return any(
        isinstance(choices, dict)
        and any(isinstance(c, dict) and c.get("bodies") for c in choices.values())
        for choices in options.values()
    )


def _coordinates(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    raw = data.get("coordinates")
    if raw is None:
        problems.add("coordinates", 'missing (the generalized coordinates, e.g. ["theta"])')
        return
    items = list_field(raw, "coordinates", problems, LIMITS["coordinates"]) or []
    for i, name in enumerate(items, 1):
        if name_field(name, f"coordinates[{i}]", "coordinate", problems):
            if name in d.coordinates:
                problems.add(f"coordinates[{i}]", f"{name!r} is declared twice")
            else:
                d.coordinates.append(name)
    if raw is not None and not items:
        problems.add("coordinates", "empty: a scene has at least one coordinate")


def _domains(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    """`domains = { r = "positive", theta = "(-pi/2, pi/2)" }`: where each coordinate lives."""
    table = table_field(data.get("domains", {}), "domains", problems) or {}
    for name, text in table.items():
        key = f"domains.{name}"
        if name not in d.coordinates:
            problems.add(key, f"{shown(name)} is not a coordinate")
            continue
        try:
            d.domains[name] = Domain.parse(text)
        except LagradeError as error:
            problems.add(key, str(error))


_INEQUALITY = re.compile(r"(<=|>=|<|>)")


def _relations(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    """`relations = ["b < R"]`: each one inequality between two expressions in the parameters
    (`<` and `<=` alike: a drawn value never lands on the boundary)."""
    items = list_field(data.get("relations", []), "relations", problems, LIMITS["relations"]) or []
    for i, raw in enumerate(items, 1):
        key = f"relations[{i}]"
        if not isinstance(raw, str):
            problems.add(key, f'{shown(raw)} is not an inequality such as "b < R"')
            continue
        parts = _INEQUALITY.split(raw)
        if len(parts) != 3 or not parts[0].strip() or not parts[2].strip():
            problems.add(key, f'{shown(raw)} is not one inequality such as "b < R"')
            continue
        left, sign, right = parts
        small, large = (left, right) if sign.startswith("<") else (right, left)
        d.relations.append((Text(key, small), Text(key, large)))


def _dissipation(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    """Rayleigh's function `dissipation = "b x_dot^2/2"` and the generalized forces
    `forces = { x = "F_0 cos(omega t)" }`, one per coordinate they act along."""
    if "dissipation" in data:
        d.dissipation = expression(data["dissipation"], "dissipation", problems)
    table = table_field(data.get("forces", {}), "forces", problems) or {}
    for name, value in table.items():
        key = f"forces.{name}"
        if name not in d.coordinates:
            problems.add(
                key, f"{shown(name)} is not a coordinate (a force is given per coordinate)"
            )
        elif (text := expression(value, key, problems)) is not None:
            d.forces[name] = text


def _parameters(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    table = table_field(data.get("parameters", {}), "parameters", problems) or {}
    if len(table) > LIMITS["parameters"]:
        problems.add("parameters", f"{len(table)} parameters; at most {LIMITS['parameters']}")
        return
    for name, spec in table.items():
        key = f"parameters.{name}"
        if not name_field(name, key, "parameter", problems):
            continue
        if name in d.coordinates:
            problems.add(key, f"{name!r} is already a coordinate")
            continue
        if (spec := table_field(spec, key, problems)) is None:
            continue
        unknown_keys(spec, PARAMETER_KEYS, key, problems)
        if "domain" not in spec:
            problems.add(f"{key}.domain", "missing (positive, nonnegative, real or an interval)")
            continue
        try:
            domain = Domain.parse(spec["domain"])
        except LagradeError as error:
            problems.add(f"{key}.domain", str(error))
            continue
        values = _values(spec.get("values", []), f"{key}.values", domain, problems)
        unit = text_field(spec, "unit", key, problems) or ""
        description = text_field(spec, "description", key, problems) or ""
        d.parameters.append(ParameterDecl(name, domain, unit, values, description))


def _values(raw: Any, key: str, domain: Domain, problems: Problems) -> tuple[float, ...]:
    items = list_field(raw, key, problems, MAX_VALUES)
    if items is None:
        return ()
    values = []
    for i, v in enumerate(items, 1):
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            problems.add(f"{key}[{i}]", f"{shown(v)} is not a finite number")
        elif not domain.contains(float(v)):
            problems.add(f"{key}[{i}]", f"{v} lies outside the domain {domain.text}")
        else:
            values.append(float(v))
    return tuple(values)


def _renames(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    if isinstance(data.get("renames"), list):
        _rename_sets(data["renames"], d, problems)
        return
    table = table_field(data.get("renames", {}), "renames", problems) or {}
    for coordinate, names in table.items():
        key = f"renames.{coordinate}"
        if coordinate not in d.coordinates:
            problems.add(key, f"{coordinate!r} is not a coordinate")
            continue
        items = list_field(names, key, problems, LIMITS["renames"])
        if not items:
            if items is not None:
                problems.add(key, "empty")
            continue
        if not all(name_field(n, key, "coordinate", problems) for n in items):
            continue
        if items[0] != coordinate:
            problems.add(key, f"the first name must be {coordinate!r} itself")
            continue
        if len(set(items)) != len(items):
            problems.add(key, "a name is offered twice")
            continue
        d.renames[coordinate] = tuple(items)


def _rename_sets(raw: list, d: Declaration, problems: Problems) -> None:
    """`renames = [["x", "y"], ["q_1", "q_2"]]`: each set names every coordinate, in order, and a
    variant takes one set whole (no `q_1` beside `y`); the first set is the coordinates."""
    sets = list_field(raw, "renames", problems, LIMITS["renames"]) or []
    found: list[tuple[str, ...]] = []
    for i, names in enumerate(sets, 1):
        key = f"renames[{i}]"
        if not isinstance(names, list) or len(names) != len(d.coordinates):
            problems.add(
                key, f"a set of names gives one name per coordinate ({len(d.coordinates)})"
            )
            return
        if not all(name_field(n, key, "coordinate", problems) for n in names):
            return
        if len(set(names)) != len(names) or tuple(names) in found:
            problems.add(key, "a name is given twice, or the set is")
            return
        found.append(tuple(names))
    if found and found[0] != tuple(d.coordinates):
        problems.add("renames[1]", f"the first set must be the coordinates {d.coordinates}")
        return
    d.rename_sets = found
    for k, coordinate in enumerate(d.coordinates):
        d.renames[coordinate] = tuple(dict.fromkeys(names[k] for names in found))


def _bodies(table: Mapping[str, Any], where: str, problems: Problems) -> list[BodyDecl]:
    if len(table) > LIMITS["bodies"]:
        problems.add(where, f"{len(table)} bodies; at most {LIMITS['bodies']}")
        return []
    bodies = []
    for name, spec in table.items():
        key = f"{where}.{name}"
        if (
            not name_field(name, key, "body", problems)
            or (spec := table_field(spec, key, problems)) is None
        ):
            continue
        unknown_keys(spec, BODY_KEYS, key, problems)
        mass = expression(spec["mass"], f"{key}.mass", problems) if "mass" in spec else None
        if "mass" not in spec:
            problems.add(f"{key}.mass", "missing")
        position: list[Text] = []
        raw = spec.get("position")
        if not isinstance(raw, list) or len(raw) not in (2, 3):
            problems.add(
                f"{key}.position",
                "missing or not a list of 2 (x, y: a plane, y up) or 3 (x, y, z: z up) expressions",
            )
        else:
            for i, x in enumerate(raw, 1):
                if (text := expression(x, f"{key}.position[{i}]", problems)) is not None:
                    position.append(text)
        if "angles" in spec:  # a rigid body in space
            spatial = _spatial(spec, key, raw, problems)
            if mass is not None and spatial is not None and len(position) == 3:
                bodies.append(BodyDecl(name, key, mass, position, None, None, *spatial))
            continue
        rigid = [k for k in ("inertia", "angle") if k in spec]
        inertia = angle = None
        if len(rigid) == 1:
            missing = "angle" if rigid == ["inertia"] else "inertia"
            problems.add(f"{key}.{missing}", "missing: a rigid body declares inertia and angle")
        elif rigid:
            inertia = expression(spec["inertia"], f"{key}.inertia", problems)
            angle = expression(spec["angle"], f"{key}.angle", problems)
            if isinstance(raw, list) and len(raw) == 3:
                problems.add(f"{key}.position", "a rigid body moves in a plane: give x and y")
        if mass is not None and len(position) == len(raw or ()) and position:
            bodies.append(BodyDecl(name, key, mass, position, inertia, angle))
    return bodies


def _spatial(
    spec: Mapping[str, Any], key: str, position: Any, problems: Problems
) -> tuple[list[Text], list[Text]] | None:
    """A rigid body in space: `inertia` its 3 principal moments about the centre of mass,
    `angles` its 3 Z-X-Z Euler angles (φ, θ, ψ), `position` its centre of mass (x, y, z)."""
    found = []
    for name, what in (("inertia", "principal moments I_1, I_2, I_3"), ("angles", "Euler angles")):
        raw = spec.get(name)
        if not isinstance(raw, list) or len(raw) != 3:
            problems.add(
                f"{key}.{name}",
                f"a rigid body in space declares a list of 3 {what} (angles: phi, theta, psi, "
                "turned about z, then the new x, then the body's axis 3)",
            )
            return None
        texts = [expression(x, f"{key}.{name}[{i}]", problems) for i, x in enumerate(raw, 1)]
        if None in texts:
            return None
        found.append(texts)
    if "angle" in spec:
        problems.add(f"{key}.angle", "a rigid body in space declares angles, not angle")
        return None
    if not isinstance(position, list) or len(position) != 3:
        problems.add(f"{key}.position", "a rigid body in space: give x, y and z")
        return None
    return found[0], found[1]  # type: ignore[return-value]


def _expressions(raw: Any, key: str, problems: Problems) -> list[Text]:
    items = list_field(raw, key, problems, LIMITS["constraints"]) or []
    found = []
    for i, x in enumerate(items, 1):
        if (text := expression(x, f"{key}[{i}]", problems)) is not None:
            found.append(text)
    return found


def _options(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    table = table_field(data.get("options", {}), "options", problems) or {}
    if len(table) > LIMITS["options"]:
        problems.add("options", f"{len(table)} options; at most {LIMITS['options']}")
        return
    for option, raw in table.items():
        key = f"options.{option}"
        if not name_field(option, key, "option", problems):
            continue
        if isinstance(raw, list):  # plain choices: ["solid", "hollow"]
            raw = (
                {c: {} for c in raw if isinstance(c, str)}
                if all(isinstance(c, str) for c in raw)
                else raw
            )
        if (choices := table_field(raw, key, problems, "a table of choices")) is None:
            continue
        if not choices or len(choices) > LIMITS["choices"]:
            problems.add(key, f"offers {len(choices)} choices; from 1 to {LIMITS['choices']}")
            continue
        parsed = [_choice(c, spec, f"{key}.{c}", problems) for c, spec in choices.items()]
        if all(c is not None for c in parsed):
            d.options[option] = parsed  # type: ignore[assignment]


def _choice(name: str, spec: Any, key: str, problems: Problems) -> ChoiceDecl | None:
    if (
        not name_field(name, key, "choice", problems)
        or (spec := table_field(spec, key, problems)) is None
    ):
        return None
    unknown_keys(spec, CHOICE_KEYS, key, problems)
    choice = ChoiceDecl(name, key, wording=text_field(spec, "wording", key, problems))
    lets = table_field(spec.get("let", {}), f"{key}.let", problems) or {}
    if len(lets) > LIMITS["lets"]:
        problems.add(f"{key}.let", f"{len(lets)} names; at most {LIMITS['lets']}")
        lets = {}
    for let, value in lets.items():
        if name_field(let, f"{key}.let.{let}", "let", problems):
            if (text := expression(value, f"{key}.let.{let}", problems)) is not None:
                choice.lets[let] = text
    if "bodies" in spec and (bodies := table_field(spec["bodies"], f"{key}.bodies", problems)):
        choice.bodies = _bodies(bodies, f"{key}.bodies", problems)
    choice.constraints = _expressions(spec.get("constraints", []), f"{key}.constraints", problems)
    if "figure" in spec and (figure := table_field(spec["figure"], f"{key}.figure", problems)):
        choice.figure = figure
    return choice


def _quantities(data: Mapping[str, Any], d: Declaration, problems: Problems) -> None:
    table = table_field(data.get("quantities", {}), "quantities", problems) or {}
    if len(table) > LIMITS["quantities"]:
        problems.add("quantities", f"{len(table)} quantities; at most {LIMITS['quantities']}")
        return
    for name, spec in table.items():
        key = f"quantities.{name}"
        if not name_field(name, key, "quantity", problems) or not (
            spec := table_field(spec, key, problems)
        ):
            continue
        unknown_keys(spec, QUANTITY_KEYS, key, problems)
        if "value" not in spec:
            problems.add(f"{key}.value", "missing (the closed form in the parameters)")
            continue
        value = expression(spec["value"], f"{key}.value", problems)
        check = None
        if "check" in spec and (check := table_field(spec["check"], f"{key}.check", problems)):
            unknown_keys(check, CHECK_KEYS, f"{key}.check", problems)
        if value is not None:
            d.quantities.append(
                QuantityDecl(
                    name,
                    key,
                    text_field(spec, "description", key, problems, required=True) or "",
                    value,
                    text_field(spec, "unit", key, problems) or "",
                    check,
                )
            )
