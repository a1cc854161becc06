"""What a lagrade question's `server.py` calls inside PrairieLearn: generate, parse, grade, test.

PrairieLearn's contract, as its server.py documentation and its Python worker (zygote.py and
question_phases.py, which run the elements first and server.py after them) define it:
- `generate` fills `data["params"]` (what question.html's mustache shows: the statement, the
  prompts) and `data["correct_answers"]` (the key's answers as a student types them: what
  `pl-string-input` shows in the answer panel and what the question test submits);
- `parse` turns an answer the grader cannot read, in whole or in one line, into a format error
  (`data["format_errors"][key]`): the submission is then invalid, not graded, and costs no
  attempt. PrairieLearn shows a format error as HTML in a popover whose sanitizer is off, so each
  one is escaped here and the parser's message with its caret set in `<pre>`;
- `grade` writes `data["partial_scores"][key] = {"score", "weight"}` and `data["score"]`, judged
  by the checker `lagrade grade` uses (rubric, follow-through from the student's own L), and
  each part's verdict, reading and feedback as plain text in `data["feedback"]["lagrade"][key]`,
  which question.html shows in the submission panel through mustache's escaping `{{ }}`;
- `test` makes the question test's submissions (correct: the key; incorrect: a wrong answer to
  every part; invalid: an unreadable one) and the scores they must get, which PrairieLearn then
  compares with what parse and grade give. server.py must supply it: the element's own test
  expects its exact-string grading, which `grade` replaces.

`parse` and `grade` judge in a worker process under `lagrade grade`'s rule (the part's alarm,
the kill at its limit + grace, the memory limit): PrairieLearn's own process never runs a check.
"""

from __future__ import annotations

import html
import json
import tomllib
from collections.abc import Mapping, MutableMapping
from typing import Any

import lagrade.grading.resume as resume
from lagrade.assign.assignment import EXPRESSION, Problem, parse_assignment, scene_resolver
from lagrade.assign.templating import environment
from lagrade.assign.variants import VariantChoice
from lagrade.assign.views import key_answers, problem_view
from lagrade.bank.registry import scene_reference
from lagrade.grading.prompts import prompt_html
from lagrade.grading.rubric import Rubric, rubric_from_table
from lagrade.grading.student import grade_part, sheet_given, stopped_part
from lagrade.judge.parts.reading import is_unreadable_line
from lagrade.judge.worker import PREPARE_LIMIT, Limits, Pool

#: Seconds per part when PrairieLearn grades (its own worker limits the whole call too); a part
#: whose check holds its worker in C code is killed `GRACE` seconds later.
PART_TIME_LIMIT = 5.0
#: What the question test submits as an unreadable answer to every part.
UNREADABLE_ANSWER = "("


def generate(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    seeds: list,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """Draw the variant from the pool by PrairieLearn's seed; render its statement and prompts;
    the key's answers as a student types them go to `correct_answers`."""
    problem, _rubric = _problem(assignment, index, scenes)
    seed = seeds[int(data.get("variant_seed", 0)) % len(seeds)]
    variant = problem.scene.variant(seed)
    choice = VariantChoice(seed, dict(variant.names), dict(variant.options), dict(variant.values))
    view = problem_view(problem, choice, f"p{index}")
    params = data.setdefault("params", {})
    params["seed"] = seed
    template = environment().get_template("prairielearn_problem.html.j2")
    params["statement_html"] = template.render(p=view)
    params["prompts"] = {part["key"]: prompt_html(part) for part in view["parts"]}
    answers = key_answers(problem, choice)
    correct = data.setdefault("correct_answers", {})
    for part in problem.parts:
        key = answers[part.quantity if part.part == EXPRESSION else part.part]
        correct[part.key] = "\n".join(key) if isinstance(key, list) else str(key)


def parse(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """Refuse an answer with an unreadable line as a format error (no attempt charged); say how
    each answer was read."""
    results = _judge_all(data, assignment, index, scenes)
    errors = data.setdefault("format_errors", {})
    shown = {}
    for key, result in results.items():
        unread = unreadable(result)
        if unread and key not in errors:  # an element's own format error stays
            errors[key] = format_error_html(unread)
        shown[key] = part_feedback(result, graded=False)
    data.setdefault("feedback", {})["lagrade"] = shown


def grade(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """A score per part, the question's score weighted by points, and each part's verdict and
    feedback for the submission panel."""
    results = _judge_all(data, assignment, index, scenes)
    scores = data.setdefault("partial_scores", {})
    errors = data.setdefault("format_errors", {})
    total = sum(r["max_points"] for r in results.values()) or 1.0
    shown = {}
    for key, r in results.items():
        unread = unreadable(r)
        if unread:  # parse refused it already; a regrade under changed rules refuses it here
            errors.setdefault(key, format_error_html(unread))
        scores[key] = {
            "score": r["points"] / r["max_points"] if r["max_points"] else 0.0,
            "weight": r["max_points"],
        }
        shown[key] = part_feedback(r, graded=True)
    data["score"] = sum(r["points"] for r in results.values()) / total
    data.setdefault("feedback", {})["lagrade"] = shown


def test(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """The question test's submission of `data["test_type"]` and what parse and grade must make
    of it: the key scores full marks, a wrong answer to every part scores 0, an unreadable
    answer to every part is a format error in each. Expected from the answers' intent, never by
    judging them here, so that the test can fail."""
    problem, _rubric = _problem(assignment, index, scenes)
    kind = data["test_type"]
    coordinates = list(problem.scene.variant(data["params"]["seed"]).coordinates)
    raw = data.setdefault("raw_submitted_answers", {})
    scores = data.setdefault("partial_scores", {})
    errors = data.setdefault("format_errors", {})
    for part in problem.parts:
        key = part.key
        errors.pop(key, None)
        scores.pop(key, None)
        correct = str(data["correct_answers"][key])
        if kind == "correct":
            raw[key] = correct
            scores[key] = {"score": 1.0, "weight": float(part.points)}
        elif kind == "incorrect":
            raw[key] = wrong_answer(part.part, correct, coordinates)
            scores[key] = {"score": 0.0, "weight": float(part.points)}
        else:
            raw[key] = UNREADABLE_ANSWER
            errors[key] = "unreadable"  # the question test compares the keys only
    data["score"] = 1.0 if kind == "correct" else 0.0


def wrong_answer(part: str, correct: str, coordinates: list[str]) -> str:
    """A readable answer to `part` that is wrong and earns nothing under any rubric: the key
    changed by a term that alters the dynamics (never a constant, a total time derivative, a
    global factor or the sign of V, which a right answer may differ by), one line at a time;
    positions that depend on no coordinate (a map of rank 0) for the transformation."""
    q = coordinates[0]
    if part == "dof":
        return str(int(correct) + 1)
    if part == "coordinates":
        return f"{q}_dot"  # a velocity is no coordinate
    if part == "cyclic":
        return "none" if correct.strip() != "none" else ", ".join(coordinates)
    if part == EXPRESSION:
        return f"2*({correct}) + 1"
    if part == "transformation":  # other positions may be the student's own coordinates: a
        return "\n".join(f"{line.partition('=')[0].strip()} = 0" for line in correct.split("\n"))
    extra = f"{q}_dot^3" if part in ("lagrangian", "T") else f"{q}^3"
    lines = []
    for line in correct.split("\n"):
        name, equals, value = line.partition("=")
        if not equals:
            lines.append(f"{line} + {extra}")
        elif part == "eom":
            lines.append(f"{name.strip()} + {extra} = {value.strip()}")
        else:
            lines.append(f"{name.strip()} = {value.strip()} + {extra}")
    return "\n".join(lines)


def unreadable(result: Mapping[str, Any]) -> list[str]:
    """The parser's messages (each with its caret) when a part's answer cannot be read, as a
    whole or in one of its lines; [] when it was read."""
    if result["verdict"] == "invalid":
        return list(result["feedback"]) or ["This answer could not be read."]
    return [line for line in result["feedback"] if is_unreadable_line(line)]


def format_error_html(messages: list[str]) -> str:
    """A format error as PrairieLearn shows it (HTML, in a popover that does not sanitize): the
    messages escaped, their carets kept in line by `<pre>`."""
    return f'<pre class="mb-0">{html.escape(chr(10).join(messages))}</pre>'


_OUTCOMES = {
    "correct": "Correct",
    "incorrect": "Incorrect",
    "invalid": "Could not be read",
    "timeout": "Not judged in time",
}


def part_feedback(result: Mapping[str, Any], graded: bool) -> dict[str, Any]:
    """What the submission panel shows of one part, as plain text (question.html's mustache
    escapes it): the verdict and points once graded, how the answer was read, the parser's
    message when it could not be, and the feedback sentences (`pre` for those with a caret).
    Every field is present, so that no mustache name falls through to an outer context."""
    unread = unreadable(result)
    shown = result["interpreted"]
    read = "; ".join(s for s in shown if s) if isinstance(shown, list) else str(shown or "")
    outcome = ""
    if graded:
        verdict = result["verdict"]
        word = _OUTCOMES.get(verdict, verdict)
        if verdict == "incorrect" and result["points"] > 0:
            word = "Partly right"
        whole = result["max_points"]
        outcome = f"{word}: {result['points']:g} of {whole:g} point{'' if whole == 1 else 's'}"
    notes = [
        {"text": line, "pre": "\n" in line}
        for line in result["feedback"]
        if graded and line not in unread
    ]
    return {
        "outcome": outcome,
        "read": "" if result["verdict"] == "invalid" else read,
        "error": "\n".join(unread),
        "notes": notes,
    }


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
    on lines or separated by `;`, a list of names by commas), as it splits a sheet's answer."""
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
