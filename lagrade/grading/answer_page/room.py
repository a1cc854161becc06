"""What the answer page's server knows (`ClassRoom`): the manifest, where sheets go, who each
token is, the due date, the log of saves and the workers; and the views of each student's
problems. The web application (`app`) and a save (`saving`) both work on it.

Drawing a view (a figure by matplotlib, the derived solution by sympy) takes a fraction of a
second per variant and must not run two at a time; it runs in a thread of its own (`drawer`),
never in the event loop's default executor, which saves use for the log and the sheet: a class
opening its pages together queues behind the drawing, a save does not. The server draws every
student's views in that thread as soon as it starts (`draw_all`), one student at a time, so a
page asked for meanwhile waits for at most one student's drawing before its own."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lagrade.assign import MULTILINE, Assignment, VariantChoice, load_assignment, problem_view
from lagrade.grading.answer_page.due import DueRule, due_rule
from lagrade.grading.answer_page.judging import Judging
from lagrade.grading.answer_page.settings import PageSettings, load_settings
from lagrade.grading.answer_page.tokens import token_table
from lagrade.grading.manifest import carried_scene_texts
from lagrade.grading.prompts import prompt_html
from lagrade.grading.rubric import Rubric, load_rubric
from lagrade.grading.savelog import SaveLog, log_path


@dataclass
class ClassRoom:
    """Everything the server knows: the manifest, where sheets go, who each token is."""

    manifest: Mapping[str, Any]
    manifest_dir: Path
    submissions: Path
    tokens: dict[str, str]  # token → student id
    assignment: Assignment
    settings: PageSettings
    rubric: Rubric
    log: SaveLog
    due: DueRule
    jobs: int = 2
    students: dict[str, Mapping[str, Any]] = field(default_factory=dict)
    _judging: Judging | None = None
    _locks: dict[str, asyncio.Lock] = field(default_factory=dict)
    _views: dict[tuple, dict[str, Any]] = field(default_factory=dict)
    _drawing: threading.Lock = field(default_factory=threading.Lock)
    _drawer: ThreadPoolExecutor | None = None

    def __post_init__(self) -> None:
        self.students = {s["id"]: s for s in self.manifest["students"]}

    # --- workers --------------------------------------------------------------------------
    def judging(self) -> Judging:
        """The killable workers that read previews and grade saves (`lagrade serve` starts
        them before it listens; otherwise the first request does)."""
        if self._judging is None:
            self._judging = Judging(self.manifest, self.rubric, self.jobs)
        return self._judging

    def close(self) -> None:
        if self._judging is not None:
            self._judging.close()
            self._judging = None
        if self._drawer is not None:
            self._drawer.shutdown(wait=False, cancel_futures=True)
            self._drawer = None

    def lock(self, student_id: str) -> asyncio.Lock:
        return self._locks.setdefault(student_id, asyncio.Lock())

    # --- one student's problems -----------------------------------------------------------
    def drawer(self) -> ThreadPoolExecutor:
        """The one thread that draws views (see the module docstring)."""
        if self._drawer is None:
            self._drawer = ThreadPoolExecutor(max_workers=1, thread_name_prefix="lagrade-draw")
        return self._drawer

    async def views(self, student_id: str) -> list[dict[str, Any]]:
        """A student's problem views, drawn in the drawing thread when not drawn yet."""
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(self.drawer(), self.problems_of, student_id)

    async def draw_all(self) -> None:
        """Every student's views, one student at a time (the server starts this at once)."""
        for student_id in self.students:
            await self.views(student_id)

    def problems_of(self, student_id: str) -> list[dict[str, Any]]:
        """The views of a student's problems (statement, figure, parameters, parts). Built one
        at a time: the figures are drawn by matplotlib, which is not thread-safe; a view is
        shared by every student with the same variant."""
        with self._drawing:
            views = []
            student = self.students[student_id]
            for problem, entry in zip(self.assignment.problems, student["problems"], strict=True):
                choice = VariantChoice(
                    int(entry["seed"]), entry["names"], entry["options"], entry["values"]
                )
                key = (problem.index, choice.key)
                if key not in self._views:
                    view = problem_view(problem, choice, f"p{problem.index}")
                    for part, asked in zip(view["parts"], problem.parts, strict=True):
                        part["prompt_html"] = prompt_html(part)
                        part["multiline"] = asked.part in MULTILINE
                    self._views[key] = view
                views.append(self._views[key])
            return views


def build_classroom(
    manifest: Mapping[str, Any],
    manifest_path: Path,
    submissions: Path,
    secret: bytes,
    jobs: int = 2,
) -> ClassRoom:
    """The ClassRoom of a loaded manifest; the assignment file is the one `generate` copied
    beside the manifest, its scenes the ones the manifest carries."""
    manifest_dir = Path(manifest_path).parent
    assignment_file = manifest_dir / manifest["assignment"]["file"]
    ids = [s["id"] for s in manifest["students"]]
    assignment = load_assignment(assignment_file, scene_texts=carried_scene_texts(manifest))
    settings = load_settings(assignment_file)
    return ClassRoom(
        manifest=manifest,
        manifest_dir=manifest_dir,
        submissions=Path(submissions),
        tokens=token_table(secret, ids),
        assignment=assignment,
        settings=settings,
        rubric=load_rubric(assignment_file),
        log=SaveLog(log_path(submissions)),
        due=due_rule(assignment.due, settings),
        jobs=jobs,
    )
