"""The command line of the LMS exports: `grade --export … --canvas-assignment-id …
--missing-as-zero` and `export gradescope`, thin over the library, with the exit statuses of
every command (2 for bad input, before anything is graded or written)."""

from __future__ import annotations

import csv
import zipfile
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.cli.main import EXIT_BAD_INPUT, main


@pytest.fixture(scope="module")
def tiny_class(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("lms-cli")
    (root / "assignment.toml").write_text(
        'title = "PS 1"\n[lms]\ncanvas_assignment_id = 4242\n'
        '[[problems]]\nscene = "simple_pendulum"\nparts = ["dof"]\nvariants = 1\n'
    )
    (root / "roster.csv").write_text(
        "id,name,email,sis_user_id\ns1,Ada,ada@uni.edu,9001\ns2,Ben,ben@uni.edu,9002\n"
    )
    generate(root / "assignment.toml", root / "roster.csv", 1, root / "ps", formats=("md",))
    (root / "subs").mkdir()
    (root / "subs" / "s1.toml").write_text("[problem1]\ndof = '1'\n")
    return root


def test_grade_writes_both_gradebooks_and_says_where_the_instructions_are(
    tiny_class, tmp_path, capsys
):
    out = tmp_path / "grades"
    argv = ["grade", str(tiny_class / "ps" / "manifest.json"), str(tiny_class / "subs")]
    status = main([*argv, "--out", str(out), "--export", "canvas", "--export", "moodle"])
    assert status == 1  # s2 is missing
    printed = capsys.readouterr().out
    assert f"how to import it: {out / 'gradebook-canvas.README.txt'}" in printed
    assert f"how to import it: {out / 'gradebook-moodle.README.txt'}" in printed
    canvas = list(csv.reader((out / "gradebook-canvas.csv").open()))
    assert canvas[0][-1] == "PS 1 (4242)"  # from the assignment's [lms] table
    assert canvas[2] == ["Ada", "", "9001", "ada@uni.edu", "", "1"]
    assert canvas[3] == ["Ben", "", "9002", "ben@uni.edu", "", ""]
    again = main([*argv, "--out", str(out), "--export", "canvas", "--missing-as-zero",
                  "--canvas-assignment-id", "77"])  # fmt: skip
    assert again == 1
    canvas = list(csv.reader((out / "gradebook-canvas.csv").open()))
    assert canvas[0][-1] == "PS 1 (77)" and canvas[3][-1] == "0"


def test_a_malformed_canvas_id_stops_grade_before_it_starts(tiny_class, tmp_path, capsys):
    out = tmp_path / "grades"
    argv = ["grade", str(tiny_class / "ps" / "manifest.json"), str(tiny_class / "subs")]
    status = main([*argv, "--out", str(out), "--export", "canvas", "--canvas-assignment-id", "x1"])
    assert status == EXIT_BAD_INPUT
    assert "'x1' is not a Canvas assignment id" in capsys.readouterr().err
    assert not out.exists()


def test_export_gradescope_writes_the_zip(tiny_class, tmp_path, capsys):
    out = tmp_path / "autograder.zip"
    status = main(
        ["export", "gradescope", str(tiny_class / "ps" / "manifest.json"), "--out", str(out)]
    )
    assert status == 0 and "Configure Autograder" in capsys.readouterr().out
    with zipfile.ZipFile(out) as zf:
        assert {"setup.sh", "run_autograder", "manifest.json"} <= set(zf.namelist())


def test_export_gradescope_needs_the_manifest(tiny_class, tmp_path, capsys):
    status = main(["export", "gradescope", str(tiny_class / "assignment.toml"), "--out",
                   str(tmp_path / "a.zip")])  # fmt: skip
    assert status == EXIT_BAD_INPUT
    assert "give the manifest.json" in capsys.readouterr().err
    assert not (tmp_path / "a.zip").exists()
