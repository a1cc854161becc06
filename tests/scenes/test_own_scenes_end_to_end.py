"""Two systems not in the bank, written from docs/scenes.md alone (a bead on a spinning parabolic
wire, with bodies, constraints and a potential; a relativistic particle given by its Lagrangian),
through the whole chain: `generate` (every key verified by the grader), then — with the scene
files deleted — `grade` (the key's own answers get full marks), `export prairielearn` (server.py
graded the way PrairieLearn calls it) and `serve` (a preview). The manifest alone carries them."""

from __future__ import annotations

import csv
import importlib.util
import json
import re
import shutil
from pathlib import Path

import pytest

from lagrade.cli.main import main
from tests.serve.conftest import post, start_server, stop_server

ASSIGNMENT = """\
title = "Systems of our own"
points = 1

[[problems]]
scene = "scenes/parabola.toml"
parts = ["dof", "coordinates", "transformation", "T", "V", "lagrangian", "eom", "momenta",
         "cyclic", "conserved", { quantity = "oscillation_frequency", points = 2 }]

[[problems]]
scene = "relativistic"
parts = ["lagrangian", "eom", "momenta", "cyclic", "conserved",
         { quantity = "acceleration_from_rest" }]
"""
ROSTER = "id,name\ns001,Ada Lovelace\ns002,Emmy Noether\ns003,Lise Meitner\ns004,Paul Dirac\n"


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> Path:
    """A class generated from the two scene files, which are then deleted."""
    root = tmp_path_factory.mktemp("own")
    shutil.copytree(Path(__file__).parent / "files", root / "scenes")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    (root / "roster.csv").write_text(ROSTER)
    argv = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    argv += ["--seed", "7", "--out", str(root / "ps"), "--formats", "md,html", "--scenes"]
    assert main([*argv, str(root / "scenes")]) == 0  # every key verified by the grader first
    shutil.rmtree(root / "scenes")
    return root


def _key_sheet(root: Path, student_id: str) -> str:
    """The student's key, in the answer sheet's own TOML, as the key file prints it."""
    key = (root / "ps" / "keys" / f"{student_id}.md").read_text()
    blocks = re.findall(r"```toml\n(.*?)```", key, flags=re.S)
    return f'student_id = "{student_id}"\n' + "\n".join(blocks)


def test_the_manifest_carries_both_scene_files(generated):
    manifest = json.loads((generated / "ps" / "manifest.json").read_text())
    scenes = manifest["scenes"]
    assert set(scenes) == {"parabola", "relativistic"}
    assert scenes["parabola"]["ref"] == "scenes/parabola.toml"
    assert scenes["relativistic"]["ref"] == "relativistic"
    original = (Path(__file__).parent / "files" / "parabola.toml").read_text()
    assert scenes["parabola"]["text"] == original
    handout = (generated / "ps" / "handouts" / "s001.md").read_text()
    assert "spinning parabolic wire" in handout and "relativistic" in handout
    assert len(list((generated / "ps" / "figures").glob("*.svg"))) >= 1  # the wire's only


def test_grading_the_keys_gives_full_marks_without_the_scene_files(generated):
    subs = generated / "subs"
    subs.mkdir(exist_ok=True)
    for sid in ("s001", "s002", "s003", "s004"):
        (subs / f"{sid}.toml").write_text(_key_sheet(generated, sid))
    out = generated / "grades"
    assert (
        main(["grade", str(generated / "ps" / "manifest.json"), str(subs), "--out", str(out)]) == 0
    )
    rows = list(csv.DictReader((out / "gradebook.csv").open()))
    assert [r["percent"] for r in rows] == ["100.0"] * 4, rows
    result = json.loads((out / "students" / "s002.json").read_text())
    verdicts = {p["key"]: p["verdict"] for prob in result["problems"] for p in prob["parts"]}
    assert set(verdicts.values()) == {"correct"}, verdicts


def test_a_wrong_answer_is_still_wrong(generated):
    subs = generated / "subs-wrong"
    subs.mkdir(exist_ok=True)
    sheet = _key_sheet(generated, "s001")
    key_l = re.search(r"\[problem2\]\nlagrangian = '(.*?)'", sheet).group(1)
    assert key_l.count(") - g*") == 1
    sheet = sheet.replace(key_l, key_l.replace(") - g*", ") + g*"))  # V added, not taken
    (subs / "s001.toml").write_text(sheet)
    out = generated / "grades-wrong"
    main(["grade", str(generated / "ps" / "manifest.json"), str(subs), "--out", str(out)])
    result = json.loads((out / "students" / "s001.json").read_text())
    verdicts = {p["key"]: p["verdict"] for p in result["problems"][1]["parts"]}
    assert verdicts["lagrangian"] == "incorrect"


def test_export_prairielearn_from_the_manifest_grades_the_key(generated):
    out = generated / "pl"
    assert (
        main(["export", "prairielearn", str(generated / "ps" / "manifest.json"), "--out", str(out)])
        == 0
    )
    folders = sorted((out / "questions").iterdir())
    assert len(folders) == 2
    for folder in folders:
        spec = importlib.util.spec_from_file_location(f"pl_{folder.name}", folder / "server.py")
        server = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(server)
        assert set(server.SCENES) == {"scenes/parabola.toml", "relativistic"}
        data = {"params": {}, "correct_answers": {}, "variant_seed": 5, "options": {}}
        server.generate(data)
        answers = dict(data["correct_answers"])  # the key, as a student types it
        data["submitted_answers"] = answers
        server.parse(data)
        assert not data.get("format_errors"), data.get("format_errors")
        server.grade(data)
        assert data["score"] == pytest.approx(1.0), data["partial_scores"]


def test_serve_previews_an_answer_without_the_scene_files(generated):
    served = start_server(generated, generated / "ps" / "manifest.json")
    try:
        status, body = post(
            served.url("s001") + "/preview",
            {"problem": 1, "key": "lagrangian", "text": "1/2 m r_dot^2 - m g a r^2"},
        )
        assert status == 200 and body["status"] == "read", body
        status, body = post(
            served.url("s001") + "/preview",
            {"problem": 2, "key": "momenta", "text": "p_x = m x_dot/sqrt(1 - x_dot^2/c^2)"},
        )
        assert status == 200 and body["status"] == "read", body
    finally:
        assert stop_server(served) == 0  # stopping is a server's normal end


def test_a_carried_scene_that_was_edited_is_refused(generated, capsys):
    manifest = json.loads((generated / "ps" / "manifest.json").read_text())
    manifest["scenes"]["parabola"]["text"] = manifest["scenes"]["parabola"]["text"].replace(
        "a r^2", "2 a r^2"
    )
    edited = generated / "edited" / "manifest.json"
    edited.parent.mkdir()
    edited.write_text(json.dumps(manifest))
    shutil.copy(generated / "ps" / "assignment.toml", edited.parent / "assignment.toml")
    (generated / "empty").mkdir()
    assert (
        main(["grade", str(edited), str(generated / "empty"), "--out", str(generated / "g2")]) == 2
    )
    assert "does not match its SHA-256" in capsys.readouterr().err


def test_a_lagrangian_scene_is_not_asked_about_bodies(tmp_path, capsys):
    shutil.copytree(Path(__file__).parent / "files", tmp_path / "scenes")
    (tmp_path / "a.toml").write_text(
        'title = "x"\n[[problems]]\nscene = "scenes/relativistic.toml"\n'
        'parts = ["T", "lagrangian"]\n'
    )
    (tmp_path / "roster.csv").write_text(ROSTER)
    argv = ["generate", str(tmp_path / "a.toml"), "--roster", str(tmp_path / "roster.csv")]
    assert main([*argv, "--seed", "1", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "scene 'relativistic' is given by its Lagrangian and declares no bodies, so 'T'" in err
