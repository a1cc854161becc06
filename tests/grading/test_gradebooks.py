"""LMS gradebooks (`grade --export canvas|moodle`): the columns each system imports, every text
cell neutralised as in gradebook.csv, and Canvas never handed a column it would take for a new
assignment."""

from __future__ import annotations

import csv
import io

from lagrade.grading.gradebooks import canvas_csv, moodle_csv

MANIFEST = {
    "assignment": {"title": "PS 3", "total_points": 10},
    "students": [
        {"id": "s1", "name": "Ada", "extra": {"Email": "ada@x.edu", "Section": "A", "year": "2"}},
        {"id": "s2", "name": '=HYPERLINK("x")', "extra": {"Email": "b@x.edu", "Section": "B"}},
    ],
}
RESULTS = [
    {
        "student": {"id": "s1", "name": "Ada"},
        "status": "graded",
        "reason": "",
        "score": 7.5,
        "max_score": 10.0,
    },
    {
        "student": {"id": "s2", "name": '=HYPERLINK("x")'},
        "status": "missing",
        "reason": "no answer sheet was submitted",
        "score": 0.0,
        "max_score": 10.0,
    },
]


def rows(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text)))


def test_canvas_has_its_identity_columns_one_assignment_and_points_possible():
    table = rows(canvas_csv(MANIFEST, RESULTS))
    assert table[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "PS 3"]
    assert table[1][0] == "Points Possible" and table[1][-1] == "10"
    assert table[2] == ["Ada", "", "s1", "ada@x.edu", "A", "7.5"]
    assert table[3][0].startswith("'=")  # a name that would run as a formula
    assert "year" not in table[0]  # Canvas would create an assignment named "year"


def test_moodle_keeps_every_roster_column_and_says_why_a_score_is_zero():
    table = rows(moodle_csv(MANIFEST, RESULTS))
    assert table[0] == [
        "ID number",
        "Full name",
        "Email",
        "Section",
        "year",
        "PS 3",
        "PS 3 (feedback)",
    ]
    assert table[1] == ["s1", "Ada", "ada@x.edu", "A", "2", "7.5", ""]
    assert table[2][0] == "s2" and table[2][5] == "0"
    assert table[2][6].startswith("missing: no answer sheet")
