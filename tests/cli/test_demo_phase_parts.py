"""`lagrade demo` asks the next lecture's parts (H and Hamilton's equations of the Kepler
problem; the equilibrium, normal modes and mode shapes of two coupled oscillators), and its
grades carry them: every strong student earns them, and each mistake planted in them is
named in that student's result."""

from __future__ import annotations

import json

import pytest

from lagrade.cli.demo_class import run_demo

NEW_PARTS = {
    3: {"hamiltonian", "hamilton_equations"},
    4: {"equilibrium", "normal_modes", "mode_shapes"},
}
#: What `write_submissions` plants in a new part, and the mistake the grader names for it.
NAMED = {
    "H in the velocities": "velocities",
    "omega squared": "squared",
    "the two vectors swapped": "swapped",
}


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    folder = tmp_path_factory.mktemp("demo")
    run_demo(folder, jobs=1)
    return folder


def _verdicts(folder, sid: str) -> dict[tuple[int, str], dict]:
    result = json.loads((folder / "grades" / "students" / f"{sid}.json").read_text())
    return {
        (n + 1, part["key"]): part
        for n, problem in enumerate(result["problems"])
        for part in problem["parts"]
    }


def test_every_graded_student_has_a_verdict_on_each_new_part(demo):
    planted = json.loads((demo / "planted.json").read_text())
    graded = [sid for sid, notes in planted.items() if notes[0].startswith("profile:")]
    assert len(graded) >= 25
    for sid in graded:
        verdicts = _verdicts(demo, sid)
        for index, parts in NEW_PARTS.items():
            assert parts <= {key for (i, key) in verdicts if i == index}, sid
        if planted[sid][0] == "profile: strong":
            assert all(
                verdicts[(i, key)]["verdict"] == "correct"
                for i, parts in NEW_PARTS.items()
                for key in parts
            ), sid


def test_each_mistake_planted_in_a_new_part_is_named(demo):
    planted = json.loads((demo / "planted.json").read_text())
    seen = set()
    for sid, notes in planted.items():
        for note in notes:
            head, _, what = note.partition(": ")
            words = head.split()
            if len(words) != 3 or words[0] != "problem" or what not in NAMED:
                continue
            part = _verdicts(demo, sid)[(int(words[1]), words[2])]
            assert part["verdict"] == "incorrect" and NAMED[what] in part["mistakes"], (sid, part)
            seen.add(what)
    assert seen == set(NAMED)  # the demo's seed plants each of them somewhere
