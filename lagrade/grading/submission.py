"""Reading one student's answer sheet from disk, defensively: the file is whatever the student
uploaded — huge, binary, in another encoding, malformed TOML — and each of those becomes a
clear reason, never an exception that stops the batch."""

from __future__ import annotations

import hashlib
import json
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

#: The largest answer sheet read; a real one is a few kilobytes.
MAX_SHEET_BYTES = 1024 * 1024
SUFFIXES = (".toml", ".json")


@dataclass(frozen=True)
class Sheet:
    """A read answer sheet: `answers[problem_index][key]` is the raw answer (string or list),
    or `reason` says why the file could not be read (status `invalid`)."""

    path: Path | None
    sha256: str
    answers: dict[int, dict[str, Any]]
    reason: str = ""
    warnings: tuple[str, ...] = ()

    @property
    def readable(self) -> bool:
        return not self.reason


def find_submission(folder: Path, student_id: str) -> tuple[Path | None, str]:
    """The file of `student_id` in `folder` (`<id>.toml` or `<id>.json`, case-insensitive), or
    None; the second value explains an ambiguity."""
    wanted = {student_id.lower() + s for s in SUFFIXES}
    matches = sorted(p for p in folder.iterdir() if p.name.lower() in wanted and p.is_file())
    if len(matches) > 1:
        names = ", ".join(p.name for p in matches)
        return matches[0], f"several files for this student ({names}); graded {matches[0].name}"
    return (matches[0] if matches else None), ""


def read_sheet(path: Path, student_id: str, problem_count: int) -> Sheet:
    """Read and validate an answer sheet, never raising over its content."""
    try:
        size = path.stat().st_size
        if size > MAX_SHEET_BYTES:
            return _bad(
                path,
                "",
                f"the file is {size / 1e6:.1f} MB; an answer sheet may be at most "
                f"{MAX_SHEET_BYTES // 1024} KiB",
            )
        data = path.read_bytes()
    except OSError as error:
        return _bad(path, "", f"the file cannot be read ({error.strerror or error})")
    digest = hashlib.sha256(data).hexdigest()
    if not data.strip():
        return _bad(path, digest, "the file is empty")
    if b"\x00" in data:
        return _bad(path, digest, "the file is binary, not a text answer sheet")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        return _bad(
            path,
            digest,
            f"the file is not UTF-8 text (byte 0x{data[error.start]:02x} at "
            f"position {error.start}); save it as UTF-8",
        )
    try:
        raw = json.loads(text) if path.suffix.lower() == ".json" else tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        return _bad(path, digest, f"the answer sheet is not valid TOML: {error}")
    except (json.JSONDecodeError, RecursionError) as error:
        return _bad(path, digest, f"the answer sheet is not valid JSON: {error}")
    if not isinstance(raw, dict):
        return _bad(path, digest, "the answer sheet must be a table of problems")
    return _structure(path, digest, raw, student_id, problem_count)


def _structure(path: Path, digest: str, raw: dict, student_id: str, problem_count: int) -> Sheet:
    warnings = []
    declared = raw.get("student_id")
    if declared is not None and str(declared).lower() != student_id.lower():
        warnings.append(
            f"the sheet says student_id = {declared!r} but the file belongs to "
            f"{student_id!r}; graded as {student_id!r}"
        )
    answers: dict[int, dict[str, Any]] = {}
    for index in range(1, problem_count + 1):
        table = raw.get(f"problem{index}", {})
        if not isinstance(table, dict):
            warnings.append(f"[problem{index}] is not a table; its answers were ignored")
            table = {}
        answers[index] = {str(k): _answer_value(v) for k, v in table.items()}
    extra = sorted(
        k
        for k in raw
        if k.startswith("problem") and k not in {f"problem{i}" for i in range(1, problem_count + 1)}
    )
    if extra:
        warnings.append(f"ignored tables that the assignment does not have: {', '.join(extra)}")
    return Sheet(path, digest, answers, "", tuple(warnings))


def _answer_value(value: Any) -> Any:
    """Strings stay; numbers become their text (dof = 2); lists of strings stay lists; anything
    else is kept as a marker the checker reports as an unreadable answer."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int | float):
        return str(value)
    if isinstance(value, list) and all(isinstance(v, str) for v in value):
        return list(value)
    return UnreadableAnswer(type(value).__name__)


@dataclass(frozen=True)
class UnreadableAnswer:
    """An answer of a shape no part accepts (a table, a date, a list of numbers)."""

    kind: str


def _bad(path: Path, digest: str, reason: str) -> Sheet:
    return Sheet(path, digest, {}, reason)
