"""`grade` called twice in one process (the API, a notebook, a test run) gives what a fresh
`lagrade grade` gives: a class shares each question, built from its first student asked it, so a
question left in the process by another class (built from another seed, whose sample points the
feedback quotes) must not be reused."""

from __future__ import annotations

import json

from lagrade.grading.batch import grade
from lagrade.grading.manifest import entry_spec, load_manifest
from lagrade.grading.student import question


def _outputs(folder):
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and p.name != ".lagrade.lock"
    }


def test_a_question_another_class_built_is_not_reused(workspace):
    manifest_path = workspace / "out" / "manifest.json"
    grade(manifest_path, workspace / "submissions", workspace / "fresh", jobs=1)
    manifest = load_manifest(manifest_path)
    first = manifest["students"][0]["problems"][0]
    other_seeds = {s["problems"][0]["seed"] for s in manifest["students"]} - {first["seed"]}
    assert other_seeds, "the class needs two variants of its first problem"
    built = question(entry_spec({**first, "seed": max(other_seeds)}))  # another class's student
    grade(manifest_path, workspace / "submissions", workspace / "again", jobs=1)
    assert question(entry_spec(first)) is not built
    fresh, again = _outputs(workspace / "fresh"), _outputs(workspace / "again")
    assert sorted(fresh) == sorted(again)
    assert [name for name in fresh if fresh[name] != again[name]] == []
    assert json.loads((workspace / "again" / "summary.json").read_text())
