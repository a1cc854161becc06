"""Lagrangian mechanics on jets: the one vocabulary every other module uses.

A coordinate q comes with plain symbols q_dot and q_ddot (its jet); nothing is a function of
time, so differentiation is ordinary partial differentiation and stays fast.

Glossary (q = (q_1 … q_n), sums over j):

- total time derivative  D_t f = ∂f/∂t + Σ q̇_j ∂f/∂q_j + Σ q̈_j ∂f/∂q̇_j
- lagrangian             L = T − V
- generalized_momenta    p_j = ∂L/∂q̇_j
- euler_lagrange         E_j = D_t(∂L/∂q̇_j) − ∂L/∂q_j   (the equations of motion are E_j = 0)
- mass_matrix, forcing   E = A(q, q̇, t) q̈ − b(q, q̇, t), so the motion solves A q̈ = b
- cyclic_coordinates     q_j with ∂L/∂q_j ≡ 0 (p_j is then conserved)
- energy_function        h = Σ q̇_j p_j − L   (conserved when ∂L/∂t ≡ 0)

"≡ 0" is decided by values (`vanishing.identically_zero`), never by whether L prints the symbol:
a potential written in Cartesian form keeps sqrt(r² sin²θ + r² cos²θ), in which θ is absent.

Example, a simple pendulum (length l, angle θ from the downward vertical):
L = ½ m l² θ̇² + m g l cos θ, p_θ = m l² θ̇, E_θ = m l² θ̈ + m g l sin θ, h = ½ m l² θ̇² − m g l cos θ.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from lagrade.mechanics.vanishing import Ranges, identically_zero
from lagrade.recent import Recent

#: Time. Scenes with explicit time dependence (a driven support, a rotating hoop) use it.
t = sp.Symbol("t", real=True)

DOT = "_dot"
DDOT = "_ddot"


@dataclass(frozen=True)
class Jet:
    """A generalized coordinate with its velocity and acceleration as independent symbols."""

    name: str
    q: sp.Symbol
    dot: sp.Symbol
    ddot: sp.Symbol


def jet(name: str) -> Jet:
    """The jet of coordinate `name`: symbols `name`, `name_dot`, `name_ddot` (all real).

    Every module that needs a coordinate's symbols gets them here, so that the parser, the bank
    and the grader agree on the very same sympy objects.
    """
    return Jet(
        name,
        sp.Symbol(name, real=True),
        sp.Symbol(name + DOT, real=True),
        sp.Symbol(name + DDOT, real=True),
    )


def total_derivative(expr: sp.Expr, jets: Sequence[Jet], time: sp.Symbol = t) -> sp.Expr:
    """D_t expr = ∂expr/∂t + Σ q̇ ∂expr/∂q + Σ q̈ ∂expr/∂q̇, for expr in t, q and q̇ (a third
    derivative has no symbol, so expr must not contain q̈). `time`: the symbol t stands for
    (an expression question may declare its own)."""
    if any(expr.has(j.ddot) for j in jets):
        raise ValueError("D_t of an expression containing an acceleration needs a third derivative")
    result = sp.diff(expr, time)
    for j in jets:
        result += j.dot * sp.diff(expr, j.q) + j.ddot * sp.diff(expr, j.dot)
    return result


def lagrangian(kinetic: sp.Expr, potential: sp.Expr) -> sp.Expr:
    """L = T − V."""
    return kinetic - potential


def generalized_momenta(L: sp.Expr, jets: Sequence[Jet]) -> tuple[sp.Expr, ...]:
    """p_j = ∂L/∂q̇_j."""
    return tuple(sp.diff(L, j.dot) for j in jets)


def euler_lagrange(L: sp.Expr, jets: Sequence[Jet]) -> tuple[sp.Expr, ...]:
    """E_j = D_t(∂L/∂q̇_j) − ∂L/∂q_j; the equations of motion are E_j = 0."""
    return tuple(
        total_derivative(p, jets) - sp.diff(L, j.q)
        for p, j in zip(generalized_momenta(L, jets), jets, strict=True)
    )


def mass_matrix(equations: Sequence[sp.Expr], jets: Sequence[Jet]) -> sp.Matrix:
    """A with E = A q̈ − b: A_ij = ∂E_i/∂q̈_j (E is linear in q̈)."""
    return sp.Matrix([[sp.diff(e, j.ddot) for j in jets] for e in equations])


def forcing(equations: Sequence[sp.Expr], jets: Sequence[Jet]) -> sp.Matrix:
    """b with E = A q̈ − b: b = −E evaluated at q̈ = 0."""
    at_rest = {j.ddot: 0 for j in jets}
    return sp.Matrix([-e.xreplace(at_rest) for e in equations])


def cyclic_coordinates(
    L: sp.Expr, jets: Sequence[Jet], ranges: Ranges | None = None
) -> tuple[str, ...]:
    """Names of the q_j with ∂L/∂q_j ≡ 0 (by values, `ranges` where the symbols are drawn), so
    p_j is conserved."""
    return tuple(
        j.name for j in jets if not L.has(j.q) or identically_zero(sp.diff(L, j.q), ranges)
    )


def energy_function(L: sp.Expr, jets: Sequence[Jet]) -> sp.Expr:
    """h = Σ q̇_j p_j − L (the Jacobi integral; T + V when the constraints are scleronomic)."""
    momenta = generalized_momenta(L, jets)
    return sp.expand(sum((j.dot * p for j, p in zip(jets, momenta, strict=True)), sp.S.Zero) - L)


def speed_squared(position: Sequence[sp.Expr], jets: Sequence[Jet]) -> sp.Expr:
    """|ṙ|² of a position r(q, t), with ṙ = D_t r."""
    return sum((total_derivative(x, jets) ** 2 for x in position), sp.S.Zero)


class Derivation:
    """The derivatives of one (L, coordinates), each computed on first use and expanded: the
    momenta p_j = ∂L/∂q̇_j, the generalized forces F_j = ∂L/∂q_j (the mistake catalogue flips
    the sign of Lagrange's equation with them) and E_j = D_t p_j − F_j."""

    def __init__(self, L: sp.Expr, jets: Sequence[Jet]):
        self.L = L
        self.jets = tuple(jets)

    @cached_property
    def momenta(self) -> tuple[sp.Expr, ...]:
        return tuple(sp.expand(p) for p in generalized_momenta(self.L, self.jets))

    @cached_property
    def forces(self) -> tuple[sp.Expr, ...]:
        return tuple(sp.expand(sp.diff(self.L, j.q)) for j in self.jets)

    @cached_property
    def equations(self) -> tuple[sp.Expr, ...]:
        return tuple(
            sp.expand(total_derivative(p, self.jets) - f)
            for p, f in zip(self.momenta, self.forces, strict=True)
        )


#: Derivations by the canonical form of (L, coordinates), most recently used last.
_DERIVED_SIZE = 256
_DERIVED: Recent = Recent(_DERIVED_SIZE)
_DERIVED_LOCK = threading.Lock()  # the answer page builds views in threads
#: The derivations renamed back, by (L, coordinates, which derivatives), most recent last.
_RENAMED: Recent = Recent(_DERIVED_SIZE)


def _shared_derivation(
    L: sp.Expr, jets: Sequence[Jet]
) -> tuple[Derivation, dict[sp.Symbol, sp.Symbol]]:
    """The derivation of L with its coordinates renamed q0·, q1·, … by position (names no one
    can type, so no parameter shares them), cached under that form, and the renaming back: a
    question asked under renamed coordinates (a variant, a batch that gives one system under
    several names) is derived once. A result renamed back is the very expression deriving
    under the own names gives (tests/bank/test_shared_derivation.py checks every scene under
    every renaming)."""
    canonical = [jet(f"q{k}\N{MIDDLE DOT}") for k in range(len(jets))]
    forward: dict[sp.Symbol, sp.Symbol] = {}
    back: dict[sp.Symbol, sp.Symbol] = {}
    for own, mine in zip(jets, canonical, strict=True):
        for a, b in ((own.q, mine.q), (own.dot, mine.dot), (own.ddot, mine.ddot)):
            forward[a], back[b] = b, a
    form = L.xreplace(forward)
    key = f"{len(jets)}:{sp.srepr(form)}"
    with _DERIVED_LOCK:  # a Derivation derives nothing until asked
        found = _DERIVED.made(key, lambda: Derivation(form, canonical))
    return found, back


class LagrangianSystem:
    """Everything the five-step method derives from L and the coordinates, each computed lazily.

    A question that asks only for the momenta never forms the mass matrix; a question about the
    mass matrix never solves for q̈. Its facts (cyclic coordinates, ∂L/∂t ≡ 0) are decided by
    values at points drawn from `ranges` (each parameter's domain; a symbol without a range is
    drawn by its sign assumption).
    """

    def __init__(self, L: sp.Expr, jets: Sequence[Jet], ranges: Ranges | None = None):
        self.L = L
        self.jets = tuple(jets)
        self.ranges = dict(ranges or {})

    @property
    def coordinates(self) -> tuple[str, ...]:
        return tuple(j.name for j in self.jets)

    # Derivatives are taken once per canonical form of L (`_shared_derivation`): the same system
    # under renamed coordinates shares them and only renames the results.
    @cached_property
    def _shared(self) -> tuple[Derivation, dict[sp.Symbol, sp.Symbol]]:
        return _shared_derivation(self.L, self.jets)

    def _renamed(self, part: str) -> tuple[sp.Expr, ...]:
        # Every variant of a scene has its own system of one L: what one of them derived is
        # found by (L, coordinates) first, without renaming L to its canonical form again.
        key = (self.L, self.jets, part)
        with _DERIVED_LOCK:
            found = _RENAMED.recalled(key)
        if found is not None:
            return found
        derivation, back = self._shared  # derived outside the lock: it may take a while
        # Renaming is a bijection of symbols with the same assumptions: an expanded sum stays
        # one, so the result needs no second `expand` (which walks the whole expression again).
        found = tuple(e.xreplace(back) for e in getattr(derivation, part))
        with _DERIVED_LOCK:
            return _RENAMED.made(key, lambda: found)

    @cached_property
    def generalized_momenta(self) -> tuple[sp.Expr, ...]:
        """p_j = ∂L/∂q̇_j, expanded."""
        return self._renamed("momenta")

    @cached_property
    def euler_lagrange(self) -> tuple[sp.Expr, ...]:
        """E_j = D_t p_j − ∂L/∂q_j, expanded; E_j = 0 are the equations of motion."""
        return self._renamed("equations")

    @cached_property
    def generalized_forces(self) -> tuple[sp.Expr, ...]:
        """∂L/∂q_j, expanded."""
        return self._renamed("forces")

    @cached_property
    def mass_matrix(self) -> sp.Matrix:
        """A in E = A q̈ − b."""
        return mass_matrix(self.euler_lagrange, self.jets)

    @cached_property
    def forcing(self) -> sp.Matrix:
        """b in E = A q̈ − b."""
        return forcing(self.euler_lagrange, self.jets)

    @cached_property
    def cyclic_coordinates(self) -> tuple[str, ...]:
        """Coordinates with ∂L/∂q_j ≡ 0 (by values); their momenta are conserved."""
        return tuple(
            j.name
            for k, j in enumerate(self.jets)
            if not self.L.has(j.q) or identically_zero(self.generalized_forces[k], self.ranges)
        )

    @cached_property
    def energy_function(self) -> sp.Expr:
        """h = Σ q̇_j p_j − L."""
        return energy_function(self.L, self.jets)

    @cached_property
    def is_time_independent(self) -> bool:
        """∂L/∂t ≡ 0 (by values), so h is conserved."""
        return not self.L.has(t) or identically_zero(sp.diff(self.L, t), self.ranges)

    @cached_property
    def conserved_quantities(self) -> dict[str, sp.Expr]:
        """p_j of every cyclic q_j, and h when ∂L/∂t = 0; keyed `p_<q>` and `h`."""
        momenta = dict(zip(self.coordinates, self.generalized_momenta, strict=True))
        found = {f"p_{name}": momenta[name] for name in self.cyclic_coordinates}
        if self.is_time_independent:
            found["h"] = self.energy_function
        return found

    @cached_property
    def accelerations(self) -> tuple[sp.Expr, ...]:
        """q̈ = A⁻¹ b, solved exactly (only when asked: this is the expensive step)."""
        A, b = self.mass_matrix, self.forcing
        if A.shape == (1, 1):
            return (sp.cancel(b[0] / A[0, 0]),)
        solution = A.LUsolve(b)
        return tuple(sp.simplify(x) for x in solution)

    def on_shell(self, expr: sp.Expr) -> sp.Expr:
        """expr with q̈ replaced by the solved accelerations (for conservation checks)."""
        return expr.xreplace(
            {j.ddot: a for j, a in zip(self.jets, self.accelerations, strict=True)}
        )
