"""Models of Canvas's and Moodle's gradebook importers, written from reading their source (not
copied: Canvas is AGPL, Moodle GPL), so that the tests read our files the way those programs do.

Canvas (instructure/canvas-lms):
- `app/models/gradebook_importer.rb`: `csv_stream` (`identify_delimiter`, the `nil` and
  `decimal_comma_to_period` converters), `row_has_student_headers?`, `update_column_count`,
  `last_student_info_column` ("Section"), `strip_non_assignment_columns`
  (`NON_ASSIGNMENT_COLUMN_HEADERS`, matched anywhere in a header), `parse_assignments`,
  `check_for_non_student_row` ("Points Possible", muted rows), `process_pp`, `process_student`
  (ID, then SIS User ID, then SIS Login ID, then name or sortable name), `no_change_to_value?`;
- `app/models/assignment.rb`: `Assignment.title_and_id` (`/\\A(.*)\\s\\((\\d+)\\)\\z/`);
- `ui/features/gradebook_uploads/jquery/process_gradebook_upload.js`:
  `populateGradeDataPerSubmission` posts every changed grade, a blank one as a removal.

Moodle (moodle/moodle):
- `lib/csvlib.class.php` `csv_import_reader::load_csv_content`: BOM and surrounding space
  trimmed, `fgetcsv`, empty lines skipped, every row as wide as the header (`csvweirdcolumns`);
- `grade/import/csv/classes/load_data.php` `prepare_import_grade_data`,
  `map_user_data_with_value`, `check_user_exists` (no user, or several, stops the import:
  `usermappingerror`), `update_grade_item` (`''` or `-` is no grade; else a number or
  `badgrade`), `insert_grade_record` (above 100 unless `unlimitedgrades`: `gradevaluetoobig`);
  the student id is kept from row to row, so a blank identifier gives the row to the student
  before it;
- `grade/import/lib.php` `grade_import_commit`: a new grade item is a `manual` item with the
  class defaults (grademax 100); a grade of None clears the one held;
- `grade/tests/behat/grade_import.feature`: a grade above the item's maximum stops the import.
"""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass, field

# --- Canvas ------------------------------------------------------------------------------------

NON_ASSIGNMENT_COLUMN_HEADERS = (
    "Current Score",
    "Current Points",
    "Current Grade",
    "Final Score",
    "Final Points",
    "Final Grade",
    "Override Score",
    "Override Grade",
    "Override Status",
)


@dataclass
class CanvasUser:
    id: int
    name: str
    sortable_name: str
    sis_user_id: str | None = None
    login: str | None = None


@dataclass
class CanvasCourse:
    users: list[CanvasUser]
    assignments: dict[int, str]  # id → title
    scores: dict[tuple[int, int], str] = field(default_factory=dict)  # (user, assignment) → score


@dataclass
class CanvasUpload:
    delimiter: str
    student_columns: int
    #: header → existing assignment id, or None for a new assignment
    assignments: dict[str, int | None]
    points_possible: dict[str, str]
    #: CSV row number → the Canvas user matched (None: an unknown student to resolve by hand)
    students: dict[int, int | None]
    #: (user, assignment) → the grade Canvas would post (None: remove the grade)
    changes: dict[tuple[int, int], str | None]


class CanvasRejected(Exception):
    """Canvas's "Invalid header row"."""


def _ruby_to_i(text: str) -> int:
    match = re.match(r"\s*[+-]?\d+", text)
    return int(match.group()) if match else 0


def _decimal_comma_to_period(value: str | None) -> str | None:
    if value is None or not re.fullmatch(r"-?[0-9.,]+%?", value):
        return value
    parts = re.split(r"[,.]", value)
    last = parts.pop()
    return last if not parts else "".join(parts) + "." + last


def _canvas_rows(text: str, delimiter: str) -> list[list[str | None]]:
    rows = []
    for raw in csv.reader(io.StringIO(text), delimiter=delimiter):
        if raw and all(c in ";, " for c in delimiter.join(raw)):  # skip_lines /^[;, ]+$/
            continue
        # Ruby's CSV reads an empty unquoted field as nil; ours never quotes an empty one.
        rows.append([_decimal_comma_to_period(c) if c != "" else None for c in raw])
    return rows


def _identify_delimiter(text: str) -> str:
    first = text.split("\n")[:3]
    counts = {}
    for sep in (";", ","):
        sizes = [len(next(csv.reader([line], delimiter=sep), [])) for line in first]
        counts[sep] = sizes[0] if len(set(sizes)) == 1 else 0
    return ";" if counts[";"] > counts[","] else ","


def _score_text(value: str | None) -> str | None:
    return None if value in (None, "", "-") else f"{float(value):.2f}"


def canvas_import(text: str, course: CanvasCourse) -> CanvasUpload:
    """What Canvas's importer makes of `text` for `course` (see the module docstring)."""
    delimiter = _identify_delimiter(text)
    rows = _canvas_rows(text, delimiter)
    header = [c or "" for c in rows[0]]
    if not (len(header) > 3 and "Student" in header[0] and "ID" in header[1]):
        raise CanvasRejected("Invalid header row")
    student_columns, sis_user_col, sis_login_col = 3, None, None
    if re.search(r"SIS\s+Login\s+ID", header[2]):
        sis_login_col, student_columns = 2, 4
    elif re.search(r"SIS\s+User\s+ID", header[2]) and re.search(r"SIS\s+Login\s+ID", header[3]):
        integration = (
            1 if re.search(r"Integration\s+ID", header[4] if len(header) > 4 else "") else 0
        )
        sis_user_col, sis_login_col = 2, 3
        student_columns += 2 + integration
    if "Section" not in header[student_columns - 1]:
        raise CanvasRejected("Invalid header row")
    strip = re.compile("|".join(NON_ASSIGNMENT_COLUMN_HEADERS))
    assignments: dict[str, int | None] = {}
    for name in header[student_columns:]:
        if strip.search(name):
            continue
        match = re.fullmatch(r"(.*)\s\((\d+)\)", name, flags=re.S)
        found = int(match.group(2)) if match and int(match.group(2)) in course.assignments else None
        if found is None:  # backward compatibility: the whole header as a title
            found = next((i for i, t in course.assignments.items() if t == name), None)
        assignments[name] = found
    index = {name: header.index(name) for name in assignments}
    points: dict[str, str] = {}
    students: dict[int, int | None] = {}
    changes: dict[tuple[int, int], str | None] = {}
    by_id = {u.id: u for u in course.users}
    for number, row in enumerate(rows[1:], start=2):
        if row[0] is not None and "Points Possible" in row[0]:
            points = {name: row[i] for name, i in index.items() if row[i] is not None}
            continue
        if all(
            re.fullmatch(r"\s*(Muted|Manual Posting.*)?\s*", c, re.I) for c in row if c is not None
        ):
            continue
        user = by_id.get(_ruby_to_i(row[1])) if row[1] else None
        if user is None and sis_user_col is not None and row[sis_user_col]:
            user = next((u for u in course.users if u.sis_user_id == row[sis_user_col]), None)
        if user is None and sis_login_col is not None and row[sis_login_col]:
            user = next((u for u in course.users if u.login == row[sis_login_col]), None)
        if user is None:
            user = next((u for u in course.users if row[0] in (u.name, u.sortable_name)), None)
        students[number] = user.id if user else None
        if user is None:
            continue
        for name, i in index.items():
            assignment = assignments[name]
            if assignment is None:
                continue
            new = row[i].strip() if row[i] is not None else None
            current = course.scores.get((user.id, assignment))
            if _score_text(new) == _score_text(current):
                continue  # no_change_to_value?
            changes[(user.id, assignment)] = new or None
    return CanvasUpload(delimiter, student_columns, assignments, points, students, changes)


# --- Moodle ------------------------------------------------------------------------------------

#: "Map to" values of Moodle's mapping form, by the label it shows.
MAP_TO = {
    "User ID": "id",
    "Username": "username",
    "ID number": "idnumber",
    "Email address": "email",
}


@dataclass
class MoodleUser:
    id: int
    email: str
    username: str
    idnumber: str = ""


@dataclass
class MoodleSite:
    users: list[MoodleUser]
    items: dict[int, tuple[str, float]]  # id → (name, grademax)
    grades: dict[tuple[int, int], float | None] = field(default_factory=dict)
    unlimitedgrades: bool = False
    gradepointmax: float = 100.0


class MoodleImportFailed(Exception):
    """ "Import failed. No data was imported.", with Moodle's reason."""


def _php_empty(value: str) -> bool:
    return value in ("", "0")


def moodle_import(
    text: str, site: MoodleSite, map_from: str, map_to: str, mappings: dict[str, str | int]
) -> MoodleSite:
    """Import `text` into `site` as Moodle's CSV grade import does with the identifier mapping
    (`map_from` header → `map_to` label) and the column `mappings` (header → "Ignore", "New
    grade item", an item id, or ("feedback", item id)); returns the site after the commit, or
    raises MoodleImportFailed with Moodle's reason, having changed nothing."""
    content = text.removeprefix("\ufeff").replace("\r\n", "\n").replace("\r", "\n").strip()
    rows = [r for r in csv.reader(io.StringIO(content)) if r]
    if any(len(r) != len(rows[0]) for r in rows):
        raise MoodleImportFailed("csvweirdcolumns")
    header = [h.strip() for h in rows[0]]
    field_name = MAP_TO[map_to]
    mapping: dict[int, str | int | tuple] = {
        i: mappings.get(h, "Ignore") for i, h in enumerate(header)
    }
    mapping[header.index(map_from)] = "user"
    buffered: list[tuple[int, int | str, float | None]] = []  # (user, item or new name, grade)
    new_items: dict[str, int] = {}
    student: int | None = None  # kept from row to row, as in load_data.php
    for line in rows[1:]:
        if len(line) <= 1:
            continue
        grades = []
        for key, value in enumerate(line):
            value = value.strip()
            kind = mapping[key]
            if kind == "user":
                if not _php_empty(value):
                    found = [u for u in site.users if getattr(u, field_name) == value]
                    if len(found) != 1:
                        raise MoodleImportFailed(f"usermappingerror: {field_name} {value!r}")
                    student = found[0].id
            elif kind == "New grade item":
                if value != "-":
                    grades.append((header[key], value))
            elif isinstance(kind, int):
                if value in ("", "-"):
                    grades.append((kind, None))
                else:
                    try:
                        grades.append((kind, float(value)))
                    except ValueError:
                        raise MoodleImportFailed("badgrade") from None
        if student is None:
            raise MoodleImportFailed("usermappingerrorusernotfound")
        limit = site.gradepointmax if site.unlimitedgrades else 100.0
        for item, grade in grades:
            if grade is not None and float(grade) > limit:
                raise MoodleImportFailed("gradevaluetoobig")
            if isinstance(item, int) and grade is not None and grade > site.items[item][1]:
                raise MoodleImportFailed("larger than the allowed grade maximum")
            buffered.append((student, item, None if grade is None else float(grade)))
    grades_after = dict(site.grades)
    items_after = dict(site.items)
    for user, item, grade in buffered:
        if isinstance(item, str):  # a new manual item, Moodle's default maximum
            if item not in new_items:
                new_items[item] = max(items_after, default=0) + 1
                items_after[new_items[item]] = (item, 100.0)
            item = new_items[item]
        grades_after[(user, item)] = grade
    return MoodleSite(
        site.users, items_after, grades_after, site.unlimitedgrades, site.gradepointmax
    )


def readme_mapping(readme: str) -> tuple[str, str, dict[str, str]]:
    """The settings our README tells the instructor to choose: (map from, map to, {column →
    what to map it to}); a column the README sends to a grade item maps to "the item"."""
    identify = re.search(r'Map from "([^"]+)", Map to "([^"]+)"', readme)
    assert identify, readme
    mappings = dict(re.findall(r'"([^"]+)" -> (the grade item|Ignore)', readme))
    return identify.group(1), identify.group(2), mappings
