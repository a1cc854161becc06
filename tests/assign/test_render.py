"""Every scene of the bank renders in every format, and the answer sheet reads back."""

from __future__ import annotations

import json
import tomllib
from html.parser import HTMLParser
from pathlib import Path

import sympy as sp

from lagrade.assign import generate
from lagrade.bank import scene_ids

from .conftest import write_roster


class _Tags(HTMLParser):
    def __init__(self):
        super().__init__()
        self.stack: list[str] = []
        self.errors: list[str] = []
        self.void = {"meta", "br", "hr", "img", "link", "input"}

    def handle_starttag(self, tag, attrs):
        if tag not in self.void:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):
        pass

    def handle_endtag(self, tag):
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"unexpected </{tag}> (open: {self.stack[-3:]})")
        else:
            self.stack.pop()


def test_every_scene_renders_in_every_format(whole_bank: Path, tmp_path: Path) -> None:
    roster = write_roster(tmp_path / "r.csv", [("a1", "Ann"), ("b2", "Ben")])
    out = tmp_path / "out"
    result = generate(whole_bank, roster, 7, out, "md,html,tex")
    assert result.warnings == []
    manifest = json.loads((out / "manifest.json").read_text())
    assert [p["scene"] for p in manifest["problems"]] == scene_ids()
    for sid in ("a1", "b2"):
        for fmt in ("md", "html", "tex"):
            for folder in ("handouts", "keys"):
                text = (out / folder / f"{sid}.{fmt}").read_text(encoding="utf-8")
                assert text.count("Problem ") >= len(scene_ids())
        html = (out / "keys" / f"{sid}.html").read_text()
        parser = _Tags()
        parser.feed(html)
        assert parser.errors == [] and parser.stack == []
        assert html.count("<svg") == len(scene_ids()) and "<math" in html
        sheet = tomllib.loads((out / "answer_sheets" / f"{sid}.toml").read_text())
        assert sheet["student_id"] == sid
        for problem in manifest["problems"]:
            fields = sheet[f"problem{problem['index']}"]
            assert sorted(fields) == sorted(p["key"] for p in problem["parts"])
            assert all(v == "" for v in fields.values())
    for student in manifest["students"]:
        for problem in student["problems"]:
            assert (out / problem["figure"]).exists()
            assert (out / problem["figure"].replace(".svg", ".pdf")).exists()


def test_key_holds_the_derived_solution(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    from lagrade.assign.tidy import tidy
    from lagrade.bank import get_scene
    from lagrade.notation.printer import latex

    out = tmp_path / "out"
    generate(small_assignment, roster, 3, out, ["md"])
    manifest = json.loads((out / "manifest.json").read_text())
    student = manifest["students"][0]
    wedge = student["problems"][0]
    variant = get_scene("wedge").variant(wedge["seed"])
    assert variant.names == wedge["names"] and variant.values == wedge["values"]
    key = (out / "keys" / f"{student['id']}.md").read_text()
    # the key shows each formula tidied (collected in the velocities and accelerations,
    # coefficients factored): the same expression as the derived one, written as a person would
    motion = [s for j in variant.jets for s in (j.dot, j.ddot)]
    for e in [*variant.euler_lagrange, variant.lagrangian]:
        shown = tidy(e, motion)
        assert sp.expand(sp.together(shown - e)) == 0
        assert latex(shown, variant.coordinates) in key
    assert r"\dot{" in key and "_dot" not in key.split("as a student")[0]
    assert wedge["quantities"]["block_acceleration"]["unit"] == "m/s^2"
    value = float(wedge["quantities"]["block_acceleration"]["value"])
    expected = float(variant.quantities["block_acceleration"].xreplace(variant.numeric_values))
    assert abs(value - expected) < 1e-3 * expected


def test_instructor_templates_override_the_shipped_ones(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "handout.md.j2").write_text("Hello {{ student.name }}: {{ problems | length }}\n")
    out = tmp_path / "out"
    generate(small_assignment, roster, 3, out, ["md"], templates_dir=mine)
    assert (out / "handouts" / "s001.md").read_text() == "Hello Student 1: 2\n"
    assert "Answer key" in (out / "keys" / "s001.md").read_text()


def test_a_template_naming_a_missing_field_fails(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    import pytest

    from lagrade.errors import AssignmentError

    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "handout.md.j2").write_text("{{ student.nickname }}\n")
    with pytest.raises(AssignmentError, match="nickname"):
        generate(small_assignment, roster, 3, tmp_path / "out", ["md"], templates_dir=mine)
    assert not (tmp_path / "out").exists()
