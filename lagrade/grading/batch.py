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
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
import lagrade.grading.gradebooks as gradebooks
import lagrade.grading.report as report
import lagrade.grading.savelog as savelog
import lagrade.grading.submission as submission
from lagrade.assign import project_version
from lagrade.errors import AssignmentError, LagradeError
from lagrade.grading.instants import shown
from lagrade.grading.manifest import load_manifest
from lagrade.grading.rubric import Rubric, load_rubric
from lagrade.grading.student import grade_student, judge_sheets, warm_up
from lagrade.grading.submission import find_submission
from lagrade.judge import Limits, Outcome, Pool, forget_problems

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
    # Each question from this class's own first student, as in a fresh process: a class graded
    # earlier in this process (by the API) may have built it from another seed.
    forget_problems()
    warm_up(manifest)
    # Children are forked: keep the collector off the parent's (now immortal) objects, or
    # every child would touch, and so copy, the whole heap (measured: half its time). Unfrozen
    # first: what an earlier run in this process froze (its questions, forgotten above) is
    # garbage now, and a process that grades again and again must not keep every class's.
    gc.unfreeze()
    gc.collect()
    gc.freeze()
    with Pool(functools.partial(grade_student, manifest, rubric), jobs=jobs, limits=limits) as pool:
        yield from judge_sheets(pool, tasks)


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
