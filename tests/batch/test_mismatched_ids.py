"""A sheet whose `student_id` is another student's (s02.toml says s05: copied, or handed in under
the wrong name) is graded as its file's student — and `grade` lists it for the instructor: in
the printed table (the row and a list after it), in summary.md and summary.json, and in the
student's JSON. `grade --as-of` without a log of saves is one clear error."""

from __future__ import annotations

import csv
import io
import json
import re

from lagrade.cli.main import main


def test_grade_lists_sheets_naming_another_student(workspace, capsys):
    sheet = workspace / "submissions" / "s02.toml"
    text = sheet.read_text()
    assert re.search(r'^student_id = "s02"$', text, flags=re.M)
    sheet.write_text(re.sub(r'^student_id = "s02"$', 'student_id = "s05"', text, flags=re.M))
    out = workspace / "grades"
    status = main(["grade", str(workspace / "out" / "manifest.json"),
                   str(workspace / "submissions"), "--out", str(out)])  # fmt: skip
    printed = capsys.readouterr().out
    assert status in (0, 1)
    row = next(line for line in printed.splitlines() if line.startswith("s02 "))
    assert "graded" in row and "sheet says student_id 's05'" in row
    assert "sheets naming another student_id (graded as the file's student):" in printed
    assert "  s02: the sheet says student_id = 's05'" in printed
    totals = next(line for line in printed.splitlines() if line.startswith("12 students:"))
    assert "; 1 sheet(s) naming another student_id" in totals
    summary = json.loads((out / "summary.json").read_text())
    assert summary["mismatched_ids"] == {"s02": "s05"}
    markdown = (out / "summary.md").read_text()
    assert "Sheets whose `student_id` is not their file's" in markdown
    assert "- `s02`: the sheet says student_id = `s05`" in markdown
    result = json.loads((out / "students" / "s02.json").read_text())
    assert result["sheet_student_id"] == "s05" and result["status"] == "graded"
    assert "sheet_student_id" not in json.loads((out / "students" / "s03.json").read_text())
    # the gradebook's reason column says it too (issue 38: it was empty)
    rows = {
        row["id"]: row for row in csv.DictReader(io.StringIO((out / "gradebook.csv").read_text()))
    }
    assert rows["s02"]["reason"] == "the sheet says student_id 's05'; graded as the file's student"
    assert rows["s03"]["reason"] == ""


def test_as_of_without_a_log_is_one_clear_error(workspace, capsys):
    status = main(["grade", str(workspace / "out" / "manifest.json"),
                   str(workspace / "submissions"), "--as-of", "2025-03-14T23:59:00"])  # fmt: skip
    err = capsys.readouterr().err
    assert status == 2
    assert err.startswith("lagrade: error: there is no log of saves at ") and "Traceback" not in err
    status = main(["grade", str(workspace / "out" / "manifest.json"),
                   str(workspace / "submissions"), "--as-of", "due"])  # fmt: skip
    assert status == 2 and "the assignment has no due date" in capsys.readouterr().err
    status = main(["grade", str(workspace / "out" / "manifest.json"),
                   str(workspace / "submissions"), "--as-of", "Friday"])  # fmt: skip
    assert status == 2 and "'Friday' is not a date and time" in capsys.readouterr().err
