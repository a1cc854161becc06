"""One student's sheet graded, part by part: each part judged by the one driver
(`lagrade.judge.driver.judge`) on the student's own variant, with what the student's other answers
bring (`given`), scored by the rubric, and a killed part costing only itself. `grade`
(`lagrade.grading.batch`), the answer page, PrairieLearn and a Dask worker all grade a sheet
here, so that they agree — with each other and with `check --seed` on the same variant."""

from __future__ import annotations

import json
import threading
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import lagrade.grading.resume as resume
from lagrade.bank import sha256
from lagrade.errors import LagradeError
from lagrade.grading.manifest import entry_spec, entry_variant
from lagrade.grading.rubric import Rubric
from lagrade.grading.submission import UnreadableAnswer, read_sheet
from lagrade.judge import (
    FOLLOWING,
    Outcome,
    PartTimeout,
    Pool,
    Problem,
    Verdict,
    cached_problem,
    judge,
    key_answer,
    prepare,
    run_checker,
    time_limit,
    timeout_verdict,
)

#: Parts that can follow from the student's own Lagrangian.
FOLLOW_L = frozenset({"eom", "momenta", "cyclic", "conserved"})
#: Parts that bring `given` to their checker: their own L, their transformation equations (the
#: coordinates they chose, which the later parts are judged in).
GIVEN_TO = FOLLOW_L | FOLLOWING


def structure_key(spec: Mapping[str, Any]) -> str:
    """What a question's derivation depends on: the scene, the variant's names and options, the
    quantity — not its numbers. Variants that share it share their derivation (T, V, L, the
    Euler–Lagrange expressions, below the judge), so a class of 1,000 with 1,000 seeds derives
    only a handful of structures; each student's question (its sample points, the handout
    values its feedback quotes) is still their own (`question`). A scene file's text is part of
    its identity (its hash, short)."""
    variant = entry_variant(spec)
    text = spec.get("scene_text")
    scene = spec["scene"] if text is None else f"{spec['scene']}@{sha256(text)[:16]}"
    return json.dumps([scene, variant.names, variant.options, spec.get("quantity")], sort_keys=True)


def question(spec: Mapping[str, Any]) -> Problem:
    """The Problem of a manifest entry: the student's own variant, as `check --seed` builds it."""
    return cached_problem(dict(spec))


def part_spec(entry: Mapping[str, Any], part: Mapping[str, Any]) -> dict[str, Any]:
    spec = entry_spec(entry)
    if part["part"] == "expression":
        spec["quantity"] = part["quantity"]
    return spec


def warm_up(manifest: dict) -> None:
    """Derive every structure the batch needs in the parent, so forked children share it.

    Besides `prepare`, one question of each structure is asked its own key once: that fills the
    lazy caches of the derivation a real answer touches, which a child would otherwise rebuild
    and throw away for every submission."""
    warm_questions(asked_questions(manifest))


def asked_questions(manifest: Mapping[str, Any]) -> dict[tuple[str, str], tuple[dict, Mapping]]:
    """Each distinct structure of the class's questions, (its key, the part), with the spec and
    part of the first student on the roster who is asked it: what a process derives before it
    judges (`warm_questions`), whichever process it is, this machine's or a Dask worker."""
    asked: dict[tuple[str, str], tuple[dict, Mapping]] = {}
    for student in manifest["students"]:
        for entry, problem in zip(student["problems"], manifest["problems"], strict=True):
            for part in problem["parts"]:
                spec = part_spec(entry, part)
                asked.setdefault((structure_key(spec), part["part"]), (spec, part))
    return asked


def warm_questions(asked: Mapping[tuple[str, str], tuple[dict, Mapping]]) -> None:
    """Derive each structure of `asked` (as `asked_questions` gives them) in this process."""
    for spec, part in asked.values():
        problem = question(spec)
        prepare(problem, part["part"], diagnosis=True)
        if part["part"] != "expression" and problem.variant is not None:
            _warm_with_key(problem, part)


def _warm_with_key(question: Problem, part: Mapping[str, Any]) -> None:
    """Ask a question its own key (trusted: `generate` verified it), under a time limit; a
    failure here only means a colder start for the children, never a stopped batch."""
    name = part["part"]
    variant = question.variant
    given = {"lagrangian": key_answer(variant, "lagrangian")} if name in FOLLOW_L else None
    # The alarm rings only in a main thread; a Dask worker warms up in one of its threads, and
    # checks the key (verified when it was generated) without it.
    main = threading.current_thread() is threading.main_thread()
    try:
        with time_limit(10.0 if main else None):
            run_checker(question, name, key_answer(variant, name, part.get("quantity")), given)
    except (PartTimeout, LagradeError, ArithmeticError, ValueError):
        pass


def _blank(answer: Any) -> bool:
    if isinstance(answer, list):
        return not any(str(a).strip() for a in answer)
    return not str(answer).strip()


def grade_part(
    entry: Mapping[str, Any],
    part: Mapping[str, Any],
    answer: Any,
    given: dict[str, Any],
    rubric: Rubric,
    limit: float,
) -> dict[str, Any]:
    """One part's result: the verdict, the points it earns and the feedback."""
    name = part["part"]
    if answer is None or (not isinstance(answer, UnreadableAnswer) and _blank(answer)):
        verdict = Verdict(
            name, "incorrect", 0.0, ("Not answered.",), "", "blank", mistakes=("blank",)
        )
    elif isinstance(answer, UnreadableAnswer):
        verdict = Verdict(
            name,
            "invalid",
            0.0,
            (f"This answer is a {answer.kind}; write it as a string.",),
            "",
            "parse",
        )
    else:
        spec = part_spec(entry, part)
        verdict = judge(spec, name, answer, _given(part, given, rubric), limit=limit)
    return _scored(part, verdict, rubric)


def stopped_part(part: Mapping[str, Any], rubric: Rubric, limit: float) -> dict[str, Any]:
    """The result of a part whose worker was killed at its limit + grace (C code the alarm
    could not interrupt): `timeout`, as if the alarm had struck (`lagrade.grading.resume`)."""
    return _scored(part, timeout_verdict(part["part"], limit), rubric)


def _scored(part: Mapping[str, Any], verdict: Verdict, rubric: Rubric) -> dict[str, Any]:
    """A part's result: the verdict's one serialised form (`Verdict.to_dict`, without timings),
    with the sheet's key for the part and the points the rubric gives it."""
    share = rubric.fraction(
        verdict.status, verdict.score, verdict.mistakes, verdict.follows_from_own_answer
    )
    return {
        "key": part["key"],
        "points": round(share * float(part["points"]), 6),
        "max_points": float(part["points"]),
        **verdict.to_dict(timings=False),
    }


def _given(part: Mapping[str, Any], given: dict[str, Any], rubric: Rubric) -> dict[str, Any] | None:
    """What the student brings besides the answer: the rubric's tolerance for a numeric
    follow-up (the handout's values are the question's own: `question`); their own L for
    follow-through; and for `conserved` whether the part asks for all of them (its `all`
    field; a manifest written before the field asked for all)."""
    name = part["part"]
    if name == "expression":
        return {"tolerance": rubric.numeric_tolerance}
    if name not in GIVEN_TO:
        return None
    if name == "conserved" and part.get("all", True):
        return {**given, "all": True}
    return given


def sheet_given(parts: Sequence[tuple[str, str]], answers: Mapping[str, Any]) -> dict[str, Any]:
    """What one problem's answers bring to its other parts (`given`): the student's own L
    (follow-through) and their transformation equations (the coordinates the later parts are
    judged in), both raw as typed: the checkers read them. The one place a sheet's `given` is
    built, for `grade`, the answer page and PrairieLearn alike; `parts` are the problem's
    (key, part name) pairs."""
    given: dict[str, Any] = {}
    for key, name in parts:
        answer = answers.get(key)
        if isinstance(answer, list) and not all(isinstance(a, str) for a in answer):
            continue
        if not isinstance(answer, str | list) or _blank(answer):
            continue
        if name in ("lagrangian", "transformation"):
            given[name] = answer
    return given


def grade_student(manifest: Mapping, rubric: Rubric, task: Mapping[str, Any]) -> dict[str, Any]:
    """Grade one student's sheet (runs inside a worker; the manifest and rubric are inherited
    when the worker is forked, only the small task crosses the pipe). Each part is noted as it
    is judged, so that a worker killed in one part costs only that part: the task `resumed`
    from the kill (`lagrade.grading.resume`) keeps the parts judged and skips the one stopped."""
    student = task["student"]
    problems = manifest["problems"]
    keys = {p["index"]: [part["key"] for part in p["parts"]] for p in problems}
    # On a Dask cluster the parent has read the file and sends its bytes (`content`).
    content = task.get("content")
    sheet = read_sheet(Path(task["path"]), student["id"], len(problems), keys, content)
    base = {"warnings": list(sheet.warnings) + ([task["note"]] if task.get("note") else [])}
    if sheet.other_id is not None:
        base["sheet_student_id"] = sheet.other_id
    if not sheet.readable:
        return {**base, "status": "invalid", "reason": sheet.reason, "problems": []}
    graded = []
    timeouts = []
    for problem, entry in zip(problems, student["problems"], strict=True):
        answers = sheet.answers.get(problem["index"], {})
        given = sheet_given([(p["key"], p["part"]) for p in problem["parts"]], answers)
        parts = []
        for part in problem["parts"]:
            part_id = f"{problem['index']}/{part['key']}"
            result = resume.earlier(task, part_id)
            if result is None and resume.stopped(task, part_id):
                result = stopped_part(part, rubric, task["part_time_limit"])
            if result is None:
                resume.begin(part_id)
                result = grade_part(
                    entry, part, answers.get(part["key"]), given, rubric, task["part_time_limit"]
                )
                resume.judged(part_id, result)
            parts.append(result)
        timeouts += [
            f"problem {problem['index']} {p['key']}" for p in parts if p["verdict"] == "timeout"
        ]
        graded.append(_problem_result(problem, entry, parts))
    status, reason = "graded", ""
    if timeouts:
        status, reason = "timeout", "ran out of time on " + ", ".join(timeouts)
    return {**base, "status": status, "reason": reason, "problems": graded}


def _problem_result(problem: Mapping, entry: Mapping, parts: list[dict]) -> dict[str, Any]:
    return {
        "index": problem["index"],
        "scene": entry["scene"],
        "title": problem["title"],
        "score": round(sum(p["points"] for p in parts), 6),
        "max_score": float(sum(p["max_points"] for p in parts)),
        "parts": parts,
    }


# --- the batch ----------------------------------------------------------------------------------


def judge_sheets(pool: Pool, tasks: list[tuple[str, dict[str, Any]]]) -> Iterator[Outcome]:
    """The Outcome of each (student id, task), as each is settled. A worker killed in a part
    leaves a task that resumes after it: judged in a later round, by a fresh worker (each round
    settles at least one part of each such sheet)."""
    while tasks:
        by_key = dict(tasks)
        tasks = []
        for outcome in pool.run(list(by_key.items())):
            again = resume.resumed(by_key[outcome.key], outcome)
            if again is not None:
                tasks.append((outcome.key, again))
                continue
            yield outcome
