"""lagrade's exported questions through PrairieLearn's real Python worker (issue 28): its
`zygote.py`, `question_phases.py` and core elements, driven as its Node side drives them
(`tests.prairielearn_node`), with a Python that has PrairieLearn's dependencies and no lagrade
(server.py runs the copy vendored into serverFilesCourse/). Skips unless LAGRADE_PRAIRIELEARN
names a PrairieLearn checkout (PrairieLearn is AGPL: it is never part of this repository); see
`tests/prairielearn_node.py` for the other variables, and `benchmarks/bench_prairielearn.py`
for every bank scene."""

from __future__ import annotations

import pytest

from lagrade.grading.prairielearn import export_prairielearn
from tests.prairielearn_node import Node, checkout
from tests.prairielearn_probe import assignment_text, new_figures, probe

PL = checkout()
pytestmark = pytest.mark.skipif(
    PL is None, reason="LAGRADE_PRAIRIELEARN does not name a PrairieLearn checkout"
)


@pytest.fixture(scope="module")
def node(tmp_path_factory):
    root = tmp_path_factory.mktemp("pl-real")
    (root / "a.toml").write_text(assignment_text(["kepler", "wedge"]), encoding="utf-8")
    export_prairielearn(root / "a.toml", 2025, root / "course")
    node = Node.real(PL, root / "course")
    yield node
    node.close()


@pytest.mark.parametrize("scene", ["kepler", "wedge"])
def test_every_phase_and_the_question_test_in_prairielearns_worker(node, scene):
    (folder,) = [p for p in (node.course / "questions").iterdir() if p.name.endswith(scene)]
    question = node.question(folder.name)
    figures = new_figures()
    faults = probe(question, figures)
    assert faults + question.issues == []
    assert all(t == {"passed": 1, "failed": 0} for t in figures["tests"].values())
    assert figures["hostile_format_errors"] == figures["hostile_parts"]
    assert figures["feedback"]["shown"] == figures["feedback"]["sentences"] > 0
