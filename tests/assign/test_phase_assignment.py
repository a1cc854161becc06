"""The next lecture's parts (`hamiltonian`, `hamilton_equations`, `equilibrium`, `normal_modes`,
`mode_shapes`) through the whole chain: `generate` (every key verified by the grader, the key shows
H, Hamilton's equations, the equilibrium and the frequencies), `grade` (the key's own answers get
full marks, a wrong H is named), and `export prairielearn` (server.py graded the way PrairieLearn
calls it). They reach every entry point through the one door, `run_checker`."""

from __future__ import annotations

import csv
import importlib.util
import json
import re
from pathlib import Path

import pytest

from lagrade.cli.main import main

ASSIGNMENT = """\
title = "Hamiltonians and small oscillations"
points = 1

[[problems]]
scene = "simple_pendulum"
parts = ["lagrangian", "hamiltonian", "hamilton_equations", "equilibrium", "normal_modes"]

[[problems]]
scene = "charged_particle"
parts = ["momenta", "hamiltonian", "hamilton_equations"]

[[problems]]
scene = "double_pendulum"
parts = ["hamiltonian", "equilibrium", "normal_modes", "mode_shapes"]
"""
ROSTER = "id,name\ns001,Ada Lovelace\ns002,Emmy Noether\n"


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("phase")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    (root / "roster.csv").write_text(ROSTER)
    argv = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    assert main([*argv, "--seed", "7", "--out", str(root / "ps"), "--formats", "md,html,tex"]) == 0
    return root


def _key_sheet(root: Path, student_id: str) -> str:
    key = (root / "ps" / "keys" / f"{student_id}.md").read_text()
    blocks = re.findall(r"```toml\n(.*?)```", key, flags=re.S)
    return f'student_id = "{student_id}"\n' + "\n".join(blocks)


def test_the_key_shows_the_new_parts_in_every_format(generated):
    keys = generated / "ps" / "keys"
    md = (keys / "s001.md").read_text()
    for heading in ("### Hamiltonian", "### Hamilton's equations", "### Stable equilibrium"):
        assert heading in md
    assert r"\dot{p}_{\theta}" in md or r"\dot{p}_{\phi}" in md or r"\dot{p}_{\psi}" in md
    assert "Normal-mode angular frequencies" in (keys / "s001.html").read_text()
    assert md.count("### Mode shapes") == 1  # asked of the double pendulum alone
    assert "Mode shapes" in (keys / "s001.html").read_text()
    assert r"\par\textbf{Mode shapes}" in (keys / "s001.tex").read_text()
    assert r"\textbf{Hamiltonian.}" in (keys / "s001.tex").read_text()
    sheet = (generated / "ps" / "answer_sheets" / "s001.toml").read_text()
    assert "hamilton_equations = '''" in sheet and "p_x_dot" in sheet
    assert "mode_shapes = '''" in sheet and "omega = frequency: (amplitudes" in sheet
    handout = (generated / "ps" / "handouts" / "s001.md").read_text()
    assert "Write the Hamiltonian H" in handout


def test_grading_the_keys_gives_full_marks(generated):
    subs = generated / "subs"
    subs.mkdir(exist_ok=True)
    for sid in ("s001", "s002"):
        (subs / f"{sid}.toml").write_text(_key_sheet(generated, sid))
    out = generated / "grades"
    manifest = str(generated / "ps" / "manifest.json")
    assert main(["grade", manifest, str(subs), "--out", str(out)]) == 0
    rows = list(csv.DictReader((out / "gradebook.csv").open()))
    assert [r["percent"] for r in rows] == ["100.0"] * 2, rows
    result = json.loads((out / "students" / "s002.json").read_text())
    verdicts = {
        (prob["index"] if "index" in prob else n, p["key"]): p["verdict"]
        for n, prob in enumerate(result["problems"])
        for p in prob["parts"]
    }
    assert set(verdicts.values()) == {"correct"}, verdicts
    assert len(verdicts) == 12


def test_a_hamiltonian_in_the_velocities_is_named(generated):
    subs = generated / "subs-wrong"
    subs.mkdir(exist_ok=True)
    sheet = _key_sheet(generated, "s001")
    lagrangian = re.search(r"\[problem1\]\nlagrangian = '(.*?)'", sheet).group(1)
    sheet = re.sub(r"(\[problem1\][^\[]*?hamiltonian = )'.*?'", rf"\1'{lagrangian}'", sheet)
    (subs / "s001.toml").write_text(sheet)
    out = generated / "grades-wrong"
    main(["grade", str(generated / "ps" / "manifest.json"), str(subs), "--out", str(out)])
    result = json.loads((out / "students" / "s001.json").read_text())
    part = next(p for p in result["problems"][0]["parts"] if p["key"] == "hamiltonian")
    assert part["verdict"] == "incorrect" and "velocities" in part["mistakes"], part


def test_export_prairielearn_grades_the_key(generated):
    out = generated / "pl"
    manifest = str(generated / "ps" / "manifest.json")
    assert main(["export", "prairielearn", manifest, "--out", str(out)]) == 0
    folders = sorted((out / "questions").iterdir())
    assert len(folders) == 3
    for folder in folders:
        spec = importlib.util.spec_from_file_location(f"pl_{folder.name}", folder / "server.py")
        server = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(server)
        data = {"params": {}, "correct_answers": {}, "variant_seed": 3, "options": {}}
        server.generate(data)
        answers = dict(data["correct_answers"])
        data["submitted_answers"] = answers
        server.parse(data)
        assert not data.get("format_errors"), data.get("format_errors")
        server.grade(data)
        assert data["score"] == pytest.approx(1.0), data["partial_scores"]


def test_a_scene_without_a_stable_equilibrium_cannot_be_asked_for_one(tmp_path):
    (tmp_path / "a.toml").write_text(
        'title = "x"\n[[problems]]\nscene = "kepler"\nparts = ["normal_modes"]\n'
    )
    (tmp_path / "r.csv").write_text(ROSTER)
    argv = ["generate", str(tmp_path / "a.toml"), "--roster", str(tmp_path / "r.csv")]
    assert main([*argv, "--seed", "1", "--out", str(tmp_path / "ps")]) != 0


def test_a_long_line_without_spaces_after_its_first_cut_is_left_whole():
    """The key's wrapped TOML (in the PDF key) looped for ever on a line whose rest had no
    space but the continuation's indentation (a normal-mode frequency of a double pendulum)."""
    from lagrade.assign.templating import _continued

    pieces = _continued("a" * 50 + " " + "b" * 200, 88)
    assert pieces == ["a" * 50 + " \\", "  " + "b" * 200]


def test_bank_show_prints_h_the_equilibria_and_the_frequencies_or_why_not(capsys):
    assert main(["bank", "show", "pendulum_on_cart", "--seed", "2"]) == 0
    out = capsys.readouterr().out
    assert "H = " in out and "Hamilton's equations:" in out
    assert "stable" in out and "unstable" in out
    assert "normal-mode angular frequencies: 0, " in out and "zero mode" in out
    assert main(["bank", "show", "kepler", "--seed", "2"]) == 0
    assert "normal modes: none (U has no stationary point" in capsys.readouterr().out
    assert main(["bank", "show", "charged_particle", "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert "velocity-dependent force" in data["phase_space"]["why_not"]


def test_bank_show_prints_each_modes_shape_or_says_none_oscillates(capsys):
    assert main(["bank", "show", "coupled_oscillators", "--seed", "2"]) == 0
    out = capsys.readouterr().out
    assert "mode shapes (amplitudes of " in out
    shapes = out.split("mode shapes (amplitudes of ")[1].splitlines()[1:3]
    assert all(s.startswith("  omega = ") and ": (1, " in s for s in shapes), shapes
    assert main(["bank", "show", "wheel"]) == 0
    assert "mode shapes: none (no mode oscillates)" in capsys.readouterr().out
    assert main(["bank", "show", "harmonic_oscillator", "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [m["vector"] for m in data["phase_space"]["mode_shapes"]] == ["1"]
