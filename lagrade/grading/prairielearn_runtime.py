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
from collections.abc import Mapping, MutableMapping
from typing import Any

import lagrade.grading.resume as resume
from lagrade.judge import PREPARE_LIMIT, Limits, Pool, is_unreadable_line

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
    rendered: Mapping[str, Any] | None = None,
) -> None:
    """Draw the variant from the pool by PrairieLearn's seed; its statement and prompts go to
    `params`, the key's answers as a student types them to `correct_answers`. `rendered`: the
    variants rendered at export (`render_pool`), as data; a seed not among them is rendered
    here."""
    seed = seeds[int(data.get("variant_seed", 0)) % len(seeds)]
    found = _from_pool(rendered, seed)
    if found is None:
        from lagrade.grading.prairielearn_variant import render_variant

        found = render_variant(assignment, index, seed, scenes)
    data.setdefault("params", {}).update(found["params"])
    data.setdefault("correct_answers", {}).update(found["correct_answers"])


def render_pool(
    assignment: str, index: int, seeds: list, scenes: Mapping[str, str] | None = None
) -> dict[str, Any]:
    """Every variant of the pool rendered once, at export, as data (`variants.json` beside
    server.py): PrairieLearn's `generate` then reads it instead of deriving the variant and
    drawing its figure in every call. A figure that variants share is kept once."""
    from lagrade.grading.prairielearn_variant import render_variant

    figures: dict[str, str] = {}
    variants: dict[str, Any] = {}
    for seed in seeds:
        found = render_variant(assignment, index, seed, scenes)
        figure = found.pop("figure")
        if figure is not None:
            name = f"figure-{len(figures)}"
            name = next((k for k, v in figures.items() if v == figure), name)
            figures[name] = str(figure)
            html = found["params"]["statement_html"]
            found["params"]["statement_html"] = html.replace(str(figure), _FIGURE.format(name))
        variants[str(seed)] = found
    return {"figures": figures, "variants": variants}


#: Where a shared figure stands in a rendered statement (an HTML comment: inert if left).
_FIGURE = "<!--lagrade-figure:{}-->"


def _from_pool(rendered: Mapping[str, Any] | None, seed: int) -> dict[str, Any] | None:
    """The rendered variant `seed`, its figure put back in its statement; None when absent."""
    if not rendered or str(seed) not in rendered.get("variants", {}):
        return None
    found = rendered["variants"][str(seed)]
    html = found["params"]["statement_html"]
    for name, svg in rendered.get("figures", {}).items():
        html = html.replace(_FIGURE.format(name), svg)
    params = {**found["params"], "statement_html": html}
    return {"params": params, "correct_answers": dict(found["correct_answers"])}


def parse(
    data: MutableMapping[str, Any],
    assignment: str,
    index: int,
    scenes: Mapping[str, str] | None = None,
) -> None:
    """Refuse an answer with an unreadable line as a format error (no attempt charged); say how
    each answer was read. Only reads (`lagrade.judge.read`): the submission is judged once, in
    `grade`."""
    readings = _backstop({**_task(data, assignment, index, scenes), "kind": "read"})
    errors = data.setdefault("format_errors", {})
    shown = {}
    for key, reading in readings.items():
        unread = reading["unreadable"]
        if unread and key not in errors:  # an element's own format error stays
            errors[key] = format_error_html(unread)
        shown[key] = {"outcome": "", "read": reading["read"], "error": "\n".join(unread)}
        shown[key]["notes"] = []
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
    from lagrade.grading.prairielearn_work import coordinates_of, parts_of

    kind = data["test_type"]
    coordinates = coordinates_of(assignment, index, data["params"]["seed"], scenes)
    raw = data.setdefault("raw_submitted_answers", {})
    scores = data.setdefault("partial_scores", {})
    errors = data.setdefault("format_errors", {})
    for key, part, points in parts_of(assignment, index, scenes):
        errors.pop(key, None)
        scores.pop(key, None)
        correct = str(data["correct_answers"][key])
        if kind == "correct":
            raw[key] = correct
            scores[key] = {"score": 1.0, "weight": points}
        elif kind == "incorrect":
            raw[key] = wrong_answer(part, correct, coordinates)
            scores[key] = {"score": 0.0, "weight": points}
        else:
            raw[key] = UNREADABLE_ANSWER
            errors[key] = "unreadable"  # the question test compares the keys only
    data["score"] = 1.0 if kind == "correct" else 0.0


def wrong_answer(part: str, correct: str, coordinates: list[str]) -> str:
    """A readable answer to `part` that is wrong and earns nothing under any rubric: the key
    changed by a term that alters the dynamics (never a constant, a total time derivative, a
    global factor or the sign of V, which a right answer may differ by), one line at a time;
    positions that depend on no coordinate (a map of rank 0) for the transformation."""
    from lagrade.assign import EXPRESSION

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
    return _backstop({**_task(data, assignment, index, scenes), "kind": "grade"})


def _task(
    data: Mapping[str, Any], assignment: str, index: int, scenes: Mapping[str, str] | None
) -> dict[str, Any]:
    return {
        "assignment": assignment,
        "index": index,
        "scenes": dict(scenes or {}),
        "seed": data["params"]["seed"],
        "submitted": dict(data.get("submitted_answers", {}) or {}),
        "part_time_limit": PART_TIME_LIMIT,
    }


def _backstop(task: dict[str, Any]) -> dict[str, dict]:
    """Run the task (`prairielearn_work.judge_task`) in a killable worker (the rule of `lagrade
    grade`: the part's alarm,
    the kill at its limit + grace, the memory limit); a kill in one part costs that part, and a
    fresh worker judges the rest. The workers end with the call: PrairieLearn runs each request
    in a process of its own and discards it, and a worker left behind would hold its pipes."""
    # Loaded here, before the worker forks, which then shares it (loaded in the worker instead,
    # measured: 0.75 s CPU for a grade call against 0.49 s).
    from lagrade.grading.prairielearn_work import judge_task

    with Pool(judge_task, jobs=1, limits=Limits(seconds=PREPARE_LIMIT)) as pool:
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
