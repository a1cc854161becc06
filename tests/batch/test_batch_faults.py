"""End to end over a generated class with planted faults: every roster student gets one row
with the right status, nothing stops the batch, and a rerun changes nothing."""

from __future__ import annotations

import csv
import json
import time
from pathlib import Path

import pytest

import lagrade.judge.driver as driver
from lagrade.grading.batch import grade
from lagrade.judge.worker import Limits


def rows(out: Path) -> dict[str, dict[str, str]]:
    with (out / "gradebook.csv").open(newline="") as f:
        return {r["id"]: r for r in csv.DictReader(f)}


def plant(submissions: Path) -> None:
    """Missing, empty, huge, binary, non-UTF-8, malformed and hostile sheets."""
    (submissions / "s01.toml").unlink()  # missing
    (submissions / "s02.toml").write_bytes(b"")  # empty
    with (submissions / "s03.toml").open("wb") as f:  # 50 MB
        f.write(b"# padding\n" * (5 * 1024 * 1024))
    (submissions / "s04.toml").write_bytes(b"\x00\x01\x02\xff" * 100)  # binary
    (submissions / "s05.toml").write_bytes("[problem1]\nlagrangian = 'ä'\n".encode("latin-1"))
    (submissions / "s06.toml").write_text("[problem1\nlagrangian = ")  # malformed TOML
    (submissions / "s07.toml").write_text(  # injection attempts
        "[problem1]\n"
        "lagrangian = \"__import__('os').system('touch PWNED')\"\n"
        'eom = "().__class__.__bases__[0].__subclasses__()"\n'
        'conserved = "9**9**9**9"\n'
        'dof = "lambda: 1"\n'
        "[problem2]\n"
        'lagrangian = "' + "(" * 5000 + '"\n'
    )


def test_every_student_gets_a_row_with_the_right_status(workspace, monkeypatch):
    monkeypatch.chdir(workspace)
    plant(workspace / "submissions")
    summary = grade(
        workspace / "out" / "manifest.json", workspace / "submissions", workspace / "grades", jobs=2
    )
    table = rows(workspace / "grades")
    assert sorted(table) == [f"s{i:02d}" for i in range(1, 13)]
    assert table["s01"]["status"] == "missing"
    for sid, reason in [
        ("s02", "empty"),
        ("s03", "MB"),
        ("s04", "binary"),
        ("s05", "UTF-8"),
        ("s06", "not valid TOML"),
    ]:
        assert table[sid]["status"] == "invalid", sid
        assert reason in table[sid]["reason"], (sid, table[sid]["reason"])
    assert table["s07"]["status"] == "graded"  # hostile text is just wrong answers
    assert float(table["s07"]["score"]) == 0
    assert not (workspace / "PWNED").exists()
    assert all(table[f"s{i:02d}"]["status"] == "graded" for i in range(8, 13))
    assert summary.counts == {"graded": 6, "missing": 1, "invalid": 5, "timeout": 0, "error": 0}
    assert not summary.all_graded
    hostile = json.loads((workspace / "grades" / "students" / "s07.json").read_text())
    verdicts = {p["key"]: p["verdict"] for p in hostile["problems"][0]["parts"]}
    assert verdicts["lagrangian"] == verdicts["eom"] == verdicts["dof"] == "invalid"


def test_outputs_exist_for_every_student(workspace):
    summary = grade(
        workspace / "out" / "manifest.json", workspace / "submissions", workspace / "grades"
    )
    out = workspace / "grades"
    for r in summary.results:
        sid = r["student"]["id"]
        assert (out / "students" / f"{sid}.json").exists()
        assert (out / "feedback" / f"{sid}.html").exists() and (
            out / "feedback" / f"{sid}.md"
        ).exists()
        gradescope = json.loads((out / "gradescope" / sid / "results.json").read_text())
        assert gradescope["score"] == pytest.approx(r["score"])
        assert {"name", "score", "max_score", "output"} <= set(gradescope["tests"][0])
    for name in ("gradebook.csv", "summary.json", "summary.md", "scores.png", "scores.svg"):
        assert (out / name).stat().st_size > 0


def test_rerun_reuses_unchanged_results_and_regrades_changed_ones(workspace):
    manifest, subs, out = (
        workspace / "out" / "manifest.json",
        workspace / "submissions",
        workspace / "grades",
    )
    first = grade(manifest, subs, out, jobs=2)
    before = {p.name: p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}
    second = grade(manifest, subs, out, jobs=2)
    after = {p.name: p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}
    assert second.reused == len(first.results)
    assert before == after  # the same inputs give the same bytes
    (subs / "s05.toml").write_text("[problem1]\ndof = '1'\n")
    third = grade(manifest, subs, out, jobs=2)
    assert third.reused == len(first.results) - 1
    assert rows(out)["s05"]["score"] == "1"


HANG = "zzhang"  # an answer that makes the planted checker hang


def test_an_answer_that_hangs_a_check_in_python_times_out_that_part_only(workspace, monkeypatch):
    real = driver.run_checker

    def hanging(problem, part, answer, given=None):
        if HANG in str(answer):
            time.sleep(60)
        return real(problem, part, answer, given)

    monkeypatch.setattr(driver, "run_checker", hanging)  # children are forked: they inherit it
    subs = workspace / "submissions"
    (subs / "s01.toml").write_text(f"[problem1]\ndof = '1'\neom = '{HANG}'\n")
    summary = grade(
        workspace / "out" / "manifest.json", subs, workspace / "grades", jobs=2, part_time_limit=0.3
    )
    table = rows(workspace / "grades")
    assert table["s01"]["status"] == "timeout" and "problem 1 eom" in table["s01"]["reason"]
    result = json.loads((workspace / "grades" / "students" / "s01.json").read_text())
    parts = {p["key"]: p["verdict"] for p in result["problems"][0]["parts"]}
    assert parts["eom"] == "timeout" and parts["dof"] == "correct"
    assert summary.counts["timeout"] == 1 and summary.counts["graded"] == 11


def test_an_answer_that_hangs_a_check_in_c_code_is_killed_and_the_batch_goes_on(
    workspace, monkeypatch
):
    real = driver.run_checker

    def spinning(problem, part, answer, given=None):
        if HANG in str(answer):
            sum(range(10**13))  # one C call: no Python signal handler runs until it returns
        return real(problem, part, answer, given)

    monkeypatch.setattr(driver, "run_checker", spinning)
    subs = workspace / "submissions"
    (subs / "s03.toml").write_text(f"[problem2]\ncyclic = '{HANG}'\n")
    summary = grade(
        workspace / "out" / "manifest.json",
        subs,
        workspace / "grades",
        jobs=2,
        part_time_limit=0.3,
        limits=Limits(seconds=4),
    )
    table = rows(workspace / "grades")
    assert table["s03"]["status"] == "timeout"
    assert table["s03"]["reason"] == "ran out of time on problem 2 cyclic"  # that part only
    result = json.loads((workspace / "grades" / "students" / "s03.json").read_text())
    parts = {p["key"]: p["verdict"] for p in result["problems"][1]["parts"]}
    assert parts == {
        "lagrangian": "incorrect",
        "eom": "incorrect",
        "momenta": "incorrect",
        "cyclic": "timeout",
    }  # blank parts are judged, the killed one is timeout
    assert summary.counts["timeout"] == 1 and summary.counts["graded"] == 11
