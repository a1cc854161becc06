"""Scene files written by hand from docs/scenes.md alone, for systems the bank does not have:
a bead on a spinning parabolic wire (bodies, constraints and a potential) and a relativistic
particle (given by its Lagrangian)."""

from __future__ import annotations

import pathlib
import shutil

import pytest

FILES = pathlib.Path(__file__).parent / "files"


@pytest.fixture
def scene_folder(tmp_path: pathlib.Path) -> pathlib.Path:
    """A copy of the hand-written scene files in a folder of their own."""
    folder = tmp_path / "scenes"
    shutil.copytree(FILES, folder)
    return folder
