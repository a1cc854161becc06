"""The `momenta` part: p_j = ∂L/∂q̇_j, each, or what follows from the student's own L."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from lagrade.errors import ParseError
from lagrade.judge.compiled import Compiled
from lagrade.judge.derivatives import gradient
from lagrade.judge.dimensions import hint_for, tells
from lagrade.judge.equivalence import expressions_equal, lagrangians_match, values_equal
from lagrade.judge.evaluate import UnsupportedExpression
from lagrade.judge.matching import full, vanish_rows
from lagrade.judge.mutations import expanded_terms
from lagrade.judge.parts.common import (
    as_sentence,
    method_name,
    reference_el,
    where_text,
    witness_point,
)
from lagrade.judge.parts.items import list_items
from lagrade.judge.parts.reading import (
    Lines,
    Read,
    Unreadable,
    line_label,
    own_lagrangian,
    read,
    read_lines,
)
from lagrade.judge.problem import Problem
from lagrade.judge.tolerances import SAME_VALUE
from lagrade.judge.verdict import Verdict, invalid
from lagrade.notation import plain


def read_momenta(problem: Problem, answer: Any) -> Lines:
    """The momenta of a `momenta` answer, one per item, each `p_q = …` or bare (in the order
    of the coordinates)."""
    jets = problem.jets
    labels = [f"p_{j.name}" for j in jets]

    def read_line(item: Any) -> Read:
        # a label of the student's own (`L_z = …`, `ℓ = …`) names the momentum the line gives:
        # read like p_θ, the line is then placed by its order
        own = line_label(problem, item) if isinstance(item, str) else None
        own = own if own not in problem.by_name and own not in labels else None
        got = read(problem, item, [*labels, *([own] if own else [])])
        if own is not None and got.has_rhs and got.label == own:
            return got.only_rhs()
        if got.has_rhs and got.label not in labels:
            text = item if isinstance(item, str) else str(item)
            raise ParseError(
                f"Write each momentum as {labels[0]} = … or give them in the order "
                f"{', '.join(j.name for j in jets)}.",
                (0, len(text)),
                text,
            )
        return got

    return read_lines(list_items(answer, "momenta"), read_line)


def check_momenta(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    jets = problem.jets
    labels = [f"p_{j.name}" for j in jets]
    lines = read_momenta(problem, answer)
    echoes = lines.echoes
    # An unreadable line keeps its place: the coordinate its label names, or the next free slot.
    by_coordinate: dict[int, Read | Unreadable] = {}
    unlabelled: list[Read | Unreadable] = []
    for got in lines.entries:
        if isinstance(got, Unreadable):
            name = line_label(problem, got.text)
            if name in labels and labels.index(name) not in by_coordinate:
                by_coordinate[labels.index(name)] = got
            else:
                unlabelled.append(got)
        elif got.has_rhs:
            k = labels.index(got.label)
            if k in by_coordinate:
                if isinstance(by_coordinate[k], Unreadable):
                    unlabelled.append(by_coordinate[k])
                else:
                    return invalid("momenta", f"{labels[k]} is given twice.", echoes)
            by_coordinate[k] = got.only_rhs()
        else:
            unlabelled.append(got)
    free_slots = [k for k in range(len(jets)) if k not in by_coordinate]
    if len(unlabelled) > len(free_slots):
        return invalid(
            "momenta", f"{len(lines.entries)} momenta given for {len(jets)} coordinates.", echoes
        )
    for k, got in zip(free_slots, unlabelled, strict=False):
        by_coordinate[k] = got
    own = own_lagrangian(problem, given)
    right, feedback, mistakes, outcomes = 0, lines.feedback(), [], []
    witness, follows_all, any_wrong = None, True, False
    for k, j in enumerate(jets):
        if k not in by_coordinate:
            feedback.append(f"p_{j.name} is missing.")
            any_wrong, follows_all = True, False
            continue
        if isinstance(by_coordinate[k], Unreadable):  # counts as wrong; its line is named above
            any_wrong, follows_all = True, False
            continue
        points = problem.points("momenta")
        reference = problem.momenta[k]
        ans = by_coordinate[k].compiled
        out = expressions_equal(ans, reference, points)
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
        # one state in the witness, the first wrong momentum's: a later sentence quotes its
        # own only when it is that one (every number quoted is in the witness)
        point = witness_point(points, out, ans, reference)
        witness = witness or point
        others = {i: got.compiled for i, got in by_coordinate.items() if isinstance(got, Read)}
        others.pop(k, None)
        mutant = problem.catalogue.match_momentum(k, ans, points, others)
        if mutant is not None:
            said = as_sentence(mutant.message)
            if said not in feedback:  # a mistake of L shows in every momentum: said once
                feedback.append(said)
                mistakes.append(mutant.kind)
        else:
            where = where_text(point, problem) if point == witness else ""
            derivative = f"∂L/∂{j.name}_dot"
            factor = _factor_finding(problem, k, ans, points)
            if factor is None:
                said = f"is not {derivative}"
            else:
                kind, said = factor[0], factor[1].format(derivative=derivative)
                mistakes.append(kind)  # a named mistake, as the catalogue's kinds name it
            feedback.append(f"p_{j.name} {said}{where}.")
        dimensions = hint_for(problem, by_coordinate[k], f"momentum:{k}") if tells(mutant) else ""
        if dimensions:
            feedback.append(f"p_{j.name}: {dimensions[0].lower()}{dimensions[1:]}")
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
        method_name(*outcomes),
        witness=witness if status != "correct" else None,
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _own_momentum_matches(problem: Problem, own_c: Compiled, ans: Compiled, k: int, points) -> bool:
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


def _own_is_same_gauge(problem: Problem, own: Compiled) -> bool:
    """The student's L is T − V plus a constant or a total derivative (factor exactly 1), so its
    momenta are right for it."""
    points = problem.points("lagrangian")
    match = lagrangians_match(own, reference_el(problem, points), problem.jets, points)
    c = match.factor
    return match.outcome.equal and c is not None and abs(c - 1) <= SAME_VALUE


def _factors(momentum: sp.Expr) -> list[sp.Expr]:
    """The factors of the momentum's terms that are not numbers, and the base of each power
    among them (r from r²), in the order they are printed: the candidates of `_factor_finding`."""
    out: dict[sp.Expr, None] = {}
    for term in expanded_terms(momentum):
        for f in sp.Mul.make_args(term):
            if f.is_number:
                continue
            out[f] = None
            if isinstance(f, sp.Pow) and f.exp.is_Integer and f.exp > 1:
                out[f.base] = None
    return list(out)


#: A momentum that is a number times ∂L/∂q̇: the number, the mistake's kind, how it is said.
_NUMBERS = (
    (2.0, "factor_two", "is twice {derivative}"),
    (0.5, "factor_half", "is half {derivative}"),
    (-1.0, "wrong_sign", "is minus {derivative}"),
)


def _factor_finding(problem: Problem, k: int, ans: Compiled, points) -> tuple[str, str] | None:
    """(mistake kind, sentence with a `{derivative}` slot): "is twice ∂L/∂q̇" when the answer
    is a number times the reference, "is ∂L/∂q̇ without its factor r^2" when the answer times
    one factor of the reference's terms is the reference at every sample point, "… with an
    extra factor r" when the answer is the reference times one; None otherwise. Checked by the
    correction it implies (the answer corrected so equals ∂L/∂q̇ at the points), never by how
    the answer is printed."""
    env, n = points.env, len(points.group)
    try:
        with np.errstate(all="ignore"):
            a, sa = full(ans.values(env), n)
            r, sr = full(problem.momenta[k].values(env), n)
            for number, kind, said in _NUMBERS:  # the whole momentum scaled: every term as one
                if vanish_rows((a - number * r)[None], (sa + number * sr)[None])[0]:
                    return kind, said
            for f in _factors(problem.system.generalized_momenta[k]):
                fv, _ = full(Compiled.of(f).values(env), n)
                shown = plain(f).replace("{", "{{").replace("}", "}}")
                if vanish_rows((a * fv - r)[None], (sa * np.abs(fv) + sr)[None])[0]:
                    return "missing_factor", f"is {{derivative}} without its factor {shown}"
                if vanish_rows((a - r * fv)[None], (sa + sr * np.abs(fv))[None])[0]:
                    return "extra_factor", f"is {{derivative}} with an extra factor {shown}"
    except (UnsupportedExpression, ValueError, ZeroDivisionError, OverflowError):
        return None
    return None
