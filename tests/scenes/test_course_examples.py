"""The scene files `examples/scenes/` ships for the course's harder systems (a coordinate domain,
dissipation, …), each taken through the chain an instructor runs: `scene check` (exit 0, its
figure drawn), `generate` with an assignment naming them (every key verified by the grader),
`grade` of each student's own key (full marks), and `export prairielearn` (the key graded the way
PrairieLearn calls server.py)."""

from __future__ import annotations

import csv
import importlib.util
import json
import re
import shutil
from pathlib import Path

import pytest

from lagrade.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "scenes"
#: Each shipped example with the parts its assignment asks (every part it can be asked).
PARTS = {
    "swinging_atwood": [
        "dof", "coordinates", "transformation", "T", "V", "lagrangian", "eom", "momenta",
        "cyclic", "conserved",
    ],
    "symmetric_top": [
        "dof", "coordinates", "transformation", "T", "V", "lagrangian", "eom", "momenta",
        "cyclic", "conserved",
    ],
    "cycloid": [
        "dof", "transformation", "T", "V", "lagrangian", "eom", "momenta", "conserved",
        {"quantity": "period"},
    ],
    "damped_oscillator": [
        "dof", "transformation", "T", "V", "lagrangian", "eom", "momenta", "cyclic", "conserved",
        {"quantity": "decay_rate"},
    ],
}  # fmt: skip
ROSTER = "id,name\ns001,Ada Lovelace\ns002,Emmy Noether\ns003,Lise Meitner\n"


def _assignment() -> str:
    lines = ['title = "A course\'s harder systems"', "points = 1", ""]
    for name, parts in PARTS.items():
        shown = ", ".join(
            json.dumps(p) if isinstance(p, str) else f'{{ quantity = "{p["quantity"]}" }}'
            for p in parts
        )
        lines += ["[[problems]]", f'scene = "scenes/{name}.toml"', f"parts = [{shown}]", ""]
    return "\n".join(lines)


def test_every_shipped_example_is_taken_through_the_chain():
    shipped = {p.stem for p in EXAMPLES.glob("*.toml")} - {"parabola"}  # parabola: its own tests
    assert shipped == set(PARTS)


@pytest.mark.parametrize("name", sorted(PARTS))
def test_scene_check_passes_and_draws_the_figure(name, tmp_path, capsys):
    figure = tmp_path / f"{name}.svg"
    assert main(["scene", "check", str(EXAMPLES / f"{name}.toml"), "--figure", str(figure)]) == 0
    assert "<svg" in figure.read_text()
    assert "does not hold" not in capsys.readouterr().out


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("course")
    shutil.copytree(EXAMPLES, root / "scenes")
    (root / "assignment.toml").write_text(_assignment())
    (root / "roster.csv").write_text(ROSTER)
    argv = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    argv += ["--seed", "11", "--out", str(root / "ps"), "--formats", "md,html"]
    assert main(argv) == 0  # every key verified by the grader first
    return root


def _key_sheet(root: Path, student_id: str) -> str:
    key = (root / "ps" / "keys" / f"{student_id}.md").read_text()
    blocks = re.findall(r"```toml\n(.*?)```", key, flags=re.S)
    return f'student_id = "{student_id}"\n' + "\n".join(blocks)


def _grade(root: Path, sheets: dict[str, str], out: str) -> Path:
    subs = root / f"subs-{out}"
    subs.mkdir()
    for sid, text in sheets.items():
        (subs / f"{sid}.toml").write_text(text)
    main(["grade", str(root / "ps" / "manifest.json"), str(subs), "--out", str(root / out)])
    return root / out


def test_each_students_key_gets_full_marks(generated):
    ids = ("s001", "s002", "s003")
    out = _grade(generated, {sid: _key_sheet(generated, sid) for sid in ids}, "keys")
    rows = list(csv.DictReader((out / "gradebook.csv").open()))
    assert [r["percent"] for r in rows] == ["100.0"] * 3, rows


def test_the_damped_oscillators_key_says_none_and_energy_is_refused(generated):
    key = (generated / "ps" / "keys" / "s001.md").read_text()
    damped = key[key.index("Damped oscillator") :]
    conserved = damped[damped.index("### Conserved quantities") :].split("###")[1]
    assert conserved.split("\n", 1)[1].strip() == "none"
    sheet = _key_sheet(generated, "s001")
    number = list(PARTS).index("damped_oscillator") + 1
    first = f"[problem{number}]\ndof = '1'\ntransformation = '''\nx_mass = "
    x = sheet[sheet.index(first) + len(first) :].split("\n", 1)[0]  # x, q or u
    before = "conserved = '''\nnone\n'''"
    assert sheet.count(before) == 1
    wrong = sheet.replace(before, f"conserved = 'm*{x}_dot^2/2 + k*{x}^2/2'")
    out = _grade(generated, {"s001": wrong}, "energy")
    result = json.loads((out / "students" / "s001.json").read_text())
    part = next(
        p
        for p in result["problems"][list(PARTS).index("damped_oscillator")]["parts"]
        if p["key"] == "conserved"
    )
    assert part["verdict"] == "incorrect", part
    assert "not conserved" in " ".join(part["feedback"])


def test_export_prairielearn_grades_each_key(generated):
    out = generated / "pl"
    assert (
        main(["export", "prairielearn", str(generated / "ps" / "manifest.json"), "--out", str(out)])
        == 0
    )
    folders = sorted((out / "questions").iterdir())
    assert len(folders) == len(PARTS)
    for folder in folders:
        spec = importlib.util.spec_from_file_location(f"pl_{folder.name}", folder / "server.py")
        server = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(server)
        data = {"params": {}, "correct_answers": {}, "variant_seed": 3, "options": {}}
        server.generate(data)
        data["submitted_answers"] = dict(data["correct_answers"])
        server.parse(data)
        assert not data.get("format_errors"), data.get("format_errors")
        server.grade(data)
        assert data["score"] == pytest.approx(1.0), data["partial_scores"]
