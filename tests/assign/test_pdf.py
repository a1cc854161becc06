"""The LaTeX compiles with pdflatex (skipped, saying why, where TeX Live is not installed)."""

from __future__ import annotations

import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest

from lagrade.assign.generate import generate
from lagrade.assign.pdf import PDFLATEX_HINT
from lagrade.bank import scene_ids

from .conftest import all_parts, write_assignment, write_roster

needs_pdflatex = pytest.mark.skipif(
    shutil.which("pdflatex") is None,
    reason="pdflatex is not on PATH; apt-get install --no-install-recommends texlive-latex-base",
)


@pytest.fixture(scope="module")
def bank_pdfs(tmp_path_factory) -> tuple[Path, list[str]]:
    """Every part of every scene as PDF (and Markdown, whose key block is known to be valid
    TOML), for a student whose name holds every LaTeX special character."""
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not on PATH; apt-get install texlive-latex-base")
    folder = tmp_path_factory.mktemp("pdf")
    assignment = write_assignment(
        folder / "bank.toml", [{"scene": s, "parts": all_parts(s)} for s in scene_ids()]
    )
    roster = write_roster(folder / "r.csv", [("x1", "Zoë & Co. 100% {weird} $name_#1 ~^\\")])
    result = generate(assignment, roster, 11, folder / "out", "pdf,md")
    return folder / "out", result.warnings


@needs_pdflatex
def test_every_scene_compiles_to_pdf(bank_pdfs) -> None:
    out, warnings = bank_pdfs
    assert warnings == []
    for folder in ("handouts", "keys"):
        pdf = (out / folder / "x1.pdf").read_bytes()
        assert pdf.startswith(b"%PDF") and len(pdf) > 5000


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="no pdftotext (poppler-utils)")
@needs_pdflatex
def test_the_keys_answer_blocks_copy_out_of_the_pdf_as_the_same_toml(bank_pdfs) -> None:
    """What a reader copies from the PDF key's "answers as a student would type them" is the
    answer sheet itself: read by pdftotext and then by TOML's reader, every block gives the
    values of the key's own TOML (no curly quotes, no line broken inside a string)."""
    out, _ = bank_pdfs
    text = subprocess.run(
        ["pdftotext", str(out / "keys" / "x1.pdf"), "-"], capture_output=True, text=True, check=True
    ).stdout
    expected = tomllib.loads(
        "\n".join(re.findall(r"```toml\n(.*?)```", (out / "keys" / "x1.md").read_text(), re.S))
    )
    assert len(expected) == len(scene_ids())
    for table, values in expected.items():
        start = text.index(f"[{table}]")
        end = text.find("\f", start)  # each block is on one page: it ends before the next
        block = text[start : end if end >= 0 else len(text)]
        block = re.split(r"\n\s*\n", block)[0]  # the block, not the page number after it
        try:
            copied = tomllib.loads(block)
        except tomllib.TOMLDecodeError as error:
            raise AssertionError(f"{table}: {error}\n{block}") from None
        assert copied == {table: values}, block


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
