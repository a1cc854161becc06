"""A variant of an exported question rendered for PrairieLearn's `generate`: its statement,
prompts and key as a student types them. At export, or in a `generate` that was not rendered
then; the only PrairieLearn work that needs the templates (`lagrade.assign`'s views, jinja2)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.assign import EXPRESSION, VariantChoice, environment, key_answers, problem_view
from lagrade.grading.prairielearn_work import problem_of
from lagrade.grading.prompts import prompt_html


def render_variant(
    assignment: str, index: int, seed: int, scenes: Mapping[str, str] | None = None
) -> dict[str, Any]:
    """What `generate` puts in `data` for the variant `seed`: its statement and prompts
    (`params`) and the key's answers as a student types them (`correct_answers`)."""
    problem, _rubric = problem_of(assignment, index, scenes)
    variant = problem.scene.variant(seed)
    choice = VariantChoice(seed, dict(variant.names), dict(variant.options), dict(variant.values))
    view = problem_view(problem, choice, f"p{index}")
    template = environment().get_template("prairielearn_problem.html.j2")
    params = {
        "seed": seed,
        "statement_html": template.render(p=view),
        "prompts": {part["key"]: prompt_html(part) for part in view["parts"]},
    }
    answers = key_answers(problem, choice)
    correct = {}
    for part in problem.parts:
        key = answers[part.quantity if part.part == EXPRESSION else part.part]
        correct[part.key] = "\n".join(key) if isinstance(key, list) else str(key)
    figure = view["figure"]["inline_svg"] if view["figure"] is not None else None
    return {"params": params, "correct_answers": correct, "figure": figure}
