"""Generated classes shared by the batch tests (each built once): one with synthetic
submissions, and a small hostile one (formula-like names, a title full of markup)."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.cli.demo_class import write_submissions

ASSIGNMENT = """\
title = "Batch test"
points = 1

[[problems]]
scene = "hoop"
parts = ["dof", "lagrangian", "eom", "conserved", { quantity = "equilibrium_angle", points = 2 }]
variants = 4

[[problems]]
scene = "wedge"
parts = ["lagrangian", "eom", "momenta", "cyclic"]
variants = 4
"""


@pytest.fixture(scope="session")
def generated_class(tmp_path_factory) -> Path:
    """An assignment for 12 students and their synthetic answer sheets (demo profiles)."""
    root = tmp_path_factory.mktemp("class")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    rows = ["id,name"] + [f"s{i:02d},Student {i}" for i in range(1, 13)]
    (root / "roster.csv").write_text("\n".join(rows) + "\n")
    generate(root / "assignment.toml", root / "roster.csv", 11, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    write_submissions(root / "pristine", manifest, malformed=None, missing=None)
    return root


@pytest.fixture
def workspace(generated_class, tmp_path) -> Path:
    """A private copy of the class: manifest folder and submissions, free to plant faults in."""
    shutil.copytree(generated_class / "out", tmp_path / "out")
    shutil.copytree(generated_class / "pristine", tmp_path / "submissions")
    return tmp_path


HOSTILE_ASSIGNMENT = """\
title = "Set <script>alert(1)</script> *bold* [x](javascript:alert(1)) `code`"
points = 1

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "eom"]
variants = 2
"""

#: Roster names a spreadsheet would run as formulas (OWASP's CSV-injection list), then plain ones.
HOSTILE_NAMES = {
    "s1": '=HYPERLINK("http://evil.example","x")',
    "s2": "+cmd|' /C calc'!A0",
    "s3": "-2+3",
    "s4": "@SUM(A1:A9)",
    "s5": "Ada Lovelace",
    "s6": "Emmy Noether",
}


@pytest.fixture(scope="session")
def hostile_class(tmp_path_factory) -> Path:
    """One cheap problem (a simple pendulum: dof, L, EOM) for six students whose names look like
    spreadsheet formulas, under a title full of Markdown and HTML (generated once)."""
    root = tmp_path_factory.mktemp("hostile-class")
    (root / "assignment.toml").write_text(HOSTILE_ASSIGNMENT)
    with (root / "roster.csv").open("w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["id", "name"])
        writer.writerows(HOSTILE_NAMES.items())
    generate(root / "assignment.toml", root / "roster.csv", 3, root / "out", formats=("md",))
    return root / "out"


@pytest.fixture
def classroom(hostile_class, tmp_path) -> Path:
    """A private copy of the hostile class in `tmp_path/class`, and `tmp_path/subs` holding a
    sheet for every student that answers `dof` (so a clean run grades everyone)."""
    shutil.copytree(hostile_class, tmp_path / "class")
    subs = tmp_path / "subs"
    subs.mkdir()
    for sid in HOSTILE_NAMES:
        (subs / f"{sid}.toml").write_text(f"student_id = '{sid}'\n[problem1]\ndof = '1'\n")
    return tmp_path
