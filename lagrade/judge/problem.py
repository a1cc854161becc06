"""The question a request is about: a bank variant, an instructor's ad-hoc Lagrangian, or a
reference expression with the domains of its variables — and everything the checks derive from
it, computed once and cached (a batch of a thousand answers to one question derives once).

    {"scene": "wedge", "seed": 3}             a bank variant (no seed: the declared form)
    {"scene": "parabola", "scene_text": "...", "seed": 3}   a scene file's variant (its text)
    {"scene": "wedge", "quantity": "block_acceleration"}   a closed-form quantity (`expression`)
    {"lagrangian": "...", "coordinates": ["theta"], "parameters": {"m": "positive", ...}}
    {"expression": "...", "parameters": {"g": "positive", "alpha": "(0, pi/2)"}}

Instructor strings are read by the project parser like any answer, never by sympify.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import sympy as sp

from lagrade.bank import get_scene, scene_from_text, sha256
from lagrade.errors import LagradeError, ParseError, ReferenceUndefined, RequestError
from lagrade.judge.catalogue import Catalogue
from lagrade.judge.clocks import PREPARE_LIMIT, Budget
from lagrade.judge.compiled import Compiled, finite_mask
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.reference import determined_mask, lagrangian_mask
from lagrade.judge.rows import Rows, equation_rows, lagrangian_rows
from lagrade.judge.sampling import Points, Space, seed_for
from lagrade.mechanics import Domain, Jet, LagrangianSystem, SceneVariant, jet, t

#: A coordinate or parameter name of an ad-hoc problem: a plain name of at most 32 characters.
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,31}$")
#: More coordinates or parameters than any mechanics problem has is a malformed request.
MAX_NAMES = 64
#: Why an ad-hoc Lagrangian cannot judge transformation equations: it has no bodies, so no
#: Cartesian positions to transform to.
NEEDS_BODIES = (
    "the transformation part needs a scene with bodies (--scene, or a bank scene in a "
    "request); an ad-hoc Lagrangian has no Cartesian positions to transform to"
)


def parser():
    """The project parser (imported on first use, so that this module loads without it)."""
    from lagrade.notation import parse

    return parse


class structural:  # noqa: N801 - used as a decorator, like cached_property
    """A cached property whose value lives in the question's `shared` store: what depends on
    the structure alone is derived once for all the variants that share it, by whichever asks
    first (its value may hold that question, which differs from the others in the handout's
    values and key only, neither of which it reads)."""

    def __init__(self, derive: Callable[[Any], Any]):
        self.derive = derive
        self.name = derive.__name__
        self.__doc__ = derive.__doc__

    def __get__(self, problem: Problem | None, owner: type | None = None) -> Any:
        if problem is None:
            return self
        store = problem.shared
        if self.name not in store:
            store[self.name] = self.derive(problem)
        return store[self.name]


@dataclass(eq=False)
class Problem:
    """One question: its coordinates (jets), parameters with domains, the reference (L, or an
    expression) and, for a bank variant, the scene's own derivations."""

    key: str
    kind: str  # "scene" | "lagrangian" | "expression"
    jets: tuple[Jet, ...]
    parameters: dict[str, sp.Symbol]
    domains: dict[sp.Symbol, Domain]
    values: dict[sp.Symbol, float]
    lagrangian: sp.Expr | None = None
    expression: sp.Expr | None = None
    variant: SceneVariant | None = None
    coordinate_domains: dict[str, tuple[float, float]] | None = None
    #: Expressions in the parameters that must be positive at every point (a scene's b < R).
    relations: tuple[sp.Expr, ...] = ()
    unit: str = ""  # the unit of a scene quantity (a numeric answer may carry it)
    imaginary_unit: str | None = None  # its spelling, where an expression question declares it
    #: What deriving this question may still take (its preparation budget), and has taken.
    budget: Budget = field(default_factory=lambda: Budget(PREPARE_LIMIT))
    #: The identity of what this question's judging depends on besides the handout's values:
    #: the scene and its presentation (names, options, quantity), not the seed. The variants of
    #: a class that share it share `shared` (`share`); it seeds the sample points.
    structure: str = ""
    #: What is derived from the structure alone (reference, points, catalogue, vocabulary),
    #: computed once for every question that shares this store.
    shared: dict = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        self.structure = self.structure or self.key

    def share(self, store: dict) -> None:
        """Derive what depends on the structure alone into `store`, which the other variants of
        this structure hold too (the driver keeps one per structure)."""
        self.shared = store

    # --- names -------------------------------------------------------------------------------
    @property
    def coordinates(self) -> tuple[str, ...]:
        return tuple(j.name for j in self.jets)

    @structural
    def by_name(self) -> dict[str, sp.Symbol]:
        """Every symbol a well-formed answer can contain, by name."""
        names = dict(self.parameters)
        for j in self.jets:
            names |= {str(j.q): j.q, str(j.dot): j.dot, str(j.ddot): j.ddot}
        return names | {"t": t}

    def vocabulary(self, labels: Sequence[str] = ()):
        """The parser's vocabulary for this question, with extra allowed names `labels` (one
        per set of labels: its lexicon is built once, not per answer)."""
        key = tuple(labels)
        cache = self.shared.setdefault("_vocabularies", {})
        if key not in cache:
            cache[key] = parser().Vocabulary(
                self.coordinates, dict(self.parameters), key, imaginary_unit=self.imaginary_unit
            )
        return cache[key]

    @structural
    def parser_symbols_are_mine(self) -> bool:
        """The parser reads every name as this problem's own symbol, so its output needs no
        `canonical` pass."""
        table = self.vocabulary()._lexicon.table
        return all(table[n].value is s for n, s in self.by_name.items() if n in table)

    @structural
    def renaming(self) -> dict[sp.Symbol, sp.Symbol]:
        """The parser's symbols → this problem's, where they differ (`canonical` for a tree)."""
        table = self.vocabulary()._lexicon.table
        return {
            table[n].value: s
            for n, s in self.by_name.items()
            if n in table and table[n].value is not s and getattr(table[n].value, "is_Symbol", 0)
        }

    def canonical(self, expr: sp.Expr) -> sp.Expr:
        """expr with every symbol replaced by this problem's symbol of the same name (the parser
        and the bank agree on symbols; this guards against a mismatch of assumptions)."""
        swap = {}
        for s in expr.free_symbols:
            mine = self.by_name.get(str(s))
            if mine is not None and mine is not s:
                swap[s] = mine
        return expr.xreplace(swap) if swap else expr

    # --- references ---------------------------------------------------------------------------
    @structural
    def system(self) -> LagrangianSystem:
        if self.lagrangian is None:
            raise RequestError("this problem gives an expression, not a Lagrangian")
        if self.variant is not None:
            return self.variant.system
        # its facts (cyclic, ∂L/∂t ≡ 0) are decided at points inside the declared domains
        ranges = {s: d.sample_range() for s, d in self.domains.items()}
        ranges |= {
            j.q: self.coordinate_domains[j.name]
            for j in self.jets
            if j.name in (self.coordinate_domains or {})
        }
        return LagrangianSystem(self.lagrangian, self.jets, ranges)

    @cached_property
    def space(self) -> Space:
        return Space(self.jets, self.domains, self.values, self.coordinate_domains or {})

    @structural
    def L(self) -> Compiled:
        return Compiled.of(self.system.L)

    @structural
    def euler_lagrange(self) -> tuple[Compiled, ...]:
        return tuple(Compiled.of(e) for e in self.system.euler_lagrange)

    @structural
    def momenta(self) -> tuple[Compiled, ...]:
        return tuple(Compiled.of(p) for p in self.system.generalized_momenta)

    @structural
    def reference_expression(self) -> Compiled:
        if self.expression is None:
            raise RequestError("this problem has no reference expression")
        return Compiled.of(self.expression)

    @property
    def has_bodies(self) -> bool:
        """A scene with bodies (not an ad-hoc L, nor a scene given by its Lagrangian)."""
        return self.variant is not None and not self.variant.scene.given_by_lagrangian

    @structural
    def kinetic_energy(self) -> sp.Expr:
        if not self.has_bodies:
            raise RequestError(
                "T and V can be checked only for scenes with bodies (this problem gives L alone)"
            )
        return self.variant.kinetic_energy

    @structural
    def potential_energy(self) -> sp.Expr:
        if not self.has_bodies:
            raise RequestError(
                "T and V can be checked only for scenes with bodies (this problem gives L alone)"
            )
        return self.variant.potential_energy

    @structural
    def kinetic(self) -> Compiled:
        """T, compiled once (the reference of the T part)."""
        return Compiled.of(self.kinetic_energy)

    @structural
    def potential(self) -> Compiled:
        """V, compiled once (the reference of the V part)."""
        return Compiled.of(self.potential_energy)

    @structural
    def dof(self) -> int:
        return self.variant.dof if self.has_bodies else len(self.jets)

    @structural
    def catalogue(self):
        """The mistakes this question invites, derived from its reference."""
        return Catalogue(self)

    # --- sample points, cached per part ---------------------------------------------------------
    def points(self, part: str) -> Points:
        """Sample points for `part`, every parameter drawn over its domain: a symbolic answer is
        judged for every value of the parameters, so one it leaves out is never taken for its
        handout value (an L without m is wrong even when m = 1 kg)."""
        cache = self.shared.setdefault("_points", {})
        if part not in cache:
            cache[part] = self._draw(part)
        return cache[part]

    def _draw(self, part: str) -> Points:
        """An expression is compared on principal branches in complex arithmetic: a complex
        value of the reference is a value (docs/formats.md). Its points are drawn where the
        reference is real when it is somewhere (the catalogue's slips and the values quoted in
        feedback are real; the default method compares the complex branches on its own), and
        where it has any value — complex on the whole domain (log(-x)), or with the imaginary
        unit declared — otherwise. Mechanics (L, its equations, momenta) is real."""
        seed, free = seed_for(self.structure, part), frozenset(self.domains)
        if not (self.kind == "expression" or part == "expression"):
            return self.space.draw(seed, free, self._kept(self._validity(part)))
        if self.imaginary_unit is None:
            try:
                valid = self._kept(finite_mask([self.reference_expression]))
                return self.space.draw(seed, free, valid)
            except ReferenceUndefined:
                pass  # complex wherever it has a value
        valid = self._kept(finite_mask([self.reference_expression], complex_values=True))
        points = self.space.draw(seed, free, valid)
        points.complex_values = True
        return points

    def _kept(self, valid):
        """`valid`, and the scene's relations between parameters kept (b < R): a point outside
        them is not one the problem is about, so it is redrawn like an undefined one."""
        if not self.relations:
            return valid
        kept = [Compiled.of(g) for g in self.relations]

        def both(env):
            ok = valid(env)
            with np.errstate(all="ignore"):
                for g in kept:
                    value = np.broadcast_to(np.asarray(g.values(env)[0], float), ok.shape)
                    ok = ok & (value > 0)
            return ok

        return both

    def _validity(self, part: str):
        if self.kind == "expression" or part == "expression":
            return finite_mask([self.reference_expression])
        if part == "transformation":
            if self.variant is None:
                raise RequestError(NEEDS_BODIES)
            return finite_mask([Compiled.of(x) for x in self.variant.transformation.values()])
        # by numbers: one hyper-dual pass over L, not sympy's derived E(L) and mass matrix
        if part in ("eom", "conserved"):
            return determined_mask(self.L, self.jets)
        return lagrangian_mask(self.L, self.jets)

    def compiled_reference(self, name: str, make: Callable[[], sp.Expr]) -> Compiled:
        """A derived reference expression (h, H, a force, T of the split), compiled once per
        structure: every variant and every part that names it reads the same program."""
        cache = self.shared.setdefault("_compiled_references", {})
        if name not in cache:
            cache[name] = Compiled.of(make())
        return cache[name]

    # --- cached reference values at points ------------------------------------------------------
    def cached(self, name: str, points: Points, make):
        """A value derived from `points` (reference rows, accelerations), computed once."""
        store = self.shared.setdefault("_derived", {})
        key = (name, id(points))
        if key not in store:
            store[key] = make()
        return store[key]

    def peek(self, name: str, points: Points):
        """What `cached(name, points, …)` holds already, or None (computes nothing)."""
        return self.shared.get("_derived", {}).get((name, id(points)))

    def reference_rows(self, points: Points) -> Rows:
        """The reference's Euler–Lagrange rows [A | c] at `points`, computed once (the eom and
        conserved checks and the mistake catalogue read the same), by one hyper-dual pass over
        L (`rows_at` for another arithmetic). A scene with dissipation or given forces has rows
        that are not L's alone (E_j + ∂F/∂q̇_j − Q_j): its derived rows, compiled."""
        if self.nonconservative:
            return self.cached("rows", points, lambda: self.rows_at(points, FLOAT))
        with np.errstate(all="ignore"):
            return self.cached(
                "rows", points, lambda: lagrangian_rows(self.L, self.jets, points.env)
            )

    @property
    def nonconservative(self) -> bool:
        """The scene declares dissipation or generalized forces."""
        return self.variant is not None and self.variant.scene.nonconservative

    def rows_at(self, points: Points, backend) -> Rows:
        """The reference rows at `points` in `backend`: high precision settles a near tie, and
        there sympy's derived E(L), compiled, costs a fraction of a hyper-dual pass over L in
        mpmath (2n copies of every point)."""
        return equation_rows(self.euler_lagrange, self.jets, points.arrays(backend), backend)


# --- building a Problem from a request ------------------------------------------------------------


def problem_key(spec: Mapping[str, Any]) -> str:
    """The identity of a problem field: its canonical JSON (a seed for the sample points and
    the key of the worker's cache), a scene file's text in it by its hash (so that the keys a
    worker remembers stay small whatever a request carries)."""
    text = spec.get("scene_text")
    if isinstance(text, str):
        spec = {**spec, "scene_text": f"sha256:{sha256(text)}"}
    return json.dumps(spec, sort_keys=True, separators=(",", ":"))


#: How a request's reader names the ad-hoc problem's fields in an error: a JSON request's keys.
#: The command line passes its flags instead (`lagrade.cli.check`), so that a message points to
#: what its reader typed.
JSON_FIELDS: Mapping[str, str] = {
    "lagrangian": 'the problem\'s "lagrangian"',
    "expression": 'the problem\'s "expression"',
    "coordinates": '"coordinates", e.g. ["theta"]',
    "parameters": '"parameters", e.g. {"m": "positive", "g": "positive"}',
}


def build_problem(spec: Any, fields: Mapping[str, str] = JSON_FIELDS) -> Problem:
    """A Problem from a request's "problem" field; a RequestError says what is wrong with it,
    naming the fields as `fields` spells them."""
    if not isinstance(spec, Mapping):
        raise RequestError('"problem" must be an object such as {"scene": "wedge", "seed": 3}')
    key = problem_key(spec)
    kinds = [k for k in ("scene", "lagrangian", "expression") if k in spec]
    if len(kinds) != 1:
        raise RequestError(
            '"problem" must have exactly one of "scene", "lagrangian" or "expression" '
            f"(it has {', '.join(kinds) or 'none'})"
        )
    if kinds[0] == "scene":
        return _scene_problem(spec, key)
    return _adhoc_problem(spec, key, kinds[0], fields)


def _scene_problem(spec: Mapping[str, Any], key: str) -> Problem:
    _only(spec, {"scene", "scene_text", "seed", "quantity"})
    scene_id, seed, text = spec["scene"], spec.get("seed"), spec.get("scene_text")
    if not isinstance(scene_id, str):
        raise RequestError('"scene" must be a scene id such as "wedge"')
    if seed is not None and (not isinstance(seed, int) or isinstance(seed, bool)):
        raise RequestError(f'"seed" must be an integer, got {seed!r}')
    if text is not None and not isinstance(text, str):
        raise RequestError('"scene_text" must be the text of a scene file')
    try:
        # a scene file travels as its text (read by the safe reader; checked when it was
        # written into the assignment), a bank scene by its id
        scene = (
            get_scene(scene_id)
            if text is None
            else scene_from_text(
                text, scene_id, origin='the problem\'s "scene_text"', validate=False
            )
        )
        variant = scene.default if seed is None else scene.variant(seed)
        jets = variant.jets
        params = dict(variant.parameter_symbols)
    except LagradeError as error:
        raise RequestError(str(error)) from None
    domains = {params[n]: d for n, d in variant.domains.items()}
    values = {params[n]: float(v) for n, v in variant.values.items()}
    expression, unit = None, ""
    if "quantity" in spec:
        quantities = variant.quantities
        if spec["quantity"] not in quantities:
            raise RequestError(
                f"scene {scene_id!r} has no quantity {spec['quantity']!r}; it has: "
                + (", ".join(quantities) or "none")
            )
        expression = quantities[spec["quantity"]]
        unit = next(q.unit for q in scene.quantities if q.name == spec["quantity"])
    return Problem(
        key,
        "scene",
        jets,
        params,
        domains,
        values,
        lagrangian=variant.lagrangian,
        expression=expression,
        variant=variant,
        coordinate_domains={n: d.sample_range() for n, d in variant.coordinate_domains.items()},
        relations=variant.scene.relations,
        unit=unit,
        structure=_structure_key(spec, variant),
    )


def _structure_key(spec: Mapping[str, Any], variant: SceneVariant) -> str:
    """A scene question's structure: the problem field without its seed, with the presentation
    the seed chose (coordinate names, options) — every variant with the same one has the same
    reference, points and catalogue; only the handout's values differ."""
    spec = {k: v for k, v in spec.items() if k != "seed"}
    presentation = {"names": variant.names, "options": variant.options}
    return problem_key({**spec, "presentation": presentation})


def _adhoc_problem(
    spec: Mapping[str, Any], key: str, kind: str, fields: Mapping[str, str]
) -> Problem:
    _only(
        spec,
        {kind, "coordinates", "parameters"}
        | ({"imaginary_unit"} if kind == "expression" else set()),
    )
    unit = spec.get("imaginary_unit")
    if unit is not None and unit not in IMAGINARY_UNITS:
        raise RequestError(
            f'"imaginary_unit" must be one of {", ".join(map(repr, IMAGINARY_UNITS))}, '
            f"not {_shown(unit)}"
        )
    text = spec[kind]
    if not isinstance(text, str) or not text.strip():
        raise RequestError(f"{fields[kind]} must not be empty")
    coords, coordinate_domains = _coordinates(
        spec.get("coordinates", []), required=kind == "lagrangian", fields=fields
    )
    raw_params = spec.get("parameters", {})
    if not isinstance(raw_params, Mapping):
        raise RequestError('"parameters" must map each name to a domain, e.g. {"m": "positive"}')
    if len(raw_params) > MAX_NAMES:
        raise RequestError(f"{len(raw_params)} parameters; a problem may have at most {MAX_NAMES}")
    params: dict[str, sp.Symbol] = {}
    domains: dict[sp.Symbol, Domain] = {}
    # In a Lagrangian t is time; an expression problem may declare t as an ordinary variable.
    taken = {n for c in coords for n in (c, c + "_dot", c + "_ddot")}
    taken |= {"t"} if kind == "lagrangian" else set()
    taken |= {unit} if unit is not None else set()
    for name, dom in raw_params.items():
        if not isinstance(name, str) or not _NAME.match(name):
            raise RequestError(f"parameter name {_shown(name)} is not a plain name {_NAME_RULE}")
        if name in taken:
            raise RequestError(
                f"parameter {name!r} clashes with a coordinate (or t, or the imaginary unit)"
            )
        try:
            domain = Domain.parse(dom)
        except LagradeError as error:
            raise RequestError(f"parameter {name!r}: {error}") from None
        params[name] = domain.symbol(name)
        domains[params[name]] = domain
    jets = tuple(jet(c) for c in coords)
    problem = Problem(
        key,
        kind,
        jets,
        params,
        domains,
        {},
        coordinate_domains=coordinate_domains,
        imaginary_unit=unit,
    )
    try:
        parsed = parser().parse_expression(text, problem.vocabulary())
    except ParseError as error:
        unknown = error.message.startswith("Unknown symbol")
        raise RequestError(
            f"{fields[kind]} does not parse: {error}"
            + (f"\nDeclare every parameter in {fields['parameters']}." if unknown else "")
        ) from None
    expr = problem.canonical(parsed.expr)
    if kind == "lagrangian":
        if any(expr.has(j.ddot) for j in jets):
            raise RequestError("the problem's Lagrangian contains an acceleration")
        problem.lagrangian = expr
    else:
        problem.expression = expr
    return problem


#: How an expression question may spell the imaginary unit.
IMAGINARY_UNITS = ("I", "i", "j")


def _coordinates(
    raw: Any, required: bool, fields: Mapping[str, str]
) -> tuple[list[str], dict[str, tuple[float, float]]]:
    """Coordinate names, given as a list or as {name: domain} (where to sample them)."""
    ranges: dict[str, tuple[float, float]] = {}
    if isinstance(raw, Mapping):
        names = list(raw)
        for name, dom in raw.items():
            if dom is not None:
                try:
                    ranges[name] = Domain.parse(dom).sample_range()
                except LagradeError as error:
                    raise RequestError(f"coordinate {name!r}: {error}") from None
    elif isinstance(raw, list | tuple):
        names = list(raw)
    else:
        raise RequestError('"coordinates" must be a list of names such as ["theta"]')
    if required and not names:
        raise RequestError(f"an ad-hoc Lagrangian needs {fields['coordinates']}")
    for name in names:
        if not isinstance(name, str) or not _NAME.match(name):
            raise RequestError(f"coordinate name {_shown(name)} is not a plain name {_NAME_RULE}")
        if name.endswith(("_dot", "_ddot")):
            raise RequestError(f"coordinate {name!r}: name the coordinate, not its velocity")
    if len(names) > MAX_NAMES:
        raise RequestError(f"{len(names)} coordinates; a problem may have at most {MAX_NAMES}")
    if len(set(names)) != len(names):
        twice = sorted({n for n in names if names.count(n) > 1})
        raise RequestError(f"coordinates name {', '.join(twice)} more than once")
    return names, ranges


_NAME_RULE = "(a letter, then letters, digits or _, at most 32 characters)"


def _shown(name: Any) -> str:
    text = repr(name)
    return text if len(text) <= 40 else text[:40] + "…"


def _only(spec: Mapping[str, Any], allowed: set[str]) -> None:
    extra = sorted(set(spec) - allowed)
    if extra:
        raise RequestError(
            f'"problem" has unknown field(s) {", ".join(map(repr, extra))}; allowed: '
            + ", ".join(sorted(allowed))
        )
