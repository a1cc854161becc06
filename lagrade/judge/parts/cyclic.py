"""The `cyclic` part: the set of coordinates q_j with ∂L/∂q_j ≡ 0, the facts of the question's
system (decided by values, `lagrade.mechanics.identically_zero`, as the key's are)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy as sp

from lagrade.errors import ParseError
from lagrade.judge.parts.items import list_items, without_none
from lagrade.judge.parts.reading import own_lagrangian, read_names
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict
from lagrade.mechanics import LagrangianSystem, identically_zero
from lagrade.notation import NameRead, plain


def read_cyclic(problem: Problem, answer: Any) -> list[NameRead]:
    """The coordinates a `cyclic` answer names, in any spelling, separated as any list; a name
    that is no coordinate (nor its velocity) cannot be read."""
    hint = f"Name the cyclic coordinates, e.g. {problem.coordinates[0]}; or write none."
    read = read_names(problem, without_none(list_items(answer, "cyclic")), hint)
    for name in read:
        if name.coordinate is None or name.order > 1:
            what = f"'{name.name}' is not a coordinate of this problem"
            raise ParseError(
                f"{what} (coordinates: {', '.join(problem.coordinates)}). {hint}",
                name.span,
                name.source,
            )
    return read


def check_cyclic(problem: Problem, answer: Any, given: Mapping | None) -> Verdict:
    """The coordinates named against ∂L/∂q = 0; a velocity named for its coordinate is half
    wrong, a name that is no coordinate unreadable."""
    names: list[str] = []
    echoes: list[str] = []
    velocity_named = []
    for name in read_cyclic(problem, answer):
        echoes.append(name.name)
        names.append(name.coordinate)
        if name.order == 1:
            velocity_named.append(name.coordinate)
    claimed = set(names)
    system = problem.system
    L = sp.expand(system.L)
    truth = set(system.cyclic_coordinates)
    feedback, mistakes = [], []
    for name in velocity_named:
        feedback.append(f"A cyclic coordinate is a coordinate ({name}), not its velocity.")
    right = 0
    for k, j in enumerate(problem.jets):
        if (j.name in claimed) == (j.name in truth):
            right += 1
            continue
        if j.name in claimed:
            if identically_zero(system.generalized_momenta[k], system.ranges):
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
                f"{j.name} is cyclic: L contains its velocity {j.name}_dot but does not "
                f"depend on {j.name} itself, so p_{j.name} is conserved."
            )
            mistakes.append("missed_cyclic")
    n = len(problem.jets)
    echo = echoes if echoes else ["none"]
    follows = False
    own = own_lagrangian(problem, given)
    if right < n and own is not None:
        own_system = LagrangianSystem(sp.expand(own.expr), problem.jets, system.ranges)
        own_cyclic = set(own_system.cyclic_coordinates)
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
        _informed_share(claimed, truth, {j.name for j in problem.jets})
        * (0.5 if velocity_named else 1.0),
        tuple(feedback),
        echo,
        "exact",
        follows_from_own_answer=follows,
        mistakes=tuple(mistakes),
    )


def _informed_share(claimed: set[str], truth: set[str], coordinates: set[str]) -> float:
    """The share of a wrong set: the cyclic coordinates found minus the others named, each as
    a fraction of its kind (TPR − FPR, never below 0). A set chosen without looking at L —
    none, every coordinate, any blind guess — earns 0 on average; counting each coordinate
    rightly left out (as a per-item score would) gave `none` half a two-coordinate part."""
    others = coordinates - truth
    found = len(claimed & truth) / len(truth) if truth else 0.0
    wrong = len(claimed & others) / len(others) if others else 0.0
    return max(0.0, found - wrong)
