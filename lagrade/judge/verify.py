"""Check a variant before its handout is written: the grader must accept the key's answers and
reject the common mistakes of the catalogue. `lagrade.assign.generation.generate` calls this
through its `verify` hook: assign, in the same layer as judge, never imports it; the command
line passes this function in."""

from __future__ import annotations

from collections.abc import Iterable

from lagrade.bank import scene_reference
from lagrade.judge.key import key_answer
from lagrade.judge.parts import run_checker
from lagrade.judge.problem import Problem, build_problem
from lagrade.mechanics import SceneVariant
from lagrade.notation import plain


def _spec(variant: SceneVariant, quantity: str | None = None) -> dict:
    spec: dict = scene_reference(variant.scene)
    if variant.seed is not None:
        spec["seed"] = variant.seed
    if quantity:
        spec["quantity"] = quantity
    return spec


def verify_variant(variant: SceneVariant, parts: Iterable) -> list[str]:
    """Problems found with this variant's key (empty when the grader agrees with it). `parts`
    are the assignment's Part objects (`.part`, `.quantity`)."""
    problems: list[str] = []
    where = f"{variant.scene.id} (seed {variant.seed})"
    built: dict[str | None, Problem] = {}
    for part in parts:
        name, quantity = part.part, getattr(part, "quantity", None)
        which = quantity if name == "expression" else None
        if which not in built:
            built[which] = build_problem(_spec(variant, which))
        problem = built[which]
        verdict = run_checker(problem, name, key_answer(variant, name, quantity))
        if verdict.status != "correct" or verdict.score < 1:
            problems.append(
                f"{where}: the grader does not accept the key's {part.key}: "
                + " ".join(verdict.feedback)
            )
        if name == "lagrangian":
            for mutant in problem.catalogue.lagrangian_mutants:
                wrong = run_checker(problem, "lagrangian", plain(mutant.expr))
                if wrong.status == "correct" and wrong.score >= 1:
                    problems.append(
                        f"{where}: the grader accepts a known mistake ({mutant.kind}) as correct"
                    )
    return problems
