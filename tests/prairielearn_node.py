"""PrairieLearn's Node side, modelled, driving PrairieLearn's real Python worker (`Node.real`)
or, where PrairieLearn is not installed, a stand-in that runs server.py in this process
(`Node.local`, for the contract test).

PrairieLearn runs a question's Python in `zygote.py` (a process that forks one worker per
request): for every phase but `generate` its Node side renders question.html's mustache, sends
the HTML and the phase's `data` dictionary to the worker, which runs the elements
(`question_phases.py`), then calls the question's server.py in the same worker. This module
plays that Node side, written from PrairieLearn's `freeform.ts`, `question-testing.ts` and
`code-caller-native.ts`: the data dictionaries each phase builds, the checks on what a phase may
change, the weighted score, the question test's comparison, the worker protocol (JSON lines on
stdin, answers on fd 3, exits confirmed on fd 4, a restart after each request, a course issue for
anything printed, a 10 s limit per call: `tests.prairielearn_workers`). Mustache is
PrairieLearn's own `mustache` (Node) when it can be found, else `chevron`.

Nothing of PrairieLearn is kept in this repository (it is AGPL): point `LAGRADE_PRAIRIELEARN` at
a checkout (its `apps/prairielearn/python/zygote.py` and `apps/prairielearn/elements/`), and
`LAGRADE_PRAIRIELEARN_PYTHON` at a Python with PrairieLearn's dependencies (its
`pyproject.toml`; default: the checkout's `.venv/bin/python`). `LAGRADE_MUSTACHE_JS` may name
the `mustache` package's folder (default: the checkout's `node_modules/mustache`).
"""

from __future__ import annotations

import copy
import json
import os
import shutil
import sys
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

from tests.prairielearn_workers import (
    Call,
    Chevron,
    CourseIssue,
    InProcess,
    Mustache,
    Zygote,
    core_elements,
)

ALL_PHASES = ("generate", "prepare", "render", "parse", "grade", "test", "file")
#: What each phase may find and change in `data` (freeform.ts, `checkData`): present, editable.
PROPS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "params": (ALL_PHASES, ("generate", "prepare", "parse", "grade")),
    "correct_answers": (ALL_PHASES, ("generate", "prepare", "parse", "grade")),
    "variant_seed": (ALL_PHASES, ()),
    "options": (ALL_PHASES, ()),
    "preferences": (ALL_PHASES, ()),
    "submitted_answers": (("render", "parse", "grade", "file"), ("parse", "grade")),
    "format_errors": (("render", "parse", "grade", "test", "file"), ("parse", "grade", "test")),
    "raw_submitted_answers": (("render", "parse", "grade", "test", "file"), ("test",)),
    "partial_scores": (("render", "grade", "test", "file"), ("grade", "test")),
    "score": (("render", "grade", "test", "file"), ("grade", "test")),
    "feedback": (("render", "parse", "grade", "test", "file"), ("grade", "parse", "test")),
    "editable": (("render",), ()),
    "manual_grading": (("render",), ()),
    "ai_grading": (("render",), ()),
    "panel": (("render",), ()),
    "correct_answer_shown": (("render",), ()),
    "num_valid_submissions": (("render", "file"), ()),
    "gradable": (("parse", "grade", "test"), ()),
    "filename": (("file",), ()),
    "test_type": (("test",), ()),
    "answers_names": (("prepare",), ("prepare",)),
}


def checkout() -> Path | None:
    """The PrairieLearn checkout named by LAGRADE_PRAIRIELEARN, if it has the worker."""
    root = os.environ.get("LAGRADE_PRAIRIELEARN")
    if not root or not (Path(root) / "apps/prairielearn/python/zygote.py").is_file():
        return None
    return Path(root)


def check_data(data: dict, before: dict, phase: str) -> None:
    for prop, (present, editable) in PROPS.items():
        if phase not in present:
            continue
        if prop not in data:
            raise CourseIssue(f'"{prop}" is missing from "data" ({phase})')
        if phase not in editable and data[prop] != before.get(prop):
            raise CourseIssue(f"data.{prop} has been illegally modified ({phase})")
    extra = [k for k in data if k not in PROPS or phase not in PROPS[k][0]]
    if extra:
        raise CourseIssue(f'"data" has invalid extra keys: {", ".join(extra)} ({phase})')


class Question:
    """One question of a course, taken through PrairieLearn's phases as freeform.ts does."""

    def __init__(self, node: Node, directory: str) -> None:
        self.node, self.directory = node, directory
        self.template = (node.course / "questions" / directory / "question.html").read_text(
            encoding="utf-8"
        )
        self.issues: list[str] = []
        self.variant: dict[str, Any] = {}

    def options(self) -> dict[str, Any]:
        course = self.node.course
        return {
            "question_path": str(course / "questions" / self.directory),
            "client_files_question_path": str(course / "questions" / self.directory / "cf"),
            "client_files_course_path": str(course / "clientFilesCourse"),
            "server_files_course_path": str(course / "serverFilesCourse"),
            "course_extensions_path": str(course / "elementExtensions"),
            "user": {"uid": "student@example.com", "name": "A Student", "uin": "1", "user_id": "1"},
            "group": None,
        }

    def _phase(self, phase: str, data: dict) -> tuple[dict, str]:
        """processQuestion: the elements (after mustache), then server.py; one request."""
        zygote = self.node.worker
        try:
            html = ""
            if phase != "generate":
                check_data(data, data, phase)
                html = self.node.mustache.render(self.template, data)
                context = {
                    "html": html,
                    "elements": self.node.elements,
                    "element_extensions": {},
                    "course_path": str(self.node.course),
                }
                call = zygote.call(self.directory, "question.html", phase, [context, data])
                self._printed(call, phase)
                data, html = call.value["data"], call.value["html"] or ""
                if phase in ("grade", "test"):
                    scores = [v for v in data["partial_scores"].values() if isinstance(v, dict)]
                    weights = sum(float(v.get("weight", 1)) for v in scores)
                    total = sum(
                        float(v.get("weight", 1)) * float(v.get("score", 0)) for v in scores
                    )
                    data["score"] = total / (weights or 1)
            before = copy.deepcopy(data)
            args = [data, html] if phase == "render" else [data]
            call = zygote.call(self.directory, "server", phase, args)
            self._printed(call, phase)
            if call.value is not None:
                if phase == "render":
                    html = call.value
                else:
                    data = call.value
            check_data(data, before, phase)
        finally:
            zygote.restart()
        return data, html

    def _printed(self, call: Call, phase: str) -> None:
        if call.output:
            self.issues.append(f"output logged on console during {phase}(): {call.output[:300]}")

    def generate(self, variant_seed: int) -> None:
        data = {
            "params": {},
            "correct_answers": {},
            "variant_seed": variant_seed,
            "options": self.options(),
            "preferences": {},
        }
        data, _ = self._phase("generate", data)
        self.variant = {"seed": variant_seed, "params": data["params"]}
        self.variant["true_answer"] = data["correct_answers"]
        prepared = {
            "params": self.variant["params"],
            "correct_answers": self.variant["true_answer"],
            "variant_seed": variant_seed,
            "options": self.options(),
            "preferences": {},
            "answers_names": {},
        }
        data, _ = self._phase("prepare", prepared)
        self.variant.update(params=data["params"], true_answer=data["correct_answers"])

    def submit(self, raw: dict[str, Any], grade: bool = True) -> dict[str, Any]:
        """saveSubmission (parse) and, when gradable, gradeVariant (grade)."""
        submission: dict[str, Any] = {"raw_submitted_answer": raw, "submitted_answer": dict(raw)}
        data = {
            "params": self.variant["params"],
            "correct_answers": self.variant["true_answer"],
            "submitted_answers": dict(raw),
            "feedback": {},
            "format_errors": {},
            "variant_seed": self.variant["seed"],
            "options": self.options(),
            "preferences": {},
            "raw_submitted_answers": dict(raw),
            "gradable": True,
        }
        data, _ = self._phase("parse", data)
        gradable = bool(data["gradable"]) and not data["format_errors"]
        submission.update(
            params=data["params"],
            true_answer=data["correct_answers"],
            submitted_answer=data["submitted_answers"],
            feedback=data["feedback"],
            format_errors=data["format_errors"],
            gradable=gradable,
            partial_scores=None,
            score=None,
        )
        if not (grade and gradable):
            return submission
        data = {
            "params": submission["params"],
            "correct_answers": submission["true_answer"],
            "submitted_answers": submission["submitted_answer"],
            "format_errors": submission["format_errors"],
            "partial_scores": {},
            "score": 0,
            "feedback": submission["feedback"],
            "variant_seed": self.variant["seed"],
            "options": self.options(),
            "preferences": {},
            "raw_submitted_answers": raw,
            "gradable": True,
        }
        data, _ = self._phase("grade", data)
        submission.update(
            format_errors=data["format_errors"],
            partial_scores=data["partial_scores"],
            score=data["score"],
            feedback=data["feedback"],
            gradable=not data["format_errors"],
            params=data["params"],
            true_answer=data["correct_answers"],
        )
        return submission

    def render(self, panel: str, submission: dict[str, Any] | None = None) -> str:
        """renderPanel: one panel's HTML for the variant and (optionally) a submission."""
        sub = submission or {}
        options = {
            **self.options(),
            "client_files_question_url": "/cfq",
            "client_files_course_url": "/cfc",
            "client_files_question_dynamic_url": "/gfq",
            "course_element_files_url": "/elements",
            "course_element_extension_files_url": "/extensions",
            "submission_files_url": None,
            "variant_id": "1",
            "external_image_capture_url": None,
            "base_url": "/pl",
            "workspace_url": None,
        }
        data = {
            "params": sub.get("params") or self.variant["params"],
            "correct_answers": sub.get("true_answer") or self.variant["true_answer"],
            "submitted_answers": sub.get("submitted_answer") or {},
            "format_errors": sub.get("format_errors") or {},
            "partial_scores": sub.get("partial_scores") or {},
            "score": sub.get("score") or 0,
            "feedback": sub.get("feedback") or {},
            "variant_seed": self.variant["seed"],
            "preferences": {},
            "raw_submitted_answers": sub.get("raw_submitted_answer") or {},
            "num_valid_submissions": 1 if submission else 0,
            "options": options,
            "editable": panel == "question",
            "manual_grading": False,
            "ai_grading": False,
            "panel": panel,
            "correct_answer_shown": panel == "answer",
        }
        _, html = self._phase("render", data)
        return html

    def test_phase(self, test_type: str) -> dict[str, Any]:
        """The test phase: the submission of `test_type` and what it must get."""
        data = {
            "params": self.variant["params"],
            "correct_answers": self.variant["true_answer"],
            "format_errors": {},
            "partial_scores": {},
            "score": 0,
            "feedback": {},
            "variant_seed": self.variant["seed"],
            "options": self.options(),
            "preferences": {},
            "raw_submitted_answers": {},
            "gradable": True,
            "test_type": test_type,
        }
        expected, _ = self._phase("test", data)
        expected["gradable"] = bool(expected["gradable"]) and not expected["format_errors"]
        return expected

    def question_test(self, test_type: str) -> list[str]:
        """question-testing.ts: test() makes a submission and its expected results, the
        submission goes through parse and grade, and the results are compared."""
        expected = self.test_phase(test_type)
        got = self.submit(expected["raw_submitted_answers"])
        problems = []
        if expected["gradable"] != got["gradable"]:
            problems.append(f"gradable: expected {expected['gradable']}, got {got['gradable']}")
        if sorted(expected["format_errors"]) != sorted(got["format_errors"] or {}):
            problems.append(
                f"format_errors keys: expected {sorted(expected['format_errors'])}, "
                f"got {sorted(got['format_errors'] or {})}"
            )
        if expected["gradable"] and got["gradable"]:
            want, have = expected["partial_scores"], got["partial_scores"]
            for key in sorted(set(want) | set(have)):
                if want.get(key) != have.get(key):
                    problems.append(
                        f"partial_scores[{key}]: expected {want.get(key)}, got {have.get(key)}"
                    )
            if expected["score"] != got["score"]:
                problems.append(f"score: expected {expected['score']}, got {got['score']}")
        return problems


class Text(HTMLParser):
    """A page's text as a reader sees it (entities decoded, spaces collapsed), and its popovers'
    contents (Bootstrap shows them as HTML)."""

    def __init__(self, page: str) -> None:
        super().__init__(convert_charrefs=True)
        self.chunks: list[str] = []
        self.popovers: list[str] = []
        self.feed(page)
        self.text = " ".join(" ".join(self.chunks).split())

    def handle_data(self, data: str) -> None:
        self.chunks.append(data)

    def handle_starttag(self, tag: str, attrs: list) -> None:
        content = dict(attrs).get("data-bs-content")
        if content:
            self.popovers.append(content)


def shown(text: str, page: str) -> bool:
    """Whether `text` is on the page as a reader sees it."""
    return " ".join(text.split()) in Text(page).text


class Node:
    """The Node side for one course folder: a worker (PrairieLearn's zygote, or `InProcess`),
    mustache and the core elements."""

    def __init__(self, course: Path, worker: Any, mustache: Any, elements: dict) -> None:
        self.course, self.worker, self.mustache, self.elements = course, worker, mustache, elements

    @classmethod
    def real(cls, pl: Path, course: Path, python: str | None = None) -> Node:
        """PrairieLearn's own worker and elements, from the checkout `pl`."""
        python = (
            python or os.environ.get("LAGRADE_PRAIRIELEARN_PYTHON") or str(pl / ".venv/bin/python")
        )
        if not Path(python).exists() and not shutil.which(python):
            python = "python3"
        node = cls(course, Zygote(pl, python, course), Mustache(pl, python), core_elements(pl))
        node.python = python
        return node

    @classmethod
    def local(cls, course: Path) -> Node:
        """This Python, server.py loaded in-process, and the documented behaviour of the few
        elements lagrade's questions use (`InProcess`) in place of PrairieLearn's."""
        return cls(course, InProcess(course), Chevron(), {})

    def question(self, directory: str) -> Question:
        return Question(self, directory)

    def close(self) -> None:
        self.worker.close()
        self.mustache.close()


if __name__ == "__main__":  # a smoke test: python -m tests.prairielearn_node COURSE QUESTION
    pl = checkout()
    if pl is None:
        sys.exit("set LAGRADE_PRAIRIELEARN to a PrairieLearn checkout")
    node = Node.real(pl, Path(sys.argv[1]))
    q = node.question(sys.argv[2])
    q.generate(1)
    print(json.dumps(q.variant["true_answer"], indent=1))
    for kind in ("correct", "incorrect", "invalid"):
        print(kind, q.question_test(kind) or "ok")
    node.close()
