"""The answer page with the next lecture's parts, over HTTP against a live server: the page
has a field for each, the preview typesets H in the momenta and Hamilton's equations with ṗ
(MathML), a mode line reads as a frequency and its vector, and the key's own answers, saved
with feedback on, come back correct part by part."""

from __future__ import annotations

import re
import tomllib

import pytest

from tests.serve.conftest import generate_class, get, post, start_server, stop_server

ASSIGNMENT = """\
title = "Hamiltonians and small oscillations"
points = 1

[answer_page]
feedback = true

[[problems]]
scene = "simple_pendulum"
parts = ["hamiltonian", "hamilton_equations"]

[[problems]]
scene = "coupled_oscillators"
parts = ["equilibrium", "normal_modes", "mode_shapes"]
"""
NEW_PARTS = {
    1: ("hamiltonian", "hamilton_equations"),
    2: ("equilibrium", "normal_modes", "mode_shapes"),
}


@pytest.fixture(scope="module")
def phase_served(tmp_path_factory):
    root = tmp_path_factory.mktemp("serve-phase")
    manifest = generate_class(root, assignment=ASSIGNMENT)
    server = start_server(root, manifest)
    yield server
    assert stop_server(server) == 0


def test_the_page_has_a_field_for_each_new_part(phase_served):
    status, page = get(phase_served.url("s001"))
    assert status == 200
    for index, parts in NEW_PARTS.items():
        for part in parts:
            assert f'data-problem="{index}" data-key="{part}"' in page, part
    # one mode (and one of Hamilton's equations) per line: a multi-line field
    assert re.search(r'<textarea id="p2-mode_shapes"', page)
    assert re.search(r'<textarea id="p1-hamilton_equations"', page)


def _key(served, student_id: str) -> dict:
    """The student's key in the answer sheet's TOML (the key's own coordinate names: a
    variant may call the pendulum's angle theta or phi)."""
    key = (served.root / "ps" / "keys" / f"{student_id}.md").read_text()
    return tomllib.loads("\n".join(re.findall(r"```toml\n(.*?)```", key, flags=re.S)))


def test_the_preview_typesets_momenta_and_their_rates(phase_served):
    url = phase_served.url("s002") + "/preview"
    key = _key(phase_served, "s002")["problem1"]
    status, result = post(url, {"problem": 1, "key": "hamiltonian", "text": key["hamiltonian"]})
    assert status == 200 and result["status"] == "read", result
    (line,) = result["lines"]
    assert line["mathml"].startswith("<math") and "<msub><mi>p</mi>" in line["mathml"]
    assert "<mover" not in line["mathml"]  # H holds no velocity: nothing is dotted
    equations = (
        "\n".join(key["hamilton_equations"])
        if isinstance(key["hamilton_equations"], list)
        else key["hamilton_equations"]
    )
    rate_line = next(x for x in equations.splitlines() if x.startswith("p_"))
    name = rate_line.split("_dot", 1)[0].removeprefix("p_")  # the coordinate
    latex = rate_line.replace(f"p_{name}_dot", f"\\dot{{p}}_{{\\{name}}}", 1)
    for text in (rate_line, latex):
        status, result = post(url, {"problem": 1, "key": "hamilton_equations", "text": text})
        assert status == 200 and result["status"] == "read", (text, result)
        rate = result["lines"][0]["mathml"]
        assert "<mover" in rate and ("&#729;" in rate or "\u02d9" in rate), rate  # ṗ: a dot
        assert re.search(r"<mover[^>]*><mi>p</mi>", rate), rate  # over the p itself


def test_the_preview_reads_a_mode_as_a_frequency_and_its_vector(phase_served):
    url = phase_served.url("s002") + "/preview"
    text = "omega = sqrt(k/m): (1, 1)\nsqrt((k + 2 k_c)/m): (1, -1 +)"
    status, result = post(url, {"problem": 2, "key": "mode_shapes", "text": text})
    assert status == 200 and result["status"] == "read", result
    assert result["lines"][0]["plain"] == "omega = sqrt(k/m): (1, 1)"
    assert "Line 2 could not be read" in result["message"]


def test_the_keys_answers_saved_with_feedback_are_correct(phase_served):
    sheet = _key(phase_served, "s003")
    answers = {
        str(index): {part: sheet[f"problem{index}"][part] for part in parts}
        for index, parts in NEW_PARTS.items()
    }
    status, reply = post(phase_served.url("s003") + "/save", {"answers": answers})
    assert status == 200 and reply["status"] == "saved", reply
    verdicts = {k: v["verdict"] for k, v in reply["feedback"]["parts"].items()}
    assert verdicts == {f"{i}/{p}": "correct" for i, parts in NEW_PARTS.items() for p in parts}
