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

Usage: python benchmarks/claims.py [--seeds 1,2] [--scenes a,b] [--show-false N] [--json PATH]
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks" / "corpus"))

from mistakes import Wrong, build  # noqa: E402

from lagrade.bank.registry import get_scene  # noqa: E402
from lagrade.judge.check import check  # noqa: E402
from lagrade.judge.mutations import swap_sin_cos  # noqa: E402
from lagrade.judge.situation import symbol_text  # noqa: E402
from lagrade.mechanics import LagrangianSystem  # noqa: E402
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
    if w.part == "lagrangian":
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
            source = {"L": ref.L, "T": ref.T, "V": -ref.V, "behind": ref.L}[where]
            t = ref.term(shown, source, ref.T, -ref.V)
            if where == "V" and t is not None:
                t = -t  # V's terms are quoted as V's
                t = ref.term(shown, ref.V) or t
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
    if body.startswith("Your equations are right but only"):
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
    if w.part in ("lagrangian", "T", "V"):
        return plain(exprs[0])
    if w.part == "momenta":
        ref_names = [line.split(" = ")[0] for line in w.answer]
        return [f"{n} = {plain(e)}" for n, e in zip(ref_names, exprs, strict=True)]
    if w.part == "eom":
        return [f"{plain(a)} = {plain(b)}" for a, b in exprs]
    if w.part == "cyclic":
        return ", ".join(exprs) if exprs else "none"
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


def unreproduced(sentence: str, witness: dict | None, ref: Reference) -> list[str]:
    """The numbers a sentence quotes for a coordinate or a velocity that its witness does not
    hold (rounded as quoted); accelerations quoted against the system's own at that state."""
    if "(for example" not in sentence:
        return []
    shown = {}
    for j in ref.jets:
        for dots, suffix in ((0, ""), (1, "_dot"), (2, "_ddot")):
            shown[symbol_text(j.name, dots)] = j.name + suffix
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
        acc = acc.subs(time, witness["t"])  # not quoted: as the witness holds it
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
        key = (w.problem["scene"], w.problem["seed"])
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
        for s in before.feedback:
            for bad in unreproduced(s, dict(before.witness or {}), ref):
                numbers.append((w.problem, w.part, w.cause, bad))
                row["numbers"] += 1
    return {"rows": rows, "false": false_claims, "numbers": numbers}


def table(rows: dict[str, Counter]) -> str:
    head = f"{'part':<12}{'wrong':>7}{'recorded':>10}{'other':>8}{'false':>8}{'nothing':>9}"
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
    return f"{name:<12}{r['wrong']:>7}{cols}{pc('nothing'):>9}{r['numbers']:>13}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--show-false", type=int, default=30)
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    seeds = tuple(int(s) for s in args.seeds.split(","))
    scenes = tuple(args.scenes.split(",")) if args.scenes else None
    corpus = build(seeds, scenes)
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
