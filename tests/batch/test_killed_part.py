"""A part whose check is held in C code, where the alarm cannot interrupt it, is killed at its
limit + grace and costs only itself: the parts judged before it keep their verdicts, the parts
after it are judged by a fresh worker, and the student's other points all count."""

from __future__ import annotations

import importlib
import json
import re
import shutil
from pathlib import Path

import pytest

import lagrade.judge.driver as driver
from lagrade.assign import generate
from lagrade.cli.demo_class import ASSIGNMENT as DEMO_ASSIGNMENT
from lagrade.cli.demo_class import write_submissions
from lagrade.grading.batch import grade
from lagrade.judge.worker import Limits
from tests.planted import HANG, spinning

check_module = importlib.import_module("lagrade.judge.driver")  # the package shadows the name

PART_LIMIT = 2.0  # the default


def _parts(out: Path, student_id: str) -> dict[str, dict]:
    result = json.loads((out / "students" / f"{student_id}.json").read_text())
    return {
        f"{problem['index']}/{part['key']}": part
        for problem in result["problems"]
        for part in problem["parts"]
    }


def _result(out: Path, student_id: str) -> dict:
    return json.loads((out / "students" / f"{student_id}.json").read_text())


def _replace_answer(sheet: Path, problem: int, key: str, answer: str) -> None:
    """Put `answer` in place of the sheet's answer to `key` in `[problem<n>]`."""
    text = sheet.read_text()
    head, section = text.split(f"[problem{problem}]", 1)
    section, sep, rest = section.partition("\n[problem")
    section, count = re.subn(
        rf"^{key} = '''[\s\S]*?'''$", f"{key} = '{answer}'", section, count=1, flags=re.M
    )
    assert count == 1, f"no {key} in problem {problem} of {sheet}"
    sheet.write_text(head + f"[problem{problem}]" + section + sep + rest)


@pytest.fixture(autouse=True, scope="module")
def _question_cache_left_as_found():
    """`grade` derives its questions in this process (`warm_up`) and shares each among the seeds
    of a class: leave the cache as it was, so that a later test comparing `check` with a fresh
    `grade` (tests/grading/test_one_checker.py) does not meet this class's questions."""
    saved = (dict(check_module._problems), set(check_module._prepared))
    yield
    check_module._problems.clear()
    check_module._problems.update(saved[0])
    check_module._prepared.clear()
    check_module._prepared.update(saved[1])


@pytest.fixture(scope="module")
def demo_class(tmp_path_factory) -> Path:
    """`lagrade demo`'s assignment for three students, their synthetic sheets and their grades."""
    root = tmp_path_factory.mktemp("demo-class")
    (root / "assignment.toml").write_text(DEMO_ASSIGNMENT)
    (root / "roster.csv").write_text("id,name\nd1,Ada\nd2,Emmy\nd3,Lise\n")
    generate(root / "assignment.toml", root / "roster.csv", 5, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    write_submissions(root / "pristine", manifest, malformed=None, missing=None)
    summary = grade(
        root / "out" / "manifest.json",
        root / "pristine",
        root / "pristine-grades",
        jobs=2,
        part_time_limit=PART_LIMIT,
    )
    assert summary.all_graded
    return root


def test_a_slow_c_level_answer_costs_only_its_part(demo_class, tmp_path, monkeypatch):
    """The demo class with one answer replaced by one that holds its worker in C (the planted
    checker, `tests/planted.py`): that student keeps every other part's points."""
    monkeypatch.setattr(driver, "run_checker", spinning(driver.run_checker))
    subs = tmp_path / "subs"
    shutil.copytree(demo_class / "pristine", subs)
    _replace_answer(subs / "d1.toml", 1, "block_acceleration", HANG)
    summary = grade(
        demo_class / "out" / "manifest.json",
        subs,
        tmp_path / "grades",
        jobs=2,
        part_time_limit=PART_LIMIT,
    )
    before = _parts(demo_class / "pristine-grades", "d1")
    after = _parts(tmp_path / "grades", "d1")
    assert set(after) == set(before)
    slow = after.pop("1/block_acceleration")
    assert slow["verdict"] == "timeout" and slow["points"] == 0
    for part_id, part in after.items():  # every other part as it was graded without the payload
        assert (part["verdict"], part["points"]) == (
            before[part_id]["verdict"],
            before[part_id]["points"],
        ), part_id
    pristine = _result(demo_class / "pristine-grades", "d1")
    lost = before["1/block_acceleration"]["points"]
    assert _result(tmp_path / "grades", "d1")["score"] == pytest.approx(pristine["score"] - lost)
    assert summary.counts["timeout"] == 1
    assert "problem 1 block_acceleration" in _result(tmp_path / "grades", "d1")["reason"]
    for other in ("d2", "d3"):
        assert _result(tmp_path / "grades", other)["score"] == pytest.approx(
            _result(demo_class / "pristine-grades", other)["score"]
        )


def test_a_part_killed_in_c_code_keeps_the_parts_before_and_after_it(
    demo_class, tmp_path, monkeypatch
):
    """The planted checker spins in C whatever the judge's own bounds become: the kill at
    limit + grace is what stops it, twice in one sheet, and each kill costs only its part."""
    monkeypatch.setattr(driver, "run_checker", spinning(driver.run_checker))
    subs = tmp_path / "subs"
    shutil.copytree(demo_class / "pristine", subs)
    _replace_answer(subs / "d2.toml", 1, "eom", HANG)
    _replace_answer(subs / "d2.toml", 2, "V", HANG)
    summary = grade(
        demo_class / "out" / "manifest.json",
        subs,
        tmp_path / "grades",
        jobs=2,
        part_time_limit=PART_LIMIT,
        limits=Limits(seconds=10),
    )
    before = _parts(demo_class / "pristine-grades", "d2")
    after = _parts(tmp_path / "grades", "d2")
    for part_id in ("1/eom", "2/V"):
        killed = after.pop(part_id)
        assert killed["verdict"] == "timeout" and killed["points"] == 0
        assert killed["feedback"] == [
            "The check ran out of time (judging the answer took longer than 2 s)."
        ]
    for part_id, part in after.items():
        assert (part["verdict"], part["points"]) == (
            before[part_id]["verdict"],
            before[part_id]["points"],
        ), part_id
    result = _result(tmp_path / "grades", "d2")
    assert result["status"] == "timeout"
    assert result["reason"] == "ran out of time on problem 1 eom, problem 2 V"
    assert summary.counts == {"graded": 2, "missing": 0, "invalid": 0, "timeout": 1, "error": 0}
