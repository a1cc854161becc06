"""PrairieLearn questions from an assignment: `lagrade export prairielearn`.

One question folder per problem, in PrairieLearn's v3 format: `info.json` (uuid, title, topic,
tags, type "v3"), `question.html` (the statement and figure rendered per variant, one
`pl-string-input` per part) and `server.py`. The `server.py` holds the assignment text, the
texts of the scene files it names (by the `scene` as written) and the problem's pool of variant
seeds, as data, and calls back into lagrade, which must be installed in the course's Python
environment:
- `generate` draws the variant from the pool by PrairieLearn's `variant_seed`, so every variant
  is one the bank reproduces and the assignment allows, and renders its statement;
- `parse` reads every answer with the grader and turns an unreadable one into a format error
  with the parser's message (PrairieLearn then charges no attempt), and shows how each readable
  answer was read;
- `grade` judges each part with the same checker `lagrade grade` uses (rubric, follow-through
  from the student's own L) and writes a score and feedback per part.

`parse` and `grade` judge in a worker process under `lagrade grade`'s rule (the part's alarm,
the kill at its limit + grace, the memory limit): PrairieLearn's own process never runs a check.
"""

from __future__ import annotations

import json
import re
import tomllib
import uuid
from collections.abc import Mapping, MutableMapping
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
import lagrade.grading.resume as resume
import lagrade.untrusted as untrusted
from lagrade.assign.assignment import (
    Assignment,
    Problem,
    load_assignment,
    parse_assignment,
    scene_resolver,
)
from lagrade.assign.templating import environment
from lagrade.assign.variants import VariantChoice, build_pool
from lagrade.assign.views import MULTILINE, problem_view
from lagrade.bank.registry import scene_reference
from lagrade.errors import AssignmentError
from lagrade.grading.batch import grade_part, sheet_given, stopped_part
from lagrade.grading.prompts import escape_html, prompt_html
from lagrade.grading.rubric import Rubric, rubric_from_table
from lagrade.judge.worker import PREPARE_LIMIT, Limits, Pool

#: Variants in a problem's pool when the assignment does not say (`variants = N`).
DEFAULT_POOL = 50
#: Seconds per part when PrairieLearn grades (its own worker limits the whole call too); a part
#: whose check holds its worker in C code is killed `GRACE` seconds later.
PART_TIME_LIMIT = 5.0
_NAMESPACE = uuid.UUID("6f1c2a4e-3d0b-5b7e-9a61-1a2b3c4d5e6f")


def export_prairielearn(
    assignment_file: Path,
    seed: int,
    out: Path,
    scenes_dir: Path | None = None,
    scene_texts: Mapping[str, str] | None = None,
) -> list[Path]:
    """Write one question folder per problem of the assignment into `out`; returns them. Its
    scene files are found as `generate` finds them, or given by `scene_texts` (a manifest's)."""
    assignment_file = Path(assignment_file)
    assignment = load_assignment(assignment_file, scenes_dir, scene_texts)
    text = untrusted.decode(assignment_file.read_bytes(), str(assignment_file))
    scenes = {p.scene_ref: p.scene.source for p in assignment.problems}
    folders = []
    for problem in assignment.problems:
        pool = build_pool(problem, seed, problem.variants or DEFAULT_POOL)
        if not pool:
            raise AssignmentError(f"problem {problem.index}: the bank offers no variant")
        folder = Path(out) / _folder_name(assignment, problem)
        atomic.write_json(folder / "info.json", _info(assignment, problem))
        atomic.write_text(folder / "question.html", _question_html(problem))
        atomic.write_text(folder / "server.py", _server_py(text, scenes, problem, pool))
        folders.append(folder)
    return folders


def _folder_name(assignment: Assignment, problem: Problem) -> str:
    slug = re.sub(r"[^a-z0-9]+", "-", assignment.title.lower()).strip("-")[:40] or "lagrade"
    return f"{slug}-p{problem.index}-{problem.scene.id}"


def _info(assignment: Assignment, problem: Problem) -> dict[str, Any]:
    """info.json: the uuid is derived from the assignment's title and the problem, so that a
    re-export updates the same PrairieLearn question instead of making a new one."""
    name = f"{assignment.title}\x1f{problem.index}\x1f{problem.scene.id}"
    return {
        "uuid": str(uuid.uuid5(_NAMESPACE, name)),
        "type": "v3",
        "title": f"{problem.title or problem.scene.title}",
        "topic": "Lagrangian mechanics",
        "tags": ["lagrade", problem.scene.id],
    }


def _question_html(problem: Problem) -> str:
    """PrairieLearn's mustache, not jinja: the statement comes rendered from `generate`."""
    fields = []
    for part in problem.parts:
        several = part.part in MULTILINE
        fields.append(
            f"<p>{{{{{{params.prompts.{part.key}}}}}}}</p>\n"
            f'<pl-string-input answers-name="{part.key}" label="{part.key}:" '
            f'size="70" display="block" allow-blank="true" show-help-text="false" '
            f'placeholder="{"several equations: separate them with ;" if several else ""}">'
            "</pl-string-input>"
        )
    body = "\n".join(fields)
    return (
        "<pl-question-panel>\n{{{params.statement_html}}}\n</pl-question-panel>\n\n"
        f"{body}\n\n"
        "<pl-submission-panel>\n{{#feedback.read}}<p>Read as: {{feedback.read}}</p>"
        "{{/feedback.read}}\n</pl-submission-panel>\n\n"
        "<pl-answer-panel>\n{{{params.key_html}}}\n</pl-answer-panel>\n"
    )


#: server.py: fixed code, with every value in it written as a Python literal by `repr` (the
#: title too, as data: an instructor's `"""` or `\N{` in a docstring would be code or a
#: SyntaxError on PrairieLearn's server). No text of the assignment is spliced in otherwise.
_SERVER = '''"""PrairieLearn server for one lagrade problem (its title is TITLE below), written by
`lagrade export prairielearn`. Needs lagrade in the course's Python environment."""

from lagrade.grading import prairielearn as lagrade_pl

TITLE = {title}
ASSIGNMENT = {assignment}
SCENES = {scenes}
PROBLEM = {index}
SEEDS = {seeds}


def generate(data):
    lagrade_pl.generate(data, ASSIGNMENT, PROBLEM, SEEDS, SCENES)


def parse(data):
    lagrade_pl.parse(data, ASSIGNMENT, PROBLEM, SCENES)


def grade(data):
    lagrade_pl.grade(data, ASSIGNMENT, PROBLEM, SCENES)
'''


def _server_py(
    assignment_text: str,
    scenes: Mapping[str, str],
    problem: Problem,
    pool: tuple[VariantChoice, ...],
) -> str:
    """server.py for `problem`: each value a Python literal (`repr` of a str, int, a dict of
    str or a list of ints), checked to compile before it is written, so an export never ships a
    file that PrairieLearn cannot load."""
    values = {
        "title": str(problem.title or problem.scene.title),
        "assignment": str(assignment_text),
        "scenes": {str(ref): str(text) for ref, text in scenes.items()},
        "index": int(problem.index),
        "seeds": [int(c.seed) for c in pool],
    }
    source = _SERVER.format(**{name: repr(value) for name, value in values.items()})
    compile(source, "server.py", "exec")  # a SyntaxError here is our bug, never shipped
    return source


# --- the runtime: what server.py calls inside PrairieLearn --------------------------------------


def generate(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    seeds: list,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """Draw the variant from the pool by PrairieLearn's seed; render its statement and key."""
    problem, _rubric = _problem(assignment, index, scenes)
    seed = seeds[int(data.get("variant_seed", 0)) % len(seeds)]
    variant = problem.scene.variant(seed)
    choice = VariantChoice(seed, dict(variant.names), dict(variant.options), dict(variant.values))
    view = problem_view(problem, choice, f"p{index}")
    env = environment()
    params = data.setdefault("params", {})
    params["seed"] = seed
    params["statement_html"] = env.get_template("prairielearn_problem.html.j2").render(p=view)
    params["prompts"] = {part["key"]: prompt_html(part) for part in view["parts"]}
    params["key_html"] = "<pre>" + escape_html(view["solution"]["sheet"]) + "</pre>"
    correct = data.setdefault("correct_answers", {})
    for part in problem.parts:  # what pl-string-input shows as the answer; grading is ours
        correct[part.key] = ""


def parse(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """Refuse an unreadable answer with the parser's message (no attempt charged); say how each
    readable answer was read."""
    read = []
    for key, result in _judge_all(data, assignment, index, scenes).items():
        if result["verdict"] == "invalid":
            data.setdefault("format_errors", {})[key] = " ".join(result["feedback"])
        elif result["interpreted"]:
            shown = result["interpreted"]
            read.append(f"{key}: {'; '.join(shown) if isinstance(shown, list) else shown}")
    if read:
        data.setdefault("feedback", {})["read"] = " | ".join(read)


def grade(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """A score and feedback per part, and the question's score weighted by points."""
    results = _judge_all(data, assignment, index, scenes)
    scores = data.setdefault("partial_scores", {})
    total = sum(r["max_points"] for r in results.values()) or 1.0
    for key, r in results.items():
        scores[key] = {
            "score": r["points"] / r["max_points"] if r["max_points"] else 0.0,
            "weight": r["max_points"],
            "feedback": " ".join(r["feedback"]) or r["verdict"],
        }
    data["score"] = sum(r["points"] for r in results.values()) / total


def _judge_all(
    data: Mapping[str, Any], assignment: str, index: int, scenes: Mapping[str, str] | None
) -> dict[str, dict]:
    """Every part's result, judged in a worker process (`_backstop`): PrairieLearn's own
    process never runs the checks, so C code that no alarm stops cannot hold it."""
    task = {
        "assignment": assignment,
        "index": index,
        "scenes": dict(scenes or {}),
        "seed": data["params"]["seed"],
        "submitted": dict(data.get("submitted_answers", {}) or {}),
        "part_time_limit": PART_TIME_LIMIT,
    }
    return _backstop(task)


def _judge_task(task: Mapping[str, Any]) -> dict[str, dict]:
    """The body of `_judge_all`, in the worker: each part noted as it is judged, so that a kill
    costs only the part it stopped (`lagrade.grading.resume`)."""
    problem, rubric = _problem(task["assignment"], task["index"], task["scenes"])
    submitted = task["submitted"]
    limit = task["part_time_limit"]
    entry = {**scene_reference(problem.scene), "seed": task["seed"]}
    answers = {part.key: _answer(submitted.get(part.key)) for part in problem.parts}
    given = sheet_given([(p.key, p.part) for p in problem.parts], answers)
    results = {}
    for part in problem.parts:
        spec = {
            "key": part.key,
            "part": part.part,
            "points": part.points,
            "quantity": part.quantity,
        }
        result = resume.earlier(task, part.key)
        if result is None and resume.stopped(task, part.key):
            result = stopped_part(spec, rubric, limit)
        if result is None:
            resume.begin(part.key)
            result = grade_part(entry, spec, answers[part.key], given, rubric, limit)
            resume.judged(part.key, result)
        results[part.key] = result
    return results


def _backstop(task: dict[str, Any]) -> dict[str, dict]:
    """Run `_judge_task` in a killable worker (the rule of `lagrade grade`: the part's alarm,
    the kill at its limit + grace, the memory limit); a kill in one part costs that part, and a
    fresh worker judges the rest. The workers end with the call: PrairieLearn runs each request
    in a process of its own and discards it, and a worker left behind would hold its pipes."""
    with Pool(_judge_task, jobs=1, limits=Limits(seconds=PREPARE_LIMIT)) as pool:
        while True:
            (outcome,) = pool.run([(0, task)])
            if outcome.status == "ok":
                return outcome.value
            if outcome.status == "refused":
                raise outcome.value
            again = resume.resumed(task, outcome)
            if again is None:
                raise RuntimeError(f"lagrade could not grade this submission: {outcome.reason}")
            task = again


def _answer(raw: Any) -> str:
    """The text of a pl-string-input as typed: the part's checker splits it (several equations
    separated by `;`, a list of names by commas), as it splits a sheet's answer."""
    return "" if raw is None else str(raw)


_problems: dict[tuple[str, int, str], tuple[Problem, Rubric]] = {}


def _problem(
    assignment: str, index: int, scenes: Mapping[str, str] | None = None
) -> tuple[Problem, Rubric]:
    """The assignment's problem and rubric, parsed once per process; its scenes from the texts
    server.py carries (a question exported before scene files names bank scenes only)."""
    key = (assignment, index, json.dumps(dict(scenes or {}), sort_keys=True))
    found = _problems.get(key)
    if found is None:
        table = tomllib.loads(assignment)
        parsed = parse_assignment(table, resolve=scene_resolver(texts=dict(scenes or {})))
        found = (parsed.problems[index - 1], rubric_from_table(table.get("rubric")))
        _problems[key] = found
    return found


def info_json(folder: Path) -> dict[str, Any]:
    """A question folder's info.json (for tests and for `lagrade export` to report)."""
    return json.loads((Path(folder) / "info.json").read_text(encoding="utf-8"))
