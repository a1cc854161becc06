"""A save on the answer page, under the student's lock: refused after the due date (or recorded
as late), written as the sheet `grade` reads and appended to the log of saves in one
transaction, and — when the assignment grades saves — graded, at most one attempt per press.

One press, one attempt: the page sends an attempt token with each press (the same token when
it retries a press whose reply never came). A save whose token the log already holds is not
written again: its reply is given again, and no second attempt is spent. A graded save whose
answers are those of the student's last graded save shows that feedback again, spending none.
"""

from __future__ import annotations

import asyncio
import functools
import re
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lagrade.errors import LagradeError
from lagrade.grading.answer_page.due import CLOSED, LATE
from lagrade.grading.answer_page.sheets import save_sheet, sheet_text
from lagrade.grading.instants import from_ns, shown
from lagrade.grading.savelog import Save, canonical_answers, now_ns

if TYPE_CHECKING:
    from lagrade.grading.answer_page.room import ClassRoom

#: Seconds one part may take when a save is graded.
SAVE_PART_TIME_LIMIT = 10.0
#: What an attempt token may be: the page makes 32 hex digits.
_TOKEN = re.compile(r"[A-Za-z0-9_-]{8,64}")


def attempt_token(body: Any) -> str | None:
    """The request's attempt token (None when it sends none); ValueError when malformed."""
    token = body.get("attempt") if isinstance(body, dict) else None
    if token is None:
        return None
    if not isinstance(token, str) or not _TOKEN.fullmatch(token):
        raise ValueError("the attempt token must be 8 to 64 letters, digits, '-' or '_'")
    return token


def due_view(room: ClassRoom) -> dict[str, Any]:
    """What the page shows about the due date now: the state and its sentence."""
    now = from_ns(now_ns())
    return {"state": room.due.state(now), "notice": room.due.notice(now)}


async def save(
    room: ClassRoom, student_id: str, answers: dict[int, dict[str, str]], token: str | None
) -> tuple[int, dict[str, Any]]:
    """(HTTP status, reply) of a save request whose answers were checked already."""
    loop = asyncio.get_running_loop()
    async with room.lock(student_id):
        earlier = None
        if token is not None:
            earlier = await loop.run_in_executor(None, room.log.by_token, student_id, token)
        if earlier is not None:
            saved = earlier
        else:
            saved_ns = now_ns()
            state = room.due.state(from_ns(saved_ns))
            if state == CLOSED:
                return 403, {"status": "closed", "message": room.due.refusal()}
            late = state == LATE
            student = room.students[student_id]
            try:
                # read back with grade's reader before anything is written
                text = sheet_text(room.manifest, student, answers, from_ns(saved_ns), late)
                write = functools.partial(
                    save_sheet,
                    room.log,
                    room.submissions,
                    student_id,
                    text,
                    answers=answers,
                    saved_ns=saved_ns,
                    token=token,
                    late=late,
                )
                saved = await loop.run_in_executor(None, write)
            except LagradeError as error:  # a full disk, a read-only folder
                return 503, {"status": "error", "message": f"Not saved: {error}"}
        reply = _saved(room, saved)
        if room.settings.feedback:
            reply.update(await _graded(room, student_id, saved))
    return 200, reply


def _saved(room: ClassRoom, saved: Save) -> dict[str, Any]:
    reply: dict[str, Any] = {
        "status": "saved",
        "file": saved.file,
        "saved_at": saved.saved_at.astimezone(room.settings.zone).strftime("%H:%M:%S"),
        "saved": shown(saved.saved_at.astimezone(room.settings.zone)),
        "late": saved.late,
    }
    if saved.late:
        reply["note"] = room.due.late_note()
    return reply


async def _graded(room: ClassRoom, student_id: str, saved: Save) -> dict[str, Any]:
    """The feedback of a saved sheet, graded with `lagrade grade`'s own function when an
    attempt remains — or the feedback it was given before (the same press again, or the same
    answers as the last graded save), spending nothing."""
    loop = asyncio.get_running_loop()
    log = room.log
    limit = room.settings.attempts

    def left(used: int) -> int | None:
        return None if limit is None else max(limit - used, 0)

    shown_before = await loop.run_in_executor(None, log.grading_of, saved.id)
    used = await loop.run_in_executor(None, log.attempts_used, student_id)
    if shown_before is not None:
        return {"feedback": shown_before, "attempts_left": left(used)}
    last = await loop.run_in_executor(None, log.last_graded, student_id)
    if last is not None and last[0] == canonical_answers(saved.answers or {}):
        return {
            "feedback": last[1],
            "attempts_left": left(used),
            "repeated": "These answers were graded before: the same feedback, no attempt spent.",
        }
    if limit is not None and used >= limit:
        return {"feedback": None, "attempts_left": 0}
    path = room.submissions / saved.file
    if not await loop.run_in_executor(None, _holds, path, saved.sheet):
        # a press replayed after a newer save replaced its sheet: that sheet is not graded
        return {"feedback": None, "attempts_left": left(used)}
    task = {
        "student": room.students[student_id],
        "path": str(path),
        "part_time_limit": SAVE_PART_TIME_LIMIT,
    }
    result = await room.judging().grade(student_id, task)
    feedback = _feedback(result)
    await loop.run_in_executor(None, log.record_grading, saved.id, feedback)
    return {"feedback": feedback, "attempts_left": left(used + 1)}


def _holds(path: Path, data: bytes) -> bool:
    try:
        return path.read_bytes() == data
    except OSError:
        return False


def _feedback(result: Mapping[str, Any]) -> dict[str, Any]:
    """What the student sees of a graded save: per part, the verdict, points and feedback."""
    if not result.get("problems"):  # invalid, or not graded at all
        return {"reason": result.get("reason", ""), "parts": {}}
    parts = {}
    for problem in result.get("problems", []):
        for part in problem.get("parts", []):
            parts[f"{problem['index']}/{part['key']}"] = {
                "verdict": part["verdict"],
                "points": part["points"],
                "max_points": part["max_points"],
                "feedback": part["feedback"],
            }
    return {"reason": "", "parts": parts}
