"""Grade a folder of answer sheets against a generated assignment's manifest.

Every student on the roster gets exactly one result: graded, or `missing`, `invalid`, `timeout`
or `error` with its reason. Submissions are graded in killable worker processes with memory and
wall-clock limits (`lagrade.judge.worker`: a hostile file costs only its author), each part under
the same time-limit rule as `lagrade check`, by the same checker. Results are written atomically
as they arrive, and a rerun reuses every result whose submission, variant, rubric and grader
version are unchanged.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import functools
import gc
import hashlib
import json
import tempfile
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
import lagrade.grading.gradebooks as gradebooks
import lagrade.grading.report as report
import lagrade.grading.resume as resume
import lagrade.grading.savelog as savelog
import lagrade.grading.submission as submission
from lagrade.assign.manifest import project_version
from lagrade.assign.views import PROMPTS
from lagrade.bank.scenefile import sha256
from lagrade.errors import AssignmentError, LagradeError
from lagrade.grading.instants import shown
from lagrade.grading.manifest import entry_spec, entry_variant, load_manifest
from lagrade.grading.rubric import Rubric, load_rubric
from lagrade.grading.submission import UnreadableAnswer, find_submission, read_sheet
from lagrade.judge.check import cached_problem, prepare, timeout_verdict
from lagrade.judge.key import key_answer
from lagrade.judge.parts import run_checker
from lagrade.judge.parts.own_coordinates import FOLLOWING
from lagrade.judge.problem import Problem
from lagrade.judge.verdict import Verdict
from lagrade.judge.worker import GRACE, Limits, Outcome, PartTimeout, Pool, deadline, time_limit

#: Parts that can follow from the student's own Lagrangian.
FOLLOW_L = frozenset({"eom", "momenta", "cyclic", "conserved"})
#: Parts that bring `given` to their checker: their own L, their transformation equations (the
#: coordinates they chose, which the later parts are judged in).
GIVEN_TO = FOLLOW_L | FOLLOWING
#: The handout's prompt for `conserved` asks for "the conserved quantities" (all of them), so a
#: graded sheet is judged for completeness too (`"all": true`); a `check` request is not unless
#: it says so.
ASKS_ALL_CONSERVED = "the conserved quantities" in PROMPTS["conserved"]
STATUSES = ("graded", "missing", "invalid", "timeout", "error")


@dataclass(frozen=True)
class BatchSummary:
    """What a grading run did: counts by status, where the outputs are, what was reused."""

    out_dir: Path
    counts: dict[str, int]
    reused: int
    results: list[dict[str, Any]] = field(repr=False)
    #: Files in the submissions folder that are no roster student's sheet: name → why.
    stray: dict[str, str] = field(default_factory=dict)
    #: The LMS gradebooks written (`exports`), each with its warnings for the instructor.
    exports: tuple[gradebooks.LmsFile, ...] = ()

    @property
    def all_graded(self) -> bool:
        return self.counts.get("graded", 0) == sum(self.counts.values())


# --- the rubric -----------------------------------------------------------------------------------


def _rubric(manifest_path: Path, manifest: dict) -> Rubric:
    info = manifest["assignment"]
    copy = manifest_path.parent / info.get("file", "assignment.toml")
    if not copy.exists():
        return Rubric()
    if hashlib.sha256(copy.read_bytes()).hexdigest() != info.get("sha256"):
        raise AssignmentError(f"{copy} changed after the assignment was generated; restore it")
    try:
        return load_rubric(copy)
    except LagradeError as error:
        raise AssignmentError(str(error)) from None


# --- grading one student -------------------------------------------------------------------------


def _question_key(spec: Mapping[str, Any]) -> str:
    """What a symbolic question depends on: the scene, the variant's names and options, the
    quantity — not its numbers, which only numeric follow-ups use (each with its own variant).
    A class of 1,000 with 1,000 seeds asks only a handful of distinct symbolic questions. A
    scene file's text is part of its identity (its hash, short)."""
    variant = entry_variant(spec)
    text = spec.get("scene_text")
    scene = spec["scene"] if text is None else f"{spec['scene']}@{sha256(text)[:16]}"
    return json.dumps([scene, variant.names, variant.options, spec.get("quantity")], sort_keys=True)


def question(spec: Mapping[str, Any]) -> Problem:
    """The Problem of a manifest entry, shared by every student who was asked the same thing."""
    return cached_problem(dict(spec), _question_key(spec))


def _spec(entry: Mapping[str, Any], part: Mapping[str, Any]) -> dict[str, Any]:
    spec = entry_spec(entry)
    if part["part"] == "expression":
        spec["quantity"] = part["quantity"]
    return spec


def warm_up(manifest: dict) -> None:
    """Derive every reference the batch needs in the parent, so forked children share it.

    Besides `prepare`, each distinct question is asked its own key once: that fills the lazy
    caches a real answer touches (compiled mutants, sample points, reference values), which a
    child would otherwise rebuild and throw away for every submission (measured: about 3× the
    grading time of a warm process)."""
    warm_questions(asked_questions(manifest))


def asked_questions(manifest: Mapping[str, Any]) -> dict[tuple[str, str], tuple[dict, Mapping]]:
    """Each distinct question of the class, (its key, the part), with the spec and part of the
    first student on the roster who is asked it. The Problem every later student shares is
    built from that student's variant (its sample points, so the points feedback quotes), so
    whichever process builds it, this machine's or a Dask worker, builds the same."""
    asked: dict[tuple[str, str], tuple[dict, Mapping]] = {}
    for student in manifest["students"]:
        for entry, problem in zip(student["problems"], manifest["problems"], strict=True):
            for part in problem["parts"]:
                spec = _spec(entry, part)
                asked.setdefault((_question_key(spec), part["part"]), (spec, part))
    return asked


def warm_questions(asked: Mapping[tuple[str, str], tuple[dict, Mapping]]) -> None:
    """Derive each question of `asked` (as `asked_questions` gives them) in this process."""
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
        deadline(limit + GRACE)
        try:
            with time_limit(limit):
                verdict = _judge(entry, part, answer, given, rubric)
        except PartTimeout:
            verdict = timeout_verdict(name, limit)
    return _scored(part, verdict, rubric)


def stopped_part(part: Mapping[str, Any], rubric: Rubric, limit: float) -> dict[str, Any]:
    """The result of a part whose worker was killed at its limit + grace (C code the alarm
    could not interrupt): `timeout`, as if the alarm had struck (`lagrade.grading.resume`)."""
    return _scored(part, timeout_verdict(part["part"], limit), rubric)


def _scored(part: Mapping[str, Any], verdict: Verdict, rubric: Rubric) -> dict[str, Any]:
    """A part's result from its verdict: the points the rubric gives it and the feedback."""
    name = part["part"]
    share = rubric.fraction(
        verdict.status, verdict.score, verdict.mistakes, verdict.follows_from_own_answer
    )
    return {
        "key": part["key"],
        "part": name,
        "verdict": verdict.status,
        "points": round(share * float(part["points"]), 6),
        "max_points": float(part["points"]),
        "feedback": list(verdict.feedback),
        "interpreted": verdict.interpreted,
        "method": verdict.method,
        "mistakes": list(verdict.mistakes),
        "follows_from_own_answer": verdict.follows_from_own_answer,
    }


def _judge(entry, part, answer, given, rubric: Rubric) -> Verdict:
    """The sheet's raw answer (its string, or the list of strings TOML gave) goes to the part's
    checker as it is: splitting, separators and reading are the checker's (the one door), so
    `grade` reads an answer exactly as `check` does."""
    name = part["part"]
    problem = question(_spec(entry, part))
    return run_checker(problem, name, answer, _given(entry, name, given, rubric))


def _given(entry, name: str, given: dict[str, Any], rubric: Rubric) -> dict[str, Any] | None:
    """What the student brings besides the answer: the handout's own values and the rubric's
    tolerance for a numeric follow-up; their own L for follow-through; and for `conserved`
    that the handout asks for all of them."""
    if name == "expression":
        own = entry_variant(entry)  # this student's numbers
        return {"values": own.values, "tolerance": rubric.numeric_tolerance}
    if name not in GIVEN_TO:
        return None
    if name == "conserved" and ASKS_ALL_CONSERVED:
        return {**given, "all": True}  # the handout asks for "the conserved quantities"
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


def _fingerprint(
    path: Path | None, student: Mapping, rubric: Rubric, version: str, missing: str = ""
) -> str:
    """What a result depends on: the submission's bytes (streamed, whatever their size), the
    student's variant, the rubric and the grader's version; for a missing sheet, the reason
    (it names a misnamed file, which can come or go)."""
    h = hashlib.sha256()
    h.update(json.dumps([student, rubric.as_dict(), version], sort_keys=True).encode())
    if path is None:
        h.update(b"\x00<missing>" + missing.encode())
        return h.hexdigest()
    h.update(b"\x00")
    submission.feed_digest(h, path)
    return h.hexdigest()


def _finish(
    student: Mapping, manifest: Mapping, outcome: dict[str, Any], fingerprint: str, version: str
) -> dict[str, Any]:
    """The full per-student result: identity, status, totals, problems, provenance."""
    max_score = float(
        manifest["assignment"].get("total_points")
        or sum(float(p["points"]) for prob in manifest["problems"] for p in prob["parts"])
    )
    problems = outcome.get("problems", [])
    score = round(sum(p["score"] for p in problems), 6)
    return {
        "student": {"id": student["id"], "name": student["name"]},
        "status": outcome["status"],
        "reason": outcome.get("reason", ""),
        "warnings": outcome.get("warnings", []),
        **_other_id(outcome),
        "score": score,
        "max_score": max_score,
        "problems": problems,
        "fingerprint": fingerprint,
        "lagrade_version": version,
    }


def grade(
    manifest_path: Path,
    submissions: Path,
    out_dir: Path | None = None,
    *,
    jobs: int = 1,
    part_time_limit: float = 2.0,
    limits: Limits | None = None,
    progress: Callable[[int, int, str], None] | None = None,
    exports: Sequence[str] = (),
    export_options: gradebooks.ExportOptions | None = None,
    as_of: dt.datetime | None = None,
    dask: str | None = None,
) -> BatchSummary:
    """Grade every roster student's sheet in `submissions`; write results into `out_dir`
    (default: `grades/` beside the manifest); `exports` adds LMS gradebooks ("canvas",
    "moodle", written with `export_options`: `lagrade.grading.gradebooks`); `as_of` grades
    each student's last save at or before that instant, from the answer page's log of saves
    (`lagrade.grading.savelog`); `dask` judges the sheets on a Dask cluster ("local", or a
    scheduler's address: `lagrade.grading.cluster`), with `jobs` the number of workers of a
    local one. See the module docstring for the guarantees."""
    manifest_path = Path(manifest_path)
    submissions = Path(submissions)
    _check_arguments(manifest_path, submissions)
    if dask is not None:  # a cluster that cannot be used stops the run before it starts
        from lagrade.grading.cluster import require

        require(dask, jobs)
    manifest = load_manifest(manifest_path)
    rubric = _rubric(manifest_path, manifest)
    if exports:  # a bad [lms] table or id stops the run before anything is graded
        copy = manifest_path.parent / manifest["assignment"].get("file", "assignment.toml")
        export_options = gradebooks.resolve_options(copy, export_options)
    out = Path(out_dir) if out_dir is not None else manifest_path.parent / "grades"
    with atomic.hold_folder(out), _sheets_at(submissions, manifest, as_of) as (folder, none):
        atomic.remove_stale_temporaries(out)
        return _grade_into(
            out,
            manifest,
            rubric,
            folder,
            jobs,
            part_time_limit,
            limits,
            progress,
            exports,
            export_options,
            none,
            dask,
        )


@contextlib.contextmanager
def _sheets_at(
    submissions: Path, manifest: Mapping[str, Any], as_of: dt.datetime | None
) -> Iterator[tuple[Path, str]]:
    """The folder to grade and why a student has no sheet there: `submissions` as it is, or
    (with `as_of`) a temporary folder of the sheets as they stood then, rebuilt from the log."""
    if as_of is None:
        yield submissions, ""
        return
    ids = [s["id"] for s in manifest["students"]]
    with tempfile.TemporaryDirectory(prefix="lagrade-as-of-") as folder:
        savelog.sheets_as_of(submissions, ids, as_of, Path(folder))
        yield Path(folder), f"nothing was saved by {shown(as_of)}"


def _check_arguments(manifest_path: Path, submissions: Path) -> None:
    """The two paths are what they should be, and the message says which is not (two swapped
    arguments are not a folder that "does not exist")."""
    swapped = manifest_path.is_dir() and submissions.is_file()
    if swapped:
        raise AssignmentError(
            f"{manifest_path} is a folder and {submissions} a file: the manifest comes first "
            f"(lagrade grade {submissions} {manifest_path})"
        )
    if not submissions.exists():
        raise AssignmentError(f"submissions folder {submissions} does not exist")
    if not submissions.is_dir():
        raise AssignmentError(f"{submissions} is a file, not the folder of answer sheets")
    if manifest_path.is_dir():
        inside = manifest_path / "manifest.json"
        raise AssignmentError(
            f"{manifest_path} is a folder, not a manifest"
            + (f"; did you mean {inside}?" if inside.is_file() else "")
        )


def _grade_into(
    out: Path,
    manifest: dict[str, Any],
    rubric: Rubric,
    submissions: Path,
    jobs: int,
    part_time_limit: float,
    limits: Limits | None,
    progress: Callable[[int, int, str], None] | None,
    exports: Sequence[str] = (),
    export_options: gradebooks.ExportOptions | None = None,
    no_sheet: str = "",
    dask: str | None = None,
) -> BatchSummary:
    """The body of `grade`, run while this process holds the output folder; `no_sheet` is why
    a student without a sheet has none, when the folder says nothing about it."""
    version = project_version()
    students = manifest["students"]
    # Reading a sheet has this long; each part then moves the deadline to its own time limit.
    limits = limits or Limits(seconds=20 + 3 * part_time_limit * _part_count(manifest))

    results: dict[str, dict[str, Any]] = {}
    tasks = []
    reused = 0
    stray = submission.stray_files(submissions, (s["id"] for s in students))
    for student in students:
        path, note = find_submission(submissions, student["id"])
        missing = (no_sheet or _missing_reason(student["id"], stray)) if path is None else ""
        fingerprint = _fingerprint(path, student, rubric, version, missing)
        previous = report.read_student_result(out, student["id"])
        if previous is not None and previous.get("fingerprint") == fingerprint:
            results[student["id"]] = _held(previous)
            reused += 1
            continue
        if path is None:
            outcome = {"status": "missing", "reason": missing, "problems": []}
            results[student["id"]] = _store(
                out, manifest, _finish(student, manifest, outcome, fingerprint, version)
            )
            continue
        tasks.append(
            (
                student["id"],
                {
                    "student": student,
                    "path": str(path),
                    "note": note,
                    "part_time_limit": part_time_limit,
                    "fingerprint": fingerprint,
                },
            )
        )

    by_id = {s["id"]: s for s in students}
    fingerprints = {key: task["fingerprint"] for key, task in tasks}
    done = len(results)
    if dask is None:
        outcomes = _judged_here(manifest, rubric, tasks, jobs, limits)
    else:
        from lagrade.grading.cluster import grade_on_cluster

        outcomes = grade_on_cluster(dask, manifest, rubric, tasks, jobs, limits, version)
    for outcome in outcomes:
        student = by_id[outcome.key]
        value = _outcome_result(outcome, out, student["id"])
        results[student["id"]] = _store(
            out, manifest, _finish(student, manifest, value, fingerprints[outcome.key], version)
        )
        done += 1
        if progress:
            progress(done, len(students), student["id"])

    ordered = [results[s["id"]] for s in students]
    report.write_class_reports(out, manifest, ordered, stray)
    books = gradebooks.write_exports(out, manifest, ordered, exports, export_options)
    counts = {s: sum(1 for r in ordered if r["status"] == s) for s in STATUSES}
    return BatchSummary(out, counts, reused, ordered, stray, tuple(books))


def _judged_here(
    manifest: dict[str, Any], rubric: Rubric, tasks: list, jobs: int, limits: Limits
) -> Iterator[Outcome]:
    """Each task's Outcome from this machine's pool, forked after the questions are derived."""
    if not tasks:
        return
    warm_up(manifest)
    # Children are forked: keep the collector off the parent's (now immortal) objects, or
    # every child would touch, and so copy, the whole heap (measured: half its time).
    gc.collect()
    gc.freeze()
    with Pool(functools.partial(grade_student, manifest, rubric), jobs=jobs, limits=limits) as pool:
        yield from judge_sheets(pool, tasks)


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


def _missing_reason(student_id: str, stray: Mapping[str, str]) -> str:
    """Why a student has no result, naming a file that seems meant as their sheet."""
    files = submission.meant_for(student_id, stray)
    if not files:
        return "no answer sheet was submitted"
    return (
        f"no answer sheet was submitted; {', '.join(files)} looks like one but is not read "
        f"(name it {student_id}.toml or {student_id}.json)"
    )


def _outcome_result(outcome: Outcome, out: Path, student_id: str) -> dict[str, Any]:
    """A worker's Outcome as a student's result: graded, or why not (a bug of ours is logged)."""
    if outcome.status == "ok":
        return outcome.value
    if outcome.status == "timeout":
        return {"status": "timeout", "reason": f"grading {outcome.reason}", "problems": []}
    report.log_error(out, student_id, outcome.reason)
    return {
        "status": "error",
        "reason": "the grader failed on this submission "
        "(logged in errors.log); the instructor should look at it",
        "problems": [],
    }


def _other_id(result: Mapping[str, Any]) -> dict[str, str]:
    """`sheet_student_id` when the sheet named another student than its file's, else nothing."""
    other = result.get("sheet_student_id")
    return {"sheet_student_id": other} if other else {}


def _part_count(manifest: Mapping) -> int:
    return sum(len(p["parts"]) for p in manifest["problems"])


def _store(out: Path, manifest: Mapping, result: dict[str, Any]) -> dict[str, Any]:
    """Write a student's outputs; return what the run keeps of the result in memory."""
    report.write_student_outputs(out, manifest, result)
    return _held(result)


def _held(result: Mapping[str, Any]) -> dict[str, Any]:
    """What the class reports need of a result, held for the whole run: not every echo, witness
    and feedback sentence, which made the parent grow by about 17 KB a student (measured over
    900 submissions); the full result is in students/<id>.json."""
    return {
        "student": dict(result["student"]),
        "status": result["status"],
        "reason": result.get("reason", ""),
        "warnings": list(result.get("warnings", [])),
        **_other_id(result),
        "score": result["score"],
        "max_score": result["max_score"],
        "problems": [
            {
                "index": problem["index"],
                "score": problem["score"],
                "max_score": problem.get("max_score"),
                "parts": [
                    {
                        "key": part["key"],
                        "verdict": part["verdict"],
                        "points": part.get("points"),
                        "max_points": part.get("max_points"),
                        "mistakes": list(part.get("mistakes", [])),
                        "feedback": list(part.get("feedback", []))[:1],
                    }
                    for part in problem["parts"]
                ],
            }
            for problem in result.get("problems", [])
        ],
    }
