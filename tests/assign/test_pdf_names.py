"""Issue 24: a PDF for every name. A roster with Đặng Thị Ngọc Hà, 王小明 or Αλέξανδρος
Παπαδόπουλος got no handout or key PDF for those students (pdflatex's errors shown only as
warnings), `generate` exited 0 and the manifest listed the missing files. Now pdflatex typesets
what it can and LuaLaTeX, with fallback fonts, the rest; a PDF neither can make is left out of
the manifest with its reason and `generate` exits 1.

Each PDF is read back with poppler's `pdftotext` (the names are in its text layer), the way a
reader's viewer or a search finds them. Skipped, saying why, without TeX Live's LuaLaTeX, fontspec
and the Noto fonts (`.ci/run` installs them)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import tomllib
import unicodedata
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.assign.pdf import PDFLATEX_HINT, TEX_PACKAGES
from lagrade.cli.main import main

from .conftest import write_assignment, write_roster


def _missing() -> list[str]:
    missing = [
        tool
        for tool in ("pdflatex", "lualatex", "kpsewhich", "pdftotext")
        if not shutil.which(tool)
    ]
    if "kpsewhich" not in missing:
        for name in ("fontspec.sty", "NotoSerif-Regular.ttf", "NotoSerifCJK-Regular.ttc"):
            run = subprocess.run(["kpsewhich", name], capture_output=True, check=False)
            if not run.stdout.strip():
                missing.append(name)
    return missing


needs_lualatex = pytest.mark.skipif(
    bool(_missing()),
    reason=f"missing {', '.join(_missing())}; apt-get install --no-install-recommends "
    + " ".join(TEX_PACKAGES),
)

NAMES = {
    "s1": "Đặng Thị Ngọc Hà",
    "s2": "王小明",
    "s3": "Αλέξανδρος Παπαδόπουλος",
    "s4": "Никола́й Ива́нович",
    "s5": "김민준",
    "s6": "Ada Lovelace",
}


def text_of(pdf: Path) -> str:
    run = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, check=True)
    return unicodedata.normalize("NFC", run.stdout.decode("utf-8"))


@pytest.fixture(scope="module")
def assignment(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("names")
    return write_assignment(
        root / "a.toml", [{"scene": "simple_pendulum", "parts": ["dof", "lagrangian"]}]
    )


@needs_lualatex
def test_a_name_in_any_script_gets_its_handout_and_key_pdf(assignment, tmp_path):
    roster = write_roster(tmp_path / "r.csv", list(NAMES.items()))
    out = tmp_path / "out"
    result = generate(assignment, roster, 5, out, "pdf")
    assert result.warnings == [] and result.unwritten == {}
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    for student in manifest["students"]:
        sid = student["id"]
        assert "unwritten" not in student
        for kind, folder in (("handout_pdf", "handouts"), ("key_pdf", "keys")):
            assert student["files"][kind] == f"{folder}/{sid}.pdf"
            text = text_of(out / folder / f"{sid}.pdf")
            assert f"Student: {unicodedata.normalize('NFC', NAMES[sid])} ({sid})" in text, (
                sid,
                text[:200],
            )


@needs_lualatex
def test_a_lualatex_key_copies_out_as_the_same_toml(assignment, tmp_path):
    """The key's answers block is copyable under LuaLaTeX too: the typewriter glyphs are picked
    by engine (OT1's straight-quote slot 13 is a carriage return in a Unicode font, which once
    stopped every LuaLaTeX key with "Missing character U+000D")."""
    roster = write_roster(tmp_path / "r.csv", [("s2", NAMES["s2"])])
    out = tmp_path / "out"
    result = generate(assignment, roster, 5, out, "pdf,md")
    assert result.unwritten == {}
    text = text_of(out / "keys" / "s2.pdf")
    expected = tomllib.loads(
        "\n".join(re.findall(r"```toml\n(.*?)```", (out / "keys" / "s2.md").read_text(), re.S))
    )
    block = re.split(r"\n\s*\n", text[text.index("[problem1]") :])[0]
    assert tomllib.loads(block) == expected, block


@needs_lualatex
def test_a_pdf_of_a_name_pdflatex_cannot_typeset_is_byte_identical_across_runs(
    assignment, tmp_path
):
    roster = write_roster(tmp_path / "r.csv", [("s2", NAMES["s2"])])
    for run in ("a", "b"):
        generate(assignment, roster, 5, tmp_path / run, "pdf")
    for folder in ("handouts", "keys"):
        for sid in ("s2",):
            a = (tmp_path / "a" / folder / f"{sid}.pdf").read_bytes()
            assert a == (tmp_path / "b" / folder / f"{sid}.pdf").read_bytes(), (folder, sid)


@needs_lualatex
def test_a_name_no_font_can_typeset_is_left_out_of_the_manifest_and_exits_1(
    assignment, tmp_path, capsys
):
    """Egyptian hieroglyphs are in none of the fonts: that student's PDFs are not made, the
    manifest says why, the others are made, and `generate` does not claim success."""
    roster = write_roster(tmp_path / "r.csv", [("s1", "Ada \U00013000 Lovelace"), ("s2", "王小明")])
    out = tmp_path / "out"
    status = main(
        ["generate", str(assignment), "--roster", str(roster), "--seed", "5", "--out", str(out),
         "--formats", "pdf"]
    )  # fmt: skip
    err = capsys.readouterr().err
    assert status == 1
    assert "handouts/s1.pdf was not made" in err and "keys/s1.pdf was not made" in err
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    first, second = manifest["students"]
    assert "handout_pdf" not in first["files"] and "key_pdf" not in first["files"]
    assert set(first["unwritten"]) == {"handout_pdf", "key_pdf"}
    assert "U+13000" in first["unwritten"]["handout_pdf"]  # the reason names the character
    assert not (out / "handouts" / "s1.pdf").exists()
    assert second["files"]["handout_pdf"] == "handouts/s2.pdf" and "unwritten" not in second
    assert (out / "handouts" / "s2.pdf").exists()


def test_without_latex_the_manifest_lists_no_pdf_and_generate_exits_1(
    assignment, tmp_path, monkeypatch, capsys
):
    monkeypatch.setattr(shutil, "which", lambda name: None)
    roster = write_roster(tmp_path / "r.csv", [("s1", "Ada")])
    out = tmp_path / "out"
    status = main(
        ["generate", str(assignment), "--roster", str(roster), "--seed", "5", "--out", str(out),
         "--formats", "pdf"]
    )  # fmt: skip
    assert status == 1
    assert PDFLATEX_HINT in capsys.readouterr().err
    (student,) = json.loads((out / "manifest.json").read_text(encoding="utf-8"))["students"]
    assert "handout_pdf" not in student["files"] and student["files"]["handout_tex"]
    assert student["unwritten"] == {"handout_pdf": PDFLATEX_HINT, "key_pdf": PDFLATEX_HINT}
