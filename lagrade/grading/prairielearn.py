"""PrairieLearn questions from an assignment: `lagrade export prairielearn`.

The output is laid out like a PrairieLearn course, to be merged into one (or written straight
into its repository):
- `questions/<folder>/` per problem, in PrairieLearn's v3 format: `info.json` (uuid, title,
  topic, tags, type "v3"), `question.html` and `server.py`;
- `serverFilesCourse/lagrade-<version>-<digest>/`: the lagrade that exported, unpacked from its
  wheel (`lagrade.grading.wheel.vendor`). Hosted PrairieLearn installs no packages, but it puts
  the course's `serverFilesCourse/` on sys.path; server.py adds this folder, so the questions
  run the very lagrade that exported them. Its dependencies (sympy, numpy, scipy, jinja2) are
  in PrairieLearn's Python image.

question.html: the statement, each part's prompt inside `pl-question-panel` (shown once, in
the question panel), one `pl-string-input` per part, and after it, inside
`pl-submission-panel`, the part's verdict, reading and feedback from `data["feedback"]`
(PrairieLearn's documented way for feedback from server.py), through mustache's escaping
`{{ }}`. server.py holds data only (the problem's title, the assignment text, the scene files
it names, its index and pool of variant seeds, the vendored folder's name), each a Python
literal, and calls `lagrade.grading.prairielearn_runtime`.
"""

from __future__ import annotations

import json
import re
import uuid
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
import lagrade.untrusted as untrusted
from lagrade.assign import (
    MULTILINE,
    AssignedProblem,
    Assignment,
    Part,
    VariantChoice,
    build_pool,
    load_assignment,
)
from lagrade.errors import AssignmentError

# Questions exported before the runtime had a module of its own call these names here.
from lagrade.grading.prairielearn_runtime import generate, grade, parse, render_pool, test
from lagrade.grading.wheel import vendor

#: Each question's variants rendered at export (statement, prompts, key), beside server.py.
VARIANTS = "variants.json"
#: Variants in a problem's pool when the assignment does not say (`variants = N`).
DEFAULT_POOL = 50
#: Where the question folders go, and the vendored lagrade, in a course's layout.
QUESTIONS = "questions"
SERVER_FILES = "serverFilesCourse"
_NAMESPACE = uuid.UUID("6f1c2a4e-3d0b-5b7e-9a61-1a2b3c4d5e6f")
_KEY = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")  # a part's key in mustache names and attributes


def export_prairielearn(
    assignment_file: Path,
    seed: int,
    out: Path,
    scenes_dir: Path | None = None,
    scene_texts: Mapping[str, str] | None = None,
) -> list[Path]:
    """Write one question folder per problem of the assignment into `out/questions/`, and the
    lagrade they run into `out/serverFilesCourse/`; returns the question folders. Its scene
    files are found as `generate` finds them, or given by `scene_texts` (a manifest's)."""
    assignment_file = Path(assignment_file)
    assignment = load_assignment(assignment_file, scenes_dir, scene_texts)
    text = untrusted.decode(assignment_file.read_bytes(), str(assignment_file))
    scenes = {p.scene_ref: p.scene.source for p in assignment.problems}
    pools = {}
    for problem in assignment.problems:
        pools[problem.index] = build_pool(problem, seed, problem.variants or DEFAULT_POOL)
        if not pools[problem.index]:
            raise AssignmentError(f"problem {problem.index}: the bank offers no variant")
        for part in problem.parts:
            if not _KEY.match(part.key):
                raise AssignmentError(f"problem {problem.index}: {part.key!r} cannot name a field")
    vendored = vendor(Path(out) / SERVER_FILES)
    folders = []
    for problem in assignment.problems:
        folder = Path(out) / QUESTIONS / _folder_name(assignment, problem)
        atomic.write_json(folder / "info.json", _info(assignment, problem))
        atomic.write_text(folder / "question.html", _question_html(problem))
        server = _server_py(text, scenes, problem, pools[problem.index], vendored)
        seeds = [int(c.seed) for c in pools[problem.index]]
        atomic.write_json(folder / VARIANTS, render_pool(text, problem.index, seeds, scenes))
        atomic.write_text(folder / "server.py", server)
        folders.append(folder)
    return folders


def vendored_folder(out: Path) -> Path:
    """The vendored lagrade an export into `out` wrote (the one server.py names)."""
    (found,) = sorted(p for p in (Path(out) / SERVER_FILES).glob("lagrade-*") if p.is_dir())
    return found


def _folder_name(assignment: Assignment, problem: AssignedProblem) -> str:
    slug = re.sub(r"[^a-z0-9]+", "-", assignment.title.lower()).strip("-")[:40] or "lagrade"
    return f"{slug}-p{problem.index}-{problem.scene.id}"


def _info(assignment: Assignment, problem: AssignedProblem) -> dict[str, Any]:
    """info.json: the uuid is derived from the assignment's title and the problem, so that a
    re-export updates the same PrairieLearn question instead of making a new one."""
    name = f"{assignment.title}\x1f{problem.index}\x1f{problem.scene.id}"
    return {
        "uuid": str(uuid.uuid5(_NAMESPACE, name)),
        "type": "v3",
        "title": f"{problem.title or problem.scene.title}",
        "topic": "Lagrangian mechanics",
        "tags": ["lagrade", problem.scene.id],
    }


def _question_html(problem: AssignedProblem) -> str:
    """PrairieLearn's mustache, not jinja: the statement and prompts come rendered (escaped) in
    `params` from `generate` (`{{{ }}}`); everything from a submission is plain text in
    `feedback`, escaped by mustache (`{{ }}`)."""
    fields = "\n\n".join(_part_html(part) for part in problem.parts)
    return (
        "<pl-question-panel>\n{{{params.statement_html}}}\n</pl-question-panel>\n\n"
        f"{fields}\n"
    )


def _part_html(part: Part) -> str:
    """One part: its prompt (question panel only), its input, and (submission panel only) how
    it was read, the parser's message when it could not be, its verdict and feedback."""
    key = part.key
    several = part.part in MULTILINE
    input_attributes = (
        f'answers-name="{key}" label="{key}:" size="70" display="block" allow-blank="true" '
        'show-help-text="false"'
        + (' multiline="true" placeholder="one per line, or separated by ;"' if several else "")
    )
    return (
        f"<pl-question-panel>\n<p>{{{{{{params.prompts.{key}}}}}}}</p>\n</pl-question-panel>\n"
        f"<pl-string-input {input_attributes}></pl-string-input>\n"
        "<pl-submission-panel>\n"
        f"{{{{#feedback.lagrade.{key}}}}}\n"
        '<div class="lagrade-feedback mb-3">\n'
        '{{#outcome}}<p class="mb-1"><strong>{{outcome}}</strong></p>{{/outcome}}\n'
        '{{#read}}<p class="mb-1">Read as: <code>{{read}}</code></p>{{/read}}\n'
        '{{#error}}<p class="mb-1">Could not be read (no attempt used):</p>'
        "<pre>{{error}}</pre>{{/error}}\n"
        "{{#notes}}{{#pre}}<pre>{{text}}</pre>{{/pre}}"
        '{{^pre}}<p class="mb-1">{{text}}</p>{{/pre}}{{/notes}}\n'
        "</div>\n"
        f"{{{{/feedback.lagrade.{key}}}}}\n"
        "</pl-submission-panel>"
    )


#: server.py: fixed code, with every value in it written as a Python literal by `repr` (the
#: title too, as data: an instructor's `"""` or `\N{` in a docstring would be code or a
#: SyntaxError on PrairieLearn's server). No text of the assignment is spliced in otherwise.
_SERVER = '''"""PrairieLearn server for one lagrade problem (its title is TITLE below), written by
`lagrade export prairielearn`. It runs the lagrade in serverFilesCourse/VENDORED (copied there
with this question), or an installed one where that folder is absent."""

import json
import os
import sys

TITLE = {title}
ASSIGNMENT = {assignment}
SCENES = {scenes}
PROBLEM = {index}
SEEDS = {seeds}
VENDORED = {vendored}
#: The pool's variants rendered at export (data: statement, prompts, key), beside this file.
VARIANTS = {variants}


def _use_vendored_lagrade():
    # PrairieLearn puts the course's serverFilesCourse/ on sys.path for server.py
    for entry in list(sys.path):
        folder = os.path.join(entry, VENDORED)
        if os.path.isfile(os.path.join(folder, "lagrade", "__init__.py")):
            if folder not in sys.path:
                sys.path.insert(0, folder)
            return


_use_vendored_lagrade()

from lagrade.grading import prairielearn_runtime as lagrade_pl  # noqa: E402


def _rendered():
    try:
        with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), VARIANTS)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None  # rendered here instead


def generate(data):
    lagrade_pl.generate(data, ASSIGNMENT, PROBLEM, SEEDS, SCENES, _rendered())


def parse(data):
    lagrade_pl.parse(data, ASSIGNMENT, PROBLEM, SCENES)


def grade(data):
    lagrade_pl.grade(data, ASSIGNMENT, PROBLEM, SCENES)


def test(data):
    lagrade_pl.test(data, ASSIGNMENT, PROBLEM, SCENES)
'''


def _server_py(
    assignment_text: str,
    scenes: Mapping[str, str],
    problem: AssignedProblem,
    pool: tuple[VariantChoice, ...],
    vendored: str,
) -> str:
    """server.py for `problem`: each value a Python literal (`repr` of a str, int, a dict of
    str or a list of ints), checked to compile before it is written, so an export never ships a
    file that PrairieLearn cannot load."""
    values = {
        "title": str(problem.title or problem.scene.title),
        "assignment": str(assignment_text),
        "scenes": {str(ref): str(text) for ref, text in scenes.items()},
        "index": int(problem.index),
        "seeds": [int(c.seed) for c in pool],
        "vendored": str(vendored),
        "variants": VARIANTS,
    }
    source = _SERVER.format(**{name: repr(value) for name, value in values.items()})
    compile(source, "server.py", "exec")  # a SyntaxError here is our bug, never shipped
    return source


def info_json(folder: Path) -> dict[str, Any]:
    """A question folder's info.json (for tests and for `lagrade export` to report)."""
    return json.loads((Path(folder) / "info.json").read_text(encoding="utf-8"))


__all__ = ["export_prairielearn", "generate", "grade", "info_json", "parse", "test"]
