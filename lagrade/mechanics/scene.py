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
from sympy.simplify.fu import TR10i

from lagrade.errors import SceneError
from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.domains import Domain
from lagrade.mechanics.figure import FigureHint

AXES = ("x", "y", "z")
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
    "expression",
)


def as_expr(value: object) -> sp.Expr:
    """A scene declaration's value as a sympy expression, without evaluating text.

    A scene file's expressions arrive already read by the notation layer (`lagrade.bank`), so
    what comes here is a sympy object or a plain number (the 0 of a fixed axle); a string is
    refused rather than parsed, so nothing here can turn text into code.
    """
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise TypeError(f"a scene declares sympy expressions or numbers, not {value!r}")
    return sp.Integer(value) if isinstance(value, int) else sp.Float(value)


@dataclass(frozen=True)
class Parameter:
    """A named constant of a scene, with the domain it lives in and, for numeric variants, its SI
    unit and a pool of values to draw from (empty pool: the parameter stays symbolic)."""

    name: str
    domain: Domain
    unit: str = ""
    values: tuple[float, ...] = ()
    description: str = ""


def param(
    name: str,
    domain: str | Domain | None = "positive",
    unit: str = "",
    values: Sequence[float] = (),
    description: str = "",
) -> Parameter:
    """Declare a parameter; `domain` is `positive`, `nonnegative`, `real` or an interval."""
    if domain is None:
        raise SceneError(
            "?", [f"parameter {name!r}: no domain (declare positive, real or an interval)"]
        )
    return Parameter(name, Domain.parse(domain), unit, tuple(values), description)


@dataclass(frozen=True)
class PointMass:
    """A point mass at `position` (2 components: motion in the x–y plane, so z = 0 is a
    constraint; or 3 components), each a function of the coordinates and t. y (or z for 3-D
    positions) points up."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, ...]

    freedoms = 3

    @property
    def planar(self) -> bool:
        return len(self.position) == 2

    def kinetic_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """T = ½ m |ṙ|²."""
        return sp.Rational(1, 2) * self.mass * mech.speed_squared(self.position, jets)


@dataclass(frozen=True)
class RigidBody:
    """A rigid body moving in the x–y plane: its centre of mass at `position`, turned by `angle`
    about the z axis, with moment of inertia `inertia` about its centre of mass. In space it has
    6 freedoms; staying in the plane costs 3 (z = 0 and the two tilts)."""

    name: str
    mass: sp.Expr
    position: tuple[sp.Expr, sp.Expr]
    inertia: sp.Expr
    angle: sp.Expr

    freedoms = 6
    planar = True

    def kinetic_energy(self, jets: Sequence[mech.Jet]) -> sp.Expr:
        """T = ½ m |ṙ_cm|² + ½ I φ̇² (König's theorem for plane motion)."""
        omega = mech.total_derivative(self.angle, jets)
        translation = sp.Rational(1, 2) * self.mass * mech.speed_squared(self.position, jets)
        return translation + sp.Rational(1, 2) * self.inertia * omega**2


Body = PointMass | RigidBody


def gravity(g: sp.Expr, bodies: Sequence[Body], axis: str = "y") -> sp.Expr:
    """V = Σ m g h for uniform gravity along −axis (h is the `axis` component of each position)."""
    index = AXES.index(axis)
    return sum((b.mass * g * b.position[index] for b in bodies), sp.S.Zero)


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
        names = {c: rng.choice(choices) for c, choices in sorted(self.renames.items())}
        options = {o: rng.choice(choices) for o, choices in sorted(self.options.items())}
        values = {}
        if numeric:
            values = {p.name: rng.choice(p.values) for p in self.parameters if p.values}
        return SceneVariant(self, seed=seed, names=names, options=options, values=values)


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
        return eqs

    @cached_property
    def cartesian(self) -> SimpleNamespace:
        """Cartesian symbols per body for writing constraints: `c.block.x`, `c.wheel.phi`."""
        per_body = {}
        for b in self.bodies:
            names = list(AXES) + (["phi"] if isinstance(b, RigidBody) else [])
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
        return subs

    def validate(self) -> None:
        """Check the declaration against itself and raise one SceneError listing every problem:
        symbols without a declared parameter, coordinates that appear nowhere, constraints that
        the transformation equations do not satisfy identically, a DOF count that differs from
        the number of coordinates, and a transformation without full rank."""
        problems: list[str] = []
        known = set(self.parameter_symbols.values()) | {mech.t}
        for j in self.jets:
            known |= {j.q, j.dot}
        if self.scene.given_by_lagrangian:
            self._validate_lagrangian(known)
            return
        used: set[sp.Symbol] = set()
        for b in self.bodies:
            for label, expr in _body_fields(b):
                for x in expr:
                    free = x.free_symbols
                    used |= free
                    for s in sorted(free - known, key=str):
                        problems.append(
                            f"bodies: {b.name}.{label} uses {s}, which is not a declared parameter"
                        )
        V = self.potential_energy
        used |= V.free_symbols
        for s in sorted(V.free_symbols - known, key=str):
            problems.append(f"potential: uses {s}, which is not a declared parameter")
        for j in self.jets:
            if j.q not in used and j.dot not in used:
                problems.append(
                    f"coordinates: {j.name!r} appears in no position and not in the potential"
                )
        subs = self._cartesian_substitution()
        for i, (label, f) in enumerate(self.constraints):
            if label != "declared":
                continue
            residual = sp.simplify(sp.expand_trig(f.xreplace(subs)))
            if residual != 0:
                problems.append(
                    f"constraints: constraint {i + 1} ({f} = 0) is not satisfied by the "
                    f"transformation equations; it leaves {residual}"
                )
        if self.dof != len(self.jets):
            problems.append(
                f"constraints: 3N - k gives {self.dof} degrees of freedom but the scene declares "
                f"{len(self.jets)} coordinates {list(self.coordinates)}"
            )
        rank = self._jacobian_rank()
        if rank < len(self.jets):
            problems.append(
                f"bodies: the transformation has rank {rank} < {len(self.jets)}; some coordinate "
                "does not move any body independently"
            )
        if problems:
            raise SceneError(self.scene.id, problems)

    def _validate_lagrangian(self, known: set[sp.Symbol]) -> None:
        """A given L: declared symbols only, no acceleration, every coordinate in it."""
        problems = []
        L = self.lagrangian
        for s in sorted(L.free_symbols - known, key=str):
            problems.append(f"lagrangian: uses {s}, which is not declared")
        for j in self.jets:
            if L.has(j.ddot):
                problems.append(f"lagrangian: contains the acceleration {j.ddot}")
            if not L.has(j.q) and not L.has(j.dot):
                problems.append(f"coordinates: {j.name!r} appears nowhere in the Lagrangian")
        if problems:
            raise SceneError(self.scene.id, problems)

    def _jacobian_rank(self) -> int:
        """Rank of ∂(positions, angles)/∂q at a seeded generic point (numerically)."""
        rows = list(self.transformation.values())
        J = sp.Matrix([[sp.diff(r, j.q) for j in self.jets] for r in rows])
        rng = random.Random(0)
        point = {
            s: rng.uniform(*self.domains[str(s)].sample_range())
            for s in self.parameter_symbols.values()
        }
        point |= {j.q: rng.uniform(0.2, 1.2) for j in self.jets} | {mech.t: 0.7}
        numeric = J.xreplace(point).evalf()
        import numpy as np

        return int(np.linalg.matrix_rank(np.array(numeric.tolist(), dtype=float), tol=1e-9))

    # --- step 4: T, V, L -----------------------------------------------------------------------
    @cached_property
    def kinetic_energy(self) -> sp.Expr:
        """T = Σ ½ m |ṙ|² (+ ½ I φ̇² for rigid bodies), expanded and trig-simplified."""
        self._needs_bodies("T")
        T = sum((b.kinetic_energy(self.jets) for b in self.bodies), sp.S.Zero)
        return _tidy(T)

    @cached_property
    def potential_energy(self) -> sp.Expr:
        """V as declared (a generalized potential may depend on velocities)."""
        self._needs_bodies("V")
        return sp.expand(as_expr(self.scene.potential(self.namespace, self.bodies)))

    @cached_property
    def lagrangian(self) -> sp.Expr:
        """L = T − V, or the scene's own L (expanded) when it is given by its Lagrangian."""
        if self.scene.lagrangian is not None:
            return sp.expand(as_expr(self.scene.lagrangian(self.namespace)))
        return mech.lagrangian(self.kinetic_energy, self.potential_energy)

    @cached_property
    def system(self) -> mech.LagrangianSystem:
        """The Euler–Lagrange machinery for this L (momenta, EOM, cyclic, h, …), all lazy."""
        return mech.LagrangianSystem(self.lagrangian, self.jets)

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
        exprs = [x for b in self.bodies for _, field in _body_fields(b) for x in field]
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
        return {
            self.parameter_symbols[n]: sp.nsimplify(v, rational=True)
            for n, v in self.values.items()
        }

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


def _body_fields(body: Body) -> list[tuple[str, tuple]]:
    """A body's declared expressions by field: position, mass, and a rigid body's inertia and
    angle."""
    fields = [("position", tuple(body.position)), ("mass", (body.mass,))]
    if isinstance(body, RigidBody):
        fields += [("inertia", (body.inertia,)), ("angle", (body.angle,))]
    return fields


def _normalized(body: Body) -> Body:
    """A declared body with every field a sympy expression (positions, mass, inertia, angle)."""
    fields = {**body.__dict__, "position": tuple(as_expr(x) for x in body.position)}
    fields["mass"] = as_expr(body.mass)
    if isinstance(body, RigidBody):
        fields["inertia"], fields["angle"] = as_expr(body.inertia), as_expr(body.angle)
    return type(body)(**fields)


def _tidy(expr: sp.Expr) -> sp.Expr:
    """T as the lecture writes it: sin² + cos² collapsed, cos a cos b + sin a sin b → cos(a − b).

    A targeted rewrite (Pythagoras both ways, keep the shorter; then fu's TR10i) instead of
    `trigsimp`, which is ~20× slower and dominated the derivation time of every scene.
    """
    expanded = sp.expand(expr)
    angles = {f.args[0] for f in expanded.atoms(sp.sin, sp.cos)}
    if not angles:
        return expanded
    via_sin = sp.expand(expanded.xreplace({sp.cos(u) ** 2: 1 - sp.sin(u) ** 2 for u in angles}))
    via_cos = sp.expand(expanded.xreplace({sp.sin(u) ** 2: 1 - sp.cos(u) ** 2 for u in angles}))
    shortest = min((expanded, via_sin, via_cos), key=sp.count_ops)
    combined = sp.expand(TR10i(shortest))
    return combined if sp.count_ops(combined) <= sp.count_ops(shortest) else shortest
