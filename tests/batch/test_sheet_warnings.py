"""Student work is never dropped silently: a misspelled part key is a warning naming the key
and the closest valid one, and a file in the submissions folder that is no roster student's
sheet is listed in the summary (and named in the `missing` reason when it is clearly meant
for that student)."""

from __future__ import annotations

import json
import re

from lagrade.cli.main import main
from lagrade.grading.batch import grade


def _result(out, sid):
    return json.loads((out / "students" / f"{sid}.json").read_text())


def test_misspelled_key_is_a_warning_with_the_closest_key(workspace):
    sheet = workspace / "submissions" / "s01.toml"
    text = sheet.read_text()
    sheet.write_text(re.sub(r"(?m)^lagrangian = ", "lagrangain = ", text, count=1))
    summary = grade(workspace / "out" / "manifest.json", workspace / "submissions")
    result = _result(summary.out_dir, "s01")
    warning = next(w for w in result["warnings"] if "lagrangain" in w)
    assert "[problem1]" in warning and "did you mean 'lagrangian'" in warning
    assert "not answered" in warning
    lagrangian = result["problems"][0]["parts"][1]
    assert lagrangian["key"] == "lagrangian" and "blank" in lagrangian["mistakes"]
    feedback = (summary.out_dir / "feedback" / "s01.md").read_text()
    assert "lagrangain" in feedback


def test_stray_files_are_reported(workspace, capsys):
    subs = workspace / "submissions"
    (subs / "s05.toml").rename(subs / "s05.txt")  # meant for s05, wrong suffix
    (subs / "s005.toml").write_text("student_id = 's005'\n")  # no such student
    (subs / ".DS_Store").write_bytes(b"\x00\x01")  # hidden: not worth a line
    status = main([
        "grade", str(workspace / "out" / "manifest.json"), str(subs), "--out",
        str(workspace / "grades"),
    ])  # fmt: skip
    assert status == 1
    printed = capsys.readouterr().out
    out = workspace / "grades"
    missing = _result(out, "s05")
    assert missing["status"] == "missing" and "s05.txt" in missing["reason"]
    assert "s05.toml" in missing["reason"]
    stray = json.loads((out / "summary.json").read_text())["stray_files"]
    assert set(stray) == {"s005.toml", "s05.txt"}
    assert "did you mean s05" in stray["s005.toml"]
    summary_md = (out / "summary.md").read_text()
    assert "s005.toml" in summary_md and "s05.txt" in summary_md
    assert "s005.toml" in printed and "s05.txt" in printed
    # the per-student table `demo` prints, one row per roster student
    assert re.search(r"(?m)^s05 +Student 5 +missing", printed)
    assert sum(1 for line in printed.splitlines() if re.match(r"s\d\d ", line)) == 12


def test_renaming_the_stray_file_regrades(workspace):
    subs = workspace / "submissions"
    (subs / "s05.toml").rename(subs / "s05.txt")
    grade(workspace / "out" / "manifest.json", subs)
    (subs / "s05.txt").rename(subs / "s05.toml")
    summary = grade(workspace / "out" / "manifest.json", subs)
    assert _result(summary.out_dir, "s05")["status"] == "graded" and not summary.stray
