"""The work behind PrairieLearn's `parse` and `grade` (`lagrade.grading.prairielearn_runtime`), in
the killable worker: the assignment's problem read from its text, a submission read or judged
part by part. Kept apart from the entry points, so that a `generate` answered from the variants
rendered at export imports none of it (nor sympy), and apart from the rendering of a variant
(`prairielearn_variant`), so that a `parse` or a `grade` imports no templates (jinja2, the
handout's views and figures), which only `generate` uses."""

from __future__ import annotations

import json
import tomllib
from collections.abc import Mapping
from typing import Any

import lagrade.grading.resume as resume
from lagrade.assign import AssignedProblem, parse_assignment, scene_resolver
from lagrade.bank import scene_reference
from lagrade.grading.rubric import Rubric, rubric_from_table
from lagrade.grading.student import grade_part, part_spec, question, sheet_given, stopped_part
from lagrade.judge import GRACE, PartTimeout, deadline, read_answer, time_limit


def coordinates_of(assignment: str, index: int, seed: int, scenes) -> list[str]:
    """The coordinates of the variant `seed`, as its statement names them."""
    problem, _rubric = problem_of(assignment, index, scenes)
    return list(problem.scene.variant(seed).coordinates)


def parts_of(assignment: str, index: int, scenes) -> list[tuple[str, str, float]]:
    """(key, part, points) of each part the problem asks."""
    problem, _rubric = problem_of(assignment, index, scenes)
    return [(part.key, part.part, float(part.points)) for part in problem.parts]


def judge_task(task: Mapping[str, Any]) -> dict[str, dict]:
    """The body of `_judge_all`, in the worker: each part noted as it is judged, so that a kill
    costs only the part it stopped (`lagrade.grading.resume`). A reading task goes to
    `_read_task`."""
    if task.get("kind") == "read":
        return read_task(task)
    problem, rubric = problem_of(task["assignment"], task["index"], task["scenes"])
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
            "all": part.all,
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


#: What a part whose reading ran out of time shows (its worker stopped at the limit + grace).
READING_TOO_LONG = "Reading this answer took too long."


def read_task(task: Mapping[str, Any]) -> dict[str, dict]:
    """How each part's answer is read, in the worker, under the part's time limit: what was
    read (the lines' echoes) and the parser's message for each line that cannot be. Noted part
    by part like a grading task, so that a reading stopped by a kill costs that part only."""
    problem, _rubric = problem_of(task["assignment"], task["index"], task["scenes"])
    entry = {**scene_reference(problem.scene), "seed": task["seed"]}
    found = {}
    for part in problem.parts:
        result = resume.earlier(task, part.key)
        if result is None and resume.stopped(task, part.key):
            result = {"read": "", "unreadable": [READING_TOO_LONG]}
        if result is None:
            resume.begin(part.key)
            result = _read_part(task, entry, part)
            resume.judged(part.key, result)
        found[part.key] = result
    return found


def _read_part(task: Mapping[str, Any], entry: Mapping[str, Any], part: Any) -> dict[str, Any]:
    spec = {"key": part.key, "part": part.part, "quantity": part.quantity}
    answer = _answer(task["submitted"].get(part.key))
    deadline(task["part_time_limit"] + GRACE)  # the parent kills C code that ignores the alarm
    try:
        with time_limit(task["part_time_limit"]):
            reading = read_answer(question(part_spec(entry, spec)), part.part, answer)
    except PartTimeout:
        return {"read": "", "unreadable": [READING_TOO_LONG]}
    read = "; ".join(line.plain for line in reading.lines if line.plain)
    return {"read": read, "unreadable": reading.unreadable_lines}


_problems: dict[tuple[str, int, str], tuple[AssignedProblem, Rubric]] = {}


def problem_of(
    assignment: str, index: int, scenes: Mapping[str, str] | None = None
) -> tuple[AssignedProblem, Rubric]:
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


def _answer(raw: Any) -> str:
    """The text of a pl-string-input as typed: the part's checker splits it (several equations
    on lines or separated by `;`, a list of names by commas), as it splits a sheet's answer."""
    return "" if raw is None else str(raw)
