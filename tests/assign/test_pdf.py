"""The LaTeX compiles with pdflatex (skipped, saying why, where TeX Live is not installed)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from lagrade.assign.generate import generate
from lagrade.assign.pdf import PDFLATEX_HINT

from .conftest import write_roster

needs_pdflatex = pytest.mark.skipif(
    shutil.which("pdflatex") is None,
    reason="pdflatex is not on PATH; apt-get install --no-install-recommends texlive-latex-base",
)


@needs_pdflatex
def test_every_scene_compiles_to_pdf(whole_bank: Path, tmp_path: Path) -> None:
    roster = write_roster(tmp_path / "r.csv", [("x1", "Zoë & Co. 100% {weird} $name_#1 ~^\\")])
    out = tmp_path / "out"
    result = generate(whole_bank, roster, 11, out, "pdf")
    assert result.warnings == []
    for folder in ("handouts", "keys"):
        pdf = (out / folder / "x1.pdf").read_bytes()
        assert pdf.startswith(b"%PDF") and len(pdf) > 5000


def test_missing_pdflatex_says_how_to_install(
    small_assignment: Path, roster: Path, tmp_path: Path, monkeypatch
) -> None:
    monkeypatch.setattr(shutil, "which", lambda name: None)
    out = tmp_path / "out"
    result = generate(small_assignment, roster, 1, out, "tex,pdf")
    assert result.warnings == [PDFLATEX_HINT]
    assert "apt-get install" in PDFLATEX_HINT
    assert (out / "handouts" / "s001.tex").exists()
    assert not (out / "handouts" / "s001.pdf").exists()


@needs_pdflatex
def test_pdfs_are_byte_identical_across_runs(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    generate(small_assignment, roster, 4, tmp_path / "a", "pdf")
    generate(small_assignment, roster, 4, tmp_path / "b", "pdf")
    for folder in ("handouts", "keys"):
        a = (tmp_path / "a" / folder / "s001.pdf").read_bytes()
        assert a == (tmp_path / "b" / folder / "s001.pdf").read_bytes()
