"""The class roster as learning-management systems export it: a CSV with at least the columns
`id` and `name` (any case, a UTF-8 byte-order mark tolerated); other columns are kept.

Student ids name output files, so they are held to a file-name-safe alphabet, and two ids that
differ only in case are rejected (they would overwrite each other on macOS and Windows).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import lagrade.untrusted as untrusted
from lagrade.errors import AssignmentError, UnreadableInput

REQUIRED = ("id", "name")


@dataclass(frozen=True)
class Student:
    """One roster row: `extra` keeps every other column under its header as written."""

    id: str
    name: str
    extra: Mapping[str, str] = field(default_factory=dict)
    line: int = 0


def load_roster(path: str | Path) -> tuple[Student, ...]:
    """Read a roster file; one AssignmentError lists every bad line."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise AssignmentError(f"roster {str(path)!r} does not exist") from None
    except OSError as exc:
        raise AssignmentError(f"cannot read the roster {str(path)!r}: {exc.strerror}") from None
    try:
        text = untrusted.decode(raw, f"roster {str(path)!r}")
    except UnreadableInput as exc:
        raise AssignmentError(f"{exc}; export it as CSV UTF-8") from None
    return parse_roster(text, source=str(path))


def parse_roster(text: str, source: str = "roster") -> tuple[Student, ...]:
    """Students from CSV text, in file order (see the module docstring for the rules)."""
    text = text.removeprefix("\ufeff")
    reader = csv.reader(io.StringIO(text, newline=""))
    problems: list[str] = []
    try:
        header = next(reader)
    except StopIteration:
        raise AssignmentError(
            f"{source} is empty; it needs a header line with id and name"
        ) from None
    except csv.Error as exc:
        raise AssignmentError(f"{source}, line 1: {exc}") from None
    columns = [h.strip() for h in header]
    lowered = [c.lower() for c in columns]
    missing = [r for r in REQUIRED if r not in lowered]
    if missing:
        raise AssignmentError(
            f"{source}, line 1: the header {', '.join(columns)!s} lacks the column(s) "
            f"{', '.join(missing)} (needed: id, name; case does not matter)"
        )
    for name in sorted({c for c in lowered if lowered.count(c) > 1}):
        problems.append(f"line 1: column {name!r} appears twice")
    id_at, name_at = lowered.index("id"), lowered.index("name")
    students: list[Student] = []
    seen: dict[str, int] = {}
    while True:
        try:
            row = next(reader)
        except StopIteration:
            break
        except csv.Error as exc:
            problems.append(f"line {reader.line_num}: {exc}")
            break
        line = reader.line_num
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != len(columns):
            problems.append(f"line {line}: {len(row)} fields, but the header has {len(columns)}")
            continue
        sid, name = row[id_at].strip(), row[name_at].strip()
        if not sid:
            problems.append(f"line {line}: the id is empty")
            continue
        unsafe = untrusted.unsafe_name_reason(sid, "id")
        if unsafe:
            problems.append(f"line {line}: {unsafe}")
            continue
        if not name:
            problems.append(f"line {line}: student {sid!r} has an empty name")
            continue
        folded = sid.casefold()
        if folded in seen:
            problems.append(
                f"line {line}: duplicate id {sid!r} (already on line {seen[folded]}; "
                "ids are compared ignoring case)"
            )
            continue
        seen[folded] = line
        extra = {
            c: v.strip()
            for i, (c, v) in enumerate(zip(columns, row, strict=True))
            if i not in (id_at, name_at)
        }
        students.append(Student(sid, name, extra, line))
    if not students and not problems:
        problems.append("no student rows after the header")
    if problems:
        lines = "\n".join(f"  - {p}" for p in problems)
        error = AssignmentError(f"{source} is not a valid roster:\n{lines}")
        error.problems = problems  # type: ignore[attr-defined]
        raise error
    return tuple(students)
