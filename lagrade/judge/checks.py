"""One checker per answer part, registered by part name; each returns a frozen Verdict and never
raises over a student's mistake (text that does not parse is `invalid`, with the parser's
message).

    dof             an integer: 3N − k
    transformation  Cartesian coordinates that satisfy the constraints identically, full rank
    lagrangian      E(L′) = c E(L): c > 0 right (constant, dF/dt, factor named), c < 0 V − T
    T, V            T equal; V equal up to a constant (another zero level)
    eom             each equation in the span of the EL rows; the set yields the same q̈
    momenta         p_j = ∂L/∂q̇_j, each
    cyclic          the set of coordinates absent from L
    conserved       each Q non-constant with D_t Q = 0 on the reference motion
    expression      equal to a reference expression on the declared domains

Later parts may carry the student's own earlier answers (`given={"lagrangian": …}`): a wrong
answer that follows correctly from them says so (`follows_from_own_answer`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.judge.adaptive import ExactThenAdaptive
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.decision import Outcome, decide
from lagrade.judge.derivatives import euler_lagrange_values, gradient, time_derivative_on_shell
from lagrade.judge.equivalence import (
    affine_match,
    differ_by_constant,
    expressions_equal,
    lagrangians_match,
    reference_values,
    values_equal,
)
from lagrade.judge.evaluate import FLOAT, UnsupportedExpression
from lagrade.judge.mutations import Mutant, plain
from lagrade.judge.problem import Problem, parser
from lagrade.judge.rows import (
    equation_rows,
    in_span,
    lagrangian_rows,
    row_rank,
    solve_accelerations,
)
from lagrade.judge.sampling import Points, coordinate_range
from lagrade.mechanics.domains import Domain

STATUSES = ("correct", "incorrect", "invalid", "timeout", "error")  # error: a bug of ours


@dataclass(frozen=True)
class Verdict:
    """The judgement of one answer part: status (correct | incorrect | invalid | timeout), score
    in [0, 1], feedback sentences, the parser's echo of what was read, the method that decided,
    the time it took, and when wrong a point where the answer and the reference differ."""

    part: str
    status: str
    score: float
    feedback: tuple[str, ...] = ()
    interpreted: str | list[str] = ""
    method: str = ""
    ms: float = 0.0
    witness: Mapping[str, float] | None = None
    follows_from_own_answer: bool = False
    mistakes: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        assert self.status in STATUSES, self.status
        assert 0.0 <= self.score <= 1.0, self.score

    def to_dict(self) -> dict[str, Any]:
        """The JSON form of a result (without the request id), in the documented key order."""
        return {
            "verdict": self.status,
            "score": self.score,
            "feedback": list(self.feedback),
            "interpreted": self.interpreted,
            "method": self.method,
            "ms": round(self.ms, 3),
            "part": self.part,
            "witness": dict(self.witness) if self.witness else None,
            "follows_from_own_answer": self.follows_from_own_answer,
            "mistakes": list(self.mistakes),
        }


def invalid(part: str, message: str, interpreted: str | list[str] = "") -> Verdict:
    return Verdict(part, "invalid", 0.0, (message,), interpreted, "parse")


# --- reading answers -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Read:
    """One parsed answer item: lhs (a label symbol or an expression), rhs, and the echo."""

    lhs: sp.Expr
    rhs: sp.Expr | None
    echo: str

    @property
    def expr(self) -> sp.Expr:
        return self.lhs if self.rhs is None else self.lhs - self.rhs


def _items(answer: Any, part: str) -> list[Any]:
    if isinstance(answer, str | sp.Basic):
        return [answer]
    if isinstance(answer, Sequence) and not isinstance(answer, str | bytes):
        return list(answer)
    raise RequestError(f"the answer to {part!r} must be a string or a list of strings")


def read(problem: Problem, item: Any, labels: Sequence[str] = (), mode: str = "answer") -> Read:
    """Parse one answer item with the project parser; sympy objects (from Python callers and
    tests, never from student text) pass through."""
    if isinstance(item, sp.Equality):
        return Read(problem.canonical(item.lhs), problem.canonical(item.rhs), plain(item))
    if isinstance(item, sp.Basic):
        return Read(problem.canonical(sp.S(item)), None, plain(item))
    if not isinstance(item, str):
        raise RequestError(f"an answer item must be a string, got {type(item).__name__}")
    p = parser()
    vocab = problem.vocabulary(labels)
    parse = {
        "answer": p.parse_answer,
        "equation": p.parse_equation,
        "expression": p.parse_expression,
    }
    return _read_parsed(problem, parse[mode](item, vocab))


def _read_parsed(problem: Problem, parsed) -> Read:
    if problem.parser_symbols_are_mine:
        return Read(parsed.lhs, parsed.rhs, parsed.plain())
    rhs = None if parsed.rhs is None else problem.canonical(parsed.rhs)
    return Read(problem.canonical(parsed.lhs), rhs, parsed.plain())


_LABEL = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=")


def read_labelled(problem: Problem, item: Any, extra_labels: Sequence[str] = ()) -> Read:
    """An expression that may be written `name = expression` (p_x = …, h = …, L = …): the name
    is dropped. `expression = const` is accepted too."""
    labels = [n for n in [*extra_labels, "const", "constant"] if n not in problem.by_name]
    if isinstance(item, str):
        m = _LABEL.match(item)
        if m and m.group(1) not in problem.by_name and m.group(1) not in labels:
            labels.append(m.group(1))
    got = read(problem, item, labels)
    if got.rhs is None:
        return got
    if isinstance(got.lhs, sp.Symbol):  # a name for the quantity (h = …, even when h is a
        return Read(got.rhs, None, got.echo)  # parameter: "parameter = expression" says nothing)
    if isinstance(got.rhs, sp.Symbol) and str(got.rhs) in ("const", "constant"):
        return Read(got.lhs, None, got.echo)
    raise _not_labelled(item)


def _not_labelled(item: Any) -> ParseError:
    text = item if isinstance(item, str) else str(item)
    return ParseError(
        "Write this answer as an expression, or as name = expression.", (0, len(text)), text
    )


def _free(problem: Problem, *exprs: sp.Expr) -> frozenset[sp.Symbol]:
    """The parameters sampled over their domains: all of them, except one the answer leaves out
    while writing its handout value as a number (`m 9.81 q` for m g q): that one keeps the
    value. A parameter that is merely missing is never pinned — with SI values (e = 1.6e-19 C)
    a dropped term would be 1e-19 of the rest and slip through any tolerance."""
    if not problem.values:  # no handout numbers: nothing can be pinned
        return frozenset(problem.domains)
    syms = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    numbers = [abs(float(n)) for e in exprs for n in e.atoms(sp.Number) if n != 0]
    pinned = {
        s
        for s, value in problem.values.items()
        if s not in syms
        and value
        and any(abs(n - abs(value)) <= 1e-3 * abs(value) for n in numbers)
    }
    return frozenset(s for s in problem.domains if s not in pinned)


def _has_acceleration(problem: Problem, expr: sp.Expr | Compiled) -> bool:
    symbols = expr.symbols if isinstance(expr, Compiled) else expr.free_symbols
    return any(j.ddot in symbols for j in problem.jets)


def _witness(
    points: Points, outcome: Outcome, *exprs: sp.Expr | Compiled
) -> dict[str, float] | None:
    """The point where the answers differ, in the symbols of `exprs` (all, without them)."""
    if outcome.where is None:
        return None
    syms = (
        set().union(*(e.symbols if isinstance(e, Compiled) else e.free_symbols for e in exprs))
        if exprs
        else None
    )
    return points.point(outcome.where, syms)


def _where(witness: Mapping[str, float] | None) -> str:
    if not witness:
        return ""
    return " (for example at " + ", ".join(f"{k} = {v:g}" for k, v in witness.items()) + ")"


def _method(*outcomes: Outcome) -> str:
    return "numeric+mpmath50" if any(o.method.endswith("mpmath50") for o in outcomes) else "numeric"


def _ratio_text(c: float) -> str:
    f = Fraction(c).limit_denominator(1000)
    return str(f) if abs(float(f) - c) <= 1e-9 * max(1, abs(c)) else f"{c:.6g}"


# --- dof ------------------------------------------------------------------------------------------


def check_dof(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    text = str(answer).strip() if not isinstance(answer, list) else ""
    if isinstance(answer, bool) or not (isinstance(answer, int) or re.fullmatch(r"[+-]?\d+", text)):
        return invalid(
            "dof", "Write the number of degrees of freedom as a whole number, e.g. 2.", text
        )
    n = int(text if not isinstance(answer, int) else answer)
    if n == problem.dof:
        return Verdict("dof", "correct", 1.0, (), str(n), "exact")
    feedback = [f"{n} is not the number of degrees of freedom."]
    mistakes: tuple[str, ...] = ()
    v = problem.variant
    if v is not None:
        freedoms = sum(b.freedoms for b in v.bodies)
        implied = sum(1 for label, _ in v.constraints if label != "declared")
        if n == freedoms:
            feedback.append(
                f"You counted {freedoms} freedoms of the bodies but subtracted no "
                "constraints (DOF = 3N − k)."
            )
            mistakes = ("no_constraints",)
        elif implied and n == problem.dof + implied:
            feedback.append(
                "Motion in a plane is a constraint too (z = 0 for each body); "
                "count it among the k constraints."
            )
            mistakes = ("forgot_planarity",)
    return Verdict("dof", "incorrect", 0.0, tuple(feedback), str(n), "exact", mistakes=mistakes)


# --- transformation ------------------------------------------------------------------------------


def check_transformation(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    v = problem.variant
    if v is None:
        raise RequestError("transformation equations can be checked only for bank scenes")
    required = list(v.transformation)
    optional = [f"z_{b.name}" for b in v.bodies if b.planar and f"z_{b.name}" not in required]
    labels = required + optional
    given_pos: dict[str, sp.Expr] = {}
    echoes = []
    for item in _items(answer, "transformation"):
        got = read(problem, item, labels, "answer")
        echoes.append(got.echo)
        if got.rhs is None or not (isinstance(got.lhs, sp.Symbol) and str(got.lhs) in labels):
            text = item if isinstance(item, str) else str(item)
            raise ParseError(
                f"Write each line as a Cartesian coordinate = expression, with one of: "
                f"{', '.join(labels)}.",
                (0, len(text)),
                text,
            )
        name = str(got.lhs)
        if name in given_pos:
            return invalid("transformation", f"{name} is given twice.", echoes)
        given_pos[name] = got.rhs
    missing = [n for n in required if n not in given_pos]
    if missing:
        return Verdict(
            "transformation",
            "incorrect",
            0.0,
            (f"Give every Cartesian coordinate; missing: {', '.join(missing)}.",),
            echoes,
            "exact",
            mistakes=("missing_coordinate",),
        )
    for name, expr in given_pos.items():
        if any(expr.has(j.dot) or expr.has(j.ddot) for j in problem.jets):
            return Verdict(
                "transformation",
                "incorrect",
                0.0,
                (f"{name} must depend on the coordinates (and t), not on velocities.",),
                echoes,
                "exact",
            )
    cart = {}
    for b in v.bodies:
        for axis, sym in vars(getattr(v.cartesian, b.name)).items():
            cart[sym] = given_pos.get(f"{axis}_{b.name}", sp.S.Zero)
    compiled_pos = {s: Compiled.of(e) for s, e in cart.items()}
    points = problem.points("transformation", _free(problem, *given_pos.values()))
    failures, outcomes = [], []
    for label, f in v.constraints:
        if f == 0:
            continue
        fc = Compiled.of(f)

        def residual(backend, fc=fc):
            env = dict(points.arrays(backend))
            n = points.n
            for s, c in compiled_pos.items():
                val = c.values(env, backend)[0]
                env[s] = (
                    np.full(n, val, dtype=float if backend is FLOAT else object)
                    if np.ndim(val) == 0
                    else val
                )
            value, size = fc.values(env, backend)
            return (
                np.broadcast_to(value, (n,)) if np.ndim(value) == 0 else value,
                np.broadcast_to(size, (n,)) if np.ndim(size) == 0 else size,
            )

        out = decide(residual)
        outcomes.append(out)
        if not out.equal:
            shown = "z = 0 (motion in the x-y plane)" if label != "declared" else f"{plain(f)} = 0"
            failures.append((shown, _witness(points, out, *given_pos.values())))
    rank = _transformation_rank(problem, list(given_pos.values()), points)
    n = len(problem.jets)
    feedback, mistakes = [], []
    for shown, w in failures:
        feedback.append(f"Your positions violate the constraint {shown}{_where(w)}.")
        mistakes.append("violates_constraint")
    if rank < n:
        feedback.append(
            f"Your positions depend on only {rank} independent combination(s) of the "
            f"{n} coordinates; the map must have full rank."
        )
        mistakes.append("rank_deficient")
    if not feedback:
        return Verdict("transformation", "correct", 1.0, (), echoes, _method(*outcomes))
    total = max(1, len(outcomes))
    score = 0.0 if rank < n else 0.5 * (total - len(failures)) / total
    return Verdict(
        "transformation",
        "incorrect",
        score,
        tuple(feedback),
        echoes,
        _method(*outcomes),
        witness=failures[0][1] if failures else None,
        mistakes=tuple(mistakes),
    )


def _transformation_rank(problem: Problem, exprs: list[sp.Expr], points: Points) -> int:
    coords = [j.q for j in problem.jets]
    with np.errstate(all="ignore"):
        rows = []
        for e in exprs:
            grads = gradient(Compiled.of(e), coords, points.env)
            rows.append(sum(grads) if grads else np.zeros((points.n, len(coords))))
        J = np.stack([np.broadcast_to(r, (points.n, len(coords))) for r in rows], axis=1)
    if not np.all(np.isfinite(J)):
        return 0
    return row_rank(np.transpose(J, (0, 2, 1)), list(range(len(coords))))


# --- lagrangian, T, V -----------------------------------------------------------------------------


def _reference_el(problem: Problem, points: Points):
    ref = problem.L
    cached = problem.cached(
        "el", points, lambda: euler_lagrange_values(ref, problem.jets, points.env)
    )

    def values(backend):
        if backend is FLOAT:
            return cached
        return euler_lagrange_values(ref, problem.jets, points.arrays(backend), backend)

    return values


def judge_lagrangian(
    problem: Problem, expr: sp.Expr
) -> tuple[str, float, list[str], Outcome, dict[str, float] | None, tuple[str, ...]]:
    """(status, score, feedback, outcome, witness, mistakes) for a Lagrangian answer; the
    witness is a point where the motion differs, when it does."""
    answer = Compiled.of(expr)
    points = problem.points("lagrangian", _free(problem, expr))
    if _has_acceleration(problem, answer):  # before E(L), which needs an L(q, q̇, t)
        return (
            "incorrect",
            0.0,
            ["A Lagrangian depends on coordinates, velocities and t, not on accelerations."],
            Outcome(False, "structure", math.inf),
            None,
            ("acceleration",),
        )
    fast = _affine_to_reference(problem, answer, points)
    if fast is not None:  # c (T − V) + k: the same motion, settled by values alone
        notes = _factor_notes(fast.factor) + ([_CONSTANT_NOTE] if fast.shifted else [])
        return ("correct", 1.0, notes, Outcome(True, "numeric", fast.worst), None, ())
    match = lagrangians_match(answer, _reference_el(problem, points), problem.jets, points)
    out = match.outcome
    factors = np.array(match.factors)
    if out.equal and np.all(np.abs(factors) < 1e-12):
        return (
            "incorrect",
            0.0,
            [
                "Your L gives no equations of motion at all (it is a constant "
                "or a total time derivative)."
            ],
            out,
            None,
            ("trivial",),
        )
    if out.equal and np.all(factors > 0):
        return (
            "correct",
            1.0,
            _same_dynamics_notes(problem, answer, match, points),
            out,
            None,
            (),
        )
    if out.equal and np.all(factors < 0):
        return (
            "incorrect",
            0.5,
            [
                "Your L gives the right equations of motion but has the "
                "opposite sign: the convention is L = T − V, and you wrote "
                "V − T (or a negative multiple)."
            ],
            out,
            None,
            ("V_minus_T",),
        )
    feedback = []
    mistakes: tuple[str, ...] = ()
    mutant = problem.catalogue.match_lagrangian(answer, points, match.answer_el)
    if mutant is not None:
        feedback.append(_sentence(mutant.message))
        mistakes = (mutant.kind,)
    witness = _witness(points, out, answer)
    feedback.append(
        "Your L does not give the equations of motion of this system" + _where(witness) + "."
    )
    return ("incorrect", 0.0, feedback, out, witness, mistakes)


def _sentence(text: str) -> str:
    if text.split(" ", 1)[0] in ("your", "the", "sin"):
        text = text[0].upper() + text[1:]
    return text if text.endswith(".") else text + "."


_CONSTANT_NOTE = (
    "Your L differs from T − V by a constant (for example m g h, another zero "
    "level of V); that does not change the motion."
)


def _affine_to_reference(problem: Problem, answer: Compiled, points: Points):
    """answer = c (T − V) + k at the points (see `affine_match`), or None."""
    try:
        with np.errstate(all="ignore"):
            values = answer.values(points.env)
    except (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError):
        return None
    return affine_match(values, reference_values(problem.L, points), points)


def _factor_notes(c: float | None) -> list[str]:
    if c is None:
        return [
            "Your L is T − V times a factor that depends on the parameters; that gives "
            "the same motion."
        ]
    if abs(c - 1) > 1e-9:
        return [
            f"Your L is {_ratio_text(c)} × (T − V); a constant factor gives the same "
            "equations of motion."
        ]
    return []


def _same_dynamics_notes(problem: Problem, answer: Compiled, match, points: Points) -> list[str]:
    """Name how a right L differs from T − V: a constant, dF/dt, a global factor."""
    notes = _factor_notes(match.factor)
    with np.errstate(all="ignore"):
        a, sa = answer.values(points.env)
        b, sb = reference_values(problem.L, points)
        factors = np.array(match.factors)[points.group]
        d = np.broadcast_to(a - factors * b, (points.n,))
        size = np.broadcast_to(sa + np.abs(factors) * sb, (points.n,))
    if np.all(np.abs(d) <= 1e-9 * size):
        return notes
    starts = np.searchsorted(points.group, points.group)
    if np.all(np.abs(d - d[starts]) <= 1e-9 * (size + np.abs(d[starts]))):
        notes.append(_CONSTANT_NOTE)
    else:
        notes.append(
            "Your L differs from T − V by a total time derivative dF/dt; that gives the "
            "same equations of motion."
        )
    return notes


def _read_single(problem: Problem, answer: Any, part: str, label: str) -> Read:
    items = _items(answer, part)
    if len(items) != 1:
        raise RequestError(f"the answer to {part!r} is a single expression")
    return read_labelled(problem, items[0], (label,))


def check_lagrangian(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = _read_single(problem, answer, "lagrangian", "L")
    status, score, feedback, out, witness, mistakes = judge_lagrangian(problem, got.expr)
    return Verdict(
        "lagrangian",
        status,
        score,
        tuple(feedback),
        got.echo,
        _method(out),
        witness=witness,
        mistakes=mistakes,
    )


def _incorrect(
    part: str,
    got: Read,
    mutant: Mutant | None,
    sentence: str,
    witness: Mapping[str, float] | None,
    method: str,
) -> Verdict:
    """A wrong single-expression answer: the named mistake (when the catalogue knows it),
    then what is wrong, with a point where it shows."""
    feedback = [_sentence(mutant.message)] if mutant is not None else []
    feedback.append(sentence + _where(witness) + ".")
    mistakes = (mutant.kind,) if mutant is not None else ()
    return Verdict(
        part,
        "incorrect",
        0.0,
        tuple(feedback),
        got.echo,
        method,
        witness=witness,
        mistakes=mistakes,
    )


def check_kinetic(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = _read_single(problem, answer, "T", "T")
    answer_c = Compiled.of(got.expr)
    points = problem.points("T", _free(problem, got.expr))
    out = expressions_equal(answer_c, problem.kinetic, points)
    if out.equal:
        return Verdict("T", "correct", 1.0, (), got.echo, _method(out))
    mutant = problem.catalogue.match_plain(problem.catalogue.kinetic_mutants, answer_c, points)
    return _incorrect(
        "T",
        got,
        mutant,
        "Your T is not the kinetic energy of this system",
        _witness(points, out, answer_c),
        _method(out),
    )


def check_potential(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = _read_single(problem, answer, "V", "V")
    answer_c = Compiled.of(got.expr)
    reference = problem.potential
    points = problem.points("V", _free(problem, got.expr))
    out = differ_by_constant(answer_c, reference, points)
    if out.equal:
        notes = ()
        if not expressions_equal(answer_c, reference, points).equal:
            notes = (
                "Your V differs from the reference by a constant (another zero level); "
                "that is fine.",
            )
        return Verdict("V", "correct", 1.0, notes, got.echo, _method(out))
    mutant = problem.catalogue.match_offset(problem.catalogue.potential_mutants, answer_c, points)
    return _incorrect(
        "V",
        got,
        mutant,
        "Your V is not the potential energy of this system (up to a constant)",
        _witness(points, out, answer_c),
        _method(out),
    )


# --- equations of motion --------------------------------------------------------------------------


def _own_lagrangian(problem: Problem, given: Mapping | None) -> sp.Expr | None:
    """The student's own L from `given`, when it parses (follow-through is best effort)."""
    if not given or "lagrangian" not in given:
        return None
    try:
        expr = read_labelled(problem, given["lagrangian"], ("L",)).expr
    except (ParseError, RequestError):
        return None
    return None if _has_acceleration(problem, expr) else expr


def check_eom(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    items = _items(answer, "eom")
    reads: list[Read] = []
    for item in items:
        if isinstance(item, str):
            for parsed in parser().parse_equations(item, problem.vocabulary()):
                reads.append(_read_parsed(problem, parsed))
        else:
            reads.append(read(problem, item))
    echoes = [r.echo for r in reads]
    if not reads:
        return invalid("eom", "Give one equation of motion per coordinate.")
    exprs = [sp.S(r.expr) for r in reads]
    compiled = [Compiled.of(e) for e in exprs]
    jets = problem.jets
    n = len(jets)
    points = problem.points("eom", _free(problem, *exprs))
    ref_rows = problem.cached(
        "rows", points, lambda: equation_rows(problem.euler_lagrange, jets, points.env)
    )
    with np.errstate(all="ignore"):
        rows = equation_rows(compiled, jets, points.env)
    right, outcomes, feedback, mistakes = [], [], [], []
    wrong: list[int] = []
    witness = None
    for k in range(len(reads)):
        label = f"Equation {k + 1} ({echoes[k]})" if len(reads) > 1 else "Your equation"
        nonlinear = decide(lambda b, k=k: _nonlinear_residual(compiled, k, jets, points, b))
        if not nonlinear.equal:
            feedback.append(
                f"{label} is not linear in the accelerations, so it cannot be an "
                "Euler–Lagrange equation."
            )
            wrong.append(k)
            outcomes.append(nonlinear)
            continue
        size = rows.size[:, k]
        norm = np.linalg.norm(rows.coef[:, k, :].astype(float), axis=1)
        if np.all(norm <= 1e-10 * np.maximum(size, 1e-300)):
            feedback.append(f"{label} says nothing (it reduces to 0 = 0).")
            mistakes.append("trivial_equation")
            wrong.append(k)
            continue
        out = decide(lambda b, k=k: _span_residual(problem, compiled, ref_rows, k, points, b))
        outcomes.append(out)
        if out.equal:
            right.append(k)
            continue
        wrong.append(k)
        witness = witness or _witness(points, out, compiled[k])
        mutant = problem.catalogue.match_row(compiled[k], points)
        if mutant is not None:
            feedback.append(f"{label}: {mutant.message}.")
            mistakes.append(mutant.kind)
        else:
            feedback.append(
                f"{label} does not follow from the Euler–Lagrange equations of this "
                f"system{_where(_witness(points, out, compiled[k]))}."
            )
    rank = row_rank(rows.coef.astype(float), right)
    follows = False
    own = _own_lagrangian(problem, given)
    if wrong and own is not None:
        follows = _follows_from_own(problem, own, compiled, wrong, points)
        if follows:
            feedback.append(
                "These equations follow correctly from your own Lagrangian, which is "
                "not the right one."
            )
    if not wrong and rank == n:
        notes = ()
        if len(reads) > n:
            notes = (f"You gave {len(reads)} equations; {n} of them are independent.",)
        return Verdict("eom", "correct", 1.0, notes, echoes, _method(*outcomes))
    if not wrong and rank < n:
        feedback.append(
            f"Your equations are right but only {rank} of them are independent; "
            f"{n} coordinates need {n} equations."
        )
        mistakes.append("too_few_equations")
        score = rank / n
    else:
        score = len(right) / max(len(reads), n)
        if len(reads) < n and not wrong:
            feedback.append(f"{n} coordinates need {n} equations.")
    return Verdict(
        "eom",
        "incorrect",
        float(min(score, 1.0)),
        tuple(feedback),
        echoes,
        _method(*outcomes),
        witness=witness,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _nonlinear_residual(compiled, k, jets, points, backend):
    env = points.arrays(backend)
    rows = equation_rows([compiled[k]], jets, env, backend)
    return rows.nonlinear[:, 0], rows.size[:, 0]


def _span_residual(problem, compiled, ref_rows, k, points, backend):
    if backend is FLOAT:
        student = equation_rows([compiled[k]], problem.jets, points.env)
        return in_span(student, ref_rows, 0)
    env = points.arrays(backend)
    student = equation_rows([compiled[k]], problem.jets, env, backend)
    ref = equation_rows(problem.euler_lagrange, problem.jets, env, backend)
    return in_span(student, ref, 0, backend)


def _follows_from_own(problem: Problem, own: sp.Expr, compiled, wrong, points) -> bool:
    own_c = Compiled.of(own)
    jets = problem.jets
    try:
        with np.errstate(all="ignore"):
            own_rows = lagrangian_rows(own_c, jets, points.env)
        if not np.all(np.isfinite(own_rows.coef.astype(float))):
            return False
        for k in wrong:

            def residual(backend, k=k):
                env = points.arrays(backend)
                s = equation_rows([compiled[k]], jets, env, backend)
                r = own_rows if backend is FLOAT else lagrangian_rows(own_c, jets, env, backend)
                return in_span(s, r, 0, backend)

            if not decide(residual).equal:
                return False
    except (UnsupportedExpression, ValueError, np.linalg.LinAlgError):
        return False
    return True


# --- momenta --------------------------------------------------------------------------------------


def check_momenta(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    jets = problem.jets
    labels = [f"p_{j.name}" for j in jets]
    items = _items(answer, "momenta")
    by_coordinate: dict[int, Read] = {}
    unlabelled: list[Read] = []
    echoes = []
    for item in items:
        got = read(problem, item, labels)
        echoes.append(got.echo)
        if got.rhs is not None:
            if not (isinstance(got.lhs, sp.Symbol) and str(got.lhs) in labels):
                text = item if isinstance(item, str) else str(item)
                raise ParseError(
                    f"Write each momentum as {labels[0]} = … or give them in the order "
                    f"{', '.join(j.name for j in jets)}.",
                    (0, len(text)),
                    text,
                )
            k = labels.index(str(got.lhs))
            if k in by_coordinate:
                return invalid("momenta", f"{labels[k]} is given twice.", echoes)
            by_coordinate[k] = Read(got.rhs, None, got.echo)
        else:
            unlabelled.append(got)
    free_slots = [k for k in range(len(jets)) if k not in by_coordinate]
    if len(unlabelled) > len(free_slots):
        return invalid(
            "momenta", f"{len(items)} momenta given for {len(jets)} coordinates.", echoes
        )
    for k, got in zip(free_slots, unlabelled, strict=False):
        by_coordinate[k] = got
    own = _own_lagrangian(problem, given)
    right, feedback, mistakes, outcomes = 0, [], [], []
    witness, follows_all, any_wrong = None, True, False
    for k, j in enumerate(jets):
        if k not in by_coordinate:
            feedback.append(f"p_{j.name} is missing.")
            any_wrong, follows_all = True, False
            continue
        expr = by_coordinate[k].expr
        ans = Compiled.of(expr)
        points = problem.points("momenta", _free(problem, expr))
        out = expressions_equal(ans, problem.momenta[k], points)
        outcomes.append(out)
        if out.equal:
            right += 1
            continue
        if own is not None and _own_momentum_matches(problem, own, ans, k, points):
            if _own_is_same_gauge(problem, own):
                right += 1
                feedback.append(
                    f"p_{j.name} is the momentum of your Lagrangian, which differs "
                    "from T − V by a total derivative; that is right for your L."
                )
                continue
            feedback.append(
                f"p_{j.name} follows correctly from your own Lagrangian, which is "
                "not the right one."
            )
            any_wrong = True
            continue
        any_wrong, follows_all = True, False
        witness = witness or _witness(points, out, ans)
        mutant = problem.catalogue.match_plain(problem.catalogue.momentum_mutants(k), ans, points)
        if mutant is not None:
            feedback.append(_sentence(mutant.message))
            mistakes.append(mutant.kind)
        else:
            feedback.append(
                f"p_{j.name} is not ∂L/∂{j.name}_dot{_where(_witness(points, out, ans))}."
            )
    score = right / len(jets)
    status = "correct" if right == len(jets) else "incorrect"
    follows = status != "correct" and any_wrong and follows_all and own is not None
    return Verdict(
        "momenta",
        status,
        score,
        tuple(feedback)
        if status != "correct"
        else tuple(f for f in feedback if "total derivative" in f),
        echoes,
        _method(*outcomes),
        witness=witness if status != "correct" else None,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _own_momentum_matches(problem: Problem, own: sp.Expr, ans: Compiled, k: int, points) -> bool:
    own_c = Compiled.of(own)
    velocity = problem.jets[k].dot

    def values(backend):
        grads = gradient(own_c, [velocity], points.arrays(backend), backend)
        v = sum(g[:, 0] for g in grads) if grads else 0
        s = sum(abs(g[:, 0]) for g in grads) if grads else 0
        return v, s

    try:
        return values_equal(ans, values, points).equal
    except (UnsupportedExpression, ValueError):
        return False


def _own_is_same_gauge(problem: Problem, own: sp.Expr) -> bool:
    """The student's L is T − V plus a constant or a total derivative (factor exactly 1), so its
    momenta are right for it."""
    points = problem.points("lagrangian", _free(problem, own))
    match = lagrangians_match(
        Compiled.of(own), _reference_el(problem, points), problem.jets, points
    )
    c = match.factor
    return match.outcome.equal and c is not None and abs(c - 1) <= 1e-9


# --- cyclic coordinates ---------------------------------------------------------------------------

_NONE = {"none", "no", "-", "", "∅", "nothing"}


def check_cyclic(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    items = (
        _items(answer, "cyclic")
        if not isinstance(answer, str)
        else re.split(r"\s*(?:,|;|\band\b)\s*", answer.strip())
    )
    names: list[str] = []
    echoes: list[str] = []
    velocity_named = []
    coords = {j.q: j.name for j in problem.jets}
    velocities = {j.dot: j.name for j in problem.jets}
    for item in items:
        if isinstance(item, str) and item.strip().lower() in _NONE:
            continue
        got = read(problem, item, (), "expression")
        echoes.append(got.echo)
        sym = got.expr
        if sym in coords:
            names.append(coords[sym])
        elif sym in velocities:
            velocity_named.append(velocities[sym])
            names.append(velocities[sym])
        else:
            text = item if isinstance(item, str) else str(item)
            raise ParseError(
                f"Name the cyclic coordinates, e.g. {problem.coordinates[0]}; or write none.",
                (0, len(text)),
                text,
            )
    claimed = set(names)
    L = sp.expand(problem.system.L)
    truth = set(problem.system.cyclic_coordinates)
    feedback, mistakes = [], []
    for name in velocity_named:
        feedback.append(f"A cyclic coordinate is a coordinate ({name}), not its velocity.")
    right = 0
    for j in problem.jets:
        if (j.name in claimed) == (j.name in truth):
            right += 1
            continue
        if j.name in claimed:
            if not L.has(j.dot):
                feedback.append(
                    f"{j.name} is not cyclic: L contains {j.name} itself (only its "
                    f"velocity {j.name}_dot is missing); cyclic means ∂L/∂{j.name} = 0."
                )
                mistakes.append("velocity_missing_not_cyclic")
            else:
                term = next((x for x in sp.Add.make_args(L) if x.has(j.q)), None)
                example = f" (for example in the term {plain(term)})" if term is not None else ""
                feedback.append(f"{j.name} is not cyclic: L depends on {j.name}{example}.")
                mistakes.append("not_cyclic")
        else:
            feedback.append(
                f"{j.name} is cyclic: L contains its velocity {j.name}_dot but not "
                f"{j.name} itself, so p_{j.name} is conserved."
            )
            mistakes.append("missed_cyclic")
    n = len(problem.jets)
    echo = echoes if echoes else ["none"]
    follows = False
    own = _own_lagrangian(problem, given)
    if right < n and own is not None:
        own_cyclic = {j.name for j in problem.jets if not sp.expand(own).has(j.q)}
        if own_cyclic == claimed and own_cyclic != truth:
            follows = True
            feedback.append(
                "This is the set of cyclic coordinates of your own Lagrangian, which "
                "is not the right one."
            )
    if right == n and not velocity_named:
        return Verdict("cyclic", "correct", 1.0, (), echo, "exact")
    return Verdict(
        "cyclic",
        "incorrect",
        right / n * (0.5 if velocity_named else 1.0),
        tuple(feedback),
        echo,
        "exact",
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


# --- conserved quantities -------------------------------------------------------------------------


def _accelerations(problem: Problem, points: Points):
    rows = problem.cached(
        "rows", points, lambda: equation_rows(problem.euler_lagrange, problem.jets, points.env)
    )
    acc = problem.cached("acc", points, lambda: solve_accelerations(rows))

    def values(backend):
        if backend is FLOAT:
            return acc
        ref = equation_rows(problem.euler_lagrange, problem.jets, points.arrays(backend), backend)
        return solve_accelerations(ref, backend)

    return values


def _conservation(
    problem: Problem, Q: Compiled, points: Points
) -> tuple[Outcome, bool, np.ndarray]:
    """(is D_t Q = 0 on-shell, is Q constant, gradient of Q at the points)."""
    jets = problem.jets
    acc = _accelerations(problem, points)

    def residual(backend):
        total, size, _grad = time_derivative_on_shell(
            Q, jets, points.arrays(backend), acc(backend), backend
        )
        return to_length(total, points.n, backend), to_length(size, points.n, backend)

    out = decide(residual)
    with np.errstate(all="ignore"):
        _t, _s, grad = time_derivative_on_shell(Q, jets, points.env, acc(FLOAT))
        grad = np.broadcast_to(np.asarray(grad, float), (points.n, 1 + 2 * len(jets)))
        value, size = Q.values(points.env)
        size = np.broadcast_to(size, (points.n,))
    constant = bool(np.all(np.abs(grad).max(axis=1) <= 1e-10 * np.maximum(size, 1e-300)))
    return out, constant, grad


def check_conserved(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    items = (
        []
        if isinstance(answer, str) and answer.strip().lower() in _NONE
        else _items(answer, "conserved")
    )
    items = [i for i in items if not (isinstance(i, str) and i.strip().lower() in _NONE)]
    reads = [read_labelled(problem, item) for item in items]
    echoes = [r.echo for r in reads] or ["none"]
    key = problem.system.conserved_quantities
    free = _free(problem, *(r.expr for r in reads))
    points = problem.points("conserved", free)
    key_rank = problem.cached(
        "key_rank",
        points,
        lambda: _gradient_rank(
            [_conservation(problem, Compiled.of(q), points)[2] for q in key.values()]
        ),
    )
    own = _own_lagrangian(problem, given)
    feedback, mistakes, outcomes = [], [], []
    right_grads = []
    witness = None
    follows_all, any_wrong = True, False
    for k, r in enumerate(reads):
        label = f"{echoes[k]}"
        if _has_acceleration(problem, r.expr):
            feedback.append(
                f"{label} contains an acceleration; a conserved quantity is a function "
                "of the coordinates, velocities and t."
            )
            mistakes.append("acceleration")
            continue
        Q = Compiled.of(r.expr)
        out, constant, grad = _conservation(problem, Q, points)
        outcomes.append(out)
        if constant:
            feedback.append(
                f"{label} is a constant; it is conserved trivially and says nothing "
                "about the motion."
            )
            mistakes.append("constant")
        elif out.equal:
            right_grads.append(grad)
        elif own is not None and _conserved_by_own(problem, own, Q, points):
            feedback.append(
                f"{label} is conserved by the motion of your own Lagrangian, which is not "
                "the right one."
            )
            any_wrong = True
        else:
            any_wrong, follows_all = True, False
            witness = witness or _witness(points, out, Q)
            mutant = problem.catalogue.match_offset(problem.catalogue.conserved_mutants, Q, points)
            if mutant is not None:
                feedback.append(_sentence(mutant.message))
                mistakes.append(mutant.kind)
            else:
                feedback.append(
                    f"{label} is not conserved: its time derivative along the motion "
                    f"is not zero{_where(_witness(points, out, Q))}."
                )
    rank = _gradient_rank(right_grads)
    n_right = len(right_grads)
    listed = len(reads)
    if key_rank == 0:
        score = 1.0 if n_right == listed else (n_right / listed if listed else 1.0)
    else:
        fraction = n_right / listed if listed else 0.0
        score = fraction * min(1.0, rank / key_rank)
        if rank < key_rank:
            names = ", ".join(key)
            noun = "quantity" if key_rank == 1 else "quantities"
            feedback.append(
                f"This system has {key_rank} independent conserved {noun} "
                f"(for example {names}); you gave {rank}."
            )
            mistakes.append("missing_conserved")
    status = "correct" if score >= 1.0 - 1e-12 and not feedback else "incorrect"
    if status == "correct":
        score = 1.0
    follows = status != "correct" and any_wrong and follows_all and own is not None
    return Verdict(
        "conserved",
        status,
        float(score),
        tuple(feedback),
        echoes,
        _method(*outcomes),
        witness=witness,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _conserved_by_own(problem: Problem, own: sp.Expr, Q: Compiled, points: Points) -> bool:
    """Follow-through: D_t Q = 0 along the motion of the student's own L (its accelerations
    from its own Euler–Lagrange equations), decided like the reference case."""
    own_c = Compiled.of(own)
    jets = problem.jets
    try:
        with np.errstate(all="ignore"):
            acc = solve_accelerations(lagrangian_rows(own_c, jets, points.env))
        if not np.all(np.isfinite(acc)):
            return False  # the own L has no motion here (a singular mass matrix)

        def residual(backend):
            env = points.arrays(backend)
            a = (
                acc
                if backend is FLOAT
                else solve_accelerations(lagrangian_rows(own_c, jets, env, backend), backend)
            )
            total, size, _grad = time_derivative_on_shell(Q, jets, env, a, backend)
            return to_length(total, points.n, backend), to_length(size, points.n, backend)

        return decide(residual).equal
    except (UnsupportedExpression, ValueError, ZeroDivisionError, np.linalg.LinAlgError):
        return False


def _gradient_rank(grads: Sequence[np.ndarray]) -> int:
    """Functional independence: the rank of the gradients, at a typical point."""
    if not grads:
        return 0
    coef = np.stack([np.asarray(g, float) for g in grads], axis=1)
    if not np.all(np.isfinite(coef)):
        coef = np.nan_to_num(coef)
    return row_rank(coef, list(range(len(grads))))


# --- expression -----------------------------------------------------------------------------------


def _domains_for(problem: Problem) -> dict:
    """Domains of every variable: parameters as declared, coordinates in their sample ranges."""
    domains = dict(problem.domains)
    for j in problem.jets:
        lo, hi = (problem.coordinate_domains or {}).get(j.name) or coordinate_range(j.name)
        domains[j.q] = Domain(j.name, sp.Float(lo), sp.Float(hi))
    return domains


def check_expression(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    got = _read_single(problem, answer, "expression", "x")
    ref = problem.reference_expression
    # The default decision (docs/methods.csv): exact where possible, bounded floats otherwise;
    # the numeric hybrid decides only what that method cannot reach, and finds witnesses.
    decided = ExactThenAdaptive().decide(got.expr, ref.expr, _domains_for(problem))
    if decided:
        return Verdict("expression", "correct", 1.0, (), got.echo, "exact_then_adaptive")
    ans = Compiled.of(got.expr)
    points = problem.points("expression", _free(problem, got.expr))
    out = expressions_equal(ans, ref, points)
    if decided is not None:
        out = Outcome(False, "exact_then_adaptive", out.worst, out.where)
    if out.equal:
        return Verdict("expression", "correct", 1.0, (), got.echo, _method(out))
    mutant = problem.catalogue.match_plain(problem.catalogue.expression_mutants, ans, points)
    return _incorrect(
        "expression",
        got,
        mutant,
        "Your answer is not equal to the expected expression",
        _witness(points, out, ans, ref),
        out.method if decided is not None else _method(out),
    )


# --- the table ------------------------------------------------------------------------------------

Checker = Callable[[Problem, Any, Mapping | None], Verdict]

CHECKERS: dict[str, Checker] = {
    "dof": check_dof,
    "transformation": check_transformation,
    "lagrangian": check_lagrangian,
    "T": check_kinetic,
    "V": check_potential,
    "eom": check_eom,
    "momenta": check_momenta,
    "cyclic": check_cyclic,
    "conserved": check_conserved,
    "expression": check_expression,
}

#: Parts that need a Lagrangian (a bank scene or an ad-hoc L), not only an expression.
NEEDS_LAGRANGIAN = frozenset(CHECKERS) - {"expression"}


def run_checker(problem: Problem, part: str, answer: Any, given: Mapping | None = None) -> Verdict:
    """Judge `answer` to `part` of `problem`. A student's mistake never raises: text that does
    not parse, or that names something the evaluator cannot compute, is `invalid` with a message.
    A malformed request (unknown part, wrong answer shape) raises RequestError."""
    checker = CHECKERS.get(part)
    if checker is None:
        raise RequestError(f"unknown part {part!r}; parts: {', '.join(CHECKERS)}")
    if part in NEEDS_LAGRANGIAN and problem.lagrangian is None:
        raise RequestError(
            f"part {part!r} needs a scene or a Lagrangian, and this problem gives "
            "only an expression"
        )
    if part == "expression" and problem.expression is None:
        raise RequestError(
            'part "expression" needs a reference expression (an "expression" '
            'problem, or a scene with "quantity")'
        )
    try:
        return checker(problem, answer, given)
    except ParseError as error:
        return invalid(part, str(error), getattr(error, "source", ""))
    except UnsupportedExpression as error:
        return invalid(part, f"Cannot evaluate your answer: {error}.")


__all__ = ["CHECKERS", "Verdict", "run_checker"]
