"""What a handout and its answer sheet tell a student: every name a part's answer may use (the
Cartesian `x_bob` of a transformation, `p_theta` of a momentum), prompts that ask for what the
field accepts, literal TOML strings for LaTeX, and SI units typeset in each format."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.bank import scene_ids
from lagrade.judge.check import check

from .conftest import all_parts, write_assignment, write_roster

FUNCTIONS = {"sin", "cos", "tan", "sqrt", "exp", "log", "pi", "none", "asin", "acos", "atan"}


@pytest.fixture(scope="module")
def out(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("handouts")
    assignment = write_assignment(
        folder / "bank.toml", [{"scene": s, "parts": all_parts(s)} for s in scene_ids()]
    )
    roster = write_roster(folder / "roster.csv", [("s001", "Ada Lovelace")])
    generate(assignment, roster, 5, folder / "out", formats=("md", "html", "tex"))
    return folder / "out"


def _sheet_names(sheet: str) -> dict[tuple[int, str], set[str]]:
    """(problem, field) → every name its comments list (left-hand sides and may-use)."""
    names: dict[tuple[int, str], set[str]] = {}
    problem, pending = 0, set()
    for line in sheet.splitlines():
        if m := re.match(r"\[problem(\d+)\]", line):
            problem, pending = int(m.group(1)), set()
        elif m := re.match(r"#   (?:Left-hand sides|May use|Coordinate names): (.*)", line):
            pending |= {n.strip() for n in m.group(1).split(",")}
        elif m := re.match(r"(\w+) = ", line):
            if problem:
                names[(problem, m.group(1))] = pending
            pending = set()
    return names


def test_the_sheet_names_every_symbol_the_key_uses(out: Path) -> None:
    sheet = (out / "answer_sheets" / "s001.toml").read_text(encoding="utf-8")
    listed = _sheet_names(sheet)
    key_md = (out / "keys" / "s001.md").read_text(encoding="utf-8")
    keys = tomllib.loads("\n".join(re.findall(r"```toml\n(.*?)```", key_md, flags=re.S)))
    assert len(keys) == len(scene_ids())
    unnamed = []
    for table, answers in keys.items():
        k = int(table.removeprefix("problem"))
        for field, answer in answers.items():
            if field == "dof":
                continue
            used = set(re.findall(r"[A-Za-z][A-Za-z0-9_]*", answer)) - FUNCTIONS
            if used - listed[(k, field)]:
                unnamed.append((table, field, sorted(used - listed[(k, field)])))
    assert unnamed == []


def test_the_transformation_part_names_the_cartesian_coordinates_the_grader_wants(out) -> None:
    handout = (out / "handouts" / "s001.md").read_text(encoding="utf-8")
    assert "Left-hand sides: `x_bob`, `y_bob`" in handout  # the simple pendulum's bob
    refused = check({"scene": "simple_pendulum"}, "transformation", ["x = l*sin(theta)"])
    assert refused.status != "correct"  # the names listed are the ones that count


def test_the_dof_prompt_asks_for_what_the_field_accepts(out: Path) -> None:
    sheet = (out / "answer_sheets" / "s001.toml").read_text(encoding="utf-8")
    prompt = next(line for line in sheet.splitlines() if "degrees of freedom" in line)
    assert "List the constraints" not in prompt and "whole number, e.g. 2" in prompt
    assert check({"scene": "wedge"}, "dof", "2", time_limit=None).status == "correct"


def test_the_sheet_uses_literal_strings_and_says_why(out: Path) -> None:
    sheet = (out / "answer_sheets" / "s001.toml").read_text(encoding="utf-8")
    assert "literal strings" in sheet and "\\t as a tab" in sheet
    latex = r"\frac{1}{2} m l^2 \dot{\theta}^2 + m g l \cos\theta"
    filled = sheet.replace("lagrangian = ''", f"lagrangian = '{latex}'", 1)
    read = tomllib.loads(filled)
    assert read["problem1"]["lagrangian"] == latex


def test_units_are_typeset_in_every_format(out: Path) -> None:
    html = (out / "handouts" / "s001.html").read_text(encoding="utf-8")
    tex = (out / "handouts" / "s001.tex").read_text(encoding="utf-8")
    md = (out / "handouts" / "s001.md").read_text(encoding="utf-8")
    assert "m/s<sup>2</sup>" in html and "m/s^2" not in html
    assert r"\mathrm{m/s^{2}}" in tex and "s\\textasciicircum" not in tex
    assert "m/s²" in md and "m/s^2" not in md


def test_a_quantity_name_is_a_word_not_a_subscript(out: Path) -> None:
    for fmt in ("md", "tex"):
        key = (out / "keys" / f"s001.{fmt}").read_text(encoding="utf-8")
        assert r"\text{block\_acceleration} =" in key
        assert "block_{acceleration}" not in key
    html = (out / "keys" / "s001.html").read_text(encoding="utf-8")
    assert "<mtext>block_acceleration</mtext><mo>=</mo>" in html
    assert "<msub><mi>block</mi>" not in html


def test_prompts_read_as_sentences_with_their_formulas_unbroken(out: Path) -> None:
    """A quantity's prompt takes its article ("Find the angular frequency of small
    oscillations", not "Find angular frequency …"), the key's heading for it starts with a
    capital, and the formulas of the prompts hold together: no-break spaces and a minus sign,
    never a hyphen a browser or TeX may break the line at."""
    html = (out / "handouts" / "s001.html").read_text(encoding="utf-8")
    tex = (out / "handouts" / "s001.tex").read_text(encoding="utf-8")
    md = (out / "handouts" / "s001.md").read_text(encoding="utf-8")
    for text in (html, md):
        assert "DOF\u00a0=\u00a03N\u00a0\u2212\u00a0k" in text and "3N - k" not in text
        assert "L\u00a0=\u00a0T\u00a0\u2212\u00a0V" in text and "L = T - V" not in text
        assert "Find the angular frequency of small oscillations" in text
        assert "Find angular" not in text and "Find acceleration" not in text
        assert "Find the the" not in text and "Find the how" not in text
        assert "Euler\u2013Lagrange equations" in text
    assert r"(DOF~=~3N~\ensuremath{-}~k)" in tex and "3N - k" not in tex
    key = (out / "keys" / "s001.md").read_text(encoding="utf-8")
    headings = re.findall(r"^### (.*)$", key, flags=re.M)
    assert "Angular frequency of small oscillations of the pendulum" in headings
    assert "The lower normal-mode angular frequency" in headings
    assert not [h for h in headings if h[:1].islower()], headings
    assert r"\textbf{The lower normal-mode angular frequency.}" in (
        out / "keys" / "s001.tex"
    ).read_text(encoding="utf-8")
