"""`grade` called twice in one process (the API, a notebook, a test run) gives what a fresh
`lagrade grade` gives: each student's question is their own variant's, so a question left in the
process by another class (built from another seed with the same structure — names and options —
whose sample points a wrong answer's feedback would quote) is never reused."""

from __future__ import annotations

from lagrade.grading.batch import grade
from lagrade.grading.manifest import entry_spec, load_manifest
from lagrade.grading.student import question, structure_key
from lagrade.judge.driver import forget_problems


def _outputs(folder):
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and p.name != ".lagrade.lock"
    }


def test_a_question_another_class_built_is_not_reused(workspace):
    manifest_path = workspace / "out" / "manifest.json"
    grade(manifest_path, workspace / "submissions", workspace / "fresh", jobs=1)
    fresh = _outputs(workspace / "fresh")
    assert any(b"for example at" in data for data in fresh.values()), "no feedback quotes a point"
    manifest = load_manifest(manifest_path)
    forget_problems()
    for entry in manifest["students"][0]["problems"]:  # each question, from another seed
        spec = entry_spec(entry)
        other = next(
            seed
            for seed in range(1, 500)
            if seed != entry["seed"]
            and structure_key({**spec, "seed": seed}) == structure_key(spec)
        )
        question({**spec, "seed": other})
    grade(manifest_path, workspace / "submissions", workspace / "again", jobs=1)
    again = _outputs(workspace / "again")
    assert sorted(fresh) == sorted(again)
    assert [name for name in fresh if fresh[name] != again[name]] == []
