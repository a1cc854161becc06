"""What is wrong in a line of a wrong transformation answer, said only when it is true.

Each of the student's lines that differs from the statement's is compared, by its values at
the sample points, with the statement's line R carrying one slip: −R (the line's sign), R with
sin and cos swapped, R without one of its terms (the support's motion, the upper bob's
position), one term negated, one term with sin and cos swapped, one term twice or half, one
term with another length in place of its own. A line is named by the first slip whose values
it has. The sentences are said only when the correction they imply — every named line put
back as R — makes the whole map valid (the constraints hold identically, full rank: what the
checker accepts), so a sentence is never said about a line whose fault is elsewhere or of
another kind. Only the statement's side is built in sympy; the student's line is compared by
its compiled values.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.errors import LagradeError
from lagrade.judge.compiled import Compiled, to_length
from lagrade.judge.mutations import expanded_terms, swap_sin_cos
from lagrade.judge.problem import Problem
from lagrade.judge.sampling import Points
from lagrade.judge.tolerances import SAME_VALUE
from lagrade.mechanics import t as time
from lagrade.notation import plain

#: The number words of a term's factor.
_TIMES = {sp.Integer(2): "twice", sp.Rational(1, 2): "half"}


@dataclass(frozen=True)
class Slip:
    """A line's slip: its sentence and the mistake's tag."""

    sentence: str
    kind: str


def _length_parameters(problem: Problem) -> list[sp.Symbol]:
    """The parameters measured in metres (a wrong length is one of them for another)."""
    v = problem.variant
    units = {p.name: p.unit for p in v.scene.parameters}
    return [s for name, s in v.parameter_symbols.items() if units.get(name) == "m"]


def _support(problem: Problem, name: str, term: sp.Expr) -> str:
    """What a missing term is, when the statement says: another body's position on the same
    axis (the cart's, the upper bob's), or a motion in time alone (a driven support)."""
    axis = name.partition("_")[0]
    v = problem.variant
    for other, expr in v.transformation.items():
        if other != name and other.startswith(f"{axis}_") and sp.expand(expr - term) == 0:
            return f", the position {other} of body {other.partition('_')[2]}"
    moving = term.free_symbols & {j.q for j in problem.jets}
    return ", the support's motion" if term.has(time) and not moving else ""


def _candidates(
    problem: Problem, name: str, R: sp.Expr
) -> Iterator[tuple[sp.Expr, Callable[[], Slip]]]:
    """The statement's line R with one slip each, and the sentence that names it (in the
    student's terms: the term as the slip made it)."""
    yield -R, lambda: Slip(f"{name} has the wrong sign", "line_sign")
    swapped = swap_sin_cos(R)
    if sp.expand(swapped - R) != 0:
        yield swapped, lambda: Slip(f"Sin and cos are swapped in {name}", "line_swap")
    terms = expanded_terms(R)
    lengths = _length_parameters(problem)
    for t in terms:
        if len(terms) > 1:
            yield (
                R - t,
                lambda t=t: Slip(
                    f"{name} lacks the term {plain(t)}{_support(problem, name, t)}", "missing_term"
                ),
            )
        if len(terms) > 1:
            yield (
                R - 2 * t,
                lambda t=t: Slip(f"The term {plain(-t)} in {name} has the wrong sign", "term_sign"),
            )
        s = swap_sin_cos(t)
        if len(terms) > 1 and sp.expand(s - t) != 0:
            yield (
                R - t + s,
                lambda s=s: Slip(
                    f"Sin and cos are swapped in the term {plain(s)} of {name}", "term_swap"
                ),
            )
        for c, word in _TIMES.items():
            yield (
                R + (c - 1) * t,
                lambda c=c, t=t, word=word: Slip(
                    f"The term {plain(c * t)} in {name} is {word} what it should be", "term_factor"
                ),
            )
        for p in lengths:
            for other in lengths:
                if other != p and t.has(p):
                    wrong = t.xreplace({p: other})
                    yield (
                        R - t + wrong,
                        lambda p=p, other=other, wrong=wrong: Slip(
                            f"The term {plain(wrong)} in {name} has the length {plain(other)} "
                            f"where {plain(p)} belongs",
                            "wrong_length",
                        ),
                    )


def _values(expr: sp.Expr | Compiled, points: Points) -> np.ndarray | None:
    try:
        c = expr if isinstance(expr, Compiled) else Compiled.of(expr)
        with np.errstate(all="ignore"):
            return np.asarray(to_length(c.values(points.env)[0], points.n), dtype=complex)
    except (LagradeError, ArithmeticError, ValueError, TypeError):
        return None


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    scale = np.maximum(np.abs(a), np.abs(b))
    return bool(np.all(np.isfinite(a)) and np.all(np.abs(a - b) <= SAME_VALUE * (1 + scale)))


def transformation_slips(
    problem: Problem,
    positions: Mapping[str, sp.Expr],
    points: Points,
    valid: Callable[[Mapping[str, sp.Expr]], bool],
) -> list[Slip]:
    """The slips of a wrong answer's lines against the statement's, when putting every named
    line back makes the map valid (`valid`: the checker's own test); else none."""
    statement = problem.variant.transformation
    slips: list[Slip] = []
    corrected = dict(positions)
    for name, R in statement.items():
        if name not in positions:
            return []
        got = _values(positions[name], points)
        right = _values(R, points)
        if got is None or right is None:
            return []
        if _same(got, right):
            continue
        for wrong, say in _candidates(problem, name, sp.expand(R)):
            values = _values(wrong, points)
            if values is not None and _same(got, values):
                slips.append(say())
                corrected[name] = R
                break
    if not slips or not valid(corrected):
        return []
    return slips


__all__ = ["Slip", "transformation_slips"]
