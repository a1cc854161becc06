"""One question taken through PrairieLearn's phases by `tests.prairielearn_node`, probing what
issue 28 found broken: the question test (correct, incorrect, invalid), HTML in every answer (no
tag of it may reach the rendered page or a popover), a readable first line and an unreadable
second in every multi-line part (format errors: not graded), a wrong answer in every part (each
feedback sentence in the rendered submission panel), each prompt once, in the question panel.
Shared by the real-worker test and `benchmarks/bench_prairielearn.py`."""

from __future__ import annotations

import json
import time
from html.parser import HTMLParser
from pathlib import Path

from lagrade.assign.assignment import PARTS
from lagrade.bank.registry import get_scene
from lagrade.mechanics.scene import LAGRANGIAN_PARTS
from tests.prairielearn_node import Question, Text, shown

ALL_PARTS = PARTS
HOSTILE = "<img src=x onerror=\"document.title='PWNED'\">"
UNREADABLE_LINE = "1/2 m (q_dot"


def assignment_text(scenes: list[str]) -> str:
    """Every scene once, asked every part it can be asked and each of its quantities."""
    lines = ['title = "Every scene through PrairieLearn"']
    for scene_id in scenes:
        scene = get_scene(scene_id)
        parts = [p for p in ALL_PARTS if not scene.given_by_lagrangian or p in LAGRANGIAN_PARTS]
        if not scene.default.conserved_quantities:
            parts.remove("conserved")
        asked = [json.dumps(p) for p in parts]
        asked += [f"{{ quantity = {json.dumps(q.name)} }}" for q in scene.quantities]
        lines += ["", "[[problems]]", f"scene = {json.dumps(scene_id)}", "variants = 4"]
        lines.append(f"parts = [{', '.join(asked)}]")
    return "\n".join(lines) + "\n"


class Tags(HTMLParser):
    """Every start tag of a page, and every popover's content (Bootstrap renders it as HTML)."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict]] = []
        self.popovers: list[str] = []

    def handle_starttag(self, tag, attrs) -> None:
        attributes = dict(attrs)
        self.tags.append((tag, attributes))
        if attributes.get("data-bs-content"):
            self.popovers.append(attributes["data-bs-content"])


def injected(page: str) -> list[str]:
    """Tags or event handlers a hostile answer put into the page or into a popover."""
    found = []
    pages = [page]
    while pages:
        parser = Tags()
        parser.feed(pages.pop())
        for tag, attributes in parser.tags:
            if tag == "img" or any(name.startswith("on") for name in attributes):
                found.append(f"<{tag} {attributes}>")
        pages += parser.popovers
    return found


def probe(question: Question, figures: dict, out: Path | None = None) -> list[str]:
    """One question through every phase; the faults found (figures counted in `figures`, the
    rendered panels written into `out` when given)."""
    faults = []
    question.generate(variant_seed=int(time.time() * 1000) % 100_000)
    correct = question.variant["true_answer"]
    keys = list(correct)
    faults += [f"correct answer of {k} is empty" for k in keys if not str(correct[k]).strip()]
    rendered = {"question": question.render("question"), "answer": question.render("answer")}
    for test_type in ("correct", "incorrect", "invalid"):
        problems = question.question_test(test_type)
        figures["tests"][test_type]["passed" if not problems else "failed"] += 1
        faults += [f"question test {test_type}: {p}" for p in problems]

    hostile = question.submit({k: HOSTILE for k in keys})
    rendered["hostile"] = question.render("submission", hostile)
    figures["hostile_format_errors"] += len(hostile["format_errors"])
    figures["hostile_parts"] += len(keys)
    faults += [f"hostile HTML reached the page: {t}" for t in injected(rendered["hostile"])]

    several = [k for k in keys if _multiline(question, k)]
    if several:
        partly = {k: correct[k] for k in keys}
        partly.update({k: correct[k].split("\n")[0] + "\n" + UNREADABLE_LINE for k in several})
        result = question.submit(partly)
        refused = set(several) & set(result["format_errors"])
        figures["partly_unreadable"]["parts"] += len(several)
        figures["partly_unreadable"]["format_errors"] += len(refused)
        if result["gradable"] or refused != set(several):
            faults.append(f"a partly unreadable answer was graded: {result['partial_scores']}")
        rendered["partly"] = question.render("submission", result)

    graded = question.submit(question.test_phase("incorrect")["raw_submitted_answers"])
    rendered["wrong"] = question.render("submission", graded)
    notes = [
        note["text"]
        for part in (graded["feedback"] or {}).get("lagrade", {}).values()
        for note in part["notes"]
    ]
    missing = [n for n in notes if not shown(n, rendered["wrong"])]
    figures["feedback"]["sentences"] += len(notes)
    figures["feedback"]["shown"] += len(notes) - len(missing)
    faults += [f"feedback not shown: {n[:80]}" for n in missing]

    for key, prompt in question.variant["params"]["prompts"].items():
        words = Text(prompt).text[:50]
        counts = {panel: Text(page).text.count(words) for panel, page in rendered.items()}
        if counts.pop("question") != 1 or any(counts.values()):
            faults.append(f"the prompt of {key} is shown {counts} times outside the question")
    if out is not None:
        for name, page in rendered.items():
            (out / f"{question.directory}-{name}.html").write_text(_page(page), encoding="utf-8")
    return faults


def _multiline(question: Question, key: str) -> bool:
    """Whether question.html asks `key` in a multi-line field."""
    return any(
        f'answers-name="{key}"' in line and 'multiline="true"' in line
        for line in question.template.splitlines()
    )


def _page(body: str) -> str:
    return f'<!doctype html><html><head><meta charset="utf-8"></head><body>{body}</body></html>'


def new_figures() -> dict:
    """The counts `probe` adds to."""
    return {
        "tests": {t: {"passed": 0, "failed": 0} for t in ("correct", "incorrect", "invalid")},
        "hostile_parts": 0,
        "hostile_format_errors": 0,
        "partly_unreadable": {"parts": 0, "format_errors": 0},
        "feedback": {"sentences": 0, "shown": 0},
    }
