"""Recompute every label of the systems corpus (systems.jsonl) without lagrade's judge.

Each case carries, beside the answer as a student typed it, its `meaning`: the same answer written
by the corpus's author in sympy's own syntax (trusted data, never student text). This script reads
the meanings and the problem's reference with sympy, derives everything from the reference
Lagrangian itself and decides each part by the definitions in README.md ("What correct means"):

- lagrangian: the reference Euler–Lagrange expressions come from sympy.physics.mechanics'
  LagrangesMethod (on functions of t), the answer's by plain sympy diff on functions of t;
  the answer is right when its expressions are c times the reference's with one constant c > 0
  (then L′ − cL is a total time derivative).
- eom: right when the set has one equation per coordinate, is linear in the accelerations with a
  nonsingular matrix, and holds at the reference accelerations (so it yields the same q̈).
- momenta: one `p_q = …` per coordinate, each equal to ∂L/∂q̇.
- cyclic: the set of coordinates L does not depend on.
- conserved: each quantity's total time derivative vanishes on the reference motion (q̈ replaced
  by the reference accelerations), it is not a constant, and the quantities are independent as
  functions of the coordinates and velocities (Jacobian rank, parameters and t held fixed).
- expression: equal on the declared domains where the reference is finite, principal branches in
  complex arithmetic.

Numbers decide: mpmath at 50 digits at random points (each draw of the parameters with several
states); a difference above 1e-30 relative is a difference. Symbols confirm where they can: a
simplification of the difference to 0 under a time limit is recorded as "proved" (the report
counts them); a proof that contradicts the numbers stops the run.

Run: python benchmarks/corpus/verify_systems.py [--ids ID ...] [--no-proofs] [--reading]
(--reading also reads each answer text with lagrade's parser — reading, not judging — and reports
where it differs from the stored meaning: a transcription slip of ours, or a misreading.)
"""

from __future__ import annotations

import argparse
import json
import random
import signal
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import mpmath
import sympy as sp
from sympy.parsing.sympy_parser import parse_expr, standard_transformations
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

SYSTEMS = Path(__file__).with_name("systems.jsonl")
DIGITS = 50
TOLERANCE = mpmath.mpf(10) ** -30
PARAMETER_DRAWS = 6
STATES_PER_DRAW = 4
PROOF_SECONDS = 8

_T = sp.Symbol("t", real=True)


class Unreadable(Exception):
    """A meaning or reference that names something the problem does not declare."""


# --- reading the trusted forms -------------------------------------------------------------------


def _interval(domain: str) -> tuple[float, float]:
    """Where to draw a variable of this domain (mirrors the domain words of docs/formats.md)."""
    key = domain.strip().lower()
    if key == "positive":
        return (0.3, 3.0)
    if key == "nonnegative":
        return (0.0, 3.0)
    if key == "real":
        return (-3.0, 3.0)
    inner = key.strip("()[]")
    low, high = (float(sp.sympify(b, locals={"pi": sp.pi})) for b in inner.split(","))
    return (low, high)


@dataclass
class Problem:
    """The question of a case, read with sympy: its symbols, reference and sampling boxes."""

    spec: dict

    @cached_property
    def coordinates(self) -> list[str]:
        raw = self.spec.get("coordinates", [])
        return list(raw) if not isinstance(raw, dict) else list(raw.keys())

    @cached_property
    def symbols(self) -> dict[str, sp.Symbol]:
        names = {n: sp.Symbol(n, real=True) for n in self.spec.get("parameters", {})}
        for q in self.coordinates:
            for suffix in ("", "_dot", "_ddot"):
                names[q + suffix] = sp.Symbol(q + suffix, real=True)
        names.setdefault("t", _T)
        for name in ("const", "constant"):  # an arbitrary constant, as lagrade's vocabulary has
            names.setdefault(name, sp.Symbol(name, real=True))
        return names

    def q(self, kind: str = "") -> list[sp.Symbol]:
        return [self.symbols[q + kind] for q in self.coordinates]

    def read(self, text: str) -> sp.Expr:
        """A trusted expression (the reference or a meaning) in sympy syntax."""
        if "^" in text:
            raise Unreadable(f"'^' in a sympy-syntax form: {text!r}")
        local = dict(self.symbols)
        local["Dt"] = self.total_derivative
        if self.spec.get("imaginary_unit"):
            local[self.spec["imaginary_unit"]] = sp.I
        expr = parse_expr(
            text,
            local_dict=local,
            global_dict=dict(vars(sp)),
            transformations=standard_transformations,
        )
        unknown = {s.name for s in sp.sympify(expr).free_symbols} - set(self.symbols)
        if unknown:
            raise Unreadable(f"unknown names {sorted(unknown)} in {text!r}")
        return sp.sympify(expr)

    def read_equation(self, text: str) -> sp.Expr:
        """lhs − rhs of `lhs = rhs` (a bare expression means = 0)."""
        if text.count("=") > 1:
            raise Unreadable(f"more than one '=' in {text!r}")
        if "=" in text:
            lhs, rhs = text.split("=")
            return self.read(lhs) - self.read(rhs)
        return self.read(text)

    def total_derivative(self, f: sp.Expr) -> sp.Expr:
        """D_t on the jets: ∂_t + Σ q̇ ∂_q + Σ q̈ ∂_q̇."""
        f = sp.sympify(f)
        out = sp.diff(f, _T)
        for q, qd, qdd in zip(self.q(), self.q("_dot"), self.q("_ddot"), strict=True):
            out += qd * sp.diff(f, q) + qdd * sp.diff(f, qd)
        return out

    @cached_property
    def lagrangian(self) -> sp.Expr:
        return self.read(self.spec["lagrangian"])

    @cached_property
    def expression(self) -> sp.Expr:
        return self.read(self.spec["expression"])

    # functions of t, for sympy.physics.mechanics and plain sympy diff
    @cached_property
    def _functions(self) -> list:
        return [dynamicsymbols(q) for q in self.coordinates]

    def to_functions(self, expr: sp.Expr) -> sp.Expr:
        mapping = {}
        for f, q, qd, qdd in zip(
            self._functions, self.q(), self.q("_dot"), self.q("_ddot"), strict=True
        ):
            mapping[qdd] = f.diff(dynamicsymbols._t, 2)
            mapping[qd] = f.diff(dynamicsymbols._t)
            mapping[q] = f
        return expr.subs(_T, dynamicsymbols._t).subs(mapping)

    def to_jets(self, expr: sp.Expr) -> sp.Expr:
        mapping = {
            f.diff(dynamicsymbols._t, 2): qdd
            for f, qdd in zip(self._functions, self.q("_ddot"), strict=True)
        }
        expr = expr.subs(mapping)
        mapping = {
            f.diff(dynamicsymbols._t): qd
            for f, qd in zip(self._functions, self.q("_dot"), strict=True)
        }
        expr = expr.subs(mapping)
        expr = expr.subs(dict(zip(self._functions, self.q(), strict=True)))
        return expr.subs(dynamicsymbols._t, _T)

    @cached_property
    def euler_lagrange(self) -> list[sp.Expr]:
        """d/dt ∂L/∂q̇ − ∂L/∂q of the reference, by LagrangesMethod."""
        method = LagrangesMethod(self.to_functions(self.lagrangian), self._functions)
        return [self.to_jets(e) for e in method.form_lagranges_equations()]

    def euler_lagrange_of(self, lagrangian: sp.Expr) -> list[sp.Expr]:
        """The same for an answer, by another route: plain sympy diff on functions of t (a
        coordinate the answer lacks gets 0, where euler_equations would leave it out)."""
        t = dynamicsymbols._t
        fn = self.to_functions(lagrangian)
        return [
            self.to_jets(sp.diff(sp.diff(fn, f.diff(t)), t) - sp.diff(fn, f))
            for f in self._functions
        ]

    # sampling
    def _boxes(self) -> dict[sp.Symbol, tuple[float, float]]:
        boxes = {self.symbols[n]: _interval(d) for n, d in self.spec.get("parameters", {}).items()}
        raw = self.spec.get("coordinates", [])
        for q in self.coordinates:
            domain = raw.get(q) if isinstance(raw, dict) else None
            boxes[self.symbols[q]] = _interval(domain) if domain else (-2.0, 2.0)
            boxes[self.symbols[q + "_dot"]] = (-2.0, 2.0)
            boxes[self.symbols[q + "_ddot"]] = (-2.0, 2.0)
        if "t" not in self.spec.get("parameters", {}):
            boxes[_T] = (-3.0, 3.0)
        for name in ("const", "constant"):
            boxes[self.symbols[name]] = (-3.0, 3.0)
        return boxes

    def draws(
        self, seed: int = 11, keep: Callable[[dict], bool] | None = None
    ) -> Iterable[list[dict[sp.Symbol, mpmath.mpf]]]:
        """PARAMETER_DRAWS groups of STATES_PER_DRAW points sharing one draw of the parameters;
        with `keep`, points it refuses are drawn again (up to 50 tries per point), so that a
        reference real on a small part of the box (|v| < c) still gets its points."""
        rng = random.Random(seed)
        boxes = self._boxes()
        parameters = {self.symbols[n] for n in self.spec.get("parameters", {})}
        for _ in range(PARAMETER_DRAWS):
            fixed = {s: mpmath.mpf(rng.uniform(*boxes[s])) for s in parameters}
            group = []
            for _ in range(STATES_PER_DRAW * 50):
                point = dict(fixed)
                for s, box in boxes.items():
                    if s not in parameters:
                        point[s] = mpmath.mpf(rng.uniform(*box))
                if keep is None or keep(point):
                    group.append(point)
                if len(group) == STATES_PER_DRAW:
                    break
            yield group


def _evaluator(expr: sp.Expr, symbols: list[sp.Symbol]) -> Callable:
    f = sp.lambdify(symbols, expr, modules="mpmath")
    return lambda point: f(*(point[s] for s in symbols))


def _value(f: Callable, point: dict) -> mpmath.mpc | None:
    """f at the point in 50 digits, or None where it has no finite value."""
    try:
        with mpmath.workdps(DIGITS):
            v = mpmath.mpmathify(f(point))
    except (ZeroDivisionError, ValueError, OverflowError):
        return None
    if not mpmath.isfinite(v):
        return None
    return v


def _real(v) -> bool:
    return v is not None and abs(mpmath.im(v)) <= TOLERANCE * (1 + abs(v))


def _same(a, b) -> bool:
    return abs(a - b) <= TOLERANCE * (1 + abs(a) + abs(b))


# --- symbolic confirmation -----------------------------------------------------------------------


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


def _vanishes(expr: sp.Expr, seconds: int = PROOF_SECONDS) -> bool | None:
    """True when sympy simplifies expr to 0 within the time; None when it cannot tell."""
    if expr == 0:
        return True
    old = signal.signal(signal.SIGALRM, _alarm)
    try:
        for simplify in (sp.expand, sp.trigsimp, sp.simplify):
            signal.alarm(seconds)
            try:
                if simplify(expr) == 0:
                    return True
            except _Timeout:
                return None
            except Exception:  # noqa: BLE001 - a simplifier that fails has proved nothing
                continue
            finally:
                signal.alarm(0)
    finally:
        signal.signal(signal.SIGALRM, old)
    return None


# --- one verdict per part -------------------------------------------------------------------------


@dataclass(frozen=True)
class Finding:
    """What the verifier computed for one case."""

    id: str
    label: str  # as stored
    computed: str  # correct | incorrect | undecided
    detail: str
    proof: str  # proved | unproved | "" (not attempted)

    @property
    def agrees(self) -> bool:
        return self.computed == self.label


class _Verifier:
    def __init__(self, problem: Problem, proofs: bool, complete: bool = False):
        self.p = problem
        self.proofs = proofs
        self.complete = complete

    @cached_property
    def all_symbols(self) -> list[sp.Symbol]:
        return list(self.p.symbols.values())

    def ev(self, expr: sp.Expr) -> Callable:
        return _evaluator(expr, self.all_symbols)

    @cached_property
    def lagrangian_value(self) -> Callable:
        return self.ev(self.p.lagrangian)

    def states(self) -> Iterable[list[dict]]:
        """Draws of points where the reference Lagrangian is real and finite."""
        for group in self.p.draws(keep=lambda pt: _real(_value(self.lagrangian_value, pt))):
            if group:
                yield group

    @cached_property
    def _acceleration_system(self) -> tuple[Callable, Callable]:
        el = sp.Matrix(self.p.euler_lagrange)
        qdd = self.p.q("_ddot")
        mass = el.jacobian(qdd)
        rest = el.subs(dict.fromkeys(qdd, 0))
        return self.ev(mass), self.ev(rest)

    def accelerations(self, point: dict) -> dict | None:
        """The reference q̈ at a point (M q̈ + rest = 0), or None where M is singular."""
        mass_f, rest_f = self._acceleration_system
        with mpmath.workdps(DIGITS):
            mass = mpmath.matrix(mass_f(point))
            rest = mpmath.matrix(rest_f(point))
            try:
                solution = mpmath.lu_solve(mass, -rest)
            except ZeroDivisionError:
                return None
        out = dict(point)
        for i, s in enumerate(self.p.q("_ddot")):
            out[s] = solution[i]
        return out

    # parts
    def lagrangian(self, meaning: str) -> tuple[str, str, str]:
        answer = self.p.read(meaning)
        ref = self.p.euler_lagrange
        ans = self.p.euler_lagrange_of(answer)
        ref_f = [self.ev(e) for e in ref]
        ans_f = [self.ev(e) for e in ans]
        scales = []
        for group in self.states():
            c = None
            for pt in group:
                r = [_value(f, pt) for f in ref_f]
                a = [_value(f, pt) for f in ans_f]
                if any(v is None for v in r + a):
                    continue
                norm = sum(abs(v) ** 2 for v in r)
                if norm <= TOLERANCE:
                    continue
                if c is None:
                    c = sum(x * mpmath.conj(y) for x, y in zip(a, r, strict=True)) / norm
                if not all(_same(x, c * y) for x, y in zip(a, r, strict=True)):
                    return "incorrect", "not c·L plus a total derivative", self._no_proof()
            if c is not None:
                scales.append(c)
        if not scales:
            return "undecided", "no point where the reference is defined", ""
        if all(mpmath.re(c) > TOLERANCE and _real(c) for c in scales):
            return "correct", f"c = {mpmath.nstr(scales[0], 6)}", self._prove_scale(ans, ref)
        return "incorrect", f"scale c = {mpmath.nstr(scales[0], 6)} is not positive", ""

    def _no_proof(self) -> str:
        return ""

    def _prove_scale(self, ans: list, ref: list) -> str:
        if not self.proofs:
            return ""
        j = next((i for i, e in enumerate(ref) if e != 0), None)
        if j is None:
            return "unproved"
        c = sp.cancel(ans[j] / ref[j])
        jets = set(self.p.q()) | set(self.p.q("_dot")) | set(self.p.q("_ddot")) | {_T}
        if c.free_symbols & jets:
            c = sp.simplify(c)
            if c.free_symbols & jets:
                return "unproved"
        results = [_vanishes(a - c * r) for a, r in zip(ans, ref, strict=True)]
        return "proved" if all(results) else "unproved"

    def eom(self, meanings: list[str]) -> tuple[str, str, str]:
        equations = [self.p.read_equation(m) for m in meanings]
        n = len(self.p.coordinates)
        qdd = self.p.q("_ddot")
        if len(equations) != n:
            return "incorrect", f"{len(equations)} equations for {n} coordinates", ""
        matrix = sp.Matrix(equations).jacobian(qdd)
        if any(sp.diff(e, a, b) != 0 for e in equations for a in qdd for b in qdd):
            return "undecided", "not linear in the accelerations", ""
        eq_f = [self.ev(e) for e in equations]
        mat_f = self.ev(matrix)
        checked = 0
        for group in self.states():
            for pt in group:
                full = self.accelerations(pt)
                if full is None:
                    continue
                values = [_value(f, full) for f in eq_f]
                if any(v is None for v in values):
                    continue
                with mpmath.workdps(DIGITS):
                    m = mpmath.matrix(mat_f(full))
                    scale = 1 + mpmath.mnorm(m, 1) * (1 + max(abs(full[s]) for s in qdd))
                    if any(abs(v) > TOLERANCE * scale for v in values):
                        return "incorrect", "does not hold at the reference accelerations", ""
                    if abs(mpmath.det(m)) <= TOLERANCE * (1 + mpmath.mnorm(m, 1)) ** n:
                        return "incorrect", "does not determine the accelerations", ""
                checked += 1
        if checked < 8:
            return "undecided", f"only {checked} points", ""
        return "correct", "same accelerations", self._prove_eom(equations)

    def _prove_eom(self, equations: list) -> str:
        if not self.proofs:
            return ""
        qdd = self.p.q("_ddot")
        old = signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(PROOF_SECONDS * 2)
        try:
            ref = sp.Matrix(self.p.euler_lagrange)
            ref_sol = ref.jacobian(qdd).LUsolve(-ref.subs(dict.fromkeys(qdd, 0)))
            ans = sp.Matrix(equations)
            ans_sol = ans.jacobian(qdd).LUsolve(-ans.subs(dict.fromkeys(qdd, 0)))
        except (_Timeout, Exception):  # noqa: BLE001 - no symbolic solution: no proof
            return "unproved"
        finally:
            signal.alarm(0)
            signal.signal(signal.SIGALRM, old)
        results = [_vanishes(a - r) for a, r in zip(ans_sol, ref_sol, strict=True)]
        return "proved" if all(results) else "unproved"

    def momenta(self, meanings: list[str]) -> tuple[str, str, str]:
        expected = {
            "p_" + q: sp.diff(self.p.lagrangian, self.p.symbols[q + "_dot"])
            for q in self.p.coordinates
        }
        given = {}
        for m in meanings:
            name, _, rhs = m.partition("=")
            given[name.strip()] = self.p.read(rhs)
        if set(given) != set(expected):
            return "incorrect", f"names {sorted(given)} for {sorted(expected)}", ""
        for name, value in given.items():
            verdict = self._equal(value, expected[name])
            if verdict != "correct":
                return "incorrect", f"{name} differs", ""
        proofs = [_vanishes(given[k] - expected[k]) for k in expected] if self.proofs else []
        return "correct", "every momentum equal", self._proved(proofs)

    def _equal(self, a: sp.Expr, b: sp.Expr) -> str:
        fa, fb = self.ev(a), self.ev(b)
        compared = 0
        for group in self.states():
            for pt in group:
                vb = _value(fb, pt)
                if vb is None:
                    continue
                va = _value(fa, pt)
                if va is None or not _same(va, vb):
                    return "incorrect"
                compared += 1
        return "correct" if compared >= 8 else "undecided"

    def _proved(self, proofs: list) -> str:
        if not self.proofs:
            return ""
        return "proved" if proofs and all(proofs) else "unproved"

    @cached_property
    def cyclic_set(self) -> set[str]:
        out = set()
        for q in self.p.coordinates:
            if self._equal(sp.diff(self.p.lagrangian, self.p.symbols[q]), sp.S.Zero) == "correct":
                out.add(q)
        return out

    def cyclic(self, names: list[str]) -> tuple[str, str, str]:
        given = set(names)
        if given == self.cyclic_set:
            return "correct", f"cyclic: {sorted(self.cyclic_set) or 'none'}", ""
        return "incorrect", f"cyclic are {sorted(self.cyclic_set) or 'none'}", ""

    def conserved(self, meanings: list[str]) -> tuple[str, str, str]:
        quantities = [self.p.read(m) for m in meanings]
        variables = self.p.q() + self.p.q("_dot")
        for i, quantity in enumerate(quantities):
            derivative = self.p.total_derivative(quantity)
            d_f = self.ev(derivative)
            grad_f = self.ev(sp.Matrix([quantity]).jacobian(variables))
            moving = False
            checked = 0
            for group in self.states():
                for pt in group:
                    full = self.accelerations(pt)
                    if full is None:
                        continue
                    v = _value(d_f, full)
                    if v is None:
                        continue
                    with mpmath.workdps(DIGITS):
                        gradient = mpmath.matrix(grad_f(full))
                        size = mpmath.mnorm(gradient, 1)
                    if abs(v) > TOLERANCE * (1 + size * 10):
                        return "incorrect", f"quantity {i + 1} is not conserved", ""
                    moving |= size > TOLERANCE
                    checked += 1
            if checked < 8:
                return "undecided", f"quantity {i + 1}: only {checked} points", ""
            if not moving:
                return "incorrect", f"quantity {i + 1} is a constant", ""
        jacobian = self.ev(sp.Matrix(quantities).jacobian(variables))
        rank = 0
        for group in self.states():
            with mpmath.workdps(DIGITS):
                m = mpmath.matrix(jacobian(group[0]))
                singular = mpmath.svd_r(m, compute_uv=False)
                top = max(abs(s) for s in singular)
                rank = max(rank, sum(1 for s in singular if abs(s) > top * TOLERANCE))
        if rank < len(quantities):
            return "incorrect", f"rank {rank} for {len(quantities)} quantities", ""
        if self.complete:
            # docs/formats.md: with "all", the system's independent set is the momenta of its
            # cyclic coordinates and, when L does not depend on t, the energy function
            needed = len(self.cyclic_set) + (
                self._equal(sp.diff(self.p.lagrangian, _T), 0) == "correct"
            )
            if len(quantities) < needed:
                return "incorrect", f"{len(quantities)} of {needed} quantities", ""
        return "correct", "conserved, not constant, independent", ""

    def expression(self, meaning: str) -> tuple[str, str, str]:
        answer, ref = self.p.read(meaning), self.p.expression
        fa, fr = self.ev(answer), self.ev(ref)
        compared = 0
        for group in self.p.draws():
            for pt in group:
                vr = _value(fr, pt)
                if vr is None:
                    continue
                va = _value(fa, pt)
                if va is None or not _same(va, vr):
                    return "incorrect", "differs where the reference is finite", ""
                compared += 1
        if compared < 10:
            return "undecided", f"only {compared} points", ""
        proof = self._proved([_vanishes(answer - ref)]) if self.proofs else ""
        return "correct", "equal", proof


def verify_case(record: dict, proofs: bool = True) -> Finding:
    """The label of one case, recomputed."""
    request = record["request"]
    problem = Problem(request["problem"])
    verifier = _Verifier(problem, proofs, bool((request.get("given") or {}).get("all")))
    part, meaning = request["part"], record["meaning"]
    meanings = meaning if isinstance(meaning, list) else [meaning]
    try:
        with mpmath.workdps(DIGITS):  # every number of the run in 50 digits, not mpmath's 15
            if part in ("lagrangian", "expression"):
                computed, detail, proof = getattr(verifier, part)(meaning)
            elif part in ("eom", "momenta", "conserved", "cyclic"):
                computed, detail, proof = getattr(verifier, part)(meanings)
            else:
                raise Unreadable(f"no rule for part {part!r}")
    except Unreadable as error:
        computed, detail, proof = "undecided", str(error), ""
    return Finding(record["id"], record["label"], computed, detail, proof)


def reading_differs(record: dict) -> str:
    """Where lagrade's parser reads the answer text otherwise than the stored meaning says ('' when
    they agree, or when the text does not parse: then lagrade's verdict says so). Diagnostic only,
    labels never depend on it: a difference is a transcription slip of ours or a misreading.
    Equations are compared up to a factor (an equation of motion may be scaled), a leading label
    (L =, E =, p_x =) is dropped from both sides."""
    from lagrade.judge.problem import build_problem
    from lagrade.notation.parse import parse_answer

    request = record["request"]
    problem = Problem(request["problem"])
    part = request["part"]
    if part == "cyclic":
        return ""
    vocabulary = build_problem(request["problem"]).vocabulary()
    texts = request["answer"] if isinstance(request["answer"], list) else [request["answer"]]
    meanings = record["meaning"] if isinstance(record["meaning"], list) else [record["meaning"]]
    if len(texts) != len(meanings):
        return f"{len(texts)} lines for {len(meanings)} meanings"
    names = list(problem.symbols.values())
    for text, meaning in zip(texts, meanings, strict=True):
        try:
            parsed = parse_answer(text, vocabulary)
        except Exception:  # noqa: BLE001 - unreadable: lagrade's verdict says so
            continue
        if parsed.rhs is not None and parsed.lhs.is_Symbol and part != "eom":
            theirs = parsed.rhs
        else:
            theirs = parsed.expr
        theirs = theirs.subs(
            {x: problem.symbols[x.name] for x in theirs.free_symbols if x.name in problem.symbols}
        )
        lhs, equals, rhs = meaning.partition("=")
        if equals and part != "eom":
            ours = problem.read(rhs)
        else:
            ours = problem.read_equation(meaning)
        fa, fb = _evaluator(ours, names), _evaluator(theirs, names)
        ratios = []
        for group in problem.draws():
            for pt in group:
                with mpmath.workdps(DIGITS):
                    a, b = _value(fa, pt), _value(fb, pt)
                    if a is None or b is None:
                        continue
                    if part != "eom":
                        if not _same(a, b):
                            return f"{text!r} is read otherwise than {meaning!r}"
                    elif abs(b) > TOLERANCE:
                        ratios.append(a / b)
        if ratios and not all(_same(r, ratios[0]) for r in ratios):
            return f"{text!r} is read otherwise than {meaning!r}"
    return ""


def load(path: Path = SYSTEMS) -> list[dict]:
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--ids", nargs="*", help="only these cases")
    parser.add_argument("--no-proofs", action="store_true", help="numbers only")
    parser.add_argument("--reading", action="store_true", help="compare lagrade's reading")
    args = parser.parse_args()
    records = load()
    if args.ids:
        records = [r for r in records if r["id"] in set(args.ids)]
    bad = []
    proved = 0
    for record in records:
        finding = verify_case(record, proofs=not args.no_proofs)
        proved += finding.proof == "proved"
        if not finding.agrees:
            bad.append(finding)
            print(
                f"DISAGREES {finding.id}: label {finding.label}, computed {finding.computed}"
                f" ({finding.detail})"
            )
        if args.reading:
            note = reading_differs(record)
            if note:
                print(f"READING {record['id']}: {note}")
    print(
        f"systems labels verified: {len(records) - len(bad)}/{len(records)}"
        f" ({proved} right answers also proved symbolically)"
    )
    return 1 if bad else 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    raise SystemExit(main())
