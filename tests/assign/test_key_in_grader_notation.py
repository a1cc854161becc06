"""The key prints answers in the very notation the grader reads: every line of "Answers as a
student would type them", read back as the answer sheet it imitates, is judged `correct`."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.judge.check import check

from .conftest import write_roster

MULTILINE = {"transformation", "eom", "momenta", "conserved"}


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> Path:
    from .conftest import all_parts, write_assignment

    folder = tmp_path_factory.mktemp("keys")
    from lagrade.bank import scene_ids

    assignment = write_assignment(
        folder / "bank.toml", [{"scene": s, "parts": all_parts(s)} for s in scene_ids()]
    )
    roster = write_roster(folder / "roster.csv", [("s001", "Ada Lovelace")])
    out = folder / "out"
    generate(assignment, roster, 11, out, formats=("md", "html"))
    return out


def _key_blocks(markdown: str) -> dict:
    blocks = re.findall(r"```toml\n(.*?)```", markdown, flags=re.S)
    return tomllib.loads("\n".join(blocks))


def test_every_key_line_of_every_scene_is_correct_in_the_grader(generated: Path) -> None:
    manifest = json.loads((generated / "manifest.json").read_text(encoding="utf-8"))
    keys = _key_blocks((generated / "keys" / "s001.md").read_text(encoding="utf-8"))
    student = manifest["students"][0]
    refused = []
    for problem, mine in zip(manifest["problems"], student["problems"], strict=True):
        answers = keys[f"problem{problem['index']}"]
        assert set(answers) == {p["key"] for p in problem["parts"]}
        for part in problem["parts"]:
            spec = {"scene": mine["scene"], "seed": mine["seed"]}
            if part["quantity"]:
                spec["quantity"] = part["quantity"]
            answer = answers[part["key"]]
            if part["part"] in MULTILINE:
                answer = [line for line in answer.splitlines() if line.strip()]
            verdict = check(spec, part["part"], answer, time_limit=None)
            if verdict.status != "correct":
                refused.append((mine["scene"], part["key"], answer, verdict.feedback))
    assert refused == []


def test_the_html_key_shows_the_same_sheet_and_no_sympy_reprs(generated: Path) -> None:
    html = (generated / "keys" / "s001.html").read_text(encoding="utf-8")
    md = (generated / "keys" / "s001.md").read_text(encoding="utf-8")
    assert "Eq(" not in html and "Eq(" not in md
    assert "[problem1]" in html and "eom = &#39;&#39;&#39;" in html
