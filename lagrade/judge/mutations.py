"""Mutations of a reference, in sympy alone: each function takes a reference (L, T, V, a momentum,
the Euler–Lagrange equations, a closed form) and returns the wrong answers of known kinds that
students write for it, each with the sentence that names the mistake in the student's terms."""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Union

import sympy as sp

from lagrade.mechanics import Jet, LagrangianSystem, SceneVariant
from lagrade.notation import plain


class Sentence:
    """A mutant's sentence, written on first use: `template.format(**given)`, with each
    expression of `shown` printed by `plain`, then each (old, new) of `edits` replaced in turn.
    Most mutants are never named (a wrong answer matches one of them, or none), and printing
    every term of a catalogue was most of the cost of its sentences; the text is the very
    string the eager f-string gave. Compared and hashed by that text."""

    __slots__ = ("_template", "_shown", "_given", "_edits", "_text")

    def __init__(
        self,
        template: str,
        shown: dict[str, sp.Basic],
        given: dict[str, Any] | None = None,
        edits: tuple[tuple[str, str], ...] = (),
    ) -> None:
        self._template, self._shown, self._given = template, shown, given or {}
        self._edits = edits
        self._text: str | None = None

    @property
    def text(self) -> str:
        if self._text is None:
            text = self._template.format(
                **{k: plain(e) for k, e in self._shown.items()}, **self._given
            )
            for old, new in self._edits:
                text = text.replace(old, new)
            self._text = text
        return self._text

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Sentence | str):
            return self.text == said_text(other)
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.text)

    def __repr__(self) -> str:
        return repr(self.text)


#: What a mutant says: its sentence, or how to write it on first use.
Said = Union[str, Sentence]  # noqa: UP007 - a runtime alias


def said_text(said: Said) -> str:
    """The sentence `said` stands for."""
    return said if isinstance(said, str) else said.text


def replaced(said: Said, old: str, new: str) -> Said:
    """`said` with `old` replaced by `new` (as str.replace), written when it is read."""
    if isinstance(said, str):
        return said.replace(old, new)
    return Sentence(said._template, said._shown, said._given, (*said._edits, (old, new)))


@dataclass(frozen=True)
class Mutant:
    """A wrong answer of a known kind: `kind` for tests and statistics, `message` for the
    student (`said`: the sentence, or a `Sentence` that writes it when first read), `expr` the
    mutated reference.

    A mutant that changes a few terms of a reference holds the reference as `base` and the
    change as scaled `pieces`, expr = base + Σ c·piece: its values are the base's plus the
    pieces' (every evaluation is linear in the expression), so the catalogue evaluates the
    reference once and each small piece once, and forms no sympy sum per mutant."""

    kind: str
    said: Said
    base: sp.Expr
    pieces: tuple[tuple[sp.Rational, sp.Expr], ...] = ()
    #: How many terms of the reference the mistake changes, where the kind says (one term of a
    #: single-term mistake, whatever its pieces); else counted from the change (`terms_changed`).
    changes: int | None = None

    @property
    def message(self) -> str:
        """The sentence that names the mistake to the student."""
        return said_text(self.said)

    @property
    def expr(self) -> sp.Expr:
        """The mutated expression (formed on first use: matching needs only the pieces)."""
        if not self.pieces:
            return self.base
        cached = self.__dict__.get("_expr")
        if cached is None:
            cached = sp.Add(self.base, *(c * e for c, e in self.pieces))
            object.__setattr__(self, "_expr", cached)
        return cached


def terms_changed(
    m: Mutant, reference: sp.Expr, counts: Callable[[sp.Expr], bool] | None = None
) -> int:
    """How many terms of `reference` the mistake m changes — those `counts` says matter (in L a
    constant term changes no motion) — : of two true explanations of a wrong answer, the one
    that changes fewer terms of what the student wrote is the one to name."""
    if m.changes is not None:
        return m.changes
    change = sp.expand(sp.Add(*(c * e for c, e in m.pieces)) if m.pieces else m.expr - reference)
    if change.has(sp.sin) and change.has(sp.cos):
        change = sp.expand(_without_sin_squared(change))  # a body's T has sin² + cos² in it
    terms = sp.Add.make_args(change)
    return max(1, sum(1 for term in terms if counts is None or counts(term)))


def _without_sin_squared(expr: sp.Expr) -> sp.Expr:
    """expr with sin(u)^n written (1 − cos(u)²) sin(u)^(n−2): sin² + cos² becomes 1 once
    expanded, at a fraction of trigsimp's cost."""
    return expr.replace(
        lambda e: e.is_Pow and isinstance(e.base, sp.sin) and e.exp.is_Integer and e.exp >= 2,
        lambda e: (1 - sp.cos(e.base.args[0]) ** 2) * sp.sin(e.base.args[0]) ** (e.exp - 2),
    )


def swap_sin_cos(expr: sp.Expr) -> sp.Expr:
    """expr with every sin(u) written as cos(u) and every cos(u) as sin(u). A subtree with no
    sin or cos in it is returned as it is, not rebuilt: rebuilding it gives the same expression
    at a cost that was most of this function's (the catalogue swaps every term of L)."""
    if isinstance(expr, sp.sin):
        return sp.cos(swap_sin_cos(expr.args[0]))
    if isinstance(expr, sp.cos):
        return sp.sin(swap_sin_cos(expr.args[0]))
    if not expr.args:
        return expr
    args = tuple(swap_sin_cos(a) for a in expr.args)
    if all(new is old for new, old in zip(args, expr.args, strict=True)):
        return expr
    return expr.func(*args)


def expanded_terms(expr: sp.Expr) -> tuple[sp.Expr, ...]:
    """The terms of expr, expanded."""
    return sp.Add.make_args(sp.expand(expr))


def velocities_in(term: sp.Expr, jets: Sequence[Jet]) -> list[sp.Symbol]:
    """The velocities q̇ that occur in term."""
    return [j.dot for j in jets if term.has(j.dot)]


def factors_of(term: sp.Expr, parameters: Iterable[sp.Symbol]) -> list[sp.Symbol]:
    """Parameters that multiply the term (not those inside a function's argument)."""
    factors = sp.Mul.make_args(term)
    bases = {f.base if isinstance(f, sp.Pow) else f for f in factors}
    return [p for p in parameters if p in bases]


def term_mutants(expr: sp.Expr, what: str, parameters: Sequence[sp.Symbol]) -> list[Mutant]:
    """Single-term mutations of expr: a term with the wrong sign, left out, with sin and cos
    swapped, twice or half its size, without one of its parameter factors."""
    return list(iter_term_mutants(expr, what, parameters))


def iter_term_mutants(
    expr: sp.Expr, what: str, parameters: Sequence[sp.Symbol]
) -> Iterator[Mutant]:
    """`term_mutants`, one term at a time (the lazy catalogue stops at the first match)."""
    terms = expanded_terms(expr)
    base = sp.Add(*terms)
    for term in terms:
        yield from one_term_mutants(base, term, what, parameters)


def one_term_mutants(
    base: sp.Expr, term: sp.Expr, what: str, parameters: Sequence[sp.Symbol]
) -> list[Mutant]:
    """The single-term mistakes of one term of `base` (its expanded sum), with their sentences."""
    return [
        Mutant(kind, _term_sentence(kind, term, what, factor), base, pieces, 1)
        for kind, pieces, factor in term_specs(term, parameters)
    ]


def _term_sentence(kind: str, term: sp.Expr, what: str, factor: sp.Symbol | None) -> Sentence:
    """The sentence of a single-term mistake (`_TERM_MESSAGES`), printed when it is read."""
    return Sentence(_TERM_MESSAGES[kind], {"t": term}, {"w": what, "p": factor})


#: The sentence of each single-term mistake: t the term, w what it is in, p the missing factor.
_TERM_MESSAGES = {
    "wrong_sign": "the term {t} in {w} has the wrong sign",
    "sin_cos_swapped": "sin and cos are swapped in the term {t} of {w}",
    "missing_factor": "the term {t} in {w} lacks the factor {p}",
    "missing_term": "{w} lacks the term {t}",
    "factor_two": "the term {t} in {w} is twice too large",
    "factor_half": "the term {t} in {w} is half what it should be",
}


def term_specs(
    term: sp.Expr,
    parameters: Sequence[sp.Symbol],
    divide: Callable[[sp.Expr, sp.Symbol], Any] = operator.truediv,
) -> list[tuple[str, tuple[tuple[sp.Rational, Any], ...], sp.Symbol | None]]:
    """The single-term mistakes of one term, in catalogue order, as (kind, pieces added to the
    reference, the parameter factor left out): the wrong sign, sin and cos swapped, without one
    of its parameter factors, left out, twice or half its size. `divide(term, p)` makes the
    piece of a term without its factor p (the fingerprints divide its values instead)."""
    one, two, half = sp.Integer(1), sp.Integer(2), sp.Rational(1, 2)
    out: list = [("wrong_sign", ((-two, term),), None)]
    if term.has(sp.sin) or term.has(sp.cos):
        swapped = swap_sin_cos(term)
        if swapped != term:
            out.append(("sin_cos_swapped", ((-one, term), (one, swapped)), None))
    for p in factors_of(term, parameters):
        out.append(("missing_factor", ((-one, term), (one, divide(term, p))), p))
    out.append(("missing_term", ((-one, term),), None))
    out.append(("factor_two", ((one, term),), None))
    out.append(("factor_half", ((-half, term),), None))
    return out


def kinetic_mutants(T: sp.Expr, jets: Sequence[Jet], what: str) -> list[Mutant]:
    """Mistakes in T itself: the ½ dropped on one term or on all of T, a missing cross term, a
    missing term of the prescribed motion (centripetal, ω²)."""
    out: list[Mutant] = []
    terms = expanded_terms(T)
    for k, term in enumerate(terms):
        rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
        vel = velocities_in(term, jets)
        coeff = term.as_coeff_Mul()[0]
        if vel and isinstance(coeff, sp.Rational) and coeff.q % 2 == 0:
            out.append(
                Mutant(
                    "dropped_half",
                    Sentence(
                        "the ½ is missing in the kinetic term {t} of {w}", {"t": term}, {"w": what}
                    ),
                    rest + 2 * term,
                )
            )
        if len(vel) >= 2:
            cross = Sentence("{w} lacks the cross term in {c}", {"c": sp.Mul(*vel)}, {"w": what})
            out.append(Mutant("missing_cross_term", cross, rest))
        if not vel:
            out.append(
                Mutant(
                    "missing_driven_term",
                    Sentence(
                        "{w} lacks the term {t} from the prescribed motion (the centripetal "
                        "or ω² term of the kinetic energy)",
                        {"t": term},
                        {"w": what},
                    ),
                    rest,
                )
            )
    return out


def body_mutants(variant: SceneVariant | None, T: sp.Expr, what: str) -> list[Mutant]:
    """Per body of a scene with two or more: its kinetic energy without the ½, or left out."""
    if variant is None or len(variant.bodies) < 2:
        return []
    out = []
    for body in variant.bodies:
        Tb = sp.expand(body.kinetic_energy(variant.jets))
        if Tb == 0:
            continue
        out.append(
            Mutant(
                "dropped_half",
                f"the ½ is missing in the kinetic energy of the {body.name} in {what}",
                T + Tb,
            )
        )
        out.append(
            Mutant("missing_body", f"{what} lacks the kinetic energy of the {body.name}", T - Tb)
        )
    return out


#: The ratios of the moments of inertia students swap (Taylor §10.1–10.4): a disc's M R² for
#: ½ M R² (2) and back (½), a rod's end 1/3 M L² for its centre 1/12 M L² (4) and back (¼), a
#: solid sphere's 2/5 M R² for a shell's 2/3 M R² (3/5) and back (5/3).
INERTIA_FACTORS = (
    sp.Integer(2), sp.Rational(1, 2), sp.Integer(4), sp.Rational(1, 4),
    sp.Rational(5, 3), sp.Rational(3, 5),
)  # fmt: skip


#: How a sentence says a ratio: "twice the right one", "5/3 times the right one".
_RATIO_WORDS = {sp.Integer(2): "twice", sp.Rational(1, 2): "half", sp.Integer(4): "four times"}


def inertia_mutants(variant: SceneVariant | None, T: sp.Expr, what: str) -> list[Mutant]:
    """Per plane rigid body: its moment of inertia a common wrong multiple (`INERTIA_FACTORS`)
    of the right one, so its rotational term ½ I φ̇² is that multiple too."""
    if variant is None:
        return []
    out = []
    for body in variant.bodies:
        of = getattr(body, "rotational_energy", None)  # a plane rigid body's ½ I φ̇²
        rotation = sp.expand(of(variant.jets)) if of is not None else sp.Integer(0)
        if rotation == 0:
            continue
        for c in INERTIA_FACTORS:
            ratio = _RATIO_WORDS.get(c, f"{c} times")
            message = f"the moment of inertia of the {body.name} in {what} is {ratio} the right one"
            out.append(Mutant("wrong_inertia", message, T, ((c - 1, rotation),), 1))
    return out


def momentum_mutants(
    system: LagrangianSystem,
    jets: Sequence[Jet],
    k: int,
    lagrangian_mutants: Iterable[Mutant],
    parameters: Sequence[sp.Symbol],
) -> list[Mutant]:
    """Mistakes in p_k = ∂L/∂q̇_k: the momentum of another coordinate, ∂L/∂q_k instead, the
    momentum of a Lagrangian with a kinetic mistake (from `lagrangian_mutants`), single terms."""
    return list(iter_momentum_mutants(system, jets, k, lagrangian_mutants, parameters))


#: The kinds of Lagrangian mistakes that show in a momentum or an equation of motion as a whole
#: (a term mistake of L is caught there by the momentum's or the row's own term mutations).
KINETIC_KINDS = ("dropped_half", "missing_cross_term", "missing_driven_term", "dropped_half_all")


def iter_momentum_mutants(
    system: LagrangianSystem,
    jets: Sequence[Jet],
    k: int,
    lagrangian_mutants: Iterable[Mutant],
    parameters: Sequence[sp.Symbol],
) -> Iterator[Mutant]:
    """`momentum_mutants` one at a time, reading `lagrangian_mutants` only as far as needed."""
    for i in range(len(jets)):
        if i != k:
            yield wrong_coordinate_mutant(system, jets, k, i)
    yield force_mutant(system, jets, k)
    for m in lagrangian_mutants:
        if m.kind in KINETIC_KINDS:
            yield lagrangian_momentum_mutant(system, jets, k, m)
    what = f"your p_{jets[k].name}"
    yield from iter_term_mutants(system.generalized_momenta[k], what, parameters)
    terms = expanded_terms(system.generalized_momenta[k])
    # a sin or cos dropped from one term of several (a momentum of one term without its factor
    # is the momenta part's own sentence, "p_φ is ∂L/∂φ̇ without its factor sin²θ")
    for term in terms if len(terms) > 1 else ():
        for f in trig_factors(term):
            yield trig_factor_mutant(sp.Add(*terms), term, f, what)


def trig_factors(term: sp.Expr) -> list[sp.Expr]:
    """The sin and cos factors of a term, with their powers (sin(θ)^2, cos(α)): a factor a
    student drops (the parameter factors are `term_specs`' own)."""
    out = []
    for f in sp.Mul.make_args(term):
        base = f.base if isinstance(f, sp.Pow) else f
        if isinstance(base, sp.sin | sp.cos):
            out.append(f)
    return out


def trig_factor_mutant(base: sp.Expr, term: sp.Expr, f: sp.Expr, what: str) -> Mutant:
    """`base` (an expanded sum) with its term `term` written without the factor f."""
    message = Sentence(_TERM_MESSAGES["missing_factor"], {"t": term, "p": f}, {"w": what})
    return Mutant(
        "missing_factor", message, base, ((-sp.Integer(1), term), (sp.Integer(1), term / f)), 1
    )


def wrong_coordinate_mutant(
    system: LagrangianSystem, jets: Sequence[Jet], k: int, i: int
) -> Mutant:
    """p_k given as the momentum of another coordinate, p_i."""
    name, other = jets[k].name, jets[i].name
    return Mutant(
        "wrong_coordinate",
        f"your p_{name} is the momentum of {other} (∂L/∂{other}_dot), not of {name}",
        system.generalized_momenta[i],
    )


def force_mutant(system: LagrangianSystem, jets: Sequence[Jet], k: int) -> Mutant:
    """p_k given as ∂L/∂q_k."""
    name = jets[k].name
    return Mutant(
        "force_not_momentum",
        f"your p_{name} is ∂L/∂{name}; the momentum is ∂L/∂{name}_dot",
        system.generalized_forces[k],
    )


def lagrangian_momentum_mutant(
    system: LagrangianSystem, jets: Sequence[Jet], k: int, m: Mutant
) -> Mutant:
    """p_k of the Lagrangian mistake m: ∂L_mut/∂q̇_k."""
    pk = sp.expand(sp.diff(m.expr, jets[k].dot))
    what = f"your p_{jets[k].name}"
    return Mutant(m.kind, _momentum_message(m, what, system.generalized_momenta[k], pk), pk)


def _momentum_message(m: Mutant, what: str, right: sp.Expr, wrong: sp.Expr) -> Said:
    missing = sp.expand(right - wrong)
    if m.kind in ("missing_cross_term", "missing_driven_term") and missing != 0:
        return Sentence("{w} lacks the term {t}", {"t": missing}, {"w": what})
    return replaced(m.said, "your L", what)


def equation_mutants(
    system: LagrangianSystem,
    jets: Sequence[Jet],
    lagrangian_mutants: Iterable[Mutant],
    parameters: Sequence[sp.Symbol],
) -> list[tuple[int, Mutant]]:
    """(row, mutant) pairs, row `row` of the Euler–Lagrange equations replaced by the mutant:
    the sign of Lagrange's equation flipped, the equations of a Lagrangian with a mistake (from
    `lagrangian_mutants`), single terms of a row."""
    return list(iter_equation_mutants(system, jets, lagrangian_mutants, parameters))


def iter_equation_mutants(
    system: LagrangianSystem,
    jets: Sequence[Jet],
    lagrangian_mutants: Iterable[Mutant],
    parameters: Sequence[sp.Symbol],
) -> Iterator[tuple[int, Mutant]]:
    """`equation_mutants` one at a time, reading `lagrangian_mutants` only as far as needed
    (deriving a mutant's equations is the costly step)."""
    E = system.euler_lagrange
    per_monomial: dict[sp.Expr, tuple[sp.Expr, ...]] = {}
    for i in range(len(jets)):
        yield (i, el_sign_mutant(system, jets, i))
    for m in lagrangian_mutants:
        if m.kind in ROW_KINDS:
            yield from lagrangian_row_mutants(system, jets, m, per_monomial)
    for i, j in enumerate(jets):
        for m in iter_term_mutants(E[i], f"your equation for {j.name}", parameters):
            yield (i, m)


#: The kinds of Lagrangian mistakes whose equations of motion the catalogue lists.
ROW_KINDS = ("sign_of_V", *KINETIC_KINDS)


def el_sign_mutant(system: LagrangianSystem, jets: Sequence[Jet], i: int) -> Mutant:
    """Row i of the Euler–Lagrange equations with the sign of Lagrange's equation flipped:
    D_t p + ∂L/∂q = E + 2 ∂L/∂q."""
    name = jets[i].name
    return Mutant(
        "el_sign",
        f"the equation for {name} has d/dt(∂L/∂{name}_dot) + ∂L/∂{name}; Lagrange's "
        "equation has a minus sign",
        system.euler_lagrange[i],
        ((sp.Integer(2), system.generalized_forces[i]),),
    )


def lagrangian_row_mutants(
    system: LagrangianSystem,
    jets: Sequence[Jet],
    m: Mutant,
    per_monomial: dict[sp.Expr, tuple[sp.Expr, ...]],
) -> list[tuple[int, Mutant]]:
    """(row, mutant) for each row the Lagrangian mistake m changes: row i of E(L_mut). E is
    linear in L: E(L_mut) = E(L) + E(L_mut − L), and L_mut − L is a term or two, so only that
    is differentiated. Both sides are expanded, so their sum (Add collects like terms; no
    expand needed) is the very expression E(L_mut) expands to (tests/grading/test_diagnose.py
    holds that). A mutant we cannot differentiate gives none."""
    E = system.euler_lagrange
    try:
        change = _linear_euler_lagrange(sp.expand(m.expr - system.L), jets, per_monomial)
    except Exception:  # noqa: BLE001 - a mutant we cannot differentiate is skipped
        return []
    out = []
    for i, delta in enumerate(change):
        if delta != 0:
            msg = replaced(m.said, "your L", f"the L behind your equation for {jets[i].name}")
            out.append((i, Mutant(m.kind, msg, E[i], ((sp.Integer(1), delta),))))
    return out


def _linear_euler_lagrange(
    change: sp.Expr, jets: Sequence[Jet], per_monomial: dict[sp.Expr, tuple[sp.Expr, ...]]
) -> tuple[sp.Expr, ...]:
    """E(change), expanded, from E of each of its monomials (E is linear): the kinetic mistakes
    of L change the same few terms of T (one term, a cross term, a body, all of T), so each
    monomial is differentiated once for all of them. The sum is expanded again, which gives the
    very expression deriving E(change) at once expands to."""
    parts: list[list[sp.Expr]] = [[] for _ in jets]
    for term in sp.Add.make_args(change):
        coefficient, monomial = term.as_coeff_Mul()
        if monomial not in per_monomial:
            per_monomial[monomial] = LagrangianSystem(monomial, jets).euler_lagrange
        for row, e in zip(parts, per_monomial[monomial], strict=True):
            row.append(coefficient * e)
    return tuple(sp.expand(sp.Add(*row)) for row in parts)


def conserved_mutants(
    system: LagrangianSystem, jets: Sequence[Jet], T: sp.Expr, V: sp.Expr
) -> list[Mutant]:
    """Quantities wrongly called conserved: T + V when it is not h or L depends on t, the momentum
    of a coordinate that is not cyclic, L itself."""
    out: list[Mutant] = []
    h = system.energy_function
    if sp.expand(T + V - h) != 0 or not system.is_time_independent:
        # its sentence, why T + V is not conserved, is decided by values where it is said
        # (`parts.conserved_claims.energy_sentence`)
        out.append(Mutant("energy_not_conserved", "T + V is not conserved here", T + V))
    cyclic = set(system.cyclic_coordinates)
    for j, pj in zip(jets, system.generalized_momenta, strict=True):
        if j.name not in cyclic:
            out.append(
                Mutant(
                    "momentum_not_conserved",
                    f"p_{j.name} is not conserved: {j.name} is not cyclic (L depends on {j.name})",
                    pj,
                )
            )
    out.append(Mutant("lagrangian_not_conserved", "L itself is not a conserved quantity", system.L))
    return out


def expression_mutants(ref: sp.Expr) -> list[Mutant]:
    """The usual slips with a closed-form result: sin for cos, the sign, upside down, a dropped
    factor. A slip that leaves the reference as it is (no sin or cos to swap) is no slip and is
    left out: an answer equal to it would be named for a mistake it does not have."""
    mutants = [
        Mutant("sin_cos_swapped", "sin and cos are swapped", swap_sin_cos(ref)),
        Mutant("wrong_sign", "the sign is wrong", -ref),
        Mutant(
            "reciprocal",
            "your answer is upside down (the reciprocal of the right one)",
            1 / ref,
        ),
    ]
    mutants += dropped_factor_mutants(ref)
    return [m for m in mutants if m.expr != ref]


def dropped_factor_mutants(ref: sp.Expr) -> list[Mutant]:
    """The closed form with one of its factors left out (the (M + m) of the wedge's
    acceleration, a sin α, the g of √(g/l)): a factor of a product of two or more, each said as
    the student's answer lacks it ("lacks the factor M + m", "lacks the division by l")."""
    factors = [f for f in sp.Mul.make_args(ref) if not f.is_number]
    if len(factors) < 2:
        return []
    out = []
    for f in factors:
        base, exponent = f.as_base_exp()
        if exponent.is_number and exponent < 0:
            message = Sentence("your answer lacks the division by {f}", {"f": 1 / f})
        else:
            message = Sentence("your answer lacks the factor {f}", {"f": f})
        out.append(Mutant("missing_factor", message, ref / f))
    return out
