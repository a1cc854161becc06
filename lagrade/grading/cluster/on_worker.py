"""What runs inside a Dask worker: a chunk of sheets or requests judged by lagrade's own killable
pool (`lagrade.judge.worker.Pool`), forked from the Dask worker's process, so that every time
and memory limit holds exactly as on one machine (the alarm, the kill at limit + GRACE, the
memory ceiling, a kill costing only its part).

One chunk at a time per Dask worker process, whatever its threads: the pool has as many
judging processes as the worker has threads, and a lock keeps the others' chunks waiting. So
nothing derives questions while a judging process is forked (a lock held mid-derivation by one
thread would be held for ever in the forked child), and a worker of N threads judges like
`lagrade grade --jobs N` on its machine. The process keeps what it derived for the chunks to
come: a grading run's questions (warmed up once each, before the pool forks), and the checking
pool whose processes keep the questions of `check --batch` requests."""

from __future__ import annotations

import functools
import gc
import multiprocessing
import threading
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from lagrade.assign import project_version
from lagrade.errors import ClusterError
from lagrade.judge import Limits, Outcome, Pool, check_pool, forget_problems, run_batch

if TYPE_CHECKING:
    from lagrade.grading.rubric import Rubric

_lock = threading.Lock()


@dataclass
class _Grading:
    """A grading run's state in this process, as the parent sent it once: its manifest
    (problems, scenes; no students), rubric, limits, scene texts and the class's questions,
    each with the student it is built from (`asked_questions`); then the questions derived so
    far, and the pool."""

    run: str
    manifest: dict[str, Any]
    rubric: Rubric
    limits: Limits
    texts: dict[str, str]
    asked: dict[tuple[str, str], tuple[dict, Any]]
    warmed: set = field(default_factory=set)
    pool: Pool | None = None


_grading: _Grading | None = None
_checking: Pool | None = None


def hold(shared: Any) -> Any:
    """A task whose result is `shared`: what every chunk of a run needs (manifest, rubric),
    sent to the scheduler once, fetched by each worker once, and computed again from the
    scheduler's copy if every worker that held it dies."""
    return shared


def grade_chunk(shared: dict[str, Any], tasks: list[tuple[str, dict]], version: str) -> list:
    """The Outcome of each (student id, task) of the chunk: sheets sent as bytes, judged by this
    process's grading pool once the chunk's questions are derived here (each from the student
    the parent's own warm-up would build it from, `asked_questions`, so that the sample points
    and the feedback quoting them are the same), with the same resume-after-a-kill rounds as on
    one machine (`judge_sheets`)."""
    # Imported here: a worker that only checks requests does not load the reports' modules.
    from lagrade.grading.student import asked_questions, grade_student, judge_sheets, warm_questions

    _same_version(version)
    with _lock:
        state = _grading_state(shared)
        for _key, task in tasks:  # the scene texts travelled once, with the manifest
            for entry in task["student"]["problems"]:
                if entry["scene"] in state.texts:
                    entry["scene_text"] = state.texts[entry["scene"]]
        chunk = {**state.manifest, "students": [task["student"] for _key, task in tasks]}
        new = {k: state.asked[k] for k in asked_questions(chunk) if k not in state.warmed}
        if new or state.pool is None:
            warm_questions(new)
            state.warmed.update(new)
            if state.pool is not None:  # its processes were forked before these questions
                state.pool.close()
            # As `grade` does before it forks (lagrade.grading.batch): the collector kept off
            # what the pool's processes inherit. Unfrozen first, so that what an earlier freeze
            # kept and has since become garbage in this long-lived process is collected.
            gc.unfreeze()
            gc.collect()
            gc.freeze()
            _may_fork()
            work = functools.partial(grade_student, state.manifest, state.rubric)
            state.pool = Pool(work, jobs=_threads(), limits=state.limits)
        return list(judge_sheets(state.pool, tasks))


def _grading_state(shared: dict[str, Any]) -> _Grading:
    """This process's state for the run `shared` belongs to: a new run replaces the last, and
    starts from no derived question."""
    global _grading
    if _grading is None or _grading.run != shared["run"]:
        if _grading is not None and _grading.pool is not None:
            _grading.pool.close()
        forget_problems()  # another class's run may have built these questions from its students
        _grading = _Grading(**shared)
    return _grading


def check_chunk(records: list[tuple[int, bytes]], time_limit: float, version: str) -> list:
    """The result line (a dict) of each (line number, request record) of the chunk, in order:
    `run_batch` with this process's checking pool, whose processes keep every question they
    have derived for the chunks to come (requests are untrusted: nothing of theirs is derived
    outside the killable pool)."""
    global _checking
    _same_version(version)
    with _lock:
        if _checking is None:
            _may_fork()
            _checking = check_pool(_threads())
        numbers = [number for number, _record in records]
        lines = [record for _number, record in records]
        return list(run_batch(lines, time_limit=time_limit, pool=_checking, numbers=numbers))


def error_outcome(key: Any, reason: str) -> Outcome:
    """The Outcome of an item whose chunk could not be judged (its Dask workers kept dying)."""
    return Outcome(key, "error", reason=reason)


def _same_version(version: str) -> None:
    mine = project_version()
    if mine != version:
        raise ClusterError(
            f"a Dask worker runs lagrade {mine}, this run lagrade {version}: install the same "
            f"lagrade on every worker"
        )


def _threads() -> int:
    """The threads of the Dask worker this runs in (1 outside one)."""
    try:
        from distributed import get_worker

        return max(1, int(get_worker().state.nthreads))
    except (ImportError, ValueError, AttributeError):
        return 1


def _may_fork() -> None:
    """Let this process fork the judging pool. Dask starts its workers as daemonic processes,
    which multiprocessing forbids to have children (daemons must not leave orphans); the pool
    upholds that itself: it kills its processes when it closes, and an idle one leaves within
    a second of its parent's death (`lagrade.judge.worker.ORPHAN_CHECK`)."""
    process = multiprocessing.current_process()
    if process.daemon:
        process.daemon = False
