"""Judging on the answer page: previews and graded saves run in killable workers under the rule of
`check --batch` and `grade` (the part's alarm, the kill at its limit + grace, the memory limit,
recycling: `lagrade.judge.live.LivePool`), and a graded save killed in one part loses only that
part (`lagrade.grading.resume`).

One student cannot hold another's preview: each student has at most one item in the workers at
a time (a lane per student, served in arrival order), and while it runs, a newer preview of the
same field replaces the older one that waits (answered `superseded`; the page shows only the
newest anyway). A student's backlog is thus one running item plus one waiting preview per field
and the save in progress. Slow items from k students hold k workers; while every worker is held
by a slow item, up to `burst` extra workers serve the others, and a slow item's worker yields
the processors to quick ones."""

from __future__ import annotations

import asyncio
import functools
import logging
from collections import deque
from collections.abc import Hashable, Mapping
from dataclasses import dataclass, field
from typing import Any

import lagrade.grading.resume as resume
from lagrade.grading.answer_page import preview as preview_module
from lagrade.grading.rubric import Rubric
from lagrade.grading.student import grade_student, warm_up
from lagrade.judge import Limits, LivePool, Outcome

#: Seconds an item has before its first part sets its own deadline (reading a saved sheet).
ITEM_SECONDS = 20.0
SUPERSEDED = {"status": "superseded", "lines": [], "message": "", "warnings": []}
_UNREADABLE = "This answer could not be read (the reader failed on it)."
_log = logging.getLogger("uvicorn.error")


def _work(manifest: Mapping[str, Any], rubric: Rubric, item: tuple) -> Any:
    """A worker's item: ("preview", entry, part, text) or ("grade", task)."""
    if item[0] == "preview":
        return preview_module.preview(*item[1:])
    return grade_student(manifest, rubric, item[1])


@dataclass(eq=False)
class _Ticket:
    field: Hashable | None  # a preview's (problem, key); None for a save, never replaced
    item: tuple
    done: asyncio.Future  # its Outcome, or None once a newer preview replaced it


@dataclass
class _Lane:
    waiting: deque[_Ticket] = field(default_factory=deque)
    running: asyncio.Task | None = None


class Judging:
    """The page's workers (`jobs`, and `burst` more while all are held by slow items) and the
    lanes that give each student one item in them at a time."""

    def __init__(
        self, manifest: Mapping[str, Any], rubric: Rubric, jobs: int, burst: int | None = None
    ) -> None:
        self.pool = LivePool(
            functools.partial(_work, manifest, rubric),
            jobs=jobs,
            burst=max(2, jobs) if burst is None else burst,
            limits=Limits(seconds=ITEM_SECONDS),
            warm=functools.partial(warm_up, manifest),
        )
        self._lanes: dict[str, _Lane] = {}

    def start(self) -> None:
        """Fork the workers' host now: before the server listens, and while it has no threads
        (the host derives the class's questions, so that every worker it forks has them)."""
        self.pool.start()

    def close(self) -> None:
        self.pool.close()

    async def preview(
        self, student_id: str, field: Hashable, entry: dict, part: dict, text: str
    ) -> dict[str, Any]:
        """How `text` is read (`preview.preview`'s reply), `timeout` when the worker had to be
        stopped, or `superseded` when a newer preview of the same field came first."""
        outcome = await self._judge(student_id, field, ("preview", entry, part, text))
        if outcome is None:
            return dict(SUPERSEDED)
        if outcome.status == "ok":
            return outcome.value
        if outcome.status == "timeout":
            return preview_module.timed_out()
        _log.warning("lagrade: a preview failed: %s", _first_line(outcome.reason))
        return {"status": "unreadable", "lines": [], "message": _UNREADABLE, "warnings": []}

    async def grade(self, student_id: str, task: dict[str, Any]) -> dict[str, Any]:
        """The result of `grade_student` for a saved sheet; a worker killed in a part costs that
        part only (the rest is judged again by a fresh worker)."""
        while True:
            outcome = await self._judge(student_id, None, ("grade", task))
            assert outcome is not None  # a save is never replaced
            again = resume.resumed(task, outcome)
            if again is None:
                break
            task = again
        if outcome.status == "ok":
            return outcome.value
        if outcome.status == "timeout":
            return {"status": "timeout", "reason": f"grading {outcome.reason}", "problems": []}
        _log.warning("lagrade: grading a save failed: %s", _first_line(outcome.reason))
        return {"status": "error", "reason": "the grader failed on this sheet", "problems": []}

    # --- one lane per student -------------------------------------------------------------
    async def _judge(self, student_id: str, field: Hashable | None, item: tuple) -> Outcome | None:
        lane = self._lanes.setdefault(student_id, _Lane())
        if field is not None:
            for older in [t for t in lane.waiting if t.field == field]:
                lane.waiting.remove(older)
                older.done.set_result(None)
        ticket = _Ticket(field, item, asyncio.get_running_loop().create_future())
        lane.waiting.append(ticket)
        self._next(student_id)
        try:
            return await ticket.done
        finally:
            if ticket in lane.waiting:  # the request went away while it waited
                lane.waiting.remove(ticket)

    def _next(self, student_id: str) -> None:
        """Start the student's next waiting item if none of theirs is in the workers."""
        lane = self._lanes[student_id]
        if lane.running is not None:
            return
        while lane.waiting:
            ticket = lane.waiting.popleft()
            if ticket.done.done():
                continue
            lane.running = asyncio.ensure_future(self.pool.outcome(student_id, ticket.item))
            lane.running.add_done_callback(functools.partial(self._finished, student_id, ticket))
            return
        del self._lanes[student_id]  # nothing of theirs left: forget the lane

    def _finished(self, student_id: str, ticket: _Ticket, task: asyncio.Task) -> None:
        self._lanes[student_id].running = None
        if not ticket.done.done():
            if task.cancelled():
                ticket.done.cancel()
            elif task.exception() is not None:
                ticket.done.set_exception(task.exception())
            else:
                ticket.done.set_result(task.result())
        self._next(student_id)


def _first_line(text: str) -> str:
    return (text.strip().splitlines() or [""])[0][:300]
