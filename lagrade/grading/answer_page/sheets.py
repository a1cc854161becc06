"""Answer sheets written by the answer page: the same TOML file `lagrade grade` reads
(`SUBMISSIONS/<id>.toml`), written atomically, the version it replaces kept in
`SUBMISSIONS/.previous/<id>.toml` (a hidden folder, which `grade` does not list as stray)."""

from __future__ import annotations

import datetime as dt
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
from lagrade.assign.templating import one_line, toml_literal, toml_string
from lagrade.errors import OutputError
from lagrade.grading.submission import (
    Sheet,
    find_submission,
    read_regular_file,
    read_sheet,
    sheet_from_bytes,
)

PREVIOUS = ".previous"
#: The longest answer the page accepts for one part (a real one is a few hundred characters;
#: the sheet reader's limit is 1 MiB for the whole file).
MAX_ANSWER_CHARS = 20_000


def part_keys(manifest: Mapping[str, Any]) -> dict[int, list[str]]:
    """The part keys of every problem, by problem index."""
    return {int(p["index"]): [part["key"] for part in p["parts"]] for p in manifest["problems"]}


def sheet_text(
    manifest: Mapping[str, Any],
    student: Mapping[str, Any],
    answers: Mapping[int, Mapping[str, str]],
) -> str:
    """The TOML answer sheet holding `answers[problem][key]` (parts left blank are omitted).
    Values are TOML literal strings, so LaTeX backslashes are kept exactly as typed."""
    info = manifest["assignment"]
    saved = dt.datetime.now(dt.UTC).replace(microsecond=0).isoformat()
    lines = [
        f"# Answer sheet: {one_line(info.get('title', ''))}",
        f"# Saved from the answer page at {saved}.",
        f"student_id = {toml_string(student['id'])}",
        f"name = {toml_string(student.get('name', ''))}",
    ]
    for index, keys in part_keys(manifest).items():
        given = answers.get(index, {})
        lines += ["", f"[problem{index}]"]
        for key in keys:
            text = given.get(key, "")
            if text.strip():
                several = "\n" in text.strip()
                lines.append(f"{key} = {toml_literal(text.strip(), multiline=several)}")
    text = "\n".join(lines) + "\n"
    _read_back(text, manifest, student["id"], answers)
    return text


def _read_back(
    text: str, manifest: Mapping[str, Any], student_id: str, answers: Mapping[int, Mapping]
) -> None:
    """Read the sheet about to be saved with `grade`'s own reader: it must be readable, warn
    about nothing and hold every answer as typed (blank ones omitted, the rest stripped), or
    OutputError: a sheet the grader would refuse is never saved as if it were fine."""
    keys = part_keys(manifest)
    data = atomic.encode_text(text)
    sheet = sheet_from_bytes(Path(f"{student_id}.toml"), data, student_id, len(keys), keys)
    meant = {
        index: {k: v.strip() for k, v in table.items() if v.strip()}
        for index, table in answers.items()
    }
    meant = {index: table for index, table in meant.items() if table}
    got = {index: table for index, table in _answers_of(sheet).items() if table}
    if not sheet.readable or sheet.warnings or got != meant:
        why = sheet.reason or "; ".join(sheet.warnings) or "an answer reads back changed"
        raise OutputError(f"the answer sheet would not read back as written ({why})")


def save_sheet(folder: Path, student_id: str, text: str) -> Path:
    """Write `text` as `<id>.toml` in `folder`, atomically; the sheet it replaces (whatever its
    suffix) is first copied to `.previous/`, and a `<id>.json` it replaces is removed so that
    `grade` finds one sheet. A symbolic link in the sheet's place is replaced, never followed."""
    folder = Path(folder)
    target = folder / f"{student_id}.toml"
    existing, _ = find_submission(folder, student_id) if folder.is_dir() else (None, "")
    if existing is not None:
        data, reason = read_regular_file(existing)
        if not reason:
            atomic.write_bytes(folder / PREVIOUS / existing.name, data)
    atomic.write_text(target, text)
    if existing is not None and existing.name != target.name:
        existing.unlink(missing_ok=True)
    return target


def saved_answers(
    folder: Path, manifest: Mapping[str, Any], student_id: str
) -> tuple[dict[int, dict[str, str]], list[str]]:
    """What the student's current sheet holds, to fill the page's fields (multi-line answers
    joined by newlines), and the reader's warnings; empty when there is no readable sheet."""
    folder = Path(folder)
    if not folder.is_dir():
        return {}, []
    path, _ = find_submission(folder, student_id)
    if path is None:
        return {}, []
    keys = part_keys(manifest)
    sheet = read_sheet(path, student_id, len(keys), keys)
    if not sheet.readable:
        return {}, [f"Your saved sheet could not be read ({sheet.reason}); saving replaces it."]
    return _answers_of(sheet), list(sheet.warnings)


def _answers_of(sheet: Sheet) -> dict[int, dict[str, str]]:
    """A read sheet's answers as the page's fields show them (several lines joined)."""
    return {
        index: {k: _text(v) for k, v in table.items() if _text(v) is not None}
        for index, table in sheet.answers.items()
    }


def _text(value: Any) -> str | None:
    if isinstance(value, str):
        return value.strip("\n")
    if isinstance(value, list):
        return "\n".join(value)
    return None
