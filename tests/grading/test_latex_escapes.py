"""LaTeX in a double-quoted TOML or JSON string: `\\theta` is a tab and "heta", `\\frac` a form
feed and "rac". The sheet reader reads a known command back as meant and warns, per answer,
naming the fix (single quotes); a control character it cannot restore is warned about too."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from lagrade.grading.submission import read_sheet

KEYS = {1: ["eom", "lagrangian", "T"]}


def _read(tmp_path: Path, text: str, suffix: str = ".toml"):
    path = tmp_path / f"s001{suffix}"
    path.write_text(text, encoding="utf-8")
    return read_sheet(path, "s001", 1, KEYS)


def test_theta_and_frac_in_double_quotes_are_read_as_meant(tmp_path: Path) -> None:
    sheet = _read(
        tmp_path,
        '[problem1]\nlagrangian = "\\frac{1}{2} m l^2 theta_dot^2 + m g l cos(\\theta)"\n'
        "T = '\\frac{1}{2} m v^2'\n",
    )
    assert sheet.answers[1]["lagrangian"] == "\\frac{1}{2} m l^2 theta_dot^2 + m g l cos(\\theta)"
    assert sheet.answers[1]["T"] == "\\frac{1}{2} m v^2"
    (warning,) = sheet.warnings
    assert "[problem1] lagrangian" in warning and "single quotes" in warning
    assert "\\frac, \\theta" in warning


def test_each_escape_of_a_known_command_is_restored(tmp_path: Path) -> None:
    sheet = _read(
        tmp_path,
        '[problem1]\neom = ["\\theta + \\beta", "\\rho \\nu = \\frac{1}{2}"]\nT = "\\tau"\n',
    )
    assert sheet.readable, sheet.reason
    assert sheet.answers[1]["eom"] == ["\\theta + \\beta", "\\rho \\nu = \\frac{1}{2}"]
    assert sheet.answers[1]["T"] == "\\tau"
    assert len(sheet.warnings) == 2
    assert all("single quotes" in w for w in sheet.warnings)
    assert "[problem1] eom" in sheet.warnings[0] and "\\theta" in sheet.warnings[0]


def test_an_unknown_command_is_not_guessed_but_warned_about(tmp_path: Path) -> None:
    sheet = _read(tmp_path, '[problem1]\nT = "\\thetadot^2"\n')
    assert sheet.answers[1]["T"] == "\thetadot^2"  # not a command the notation reads
    (warning,) = sheet.warnings
    assert "a tab" in warning and "single quotes" in warning


def test_json_sheets_follow_the_same_rule(tmp_path: Path) -> None:
    raw = '{"problem1": {"T": "\\frac{m}{2} \\dot{x}^2"}}'
    sheet = _read(tmp_path, raw.replace("\\dot", "\\\\dot"), ".json")
    assert sheet.answers[1]["T"] == "\\frac{m}{2} \\dot{x}^2"
    assert any("single quotes" in w for w in sheet.warnings)
    good = _read(tmp_path, json.dumps({"problem1": {"T": "\\frac{m}{2}"}}), ".json")
    assert good.answers[1]["T"] == "\\frac{m}{2}" and not good.warnings


def test_real_line_breaks_and_single_quotes_are_left_alone(tmp_path: Path) -> None:
    sheet = _read(
        tmp_path,
        "[problem1]\neom = '''\n\\ddot{\\theta} = 0\nu_dot = 0\n'''\nT = '\\frac{1}{2}'\n",
    )
    assert sheet.answers[1]["eom"] == "\\ddot{\\theta} = 0\nu_dot = 0\n"
    assert sheet.answers[1]["T"] == "\\frac{1}{2}"
    assert not sheet.warnings


# Issue 38: a backslash sequence the format cannot read at all. TOML 1.0 (toml.io, "String"):
# "All other escape sequences not listed above are reserved; if they are used, TOML should
# produce an error" -- so `"\dot{q}"`, LaTeX's velocity (Taylor, Classical Mechanics, ch. 7;
# Goldstein ch. 1: \dot q), voided the whole sheet. JSON (RFC 8259, section 7) likewise.
UNKNOWN = [
    ('T = "\\dot{x}^2"', "\\dot{x}^2", "\\dot"),
    ('eom = "\\ddot{q} + \\omega^2 q = 0"', "\\ddot{q} + \\omega^2 q = 0", "\\ddot, \\omega"),
    ('T = "\\sin\\alpha"', "\\sin\\alpha", "\\sin, \\alpha"),
    ('T = "\\left(\\dot q\\right)^2"', "\\left(\\dot q\\right)^2", "\\left, \\dot, \\right"),
    ('T = "\\cos\\theta \\, \\dot x"', "\\cos\\theta \\, \\dot x", "\\cos, \\,, \\dot, \\theta"),
    ('eom = ["\\dot{q} = 0", "\\ddot q = 0"]', ["\\dot{q} = 0", "\\ddot q = 0"], "\\dot, \\ddot"),
]


@pytest.mark.parametrize(("line", "meant", "named"), UNKNOWN)
def test_an_escape_the_format_cannot_read_is_read_as_meant_with_a_note(
    tmp_path: Path, line: str, meant, named: str
) -> None:
    sheet = _read(tmp_path, f"[problem1]\n{line}\nlagrangian = 'm g'\n")
    assert sheet.readable, sheet.reason
    key = line.split(" = ")[0]
    assert sheet.answers[1][key] == meant
    assert sheet.answers[1]["lagrangian"] == "m g"
    (warning,) = sheet.warnings  # one sentence per answer, naming what was read and the fix
    assert f"[problem1] {key}" in warning and named in warning and "single quotes" in warning


def test_json_escapes_the_format_cannot_read(tmp_path: Path) -> None:
    sheet = _read(tmp_path, '{"problem1": {"T": "\\dot{x}^2", "eom": "\\\\ddot{x} = 0"}}', ".json")
    assert sheet.readable, sheet.reason
    assert sheet.answers[1] == {"T": "\\dot{x}^2", "eom": "\\ddot{x} = 0"}
    (warning,) = sheet.warnings
    assert "[problem1] T" in warning and "\\dot" in warning


def test_a_sheet_broken_otherwise_still_names_single_quotes(tmp_path: Path) -> None:
    sheet = _read(tmp_path, '[problem1]\nT = "\\dot{x}^2"\neom = [\n')
    assert not sheet.readable and "single quotes" in sheet.reason
