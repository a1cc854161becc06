"""The Scene type: what a scene declares (coordinates, parameters, bodies, potential, constraints,
statement), and the SceneVariant that derives everything else from it on demand.

A scene is a few declarative lines; the five-step solution (constraints and DOF, transformation
equations, T and V, L, Euler–Lagrange equations, momenta, cyclic coordinates, conserved
quantities) is derived by `lagrade.mechanics.lagrange`, lazily and cached, so asking for L never
solves for the accelerations.
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from types import SimpleNamespace
from typing import Any

import sympy as sp

import lagrade.mechanics.lagrange as mech
from lagrade.errors import SceneError
from lagrade.mechanics.bodies import (
    AXES,
    Body,
    RigidBody,
    SpatialRigidBody,
    _normalized,
    as_expr,
    body_fields,
    collapse_trig,
)
from lagrade.mechanics.dissipation import DissipativeSystem
from lagrade.mechanics.domains import (
    Domain,
    Parameter,
    exact_number,
    keeps,
    vanishes_within,
    within,
)
from lagrade.mechanics.figure import FigureHint
from lagrade.mechanics.validation import validate_variant
from lagrade.mechanics.vanishing import without_absent

#: Draws from the value pools before a scene's relations are taken as impossible to keep.
RELATION_DRAWS = 64


#: What a scene given by its Lagrangian alone can be asked (everything that follows from L).
LAGRANGIAN_PARTS = (
    "lagrangian",
    "eom",
    "momenta",
    "cyclic",
    "conserved",
    "hamiltonian",
    "hamilton_equations",
    "equilibrium",
    "normal_modes",
    "mode_shapes",
    "expression",
)


@dataclass(frozen=True)
class Quantity:
    """A numeric follow-up a problem can ask for (the wedge's acceleration, the hoop's equilibrium
    angle), as a closed form in the parameters. `claim` says what the value is in terms of the
    motion (`claim(s)`: the state and the accelerations there, or the normal-mode frequencies),
    so that it can be checked against the derived motion (`lagrade scene check`)."""

    name: str
    description: str
    expr: Callable[[SimpleNamespace], sp.Expr]
    unit: str = ""
    claim: Callable[[SimpleNamespace], Any] | None = None


@dataclass(frozen=True, eq=False)
class Scene:
    """The declaration of a mechanical system, as the lecture would pose it: what a scene file
    (`docs/scenes.md`, read by `lagrade.bank`) says, as functions of the variant's symbols.

    `bodies(s)` and `potential(s, bodies)` receive a namespace `s` of symbols: each coordinate
    `q` with `q_dot`, every parameter, `t`, and the presentation options as `s.opt[...]`.
    `constraints(s, c)` receives in `c` each body's Cartesian symbols (`c.block.x`, `c.wheel.phi`)
    and returns expressions that vanish on the constraint surface (besides planarity, which 2-D
    positions declare by themselves). `renames` offers other names for a coordinate and
    `options` other presentation choices; a seeded variant draws from both.

    A scene given by its Lagrangian alone (`lagrangian(s)`: a charged particle, a relativistic
    one) declares no bodies; it has L and all that follows from it, but no transformation
    equations, T, V, constraints or DOF, and asking for them is a SceneError that says so.

    `coordinate_domains` says where a coordinate lives (`r` positive): the consistency checks,
    what is shown and the judge's sample points keep to it. `dissipation(s)` (Rayleigh's F) and
    `forces(s)` (generalized forces Q by coordinate) enter the equations of motion,
    E_j + ∂F/∂q̇_j = Q_j (`lagrade.mechanics.dissipation`).

    In `statement`, `{theta}` stands for a coordinate (under the variant's name), `{angle_from}`
    for an option's choice (as `wording[option][choice]` reads, else the choice itself), and
    `{a}` for a parameter whose name is also an English word; handouts set coordinates and
    parameters as math. `figure(options)` is what the geometry cannot tell the figure of a
    presentation; `source` the text of the scene file the scene was read from (what a manifest
    carries).

    Scenes compare by identity: two readings of one file are one scene only when the reader
    returns the same object (`lagrade.bank` does, by the file's hash).
    """

    id: str
    title: str
    statement: str
    coordinates: tuple[str, ...]
    parameters: tuple[Parameter, ...]
    bodies: Callable[[SimpleNamespace], Sequence[Body]] = lambda s: ()
    potential: Callable[[SimpleNamespace, Sequence[Body]], sp.Expr] = lambda s, bodies: 0
    constraints: Callable[[SimpleNamespace, SimpleNamespace], Sequence[sp.Expr]] = lambda s, c: ()
    renames: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    options: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    quantities: tuple[Quantity, ...] = ()
    tags: tuple[str, ...] = ()
    wording: Mapping[str, Mapping[str, str]] = field(default_factory=dict)
    lagrangian: Callable[[SimpleNamespace], sp.Expr] | None = None
    figure: Callable[[Mapping[str, str]], FigureHint] = lambda options: FigureHint()
    source: str = ""
    coordinate_domains: Mapping[str, Domain] = field(default_factory=dict)
    relations: tuple[sp.Expr, ...] = ()
    rename_sets: tuple[tuple[str, ...], ...] = ()
    dissipation: Callable[[SimpleNamespace], sp.Expr] | None = None
    forces: Callable[[SimpleNamespace], Mapping[str, sp.Expr]] | None = None

    @property
    def nonconservative(self) -> bool:
        """The scene declares a dissipation function or generalized forces."""
        return self.dissipation is not None or self.forces is not None

    @property
    def given_by_lagrangian(self) -> bool:
        """The scene declares L itself, not bodies: parts about bodies cannot be asked."""
        return self.lagrangian is not None

    def __post_init__(self) -> None:
        problems = []
        seen: set[str] = set()
        for name in self.coordinates:
            if name in seen:
                problems.append(f"coordinates: {name!r} is declared twice")
            seen.add(name)
        for p in self.parameters:
            if p.name in seen:
                problems.append(f"parameters: {p.name!r} is already a coordinate or parameter")
            seen.add(p.name)
        for canonical, choices in self.renames.items():
            if canonical not in self.coordinates:
                problems.append(f"renames: {canonical!r} is not a coordinate")
            if not choices or choices[0] != canonical:
                problems.append(
                    f"renames: the first name for {canonical!r} must be {canonical!r} itself"
                )
        for name in self.coordinate_domains:
            if name not in self.coordinates:
                problems.append(f"domains: {name!r} is not a coordinate")
        for name, choices in self.options.items():
            if not choices:
                problems.append(f"options: {name!r} offers no choice")
        for name, words in self.wording.items():
            if name not in self.options or set(words) != set(self.options[name]):
                problems.append(f"wording: {name!r} must word each choice of an option")
        if problems:
            raise SceneError(self.id, problems)

    @cached_property
    def default(self) -> SceneVariant:
        """The variant with the declared names, the first option of each choice, symbolic values."""
        return SceneVariant(self)

    def variant(self, seed: int, numeric: bool = True) -> SceneVariant:
        """A reproducible variant: coordinate names, options and (if `numeric`) parameter values
        drawn from the declared pools with a generator seeded by (scene id, seed)."""
        rng = random.Random(f"{self.id}:{seed}")
        if self.rename_sets:  # one consistent set of names (x, y or q_1, q_2)
            names = dict(zip(self.coordinates, rng.choice(self.rename_sets), strict=True))
        else:
            names = {c: rng.choice(choices) for c, choices in sorted(self.renames.items())}
        options = {o: rng.choice(choices) for o, choices in sorted(self.options.items())}
        values = {}
        if numeric:
            values = self._values(rng)
        return SceneVariant(self, seed=seed, names=names, options=options, values=values)

    def _values(self, rng: random.Random) -> dict[str, float]:
        """Parameter values drawn from the pools, again until they keep the scene's relations
        (b < R; a scene without relations draws once, as it always has)."""
        symbols = {p.name: p.domain.symbol(p.name) for p in self.parameters}
        for _ in range(RELATION_DRAWS):
            values = {p.name: rng.choice(p.values) for p in self.parameters if p.values}
            if keeps(self.relations, {symbols[n]: v for n, v in values.items()}):
                return values
        kept = ", ".join(f"{r} > 0" for r in self.relations)
        raise SceneError(self.id, [f"relations: no values drawn from the pools keep {kept}"])


class _Declared(SimpleNamespace):
    """The names a scene's declarations may use (`s.m`, `c.bob.x`): a name the scene did not
    declare is a SceneError that names it, not a bare AttributeError from inside a lambda."""

    def __init__(self, scene_id: str = "?", prefix: str = "", /, **names: Any):
        super().__init__(**names)
        self.__dict__["_origin"] = (scene_id, prefix)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        scene_id, prefix = self.__dict__.get("_origin", ("?", ""))
        offered = ", ".join(k for k in vars(self) if not k.startswith("_"))
        problem = f"declarations: {prefix}.{name} is not declared ({prefix} offers: {offered})"
        raise SceneError(scene_id, [problem])


class SceneVariant:
    """One presentation of a scene (names, options, numeric values) and everything derived from
    it, each result computed on first use and cached."""

    def __init__(
        self,
        scene: Scene,
        seed: int | None = None,
        names: Mapping[str, str] | None = None,
        options: Mapping[str, str] | None = None,
        values: Mapping[str, float] | None = None,
    ):
        self.scene = scene
        self.seed = seed
        self.names = {c: c for c in scene.coordinates} | dict(names or {})
        self.options = {o: choices[0] for o, choices in scene.options.items()} | dict(options or {})
        self.values = dict(values or {})
        problems = []
        for o, v in self.options.items():
            if o not in scene.options or v not in scene.options[o]:
                problems.append(
                    f"options: {o}={v!r} is not offered (offered: {scene.options.get(o)})"
                )
        clash = set(self.names.values()) & {p.name for p in scene.parameters}
        if clash or len(set(self.names.values())) != len(self.names):
            problems.append(f"renames: coordinate names {sorted(self.names.values())} clash")
        if problems:
            raise SceneError(scene.id, problems)

    def __repr__(self) -> str:
        return f"SceneVariant({self.scene.id!r}, seed={self.seed})"

    # --- symbols -------------------------------------------------------------------------------
    @cached_property
    def jets(self) -> tuple[mech.Jet, ...]:
        """One jet per coordinate, named as this variant presents it."""
        return tuple(mech.jet(self.names[c]) for c in self.scene.coordinates)

    @property
    def coordinates(self) -> tuple[str, ...]:
        """Coordinate names as this variant presents them."""
        return tuple(j.name for j in self.jets)

    @cached_property
    def parameter_symbols(self) -> dict[str, sp.Symbol]:
        return {p.name: p.domain.symbol(p.name) for p in self.scene.parameters}

    @cached_property
    def domains(self) -> dict[str, Domain]:
        """Each parameter's domain, by name."""
        return {p.name: p.domain for p in self.scene.parameters}

    @cached_property
    def coordinate_domains(self) -> dict[str, Domain]:
        """Each coordinate's declared domain, keyed by this variant's name for it (a coordinate
        declared without one is real)."""
        return {self.names[c]: d for c, d in self.scene.coordinate_domains.items()}

    def within_domains(self, expr: sp.Expr, then=lambda e: e) -> sp.Expr:
        """expr simplified as the coordinates' domains allow (√(r²) = r for r > 0), and by
        `then` under their assumptions."""
        declared = self.coordinate_domains
        signs = {j.q: declared[j.name] for j in self.jets if j.name in declared}
        return within(expr, signs, then)

    @cached_property
    def sample_box(self) -> dict[sp.Symbol, tuple[float, float]]:
        """Where the scene's own checks draw generic points: the parameters and the declared
        coordinates inside their domains, the other coordinates over ±2.5 (both signs: a
        constraint that holds only for r > 0 needs r's domain declared), q̇ in ±2, t in (0.1, 3)."""
        box = {s: self.domains[str(s)].sample_range() for s in self.parameter_symbols.values()}
        for j in self.jets:
            domain = self.coordinate_domains.get(j.name)
            box[j.q] = domain.sample_range() if domain is not None else (-2.5, 2.5)
            box[j.dot] = (-2.0, 2.0)
        return box | {mech.t: (0.1, 3.0)}

    def vanishes_in_domains(self, expr: sp.Expr) -> bool:
        """Whether expr is 0 wherever the domains let the coordinates go (numerically): a
        constraint with √ or atan2 that holds on the physical branch only."""
        return vanishes_within(expr, self.sample_box, self.scene.relations)

    @cached_property
    def ranges(self) -> dict[sp.Symbol, tuple[float, float]]:
        """Where the facts (`vanishing`) draw each parameter and each coordinate that declares a
        domain: inside it."""
        box = {s: self.domains[n].sample_range() for n, s in self.parameter_symbols.items()}
        for j in self.jets:
            domain = self.coordinate_domains.get(j.name)
            if domain is not None:
                box[j.q] = domain.sample_range()
        return box

    @cached_property
    def namespace(self) -> SimpleNamespace:
        """What a scene's declarations see: canonical names bound to this variant's symbols."""
        ns: dict[str, Any] = dict(self.parameter_symbols)
        for canonical, j in zip(self.scene.coordinates, self.jets, strict=True):
            ns[canonical], ns[canonical + mech.DOT] = j.q, j.dot
        ns["t"] = mech.t
        ns["opt"] = dict(self.options)
        return _Declared(self.scene.id, "s", **ns)

    @cached_property
    def figure(self) -> FigureHint:
        """What the geometry cannot tell this presentation's figure (the scene's `[figure]`)."""
        return self.scene.figure(self.options)

    # --- step 1–3: bodies, transformation equations, constraints, DOF ---------------------------
    @cached_property
    def bodies(self) -> tuple[Body, ...]:
        """The bodies in this variant's symbols; none for a scene given by its Lagrangian."""
        return tuple(_normalized(b) for b in self.scene.bodies(self.namespace))

    def _needs_bodies(self, what: str) -> None:
        """Refuse `what` (T, V, the transformation, …) for a scene given by its Lagrangian."""
        if self.scene.given_by_lagrangian:
            raise SceneError(
                self.scene.id,
                [
                    f"{what}: the scene is given by its Lagrangian and declares no bodies, so "
                    f"it has no {what}; ask for {', '.join(LAGRANGIAN_PARTS)}"
                ],
            )

    @cached_property
    def transformation(self) -> dict[str, sp.Expr]:
        """The transformation equations: each body's Cartesian coordinates (and rotation angle)
        in terms of the generalized coordinates and t, keyed `x_block`, `phi_wheel`, …"""
        self._needs_bodies("transformation equations")
        eqs: dict[str, sp.Expr] = {}
        for b in self.bodies:
            for axis, value in zip(AXES, b.position, strict=False):
                eqs[f"{axis}_{b.name}"] = value
            if isinstance(b, RigidBody):
                eqs[f"phi_{b.name}"] = b.angle
            if isinstance(b, SpatialRigidBody):
                eqs |= {f"{a}_{b.name}": e for a, e in zip(b.ANGLES, b.angles, strict=True)}
        return eqs

    @cached_property
    def cartesian(self) -> SimpleNamespace:
        """Cartesian symbols per body for writing constraints: `c.block.x`, `c.wheel.phi`."""
        per_body = {}
        for b in self.bodies:
            names = list(AXES) + (["phi"] if isinstance(b, RigidBody) else [])
            names += list(SpatialRigidBody.ANGLES) if isinstance(b, SpatialRigidBody) else []
            symbols = {a: sp.Symbol(f"{a}_{b.name}", real=True) for a in names}
            per_body[b.name] = _Declared(self.scene.id, f"c.{b.name}", **symbols)
        return _Declared(self.scene.id, "c", **per_body)

    @cached_property
    def constraints(self) -> tuple[tuple[str, sp.Expr], ...]:
        """Every holonomic constraint f(x, y, z, t) = 0 with a short description: the declared
        ones, then planarity (z = 0 for 2-D point masses; z = 0 and no tilt for rigid bodies)."""
        self._needs_bodies("constraints")
        declared = tuple(
            ("declared", as_expr(f)) for f in self.scene.constraints(self.namespace, self.cartesian)
        )
        implied = []
        for b in self.bodies:
            if b.planar:
                implied.append(("motion in the x-y plane", getattr(self.cartesian, b.name).z))
            if isinstance(b, RigidBody):
                implied.append(("no tilt about the x axis (it turns about z only)", sp.S.Zero))
                implied.append(("no tilt about the y axis (it turns about z only)", sp.S.Zero))
        return declared + tuple(implied)

    @cached_property
    def dof(self) -> int:
        """DOF = Σ freedoms − k: 3 per point mass, 6 per rigid body, minus the constraints."""
        self._needs_bodies("degrees of freedom")
        return sum(b.freedoms for b in self.bodies) - len(self.constraints)

    def _cartesian_substitution(self) -> dict[sp.Symbol, sp.Expr]:
        subs: dict[sp.Symbol, sp.Expr] = {}
        for b in self.bodies:
            c = getattr(self.cartesian, b.name)
            position = tuple(b.position) + (sp.S.Zero,) * (3 - len(b.position))
            for axis, value in zip(AXES, position, strict=True):
                subs[getattr(c, axis)] = value
            if isinstance(b, RigidBody):
                subs[c.phi] = b.angle
            if isinstance(b, SpatialRigidBody):
                for a, e in zip(b.ANGLES, b.angles, strict=True):
                    subs[getattr(c, a)] = e
        return subs

    def validate(self) -> None:
        """Check the declaration against itself and raise one SceneError listing every problem
        (`lagrade.mechanics.validation`)."""
        validate_variant(self)

    # --- step 4: T, V, L -----------------------------------------------------------------------
    @cached_property
    def _presented(self) -> SceneVariant:
        """The first variant of this scene with this presentation (names and options): T, V and
        L depend on nothing else (the values are numbers for the handout, never in them), so the
        variants of a class that share a presentation derive them once. A variant of another
        kind (a student's own coordinates: other positions) derives its own."""
        if type(self) is not SceneVariant:
            return self
        key = (tuple(sorted(self.names.items())), tuple(sorted(self.options.items())))
        shared = self.scene.__dict__.setdefault("_presentations", {})
        return shared.setdefault(key, self)

    @cached_property
    def kinetic_energy(self) -> sp.Expr:
        """T = Σ ½ m |ṙ|² (+ ½ I φ̇² for rigid bodies), expanded and trig-simplified."""
        self._needs_bodies("T")
        if self._presented is not self:
            return self._presented.kinetic_energy
        T = sum((b.kinetic_energy(self.jets) for b in self.bodies), sp.S.Zero)
        return collapse_trig(self.within_domains(T))

    @cached_property
    def _declared_potential(self) -> sp.Expr:
        """V as the scene declares it, expanded."""
        self._needs_bodies("V")
        if self._presented is not self:
            return self._presented.potential_energy
        V = as_expr(self.scene.potential(self.namespace, self.bodies))
        return sp.expand(self.within_domains(V))

    @cached_property
    def potential_energy(self) -> sp.Expr:
        """V as declared (a generalized potential may depend on velocities), written without
        the coordinates (and t) that L's facts show absent and V does not depend on either."""
        V = self._declared_potential
        return without_absent(V, self._absent, self.ranges) if self._absent else V

    @cached_property
    def _derived_lagrangian(self) -> sp.Expr:
        """L = T − V, or the scene's own L, expanded, as derived (before `_absent` is written
        out)."""
        if self.scene.lagrangian is not None:
            return sp.expand(as_expr(self.scene.lagrangian(self.namespace)))
        return mech.lagrangian(self.kinetic_energy, self._declared_potential)

    @cached_property
    def _absent(self) -> list[sp.Symbol]:
        """The coordinates (and t) L prints but does not depend on, by its facts (decided by
        values: ∂L/∂q_j, which the equations of motion need anyway, shared by canonical form):
        a potential in Cartesian form keeps sqrt(r² sin²θ + r² cos²θ), in which θ is absent."""
        L = self._derived_lagrangian
        facts = mech.LagrangianSystem(L, self.jets, self.ranges)
        cyclic = set(facts.cyclic_coordinates)
        absent = [j.q for j in self.jets if j.name in cyclic and L.has(j.q)]
        if L.has(mech.t) and facts.is_time_independent:
            absent.append(mech.t)
        return absent

    @cached_property
    def lagrangian(self) -> sp.Expr:
        """L = T − V, or the scene's own L (expanded) when it is given by its Lagrangian, written
        without the coordinates (and t) it prints but does not depend on (sqrt(r² sin²θ +
        r² cos²θ) is |r|), each replaced by a value at which L is unchanged by values: the key,
        the facts and the judge read one L in which a cyclic coordinate is not printed."""
        L = self._derived_lagrangian
        return without_absent(L, self._absent, self.ranges) if self._absent else L

    @cached_property
    def system(self) -> mech.LagrangianSystem:
        """The Euler–Lagrange machinery for this L (momenta, EOM, cyclic, h, …), all lazy; with
        the scene's dissipation and forces in its equations of motion when it declares them."""
        if not self.scene.nonconservative:
            return mech.LagrangianSystem(self.lagrangian, self.jets, self.ranges)
        return DissipativeSystem(
            self.lagrangian, self.jets, self.dissipation, self.generalized_forces, self.ranges
        )

    @cached_property
    def dissipation(self) -> sp.Expr:
        """Rayleigh's dissipation function F(q, q̇, t) (0 when the scene declares none)."""
        if self.scene.dissipation is None:
            return sp.S.Zero
        return sp.expand(self.within_domains(as_expr(self.scene.dissipation(self.namespace))))

    @cached_property
    def generalized_forces(self) -> tuple[sp.Expr, ...]:
        """The given generalized forces Q_j, one per coordinate (0 where none is given)."""
        given = {} if self.scene.forces is None else self.scene.forces(self.namespace)
        return tuple(as_expr(given.get(c, 0)) for c in self.scene.coordinates)

    # --- conveniences -------------------------------------------------------------------------
    @property
    def generalized_momenta(self) -> tuple[sp.Expr, ...]:
        return self.system.generalized_momenta

    @property
    def euler_lagrange(self) -> tuple[sp.Expr, ...]:
        return self.system.euler_lagrange

    @property
    def cyclic_coordinates(self) -> tuple[str, ...]:
        return self.system.cyclic_coordinates

    @property
    def conserved_quantities(self) -> dict[str, sp.Expr]:
        return self.system.conserved_quantities

    @cached_property
    def quantities(self) -> dict[str, sp.Expr]:
        """The scene's numeric follow-ups as closed forms in the parameters."""
        return {q.name: as_expr(q.expr(self.namespace)) for q in self.scene.quantities}

    @cached_property
    def used_parameters(self) -> tuple[str, ...]:
        """The parameters this variant needs, in declaration order: those its bodies, potential,
        constraints or quantities contain, or its statement names. An option can leave one out
        (no k for uniform gravity, no M for a massless pulley), and a handout that lists it
        anyway sends students looking for a term that is not there."""
        exprs = [x for b in self.bodies for _, field in body_fields(b) for x in field]
        exprs += list(self.quantities.values())
        if self.scene.given_by_lagrangian:
            exprs.append(self.lagrangian)
        else:
            exprs += [self.potential_energy, *(f for _, f in self.constraints)]
        symbols: set[sp.Basic] = set().union(*(as_expr(x).free_symbols for x in exprs))
        words = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", self.statement()))
        return tuple(
            name
            for name, symbol in self.parameter_symbols.items()
            if symbol in symbols or name in words
        )

    @cached_property
    def numeric_values(self) -> dict[sp.Symbol, sp.Expr]:
        """The drawn parameter values as exact numbers (decimals read as rationals)."""
        return {self.parameter_symbols[n]: exact_number(v) for n, v in self.values.items()}

    @property
    def statement_fill(self) -> dict[str, str]:
        """What each `{field}` of the statement reads as in this variant: a coordinate's name,
        an option's wording, a parameter's name."""
        words = {o: self.scene.wording.get(o, {}).get(v, v) for o, v in self.options.items()}
        return (
            {p.name: p.name for p in self.scene.parameters}
            | {c: self.names[c] for c in self.scene.coordinates}
            | words
        )

    def statement(self) -> str:
        """The problem text with this variant's coordinate names and option words filled in."""
        return self.scene.statement.format(**self.statement_fill)
