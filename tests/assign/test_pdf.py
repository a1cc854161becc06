"""The LaTeX compiles with pdflatex (skipped, saying why, where TeX Live is not installed)."""

from __future__ import annotations

import re
import shutil
import subprocess
import tomllib
import unicodedata
from pathlib import Path

import pytest

from lagrade.assign import generate
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
    # a block longer than what is left of its page goes on on the next: the page's number and
    # the page break between its lines are the PDF's, not the block's
    text = re.sub(r"\n\s*\n\d+\s*\f", "\n", text)
    expected = tomllib.loads(
        "\n".join(re.findall(r"```toml\n(.*?)```", (out / "keys" / "x1.md").read_text(), re.S))
    )
    assert len(expected) == len(scene_ids())
    for table, values in expected.items():
        start = text.index(f"[{table}]")
        end = text.find("\f", start)  # the next page break (none inside a block, above)
        block = text[start : end if end >= 0 else len(text)]
        # the block, not the page number after it nor the next problem on the next page
        block = re.split(r"\n\s*\n|\nProblem \d+: ", block)[0]
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


#: A Lagrangian too long for one line of the page: twelve terms in one bracket (which sympy
#: sets as a single \left( … \right) box) and two after it; each coefficient is a different
#: prime, so each term can be found in the text of the PDF.
LONG_L = (
    "m (x_dot^2 + y_dot^2)/2 - 101 k x^2 - 103 k y^2 - 107 k x y - 109 k x^3 - 113 k y^3"
    " - 127 k x^2 y - 131 k x y^2 - 137 k x^4 - 139 k y^4 - 149 k x^3 y - 151 k x^2 y^2"
    " - 157 k x y^3"
)
LONG_SCENE = f"""\
title = "Particle in a polynomial well"
statement = "A particle of mass m moves in a plane in a polynomial potential. Use {{x}} and {{y}}."
coordinates = ["x", "y"]
lagrangian = "{LONG_L}"

[parameters]
m = {{ domain = "positive", unit = "kg", values = [1.0], description = "mass" }}
k = {{ domain = "positive", unit = "N/m", values = [2.0], description = "stiffness" }}
"""
COEFFICIENTS = ("101", "103", "107", "109", "113", "127", "131", "137", "139", "149", "151", "157")
#: The right edge of the text on the page: US letter (612 pt) less geometry's 2.3 cm margin.
RIGHT_EDGE = 612 - 2.3 / 2.54 * 72


def words_past_the_margin(pdf: Path) -> list[str]:
    """Every word pdftotext places right of the text area (what a clipped formula leaves)."""
    boxes = subprocess.run(
        ["pdftotext", "-bbox", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    return [
        f"{word} (ends at {float(x_max):.0f} pt)"
        for x_max, word in re.findall(
            r'<word xMin="[\d.]+" yMin="[\d.]+" xMax="([\d.]+)"[^>]*>'
            r"([^<]*)</word>",
            boxes,
        )  # fmt: skip
        if float(x_max) > RIGHT_EDGE + 1
    ]


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="no pdftotext (poppler-utils)")
@needs_pdflatex
def test_a_long_lagrangian_is_broken_across_lines_never_clipped(tmp_path: Path) -> None:
    """The key's L and h of a long Lagrangian: every term is in the PDF's text, and no word
    lies past the right margin (before, the line ran off the page: m ẋ²/2 and m ẏ²/2 lost)."""
    (tmp_path / "well.toml").write_text(LONG_SCENE)
    assignment = write_assignment(
        tmp_path / "a.toml", [{"scene": "well.toml", "parts": ["lagrangian", "eom", "conserved"]}]
    )
    roster = write_roster(tmp_path / "r.csv", [("x1", "Zoe")])
    generate(assignment, roster, 1, tmp_path / "out", "pdf")
    pdf = tmp_path / "out" / "keys" / "x1.pdf"
    text = subprocess.run(
        ["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    text = unicodedata.normalize("NFKC", text)  # ẋ as one character, however the font has it
    lagrangian = text[text.index("Lagrangian.\n") : text.index("Generalized momenta.")]
    energy = text[text.index("Conserved quantities.") :]
    for block in (lagrangian, energy):
        assert all(c in block for c in COEFFICIENTS), block
        assert "m\u1e8b2" in block and "m\u1e8f 2" in block, block  # m ẋ²/2, m ẏ²/2
    assert words_past_the_margin(pdf) == []


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="no pdftotext (poppler-utils)")
@needs_pdflatex
def test_no_formula_of_a_bank_key_runs_past_the_margin(bank_pdfs) -> None:
    """Every scene's key (the double pendulum's L and h were 43 pt too wide)."""
    out, _ = bank_pdfs
    assert words_past_the_margin(out / "keys" / "x1.pdf") == []
