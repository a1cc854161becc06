"""LMS gradebooks (`grade --export canvas|moodle`), field by field, read back the way Canvas's and
Moodle's importers read them (`tests/grading/lms_importers.py`, models written from their
source, which it cites), for a roster with Canvas ids, SIS ids, emails, sections, a name that
looks like a formula, and students who are missing, unreadable or failed by the grader."""

from __future__ import annotations

import csv
import io

import pytest

from lagrade.errors import AssignmentError
from lagrade.grading.canvas import canvas_gradebook
from lagrade.grading.gradebooks import resolve_options, write_exports
from lagrade.grading.lms import ExportOptions
from lagrade.grading.moodle import moodle_gradebook
from tests.grading.lms_importers import (
    CanvasCourse,
    CanvasRejected,
    CanvasUser,
    MoodleImportFailed,
    MoodleSite,
    MoodleUser,
    canvas_import,
    moodle_import,
    readme_mapping,
)

HOSTILE = '=HYPERLINK("x")'
#: id, name, roster columns as an LMS export or a registrar's list would head them
ROSTER = [
    (
        "s01",
        "Ada Lovelace",
        {"canvas_user_id": "101", "SIS User ID": "900001", "Email": "ada@uni.edu", "Section": "A"},
    ),
    ("s02", "Ben Okri", {"SIS User ID": "900002", "Email": "ben@uni.edu", "Section": "A"}),
    ("s03", "Chen Wei", {"Email": "chen@uni.edu", "Section": "B"}),
    ("s04", "Dana Scully", {"Section": "B"}),
    ("s05", "Eve Moneypenny", {"SIS User ID": "900005", "Email": "eve@uni.edu", "Section": "A"}),
    ("s06", "Finn Mertens", {"SIS User ID": "900006", "Email": "finn@uni.edu", "Section": "B"}),
    ("s07", "Gus Fring", {"SIS User ID": "900007", "Email": "gus@uni.edu", "Section": "B"}),
    ("s08", HOSTILE, {"SIS User ID": "900008", "Email": "mal@uni.edu", "Section": "A"}),
]
#: status, score: graded, a timeout after some parts, missing, invalid, our own error
OUTCOMES = {
    "s01": ("graded", 7.5),
    "s02": ("graded", 10.0),
    "s03": ("timeout", 4.0),
    "s04": ("graded", 6.0),
    "s05": ("missing", 0.0),
    "s06": ("invalid", 0.0),
    "s07": ("error", 0.0),
    "s08": ("graded", 3.0),
}
REASONS = {
    "s03": "ran out of time on problem 2 eom",
    "s05": "no answer sheet was submitted",
    "s06": "s06.toml is not valid TOML",
    "s07": "the grader failed on this submission",
}


def manifest(title: str = "PS 3", roster=ROSTER, total: float = 10) -> dict:
    return {
        "assignment": {"title": title, "total_points": total, "file": "assignment.toml"},
        "students": [{"id": i, "name": n, "extra": extra} for i, n, extra in roster],
    }


def results(roster=ROSTER, total: float = 10.0) -> list[dict]:
    out = []
    for sid, name, _ in roster:
        status, score = OUTCOMES.get(sid, ("graded", 5.0))
        judged = status in ("graded", "timeout")
        out.append(
            {
                "student": {"id": sid, "name": name},
                "status": status,
                "reason": REASONS.get(sid, ""),
                "score": score,
                "max_score": total,
                "problems": [{"index": 1, "score": score}] if judged else [],
            }
        )
    return out


def table(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text)))


def course(**scores) -> CanvasCourse:
    """Canvas users for the roster (logins are emails here), a decoy user 12, and two
    assignments; `scores` are grades already in Canvas, `user_assignment="8"`."""
    users = [
        CanvasUser(101, "Ada Lovelace", "Lovelace, Ada", "900001", "ada@uni.edu"),
        CanvasUser(102, "Ben Okri", "Okri, Ben", "900002", "ben@uni.edu"),
        CanvasUser(103, "Chen Wei", "Wei, Chen", None, "chen@uni.edu"),
        CanvasUser(104, "Dana Scully", "Scully, Dana", None, "dana.s"),
        CanvasUser(105, "Eve Moneypenny", "Moneypenny, Eve", "900005", "eve@uni.edu"),
        CanvasUser(106, "Finn Mertens", "Mertens, Finn", "900006", "finn@uni.edu"),
        CanvasUser(107, "Gus Fring", "Fring, Gus", "900007", "gus@uni.edu"),
        CanvasUser(108, "Mallory", "Mallory", "900008", "mal@uni.edu"),
        CanvasUser(12, "Decoy", "Decoy", "1", "decoy"),
    ]
    held = {(int(k.split("_")[0]), int(k.split("_")[1])): v for k, v in scores.items()}
    return CanvasCourse(users, {12345: "PS 3", 777: "Homework 1"}, held)


# --- Canvas --------------------------------------------------------------------------------------


def test_canvas_columns_field_by_field():
    """The header Canvas's `row_has_student_headers?` and `update_column_count` accept
    (Student, ID, SIS User ID, SIS Login ID, then Section as `last_student_info_column`), the
    assignment as `Title (ID)` (`Assignment.title_and_id`), the Points Possible row
    (`check_for_non_student_row`), and each student's identity from the roster."""
    rows = table(canvas_gradebook(manifest(), results(), ExportOptions("12345")).csv)
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "PS 3 (12345)"]
    assert rows[1] == ["Points Possible", "", "", "", "", "10"]
    assert rows[2] == ["Ada Lovelace", "101", "900001", "ada@uni.edu", "A", "7.5"]
    assert rows[3] == ["Ben Okri", "", "900002", "ben@uni.edu", "A", "10"]
    assert rows[4] == ["Chen Wei", "", "", "chen@uni.edu", "B", "4"]  # timed out, parts count
    assert rows[5] == ["Dana Scully", "", "", "", "B", "6"]
    assert rows[6] == ["Eve Moneypenny", "", "900005", "eve@uni.edu", "A", ""]  # missing
    assert rows[7] == ["Finn Mertens", "", "900006", "finn@uni.edu", "B", ""]  # invalid
    assert rows[8] == ["Gus Fring", "", "900007", "gus@uni.edu", "B", ""]  # our error
    assert rows[9] == ["'" + HOSTILE, "", "900008", "mal@uni.edu", "A", "3"]
    assert len(rows) == 10


def test_canvas_fills_the_existing_assignment_for_the_right_students():
    """Read by the importer model: comma-delimited (`identify_delimiter`), five identity
    columns, the column bound to assignment 12345 (not a new one), every row on its own Canvas
    user by ID, SIS User ID, SIS Login ID or name (`process_student`), grades posted only where
    they change (`no_change_to_value?`)."""
    book = canvas_gradebook(manifest(), results(), ExportOptions("12345"))
    upload = canvas_import(book.csv, course())
    assert (upload.delimiter, upload.student_columns) == (",", 5)
    assert upload.assignments == {"PS 3 (12345)": 12345}
    assert upload.points_possible == {"PS 3 (12345)": "10"}
    assert list(upload.students.values()) == [101, 102, 103, 104, 105, 106, 107, 108]
    assert upload.changes == {
        (101, 12345): "7.5",
        (102, 12345): "10",
        (103, 12345): "4",
        (104, 12345): "6",
        (108, 12345): "3",
    }


def test_students_without_a_graded_submission_are_blank_not_zero():
    """A blank cell changes nothing for a student Canvas holds no grade for (missing, invalid,
    our error); with --missing-as-zero the students who handed in nothing readable get 0, and a
    student the grader failed stays blank. Where Canvas holds a grade typed in by hand, the
    blank is a removal (`populateGradeDataPerSubmission` posts it), as the README says."""
    held = course(**{"106_12345": "8"})
    blank = canvas_import(canvas_gradebook(manifest(), results(), ExportOptions("12345")).csv, held)
    assert (105, 12345) not in blank.changes and (107, 12345) not in blank.changes
    assert blank.changes[(106, 12345)] is None
    zero = canvas_gradebook(manifest(), results(), ExportOptions("12345", missing_as_zero=True))
    upload = canvas_import(zero.csv, held)
    assert upload.changes[(105, 12345)] == "0" and upload.changes[(106, 12345)] == "0"
    assert (107, 12345) not in upload.changes
    assert "removed" in blank_readme() and "Gus Fring" in blank_readme()


def blank_readme() -> str:
    return canvas_gradebook(manifest(), results(), ExportOptions("12345")).readme


def test_without_an_assignment_id_canvas_matches_the_title_or_creates_one():
    """Without the id the header is the bare title: Canvas binds it by exact title (its
    "backward compat" branch) or creates a new assignment, so the file says so."""
    book = canvas_gradebook(manifest(), results(), ExportOptions())
    assert canvas_import(book.csv, course()).assignments == {"PS 3": 12345}
    other = canvas_gradebook(manifest("Problem set 3"), results(), ExportOptions())
    assert canvas_import(other.csv, course()).assignments == {"Problem set 3": None}
    assert any("no Canvas assignment id" in w for w in other.warnings)
    assert "creates a new one" in other.readme


def test_a_title_canvas_would_drop_or_misread_is_warned():
    """`strip_non_assignment_columns` drops any header containing "Final Grade" (and the other
    computed columns); a title ending in "(2024)" is read as assignment id 2024."""
    dropped = canvas_gradebook(manifest("Final Grade project"), results(), ExportOptions("5"))
    assert canvas_import(dropped.csv, course()).assignments == {}
    assert any("'Final Grade'" in w for w in dropped.warnings)
    year = canvas_gradebook(manifest("Mechanics (2024)"), results(), ExportOptions())
    assert any("reads as an assignment id" in w for w in year.warnings)


def test_canvas_identifiers_that_would_match_the_wrong_user_are_left_blank():
    """Canvas reads ID with Ruby's `to_i` ("12abc" is user 12: the model shows the wrong match
    a verbatim copy would make); a login shared by two roster rows would put both on one user;
    a value the spreadsheet rule would alter could not match. Each is left blank and named,
    and the row falls back to the next identifier."""
    verbatim = "Student,ID,SIS User ID,SIS Login ID,Section,PS 3 (12345)\nAda,12abc,,,,5\n"
    assert list(canvas_import(verbatim, course()).students.values()) == [12]
    roster = [
        ("s01", "Ada Lovelace", {"canvas_id": "12abc", "sis_id": "900001", "email": "x@uni.edu"}),
        ("s02", "Ben Okri", {"sis_id": "900002", "email": "x@uni.edu"}),
        ("s03", "Chen Wei", {"sis_login_id": "-chen", "email": "chen@uni.edu"}),
    ]
    book = canvas_gradebook(manifest(roster=roster), results(roster), ExportOptions("12345"))
    rows = table(book.csv)
    assert rows[2][1:4] == ["", "900001", ""]
    assert rows[3][1:4] == ["", "900002", ""]
    assert rows[4][1:4] == ["", "", ""]
    assert list(canvas_import(book.csv, course()).students.values()) == [101, 102, 103]
    said = " ".join(book.warnings)
    assert "'12abc' is not a number" in said and "'x@uni.edu' is shared" in said
    assert "'-chen' would be read as a spreadsheet formula" in said


def test_students_canvas_can_match_only_by_name_are_named():
    book = canvas_gradebook(manifest(), results(), ExportOptions("12345"))
    assert any("by name only" in w and "s04 (Dana Scully)" in w for w in book.warnings)


def test_canvas_rejects_a_file_without_its_identity_header():
    """The model is not vacuous: the header rule it applies does reject a plain gradebook."""
    with pytest.raises(CanvasRejected):
        canvas_import("id,name,score\ns01,Ada,5\n", course())


# --- Moodle --------------------------------------------------------------------------------------


def moodle_site(**held) -> MoodleSite:
    users = [
        MoodleUser(i, extra["Email"], sid, "")
        for i, (sid, _, extra) in enumerate(ROSTER, start=1)
        if "Email" in extra
    ]
    grades = {(int(k.split("_")[0]), int(k.split("_")[1])): v for k, v in held.items()}
    return MoodleSite(users, {55: ("PS 3", 10.0)}, grades)


def import_as_readme_says(book, site: MoodleSite, item: int = 55) -> MoodleSite:
    """Choose on Moodle's mapping form exactly what the README says."""
    map_from, map_to, columns = readme_mapping(book.readme)
    mappings = {c: (item if what == "the grade item" else "Ignore") for c, what in columns.items()}
    return moodle_import(book.csv, site, map_from, map_to, mappings)


def test_moodle_columns_field_by_field():
    """The identifier first (Moodle's default "Map from" is the first column), the lagrade id,
    the name, the grade out of the assignment's maximum and a feedback; only students with a
    grade and an email."""
    book = moodle_gradebook(manifest(), results(), ExportOptions())
    rows = table(book.csv)
    assert rows[0] == ["Email address", "lagrade id", "Full name", "PS 3", "PS 3 (feedback)"]
    assert rows[1] == [
        "ada@uni.edu",
        "s01",
        "Ada Lovelace",
        "7.5",
        "Graded by lagrade: 7.5 of 10 points.",
    ]
    assert rows[2][:4] == ["ben@uni.edu", "s02", "Ben Okri", "10"]
    assert rows[3][:4] == ["chen@uni.edu", "s03", "Chen Wei", "4"]
    assert rows[3][4].startswith("timeout: ran out of time")
    assert rows[4] == [
        "mal@uni.edu",
        "s08",
        "'" + HOSTILE,
        "3",
        "Graded by lagrade: 3 of 10 points.",
    ]
    assert len(rows) == 5
    readme = book.readme
    assert 'Map from "Email address", Map to "Email address"' in readme
    assert "Maximum grade 10" in readme
    for student in ("s05 (Eve Moneypenny)", "s06 (Finn Mertens)", "s07 (Gus Fring)"):
        assert student in readme  # left out, Moodle keeps what it holds
    assert any("s04 (Dana Scully)" in w for w in book.warnings)  # a grade but no email


def test_moodle_imports_the_file_with_the_readme_settings():
    """Every row finds its user and lands on the grade item; nothing stops the import; a grade
    typed into Moodle for a student who handed in nothing is kept (no row, so no blank to clear
    it: `update_grade_item` reads '' as no grade)."""
    site = moodle_site(**{"5_55": 9.0})  # Eve (missing) has a grade typed in Moodle
    book = moodle_gradebook(manifest(), results(), ExportOptions())
    after = import_as_readme_says(book, site)
    assert after.grades == {(1, 55): 7.5, (2, 55): 10.0, (3, 55): 4.0, (8, 55): 3.0, (5, 55): 9.0}


def test_moodle_missing_as_zero_gives_zero_with_the_reason():
    book = moodle_gradebook(manifest(), results(), ExportOptions(missing_as_zero=True))
    after = import_as_readme_says(book, moodle_site(**{"5_55": 9.0}))
    assert after.grades[(5, 55)] == 0.0 and after.grades[(6, 55)] == 0.0
    assert (7, 55) not in after.grades  # Gus: the grader failed, no row
    rows = {r[1]: r for r in table(book.csv)[1:]}
    assert rows["s05"][4] == "missing: no answer sheet was submitted (0 of 10 points)"
    assert "s07" not in rows  # the grader's failure is never sent as 0


def test_a_blank_identifier_would_give_the_row_to_the_student_above():
    """Why no row has a blank identifier: `prepare_import_grade_data` keeps the student id from
    the previous row when the user field is blank."""
    text = "Email address,PS 3\nada@uni.edu,7\n,2\n"
    after = moodle_import(text, moodle_site(), "Email address", "Email address", {"PS 3": 55})
    assert after.grades == {(1, 55): 2.0}  # Ada got the anonymous row's 2
    ours = table(moodle_gradebook(manifest(), results(), ExportOptions(True, True)).csv)
    assert all(row[0] for row in ours[1:])


def test_an_unknown_user_stops_moodle_and_the_readme_says_what_to_do():
    site = moodle_site()
    site.users = [u for u in site.users if u.email != "ben@uni.edu"]
    book = moodle_gradebook(manifest(), results(), ExportOptions())
    with pytest.raises(MoodleImportFailed, match="usermappingerror"):
        import_as_readme_says(book, site)
    assert "stops the whole import" in book.readme and "delete that row" in book.readme


def test_a_new_grade_item_would_be_out_of_100_so_the_readme_asks_for_the_total():
    """`grade_import_commit` creates a "New grade item" with the class default, grademax 100:
    a 7.5 out of 10 would read as 7.5 %. The README has the item made first, out of 10."""
    book = moodle_gradebook(manifest(), results(), ExportOptions())
    after = moodle_import(
        book.csv, moodle_site(), "Email address", "Email address", {"PS 3": "New grade item"}
    )
    assert after.items[56] == ("PS 3", 100.0)
    assert "Maximum grade 10 (the assignment's total)" in book.readme


def test_grades_above_100_need_the_site_setting():
    roster = ROSTER[:2]
    book = moodle_gradebook(
        manifest(roster=roster, total=150), results(roster, 150.0), ExportOptions()
    )
    assert any("refuses grades above 100" in w for w in book.warnings)
    text = "Email address,PS 3\nada@uni.edu,120\n"
    site = moodle_site()
    site.items = {55: ("PS 3", 150.0)}
    with pytest.raises(MoodleImportFailed, match="gradevaluetoobig"):
        moodle_import(text, site, "Email address", "Email address", {"PS 3": 55})


def test_moodle_matches_by_id_number_when_the_roster_has_more_of_them():
    roster = [
        ("s01", "Ada", {"idnumber": "A1", "email": "ada@uni.edu"}),
        ("s02", "Ben", {"ID number": "B2"}),
        ("s03", "Chen", {"id_number": "C3"}),
    ]
    book = moodle_gradebook(manifest(roster=roster), results(roster), ExportOptions())
    rows = table(book.csv)
    assert rows[0][:3] == ["ID number", "Email address", "lagrade id"]
    assert [r[0] for r in rows[1:]] == ["A1", "B2", "C3"]
    assert 'Map from "ID number", Map to "ID number"' in book.readme
    site = MoodleSite(
        [
            MoodleUser(1, "ada@uni.edu", "a", "A1"),
            MoodleUser(2, "", "b", "B2"),
            MoodleUser(3, "", "c", "C3"),
        ],
        {55: ("PS 3", 10.0)},
    )
    assert import_as_readme_says(book, site).grades == {(1, 55): 7.5, (2, 55): 10.0, (3, 55): 4.0}


# --- options and files ---------------------------------------------------------------------------


def test_the_canvas_assignment_id_comes_from_the_flag_or_the_lms_table(tmp_path):
    assignment = tmp_path / "assignment.toml"
    assignment.write_text('title = "PS 3"\n[lms]\ncanvas_assignment_id = 12345\n')
    assert resolve_options(assignment, None).canvas_assignment_id == "12345"
    flag = resolve_options(assignment, ExportOptions("678", missing_as_zero=True))
    assert flag == ExportOptions("678", True)
    assignment.write_text('title = "PS 3"\n[lms]\ncanvas_assignment_id = "abc"\n')
    with pytest.raises(AssignmentError, match="not a Canvas assignment id"):
        resolve_options(assignment, None)
    assignment.write_text('title = "PS 3"\n[lms]\ncanvas_id = 5\n')
    with pytest.raises(AssignmentError, match="unknown field 'canvas_id'"):
        resolve_options(assignment, None)
    with pytest.raises(AssignmentError, match="not a Canvas assignment id"):
        resolve_options(tmp_path / "absent.toml", ExportOptions("12 345"))


def test_each_export_is_written_with_its_readme(tmp_path):
    books = write_exports(tmp_path, manifest(), results(), ["canvas", "moodle"], ExportOptions("9"))
    assert [b.kind for b in books] == ["canvas", "moodle"]
    for kind in ("canvas", "moodle"):
        assert (tmp_path / f"gradebook-{kind}.csv").read_text().count("\n") > 2
        assert "how to import it" in (tmp_path / f"gradebook-{kind}.README.txt").read_text()
