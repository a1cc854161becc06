"""A generated class with synthetic submissions, shared by the batch tests (built once)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from lagrade.assign.generate import generate
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
