"""Answer sheets written by the answer page: the same TOML file `lagrade grade` reads
(`SUBMISSIONS/<id>.toml`), written atomically, each save appended to the log of saves beside
it (`lagrade.grading.savelog`) in the same transaction. The log holds every version, so no
copy of the replaced sheet is kept beside it (the `.previous/` folder of earlier versions)."""

from __future__ import annotations

import datetime as dt
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
from lagrade.assign import one_line, toml_literal, toml_string
from lagrade.errors import OutputError
from lagrade.grading.savelog import Save, SaveLog, modified_ns
from lagrade.grading.submission import (
    Sheet,
    find_submission,
    read_regular_file,
    read_sheet,
    sheet_from_bytes,
)

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
    saved: dt.datetime | None = None,
    late: bool = False,
) -> str:
    """The TOML answer sheet holding `answers[problem][key]` (parts left blank are omitted).
    Values are TOML literal strings, so LaTeX backslashes are kept exactly as typed."""
    info = manifest["assignment"]
    saved = (saved or dt.datetime.now(dt.UTC)).astimezone(dt.UTC).replace(microsecond=0)
    when = saved.isoformat() + (", late (after the due date)" if late else "")
    lines = [
        f"# Answer sheet: {one_line(info.get('title', ''))}",
        f"# Saved from the answer page at {when}.",
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


def save_sheet(
    log: SaveLog,
    folder: Path,
    student_id: str,
    text: str,
    *,
    answers: Mapping[int, Mapping[str, str]],
    saved_ns: int,
    token: str | None = None,
    late: bool = False,
) -> Save:
    """Write `text` as `<id>.toml` in `folder`, atomically, and append it to `log` in the same
    transaction (`SaveLog.record`). A sheet it replaces that the log does not hold as the
    student's last (one from before the log, or put there by hand) is logged first; a `<id>.json`
    it replaces is removed so that `grade` finds one sheet. A symbolic link in the sheet's place
    is replaced, never followed."""
    folder = Path(folder)
    target = folder / f"{student_id}.toml"
    existing, _ = find_submission(folder, student_id) if folder.is_dir() else (None, "")
    old = b""
    if existing is not None:
        old, reason = read_regular_file(existing)
        if reason:
            old = b""
        else:
            log.keep_found(student_id, existing.name, old, modified_ns(existing))
    data = atomic.encode_text(text)

    def write() -> Callable[[], None]:
        atomic.write_bytes(target, data)
        if existing is not None and existing.name != target.name:
            existing.unlink(missing_ok=True)
        return undo

    def undo() -> None:  # the row could not be committed: the folder as it was
        if existing is not None and old:
            atomic.write_bytes(existing, old)
        if existing is None or existing.name != target.name:
            target.unlink(missing_ok=True)

    return log.record(
        student_id,
        target.name,
        data,
        answers=answers,
        token=token,
        late=late,
        saved_ns=saved_ns,
        write=write,
    )


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
