"""Is every claim the feedback makes true? For each wrong answer of the corpus
(`benchmarks/corpus/mistakes.py`: bank variants with one recorded mistake applied), every
specific sentence of the verdict's feedback (a missing term, a wrong sign, a factor, "½ missing
in T", "h is conserved", "x is cyclic", …) is read as a claim and checked by the correction it
implies: the correction is applied to the answer (a sympy form made by the corpus, never student
text) and the answer judged again. A true claim's correction makes the answer right, or the
claimed item right (the score rises). Every number quoted "at θ = …, moving with θ̇ = …" must be
in the verdict's `witness`, and accelerations quoted must be what the system's equations give at
that state with the handout's values.

Prints a table by part: wrong answers, % naming the recorded mistake, % naming another true
mistake (a true claim, not the cause's), % with a false claim, % saying nothing specific; then
the false claims and the unreproduced numbers, one line each.

Usage: python benchmarks/claims.py [--seeds 1,2] [--scenes a,b] [--parts T,V] [--show-false N]
                                  [--json PATH]
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks" / "corpus"))
sys.path.insert(0, str(ROOT / "benchmarks"))

from claims_more import oscillation_claims, quoted_frequencies, setup_claims  # noqa: E402
from mistakes import Wrong, build  # noqa: E402

from lagrade.bank.registry import get_scene  # noqa: E402
from lagrade.judge.check import check  # noqa: E402
from lagrade.judge.mutations import swap_sin_cos  # noqa: E402
from lagrade.judge.situation import symbol_text  # noqa: E402
from lagrade.mechanics import LagrangianSystem, phase_space  # noqa: E402
from lagrade.mechanics import t as mech_t  # noqa: E402
from lagrade.notation import plain  # noqa: E402

#: The claim kinds that name each recorded cause (a true claim of another kind names "another
#: true mistake").
NAMES = {
    "sign_of_V": {"sign_of_V"},
    "V_minus_T": {"V_minus_T"},
    "dropped_half_all": {"half_all"},
    "dropped_term": {"term_missing", "missing_body", "missing_cross", "missing_driven"},
    "factor_two": {"term_twice", "half_term", "half_body"},
    "term_sign": {"term_sign"},
    "part_cross_term": {"term_half", "cross_part"},
    "one_momentum_doubled": {"term_twice", "extra_factor", "half_term", "momentum_twice"},
    "momentum_trig_dropped": {"missing_factor", "term_factor"},
    "momentum_term_dropped": {"term_missing", "missing_cross", "missing_driven"},
    "momentum_of_wrong_L": {"term_half", "cross_part", "wrong_L"},
    "missing_equation": {"too_few", "missing_equation"},
    "negated_rhs": {"negated_rhs"},
    "el_sign": {"el_sign"},
    "eom_of_wrong_L": {"wrong_L", "behind"},
    "eom_of_own_L": {"wrong_L"},
    "row_term_sign": {"term_sign"},
    "cyclic_extra": {"not_cyclic"},
    "cyclic_missed": {"is_cyclic"},
    "energy_offered": {"energy_not_conserved"},
    "conserved_trig_dropped": {"missing_factor", "term_factor"},
    "conserved_not_cyclic": {"momentum_not_conserved"},
    "T_dropped_half": {"half_all"},
    "T_dropped_term": {"term_missing", "missing_body", "missing_cross", "missing_driven"},
    "T_factor_two": {"term_twice", "half_term", "half_body"},
    # a body in pure rotation (a pulley): its ½ missing is its moment of inertia doubled
    "T_wrong_inertia": {"wrong_inertia", "half_body"},
    "T_sin_cos": {"swap_all", "term_swap"},
    "V_sign": {"sign_of_V"},
    "V_dropped_term": {"term_missing"},
    "V_sin_cos": {"swap_all", "term_swap"},
    "V_term_sign": {"term_sign"},
    "H_velocities": {"H_velocities"},
    "H_is_L": {"H_is_L"},
    "H_sign_of_V": {"H_sign_of_V"},
    "H_dropped_half": {"H_half"},
    "H_vector_potential": {"H_offset"},
    "Heq_p_dot_sign": {"sign_p_dot"},
    "Heq_missing": {"too_few"},
    "Heq_no_mass": {"mass_not_divided"},
    "X_sign": {"x_sign"},
    "X_sin_cos": {"x_swap"},
    "X_upside_down": {"x_reciprocal"},
    "X_dropped_factor": {"x_factor"},
    # the set-up parts
    "DOF_no_constraints": {"no_constraints"},
    "DOF_planarity": {"forgot_planarity"},
    "COORD_velocity": {"velocity_named"},
    "COORD_missing": {"coordinate_missing"},
    "TR_term_sign": {"term_sign", "line_sign"},
    "TR_sin_cos": {"line_swap", "term_swap"},
    "TR_dropped_term": {"missing_term"},
    # a length doubled is its term twice; a length for another is named as such
    "TR_wrong_length": {"wrong_length", "term_factor"},
    # small oscillations
    "EQ_unstable": {"unstable"},
    "EQ_wrong_angle": {"not_equilibrium"},
    "EQ_term_sign": {"not_equilibrium"},
    "NM_squared": {"squared"},
    "NM_missing": {"missing_mode"},
    "NM_uncoupled": {"uncoupled"},
    "NM_cycles": {"cycles"},
    "NM_factor_two": {"factor_two", "factor_half"},
    "MS_swapped": {"swapped"},
    "MS_K_alone": {"mass_ignored"},
    "MS_missing": {"missing_mode"},
}


@dataclass
class Claim:
    kind: str
    sentence: str
    #: The answer's forms corrected as the claim implies; None when it cannot be applied.
    corrected: tuple | None
    #: How the corrected answer must be judged: "correct" or "better" (the score rises).
    needs: str = "better"
    #: A second check of the claim, by values (a quantity said to be conserved is).
    also: Callable[[], bool] | None = None


# --- the reference forms a sentence can quote --------------------------------------------------


class Reference:
    """The variant's reference forms, and the terms a sentence may quote, by their print."""

    def __init__(self, problem: dict):
        self.variant = v = get_scene(problem["scene"]).variant(problem["seed"])
        self.jets = v.jets
        self.system = v.system
        self.T = sp.expand(v.kinetic_energy)
        self.V = sp.expand(v.potential_energy)
        self.L = self.T - self.V
        self.p = [sp.expand(x) for x in self.system.generalized_momenta]
        self.E = [sp.expand(x) for x in self.system.euler_lagrange]
        self.F = list(self.system.generalized_forces)
        self.index = {j.name: k for k, j in enumerate(self.jets)}
        self.quantity = (
            self.variant.quantities[problem["quantity"]] if "quantity" in problem else None
        )

    @cached_property
    def phase(self):
        """H, its parts and Hamilton's equations (mechanics.hamilton)."""
        return phase_space(self.system)

    @cached_property
    def in_momenta(self) -> dict:
        """q̇ → q̇(q, p): velocity space carried to phase space."""
        dots = [j.dot for j in self.jets]
        return dict(zip(dots, self.phase.velocities, strict=True))

    def body_rotation(self, name: str) -> sp.Expr | None:
        for b in self.variant.bodies:
            if b.name == name and hasattr(b, "rotational_energy"):
                return sp.expand(b.rotational_energy(self.jets))
        return None

    def term(self, shown: str, *sources: sp.Expr) -> sp.Expr | None:
        for source in sources:
            for term in sp.Add.make_args(sp.expand(source)):
                if plain(term) == shown:
                    return term
        return None

    def symbol(self, shown: str) -> sp.Expr | None:
        for f in (*self.variant.parameter_symbols.values(), *(j.q for j in self.jets)):
            for g in (f, sp.sin(f), sp.cos(f)):
                for e in (1, 2, 3):
                    if plain(g**e) == shown:
                        return g**e
        for k in range(len(self.jets)):  # a factor of a momentum's term
            for term in sp.Add.make_args(self.p[k]):
                for f in sp.Mul.make_args(term):
                    if plain(f) == shown:
                        return f
        return None

    def body_T(self, name: str) -> sp.Expr | None:
        for b in self.variant.bodies:
            if b.name == name:
                return sp.expand(b.kinetic_energy(self.jets))
        return None


# --- the claims of one sentence ----------------------------------------------------------------

_EXAMPLE = re.compile(r" \(for example .*\)\.?$|\.$")
_LABEL = re.compile(r"^(Equation (\d+) \(.*?\)|Your equation): ")


def _term_delta(kind: str, t: sp.Expr, p: sp.Expr | None = None) -> sp.Expr:
    """What to add to an answer whose term t has the mistake `kind` (the correction)."""
    return {
        "term_sign": 2 * t,
        "term_swap": t - swap_sin_cos(t),
        "term_factor": t - (t / p if p is not None else 0),
        "term_missing": t,
        "term_twice": -t,
        "term_half": t / 2,
        "half_term": -t,
    }[kind]


_TERM = [
    ("term_sign", re.compile(r"^[Tt]he term (.+) in (.+) has the wrong sign$")),
    ("term_swap", re.compile(r"^[Ss]in and cos are swapped in the term (.+) of (.+)$")),
    ("term_factor", re.compile(r"^[Tt]he term (.+) in (.+) lacks the factor (.+)$")),
    ("term_twice", re.compile(r"^[Tt]he term (.+) in (.+) is twice too large$")),
    ("term_half", re.compile(r"^[Tt]he term (.+) in (.+) is half what it should be$")),
    ("half_term", re.compile(r"^[Tt]he ½ is missing in the kinetic term (.+) of (.+)$")),
    ("term_missing", re.compile(r"^(?:Your|your|The|the) (.+?) lacks the term (.+?)( from .*)?$")),
]


def _where(what: str, ref: Reference) -> tuple[str, int | None]:
    """What a sentence's "your L" / "your p_x" / "your equation for x" / "the L behind your
    equation for x" names: ("L"|"T"|"V"|"p"|"row"|"behind", index)."""
    what = what.strip()
    m = re.match(r"(?:the L behind )?your equation for (\w+)", what)
    if m:
        return ("behind" if what.startswith("the L") else "row"), ref.index.get(m.group(1))
    m = re.match(r"your p_(\w+)", what)
    if m:
        return "p", ref.index.get(m.group(1))
    return {"your L": "L", "your T": "T", "your V": "V"}.get(what, "?"), None


def scale(student: sp.Expr, claimed: sp.Expr) -> sp.Expr:
    """c with student = c · claimed (the answer as the claim reads it, scaled as the student
    wrote it), from values at two points; 1 when it is no constant."""
    symbols = sorted(student.free_symbols | claimed.free_symbols, key=str)
    ratios = []
    for k in (0.37, 0.71):
        at = {s: k + 0.13 * i for i, s in enumerate(symbols)}
        b = complex(claimed.subs(at).evalf())
        if b == 0:
            return sp.Integer(1)
        ratios.append(complex(student.subs(at).evalf()) / b)
    c = ratios[0]
    if abs(c.imag) > 1e-9 or abs(c - ratios[1]) > 1e-9 * max(1, abs(c)) or c == 0:
        return sp.Integer(1)
    return sp.Rational(c.real).limit_denominator(1000)


def _row_fixed(w: Wrong, at: int, reference: sp.Expr, delta: sp.Expr) -> tuple:
    """The answer with row `at` corrected by delta, scaled as the student's row is."""
    a, b = w.exprs[at]
    c = scale(sp.expand(a - b), reference - delta)
    return tuple((x + c * delta, y) if i == at else (x, y) for i, (x, y) in enumerate(w.exprs))


def _with_L_change(w: Wrong, ref: Reference, dL: sp.Expr, row: int | None = None):
    """The answer corrected by a change of its Lagrangian dL: L + dL; each momentum + ∂dL/∂q̇;
    equation `row` (or each) + E(dL)."""
    if w.part in ("lagrangian", "T"):  # a kinetic change of L is the same change of T
        return (w.exprs[0] + dL,)
    if w.part == "momenta":
        return tuple(e + sp.diff(dL, j.dot) for e, j in zip(w.exprs, ref.jets, strict=True))
    if w.part == "eom":
        dE = LagrangianSystem(sp.expand(dL), ref.jets).euler_lagrange
        out = list(w.exprs)
        for i in range(len(out)):
            if (row is None or i == row) and i < len(ref.E):
                out[i] = _row_fixed(w, i, ref.E[i], dE[i])[i] if dE[i] != 0 else out[i]
        return tuple(out)
    return None


def _row_of(label: str | None, total: int) -> int | None:
    if label is None:
        return None
    m = _LABEL.match(label)
    if m is None:
        return None
    return int(m.group(2)) - 1 if m.group(2) else 0


def claims_of(sentence: str, w: Wrong, ref: Reference) -> list[Claim]:
    """The specific claims of one feedback sentence, each with its correction."""
    label = _LABEL.match(sentence)
    body = sentence[label.end() :] if label else sentence
    body = _EXAMPLE.sub("", body).strip()
    row = _row_of(sentence, len(w.exprs)) if label else None
    one = lambda kind, corrected, needs="better", also=None: [  # noqa: E731
        Claim(kind, sentence, corrected, needs, also)
    ]

    found = setup_claims(body, w, ref, one)
    if found is None:
        found = oscillation_claims(body, w, ref, one)
    if found is not None:
        return found
    if re.match(r"^Your L adds V instead of subtracting it", body):
        return one("sign_of_V", (w.exprs[0] - 2 * ref.V,), "correct")
    if body.startswith("Your V has the wrong sign"):
        return one("sign_of_V", (-w.exprs[0],), "correct")
    if body.startswith("Your L gives the right equations of motion but has the opposite sign"):
        return one("V_minus_T", (-w.exprs[0],), "correct")
    if re.match(r"^[Tt]he ½ is missing in (the kinetic energy|your T)$", body):
        needs = "correct" if w.part in ("lagrangian", "momenta", "T") else "better"
        if w.part == "T":
            return one("half_all", (w.exprs[0] - ref.T,), needs)
        return one("half_all", _with_L_change(w, ref, -ref.T, row), needs)
    m = re.match(r"^[Tt]he ½ is missing in the kinetic energy of the (\w+) in (.+)$", body)
    if m:
        Tb = ref.body_T(m.group(1))
        return one("half_body", None if Tb is None else _with_L_change(w, ref, -Tb, row))
    m = re.match(r"^(.+) lacks the kinetic energy of the (\w+)$", body)
    if m:
        Tb = ref.body_T(m.group(2))
        return one("missing_body", None if Tb is None else _with_L_change(w, ref, Tb, row))
    m = re.match(r"^(.+) lacks the cross term in (.+)$", body)
    if m:
        where, k = _where(m.group(1), ref)
        shown = m.group(2)
        cross = sp.Add(
            *(
                x
                for x in sp.Add.make_args(ref.T)
                if plain(sp.Mul(*[j.dot for j in ref.jets if x.has(j.dot)])) == shown
            )
        )
        if where == "T":
            return one("missing_cross", (w.exprs[0] + cross,), "correct")
        return one("missing_cross", _with_L_change(w, ref, cross, k if where == "behind" else row))
    m = re.match(r"^[Ss]in and cos are swapped in (your L|your T|your V)$", body)
    if m:
        return one("swap_all", (swap_sin_cos(w.exprs[0]),), "correct")
    for kind, pattern in _TERM:
        m = pattern.match(body)
        if not m:
            continue
        if kind == "term_missing":
            what, shown = m.group(1), m.group(2)
            if m.group(3):
                kind = "missing_driven"
        else:
            shown, what = m.group(1), m.group(2)
        where, k = _where(what if what.startswith(("your", "the L")) else f"your {what}", ref)
        factor = ref.symbol(m.group(3)) if kind == "term_factor" else None
        if where in ("L", "T", "V", "behind"):
            if where == "V":  # V's terms are quoted as V's
                t = ref.term(shown, ref.V)
            else:
                source = {"L": ref.L, "T": ref.T, "behind": ref.L}[where]
                t = ref.term(shown, source, ref.T, -ref.V)
            if t is None:
                return one(kind, None)
            delta = _term_delta(kind if kind != "missing_driven" else "term_missing", t, factor)
            if where in ("T", "V"):
                return one(kind, (w.exprs[0] + delta,), "correct")
            return one(kind, _with_L_change(w, ref, delta, k if where == "behind" else row))
        if where == "p" and k is not None and kind == "half_term":
            t = ref.term(shown, ref.T)
            return one(kind, None if t is None else _with_L_change(w, ref, -t))
        if where == "p" and k is not None:
            t = ref.term(shown, ref.p[k])
            if t is None:
                return one(kind, None)
            delta = _term_delta(kind if kind != "missing_driven" else "term_missing", t, factor)
            if w.part == "conserved":
                return one(kind, _conserved_replaced(w, ref, k, delta))
            return one(kind, tuple(e + delta if i == k else e for i, e in enumerate(w.exprs)))
        if where == "row" and k is not None and w.part == "eom":
            t = ref.term(shown, ref.E[k])
            at = row if row is not None else k
            if t is None or at >= len(w.exprs):
                return one(kind, None)
            delta = _term_delta(kind if kind != "missing_driven" else "term_missing", t, factor)
            return one(kind, _row_fixed(w, at, ref.E[k], delta))
        return one(kind, None)
    m = re.match(r"^p_(\w+) is ∂L/∂\w+ (without its|with an extra) factor (.+?)$", body)
    if m:
        k, f = ref.index.get(m.group(1)), ref.symbol(m.group(3))
        if k is None or f is None:
            return one("missing_factor", None)
        fix = (lambda e: e * f) if m.group(2) == "without its" else (lambda e: e / f)
        kind = "missing_factor" if m.group(2) == "without its" else "extra_factor"
        return one(kind, tuple(fix(e) if i == k else e for i, e in enumerate(w.exprs)))
    m = re.match(r"^p_(\w+) is (twice|half|minus) ∂L/∂\w+$", body)
    if m:
        k = ref.index.get(m.group(1))
        number = {"twice": 2, "half": sp.Rational(1, 2), "minus": -1}[m.group(2)]
        fixed = tuple(e / number if i == k else e for i, e in enumerate(w.exprs))
        return one("momentum_twice" if number == 2 else "momentum_number", fixed)
    m = re.match(r"^(?:Your |your )?p_(\w+) is the momentum of (\w+) ", body)
    if m:
        k, i = ref.index.get(m.group(1)), ref.index.get(m.group(2))
        fixed = tuple(e - ref.p[i] + ref.p[k] if j == k else e for j, e in enumerate(w.exprs))
        return one("other_momentum", fixed)
    m = re.match(r"^(?:Your |your )?p_(\w+) is ∂L/∂\w+; the momentum is", body)
    if m:
        k = ref.index.get(m.group(1))
        fixed = tuple(e - ref.F[k] + ref.p[k] if j == k else e for j, e in enumerate(w.exprs))
        return one("force_not_momentum", fixed)
    m = re.match(r"^[Tt]he equation for (\w+) has d/dt\(∂L/∂\w+\) \+ ∂L/∂\w+", body)
    if m:
        k = ref.index.get(m.group(1))
        at = row if row is not None else k
        return one("el_sign", _row_fixed(w, at, ref.E[k], -2 * ref.F[k]))
    if body == "the right-hand side has the wrong sign" and row is not None:
        fixed = tuple((a, -b) if i == row else (a, b) for i, (a, b) in enumerate(w.exprs))
        return one("negated_rhs", fixed)
    if body.startswith(("Your equations are right but only", "Your equation is right;")):
        if w.part == "hamilton_equations":
            every = tuple((e.lhs, e.rhs) for e in ref.phase.hamilton_equations)
            return one("too_few", tuple(w.exprs) + every, "correct")
        return one("too_few", tuple(w.exprs) + tuple((e, 0) for e in ref.E), "correct")
    m = re.match(r"^(These equations|Your wrong equations) follow correctly from your own "
                 r"Lagrangian, which is not the right one(?:: (.+))?$", body)  # fmt: skip
    if m:
        return _own_lagrangian_claims(m.group(1), m.group(2), sentence, w, ref)
    m = re.match(r"^(\w+) is not cyclic: L depends on \1", body)
    if m:
        return one("not_cyclic", tuple(x for x in w.exprs if x != m.group(1)))
    m = re.match(r"^(\w+) is cyclic: ", body)
    if m:
        return one("is_cyclic", tuple(w.exprs) + (m.group(1),))
    found = _energy_claims(body, w, ref, one) or _phase_claims(sentence, body, row, w, ref, one)
    if found is not None:
        return found
    found = _expression_claims(body, w, ref, one)
    if found is not None:
        return found
    if body.startswith("T + V is not conserved here"):
        energy = sp.expand(ref.T + ref.V)
        h = ref.system.energy_function
        out = one("energy_not_conserved", None, also=lambda: not _conserved_alone(w, energy))
        if "h = Σ q̇ ∂L/∂q̇ − L is" in body:
            out += one("h_conserved", None, also=lambda: _conserved_alone(w, h))
        if "h is not conserved either" in body:
            out += one("h_not_conserved", None, also=lambda: not _conserved_alone(w, h))
        at_rest = {j.dot: 0 for j in ref.jets}
        reasons = {  # each reason the sentence gives, checked on the reference's forms
            "the constraint moves": lambda: sp.expand(ref.T.subs(at_rest)) != 0,
            "V depends on the velocities": lambda: any(ref.V.has(j.dot) for j in ref.jets),
            "L depends on t explicitly": lambda: sp.diff(ref.L, mech_t) != 0,
        }
        for said, holds in reasons.items():
            if said in body:
                out += one("energy_reason", None, also=holds)
        return out
    m = re.match(r"^(.+) is missing a factor (.+): \2 times it is conserved$", body)
    if m:
        f = ref.symbol(m.group(2))
        at = [i for i, q in enumerate(w.exprs) if plain(q) == m.group(1)]
        if f is None or len(at) != 1:
            return one("missing_factor", None)
        fixed = tuple(q * f if i == at[0] else q for i, q in enumerate(w.exprs))
        return one("missing_factor", fixed)
    m = re.match(r"^p_(\w+) is not conserved: (\w+) is not cyclic", body)
    if m:
        k = ref.index.get(m.group(1))
        p = ref.p[k]
        return one("momentum_not_conserved", None, also=lambda: not _conserved_alone(w, p))
    if body.startswith("L itself is not a conserved quantity"):
        L = ref.L
        return one("lagrangian_not_conserved", None, also=lambda: not _conserved_alone(w, L))
    return []  # a sentence that names no mistake


def _energy_claims(body: str, w: Wrong, ref: Reference, one) -> list | None:
    """The T part's sentence of a wrong moment of inertia: the body's rotational term ½ I φ̇²
    taken c times; its correction takes (c − 1) of it away."""
    m = re.match(r"^[Tt]he moment of inertia of the (\w+) in your T is (.+?) the right one$", body)
    if m is None:
        return None
    rotation = ref.body_rotation(m.group(1))
    if rotation is None:
        return one("wrong_inertia", None)
    words = {"twice": "2", "half": "1/2", "four times": "4"}
    c = sp.Rational(words.get(m.group(2), m.group(2).removesuffix(" times")))
    return one("wrong_inertia", (w.exprs[0] - (c - 1) * rotation,), "correct")


def _phase_claims(sentence: str, body: str, row: int | None, w: Wrong, ref: Reference, one):
    """The sentences of the `hamiltonian` and `hamilton_equations` parts, each with the
    correction it implies, in the momenta."""
    if w.part == "hamiltonian":
        return _hamiltonian_claims(body, w, ref, one)
    if w.part != "hamilton_equations":
        return None
    rates = {j.dot for j in ref.jets}, set(ref.phase.rates)
    m = re.match(r"^the sign of (ṗ|q̇) is wrong", body)
    if m and row is not None and row < len(w.exprs):
        flip = rates[1] if m.group(1) == "ṗ" else rates[0]
        a, b = (x.xreplace({r: -r for r in flip}) for x in w.exprs[row])
        fixed = tuple((a, b) if i == row else e for i, e in enumerate(w.exprs))
        return one("sign_p_dot" if m.group(1) == "ṗ" else "sign_q_dot", fixed)
    m = re.match(r"^(Equation (\d+) \(.*\)|Your equation) gives (\S+) as (.+?) times what it is",
                 sentence)  # fmt: skip
    if m:
        at = int(m.group(2)) - 1 if m.group(2) else 0
        k = next((k for k, j in enumerate(ref.jets) if symbol_text(j.name, 1) == m.group(3)), None)
        if k is None or at >= len(w.exprs) or plain(ref.phase.velocity_matrix[k, k]) != m.group(4):
            return one("mass_not_divided", None)
        q_dot, mass = ref.jets[k].dot, ref.phase.velocity_matrix[k, k]
        a, b = (x.xreplace({q_dot: mass * q_dot}) for x in w.exprs[at])
        fixed = tuple((a, b) if i == at else e for i, e in enumerate(w.exprs))
        return one("mass_not_divided", fixed)
    return None


def _hamiltonian_claims(body: str, w: Wrong, ref: Reference, one) -> list | None:
    """H's sentences: each says what the answer is (L in the momenta, h with a slip, …); its
    correction takes that away and puts H in its place."""
    hs, answer = ref.phase, w.exprs[0]
    H, U = hs.hamiltonian, hs.effective_potential
    to_p = ref.in_momenta

    def holds(kind: str, corrected: sp.Expr):
        return one(kind, None, also=lambda: _is_H(corrected, ref))

    if body.startswith("H must be written in the coordinates and the momenta"):
        velocities = any(answer.has(j.dot) for j in ref.jets)
        return one("H_velocities", None, also=lambda: velocities)
    if body.startswith("As a function of the velocities it is the energy function h"):
        return holds("h_right", answer.xreplace(to_p))
    if body.startswith("Your H is the Lagrangian L = T − V written in the momenta"):
        return holds("H_is_L", answer - ref.system.L.xreplace(to_p) + H)
    if body.startswith("V has the wrong sign in your H"):
        return holds("H_sign_of_V", answer + 2 * ref.V)
    if body.startswith("The ½ is missing in the kinetic part of your H"):
        return holds("H_half", answer - (H - U))
    if body.startswith("Your H lacks the shift of the momenta"):
        p = sp.Matrix(hs.momenta)
        unshifted = (p.T * hs.inverse_matrix * p)[0, 0] / 2 + U
        return holds("H_offset", answer - unshifted + H)
    if body.startswith("Your H puts each momentum where its velocity was"):
        h_of_p = ref.system.energy_function.xreplace(dict(zip(to_p, hs.momenta, strict=True)))
        return holds("H_velocity_is_p", answer - h_of_p + H)
    if body.startswith("Your H has the velocities as the mass matrix times the momenta"):
        Ap = hs.velocity_matrix * sp.Matrix(hs.momenta)
        h_of_Ap = ref.system.energy_function.xreplace(dict(zip(to_p, Ap, strict=True)))
        return holds("H_multiplied", answer - h_of_Ap + H)
    if body.startswith("Your H is the energy T + V"):
        return holds("H_energy", answer - (ref.T + ref.V).xreplace(to_p) + H)
    return None


def _is_H(corrected: sp.Expr, ref: Reference) -> bool:
    """The corrected answer is H up to a constant, by values at three points of phase space
    with the handout's parameter values (its text, H of a coupled system with a slip taken
    away, is often longer than an answer may be, so it is not judged again as an answer)."""
    H = ref.phase.hamiltonian
    handout = {s: float(ref.variant.values[n]) for n, s in ref.variant.parameter_symbols.items()}
    free = sorted((corrected.free_symbols | H.free_symbols) - set(handout), key=str)
    differences = []
    for k in (0.31, 0.47, 0.83):
        at = {**handout, **{s: k + 0.17 * i for i, s in enumerate(free)}}
        a, b = complex(sp.N(corrected.xreplace(at))), complex(sp.N(H.xreplace(at)))
        differences.append((a - b, abs(a) + abs(b)))
    first = differences[0][0]
    return all(abs(d - first) <= 1e-9 * (size + 1e-300) for d, size in differences)


def _expression_claims(body: str, w: Wrong, ref: Reference, one) -> list | None:
    """The closed-form slips of the `expression` part, each corrected on the answer."""
    if w.part != "expression":
        return None
    answer = w.exprs[0]
    if re.match(r"^[Ss]in and cos are swapped$", body):
        return one("x_swap", (swap_sin_cos(answer),), "correct")
    if body == "The sign is wrong":
        return one("x_sign", (-answer,), "correct")
    if body.startswith("Your answer is upside down"):
        return one("x_reciprocal", (1 / answer,), "correct")
    m = re.match(r"^Your answer lacks the (factor|division by) (.+)$", body)
    if m:
        factors = {plain(f): f for f in sp.Mul.make_args(ref.quantity)}
        factors |= {plain(1 / f): 1 / f for f in sp.Mul.make_args(ref.quantity)}
        f = factors.get(m.group(2))
        if f is None:
            return one("x_factor", None)
        return one("x_factor", (answer * f if m.group(1) == "factor" else answer / f,), "correct")
    return None


def _own_lagrangian_claims(which: str, said: str | None, sentence: str, w: Wrong, ref) -> list:
    """The follow-through sentence: the equations it speaks of (all, or the wrong ones) are in
    the span of the own L's Euler–Lagrange rows, checked at two points; and the own L's mistake
    it names, checked as the Lagrangian part's sentence is (its correction makes that L
    right)."""
    if w.own_L is None or w.given is None:
        return [Claim("wrong_L", sentence, None)]  # an own L we cannot check: counted false
    rows = [sp.expand(a - b) for a, b in w.exprs]
    if which == "Your wrong equations":
        rows = [r for r in rows if not _in_span(r, ref.E, ref)]
    own_E = [sp.expand(e) for e in LagrangianSystem(w.own_L, ref.jets).euler_lagrange]
    holds = all(_in_span(r, own_E, ref) for r in rows) and not all(
        _in_span(e, ref.E, ref) for e in own_E
    )
    out = [Claim("wrong_L", sentence, None, also=lambda: holds)]
    if said is None:
        return out
    as_L = Wrong(w.problem, "lagrangian", w.given["lagrangian"], w.cause, (w.own_L,))
    before = check(w.problem, "lagrangian", as_L.answer)
    for c in claims_of(said[0].upper() + said[1:] + ".", as_L, ref):
        ok = is_true(c, as_L, before)
        out.append(Claim(c.kind, sentence, None, also=lambda ok=ok: ok))
    if len(out) == 1:
        out.append(Claim("unchecked_L_sentence", sentence, None))  # counted false
    return out


def _in_span(row: sp.Expr, basis: list, ref: Reference) -> bool:
    """row = Σ c_i(q, q̇, t) basis_i: the rows [A | c] (linear in the accelerations) at two
    points with the handout's values have the rank of the basis alone."""
    acc = [j.ddot for j in ref.jets]
    values = {ref.variant.parameter_symbols[n]: float(x) for n, x in ref.variant.values.items()}

    def coef(e):
        return [sp.diff(e, a) for a in acc] + [e.subs({a: 0 for a in acc})]

    symbols = sorted(set().union(*(e.free_symbols for e in [row, *basis])) - set(acc)
                     - set(values), key=str)  # fmt: skip
    for k in (0.37, 0.61):
        at = {**values, **{s: k + 0.11 * i for i, s in enumerate(symbols)}}
        S = sp.Matrix([coef(e) for e in [*basis, row]]).subs(at).evalf()
        s_ = np.array(S, dtype=float)
        scale = np.abs(s_).max(axis=0)  # per column: SI values differ by decades (G M m)
        s_ = s_ / np.where(scale > 0, scale, 1.0)
        b = s_[:-1]
        if np.linalg.matrix_rank(s_, 1e-9) != np.linalg.matrix_rank(b, 1e-9):
            return False
    return True


def _conserved_replaced(w: Wrong, ref: Reference, k: int, delta: sp.Expr):
    """A conserved answer with the item equal to p_k's wrong form corrected by delta."""
    return tuple(q + delta for q in w.exprs)  # checked: the score must rise


def _conserved_alone(w: Wrong, q: sp.Expr) -> bool:
    """q alone is judged a conserved quantity (a part that asks for all of them gives it a
    share of the score)."""
    v = check(w.problem, "conserved", [plain(q)])
    return v.status == "correct" or v.score > 0


# --- judging a correction -----------------------------------------------------------------------


def answer_of(w: Wrong, exprs: tuple) -> str | list[str]:
    """The answer text of corrected forms, as the corpus prints its answers."""
    if w.part in ("lagrangian", "T", "V", "hamiltonian", "expression"):
        return plain(exprs[0])
    if w.part == "momenta":
        ref_names = [line.split(" = ")[0] for line in w.answer]
        return [f"{n} = {plain(e)}" for n, e in zip(ref_names, exprs, strict=True)]
    if w.part in ("eom", "hamilton_equations"):
        return [f"{plain(a)} = {plain(b)}" for a, b in exprs]
    if w.part == "cyclic":
        return ", ".join(exprs) if exprs else "none"
    if w.part == "coordinates":
        return ", ".join(exprs)
    if w.part == "transformation":
        return [f"{name} = {plain(e)}" for name, e in exprs]
    return [plain(q) for q in exprs]


def is_true(claim: Claim, w: Wrong, before) -> bool:
    if claim.also is not None and not claim.also():
        return False
    if claim.corrected is None:
        return claim.also is not None
    after = check(w.problem, w.part, answer_of(w, claim.corrected), given=w.given)
    if after.status == "correct":
        return True
    return claim.needs == "better" and after.score > before.score + 1e-9


# --- the numbers quoted -------------------------------------------------------------------------

_QUOTED = re.compile(r"([^\s,()]+) = (−?[\d.]+(?:e[−+]?\d+)?)")


def unreproduced(
    sentence: str, witness: dict | None, ref: Reference, values: tuple = ()
) -> list[str]:
    """The numbers a sentence quotes for a coordinate, a velocity or a momentum that its witness
    does not hold (rounded as quoted); accelerations quoted against the system's own at that
    state; the values quoted of the answer and the reference (`values`: both forms) against
    what they are there with the student's own parameter values."""
    if "at the first point drawn" in sentence:
        return quoted_frequencies(sentence, witness, ref)
    if "(for example" not in sentence:
        return []
    shown = {}
    for j in ref.jets:
        for dots, suffix in ((0, ""), (1, "_dot"), (2, "_ddot")):
            shown[symbol_text(j.name, dots)] = j.name + suffix
        shown[f"p_{symbol_text(j.name)}"] = f"p_{j.name}"  # a momentum on phase space
    out = []
    tail = sentence[sentence.index("(for example") :]
    state_part, _, values_part = tail.partition(", where ")
    for sym, number in _QUOTED.findall(state_part):
        key = shown.get(sym)
        if key is None:
            continue
        value = float(number.replace("−", "-"))
        got = (witness or {}).get(key)
        if got is None or float(f"{got:.3g}") != value:
            out.append(f"{sym} = {number} (witness: {got})")
    if values_part and "the reference" in values_part:
        out += _accelerations(values_part, witness or {}, ref, shown)
    if values and " and the reference's is " in tail:
        out += _values(tail, witness or {}, ref, values)
    return out


_NUMBER = r"(−?[\d.]+(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)"
_SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _number(text: str) -> float:
    """A number as `situation.rounded` prints it: −0.0322, 2.5×10⁻⁷."""
    mantissa, _, power = text.replace("−", "-").partition("×10")
    return float(mantissa) * 10 ** int(power.translate(_SUPERSCRIPT) or 0)


def _values(tail: str, witness: dict, ref: Reference, values: tuple) -> list[str]:
    """ ", where your T is 0.0322 J and the reference's is 0.0161 J": both sides at the quoted
    state (the witness, as quoted) with the handout's values of the parameters (the student's
    own variant; a parameter the witness holds at the handout's value is that value)."""
    m = re.search(rf"where your \w+ is {_NUMBER}(?: \S+)? and the reference's is {_NUMBER}", tail)
    if not m:
        return []
    handout = {s: float(ref.variant.values[n]) for n, s in ref.variant.parameter_symbols.items()}
    state = {}
    for j in ref.jets:
        for sym, key in ((j.q, j.name), (j.dot, f"{j.name}_dot")):
            if key in witness:
                state[sym] = float(f"{witness[key]:.3g}")
    out = []
    for expr, quoted in zip(values, (m.group(1), m.group(2)), strict=True):
        at = {**handout, **state, mech_t: float(f"{witness.get('t', 0.0):.3g}")}  # as quoted
        if expr.free_symbols - set(at):
            out.append(
                f"{quoted} (the witness lacks {sorted(map(str, expr.free_symbols - set(at)))})"
            )
            continue
        got = complex(sp.N(expr.xreplace(at)))
        if abs(got.real - _number(quoted)) > 5e-3 * max(abs(got.real), 1e-300):
            out.append(f"{quoted} (the variant gives {got.real:.4g})")
    return out


def _accelerations(text: str, witness: dict, ref: Reference, shown: dict) -> list[str]:
    """ "the reference θ̈ = −108 rad/s²": the system's q̈ at the witness state, handout values."""
    m = re.search(r"the reference (\S+) = (−?[\d.]+(?:e[−+]?\d+)?)", text)
    if not m:
        return []
    key = shown.get(m.group(1), "")
    name = key[: -len("_ddot")]
    state = {}
    for j in ref.jets:
        for s, k in ((j.q, j.name), (j.dot, f"{j.name}_dot")):
            if k not in witness:
                return [f"{m.group(0)} (witness lacks {k})"]
            state[s] = float(f"{witness[k]:.3g}")  # the state as quoted
    values = {ref.variant.parameter_symbols[n]: float(x) for n, x in ref.variant.values.items()}
    M = ref.system.mass_matrix.subs(values).subs(state)
    F = ref.system.forcing.subs(values).subs(state)
    acc = M.LUsolve(F)
    k = ref.index[name]
    time = mech_t
    if acc[k].has(time):
        if "t" not in witness:
            return [f"{m.group(0)} (witness lacks t)"]
        acc = acc.subs(time, float(f"{witness['t']:.3g}"))  # as quoted (or would be)
    got = float(acc[k])
    quoted = float(m.group(2).replace("−", "-"))
    if abs(got - quoted) > 5e-3 * max(abs(got), abs(quoted)):  # three figures, as quoted
        return [f"{m.group(0)} (the system gives {got:.4g})"]
    return []


# --- the table ----------------------------------------------------------------------------------


def run(corpus: list[Wrong]) -> dict:
    rows: dict[str, Counter] = defaultdict(Counter)
    false_claims, numbers = [], []
    refs: dict[tuple, Reference] = {}
    for w in corpus:
        before = check(w.problem, w.part, w.answer, given=w.given)
        if before.status != "incorrect":
            rows[w.part]["not wrong"] += 1
            continue
        key = (w.problem["scene"], w.problem["seed"], w.problem.get("quantity"))
        ref = refs.setdefault(key, Reference(w.problem))
        claims = [c for s in before.feedback for c in claims_of(s, w, ref)]
        truth = [(c, is_true(c, w, before)) for c in claims]
        row = rows[w.part]
        row["wrong"] += 1
        if any(not ok for _, ok in truth):
            row["false"] += 1
            for c, ok in truth:
                if not ok:
                    false_claims.append((w.problem, w.part, w.cause, c.kind, c.sentence))
        elif not truth:
            row["nothing"] += 1
        elif any(c.kind in NAMES.get(w.cause, ()) for c, _ in truth):
            row["recorded"] += 1
        else:
            row["other"] += 1
        values = _quoted_forms(w, ref)
        for s in before.feedback:
            for bad in unreproduced(s, dict(before.witness or {}), ref, values):
                numbers.append((w.problem, w.part, w.cause, bad))
                row["numbers"] += 1
    return {"rows": rows, "false": false_claims, "numbers": numbers}


def _quoted_forms(w: Wrong, ref: Reference) -> tuple:
    """(the answer, the reference) of a one-expression part whose sentence quotes both values."""
    reference = {"T": ref.T, "expression": ref.quantity}.get(w.part)
    return () if reference is None else (w.exprs[0], reference)


def table(rows: dict[str, Counter]) -> str:
    head = f"{'part':<20}{'wrong':>7}{'recorded':>10}{'other':>8}{'false':>8}{'nothing':>9}"
    lines = [head + f"{'bad numbers':>13}"]
    total: Counter = Counter()
    for part in sorted(rows):
        total.update(rows[part])
        lines.append(_line(part, rows[part]))
    lines.append(_line("all", total))
    return "\n".join(lines)


def _line(name: str, r: Counter) -> str:
    n = r["wrong"] or 1

    def pc(k):
        return f"{100 * r[k] / n:.0f} %"

    cols = "".join(f"{pc(k):>{w}}" for k, w in (("recorded", 10), ("other", 8), ("false", 8)))
    return f"{name:<20}{r['wrong']:>7}{cols}{pc('nothing'):>9}{r['numbers']:>13}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--parts", default="", help="only these parts (comma-separated)")
    ap.add_argument("--show-false", type=int, default=30)
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    seeds = tuple(int(s) for s in args.seeds.split(","))
    scenes = tuple(args.scenes.split(",")) if args.scenes else None
    parts = tuple(args.parts.split(",")) if args.parts else None
    corpus = build(seeds, scenes, parts)
    result = run(corpus)
    print(table(result["rows"]))
    by_kind = Counter(k for _, _, _, k, _ in result["false"])
    print(f"\nfalse claims: {len(result['false'])} {dict(by_kind)}")
    for problem, part, cause, kind, sentence in result["false"][: args.show_false]:
        print(f"  {problem['scene']}/{problem['seed']} {part} [{cause}] {kind}: {sentence}")
    print(f"\nnumbers not reproduced from the witness: {len(result['numbers'])}")
    for problem, part, cause, bad in result["numbers"][: args.show_false]:
        print(f"  {problem['scene']}/{problem['seed']} {part} [{cause}]: {bad}")
    if args.json:
        Path(args.json).write_text(
            json.dumps({"rows": {k: dict(v) for k, v in result["rows"].items()}}, indent=1)
        )


if __name__ == "__main__":
    main()
