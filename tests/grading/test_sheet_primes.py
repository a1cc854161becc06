"""A prime inside a one-line answer of the answer sheet: the sheet asks for answers between
single quotes (TOML literal strings), and `θ'` (a prime, read as a time derivative since
issue 38) ends such a string, so `lagrangian = '1/2 m r'^2'` voided the whole sheet (0 on
every part). Found on the round trip of issue 38; primes are how Taylor's and Goldstein's
readers often write velocities (ẋ as x'). The reader recovers each such line as a multi-line
literal string, with a note per answer; what it cannot recover keeps the first error."""

from __future__ import annotations

from pathlib import Path

from lagrade.grading.sheet_quotes import quote_primes
from lagrade.grading.submission import read_sheet

KEYS = {1: ["lagrangian", "eom", "T"], 2: ["T"]}


def _read(tmp_path: Path, text: str):
    path = tmp_path / "s001.toml"
    path.write_text(text, encoding="utf-8")
    return read_sheet(path, "s001", 2, KEYS)


def test_primes_in_single_quotes_are_read_as_typed(tmp_path: Path) -> None:
    sheet = _read(
        tmp_path,
        'student_id = "s001"\n[problem1]\n'
        "lagrangian = '1/2 m (r'^2 + r^2 θ'^2) - m g r'  # mine\n"
        "T = '1/2 m x''\n[problem2]\nT = '1/2 m v^2'\n",
    )
    assert sheet.readable, sheet.reason
    assert sheet.answers[1]["lagrangian"] == "1/2 m (r'^2 + r^2 θ'^2) - m g r"
    assert sheet.answers[1]["T"] == "1/2 m x'"
    assert sheet.answers[2]["T"] == "1/2 m v^2"
    assert len(sheet.warnings) == 2, sheet.warnings
    assert sheet.warnings[0].startswith("[problem1] lagrangian: the answer holds a quote")
    assert "'''" in sheet.warnings[0]


def test_a_multi_line_answer_is_left_alone(tmp_path: Path) -> None:
    text = "[problem1]\neom = '''\nx = 'r'' + 1'\nr'' = 0\n'''\nT = 'x''\n"
    fixed, places = quote_primes(text)
    assert places == ["[problem1] T"]  # the line inside ''' … ''' is not touched
    assert "x = 'r'' + 1'" in fixed
    sheet = _read(tmp_path, text)
    assert sheet.answers[1]["eom"] == "x = 'r'' + 1'\nr'' = 0\n"
    assert sheet.answers[1]["T"] == "x'"


def test_a_valid_sheet_is_not_rewritten(tmp_path: Path) -> None:
    sheet = _read(tmp_path, "[problem1]\nT = '''1/2 m x'^2'''\nlagrangian = \"x' y'\"\n")
    assert sheet.readable and sheet.warnings == ()
    assert sheet.answers[1]["lagrangian"] == "x' y'"


def test_what_cannot_be_recovered_keeps_the_first_error(tmp_path: Path) -> None:
    sheet = _read(tmp_path, "[problem1]\nT = 'x'''y'\nlagrangian = = 2\n")
    assert not sheet.readable
    assert "not valid TOML" in sheet.reason and "line 2" in sheet.reason, sheet.reason
