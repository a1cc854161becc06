"""`lagrade scene check`, `lagrade scene new`, and `lagrade bank list/show` on scene files and
folders: what an instructor writing their own system runs."""

from __future__ import annotations

import json

import pytest

from lagrade.cli.main import main


def test_check_prints_the_solution_checks_quantities_and_draws(scene_folder, tmp_path, capsys):
    figure = tmp_path / "parabola.svg"
    assert (
        main(["scene", "check", str(scene_folder / "parabola.toml"), "--figure", str(figure)]) == 0
    )
    out = capsys.readouterr().out
    for step in ("DOF:         1", "transformation:", "T = ", "V = ", "L = ", "p_r = "):
        assert step in out, step
    assert "equations of motion" in out and "cyclic: none" in out and "h (energy" in out
    assert "oscillation_frequency = sqrt(2*a*g - omega**2): holds" in out
    assert figure.read_bytes().startswith(b"<?xml") and b"<svg" in figure.read_bytes()


def test_check_of_a_lagrangian_scene_has_no_figure(scene_folder, tmp_path, capsys):
    assert main(["scene", "check", str(scene_folder / "relativistic.toml"), "--figure",
                 str(tmp_path / "r.svg")]) == 0  # fmt: skip
    out = capsys.readouterr().out
    assert "given by its Lagrangian" in out and "cyclic: x" in out
    assert "figure: none" in out and not (tmp_path / "r.svg").exists()


def test_a_quantity_the_motion_contradicts_fails_the_check(scene_folder, tmp_path, capsys):
    path = scene_folder / "parabola.toml"
    path.write_text(path.read_text().replace("sqrt(2 g a - omega^2)", "sqrt(g a - omega^2)"))
    assert main(["scene", "check", str(path), "--figure", str(tmp_path / "p.svg")]) == 1
    out = capsys.readouterr().out
    assert "oscillation_frequency: DOES NOT HOLD: the normal-mode angular frequencies are" in out


def test_new_writes_a_template_that_checks(tmp_path, capsys):
    assert main(["scene", "new", "collar", "--out", str(tmp_path)]) == 0
    path = tmp_path / "collar.toml"
    assert "docs/scenes.md" in path.read_text()
    assert main(["scene", "check", str(path), "--figure", str(tmp_path / "c.svg")]) == 0
    assert "small_oscillation_frequency" in capsys.readouterr().out
    assert main(["scene", "new", "collar", "--out", str(tmp_path)]) == 2  # never overwrites
    assert "exists" in capsys.readouterr().err


@pytest.mark.parametrize("name", ["../up", "a b", "", "x" * 65, ".hidden"])
def test_new_refuses_a_name_that_is_no_id(name, tmp_path, capsys):
    assert main(["scene", "new", name, "--out", str(tmp_path)]) == 2
    assert "cannot name a scene" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_bank_list_takes_folders_files_and_ids(scene_folder, capsys):
    assert main(["bank", "list", str(scene_folder), "wedge"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == ["parabola", "relativistic", "wedge"]


def test_bank_list_names_a_broken_file_and_lists_the_rest(scene_folder, capsys):
    (scene_folder / "broken.toml").write_text('title = "x"\n')
    assert main(["bank", "list", str(scene_folder)]) == 2
    captured = capsys.readouterr()
    assert "parabola" in captured.out and "relativistic" in captured.out
    assert "broken.toml is not a valid scene file" in captured.err


def test_bank_show_reads_a_file(scene_folder, capsys):
    assert main(["bank", "show", str(scene_folder / "parabola.toml"), "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["id"] == "parabola" and data["dof"] == 1 and data["cyclic"] == []
    assert main(["bank", "show", str(scene_folder / "relativistic.toml"), "--format", "latex"]) == 0
    assert r"\dot{x}" in capsys.readouterr().out


def test_the_walk_through_file_is_the_one_tested_and_shipped():
    """docs/scenes.md's example is, line for line, the file these tests take through the chain
    and the one examples/ ships (after their two header comment lines)."""
    import pathlib
    import re

    root = pathlib.Path(__file__).resolve().parents[2]
    doc = (root / "docs" / "scenes.md").read_text()
    (block,) = re.findall(r"```toml\n(title = \"Bead on a spinning.*?)```", doc, flags=re.S)
    for copy in (root / "tests/scenes/files/parabola.toml", root / "examples/scenes/parabola.toml"):
        body = copy.read_text().split("\n", 3)[3]
        assert body == block, copy
