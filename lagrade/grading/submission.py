"""Reading one student's answer sheet from disk, defensively: the file is whatever the student
uploaded — huge, binary, in another encoding, malformed TOML — and each of those becomes a
clear reason, never an exception that stops the batch."""

from __future__ import annotations

import difflib
import errno
import hashlib
import os
import stat
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.errors import UnreadableInput
from lagrade.grading.latex_escapes import escape_unknown, unmark
from lagrade.grading.latex_escapes import repair as repair_escapes
from lagrade.grading.latex_escapes import warning as escape_warning
from lagrade.grading.sheet_quotes import quote_primes
from lagrade.grading.sheet_quotes import warning as quote_warning

#: The largest answer sheet read; a real one is a few kilobytes.
MAX_SHEET_BYTES = 1024 * 1024
SUFFIXES = (".toml", ".json")
#: Stray files given a "did you mean" (a folder of ten thousand strays costs no more).
MAX_SUGGESTED = 50
#: Unknown keys reported one by one per problem; more are counted.
MAX_KEY_WARNINGS = 10


@dataclass(frozen=True)
class Sheet:
    """A read answer sheet: `answers[problem_index][key]` is the raw answer (string or list),
    or `reason` says why the file could not be read (status `invalid`)."""

    path: Path | None
    sha256: str
    answers: dict[int, dict[str, Any]]
    reason: str = ""
    warnings: tuple[str, ...] = ()
    #: The `student_id` the sheet gives itself when it is not the file's student ("s002" in
    #: s001.toml), else None: graded as the file's student, and listed for the instructor.
    other_id: str | None = None

    @property
    def readable(self) -> bool:
        return not self.reason


def find_submission(folder: Path, student_id: str) -> tuple[Path | None, str]:
    """The file of `student_id` in `folder` (`<id>.toml` or `<id>.json`, case-insensitive), or
    None; the second value explains an ambiguity. Entries are matched by name only: whether
    one is a regular file (not a link, a folder or a device) is `read_sheet`'s to say."""
    wanted = {student_id.lower() + s for s in SUFFIXES}
    matches = sorted(p for p in folder.iterdir() if p.name.lower() in wanted)
    if len(matches) > 1:
        regular = [p for p in matches if _is_regular(p)] or matches
        names = ", ".join(p.name for p in matches)
        return regular[0], f"several files for this student ({names}); graded {regular[0].name}"
    return (matches[0] if matches else None), ""


def stray_files(folder: Path, student_ids: Iterable[str]) -> dict[str, str]:
    """Every entry of `folder` that no roster student's sheet is, by name, with a sentence
    for the instructor (who it seems meant for, or the closest roster id). Hidden entries
    (`.DS_Store`, an editor's swap file) are skipped. Entries are listed, never opened."""
    ids = {i.lower(): i for i in student_ids}
    sheets = {i + s for i in ids for s in SUFFIXES}
    stray = {}
    for entry in sorted(folder.iterdir()):
        name = untrusted.bounded(entry.name, 200)  # any bytes can name a file
        if name.startswith(".") or name.lower() in sheets:
            continue
        stem = name.split(".", 1)[0].lower()
        if stem in ids:
            stray[name] = (
                f"looks meant for {ids[stem]} but is not read: an answer sheet is named "
                f"{ids[stem]}.toml or {ids[stem]}.json"
            )
            continue
        hint = _closest_ids(stem, ids) if len(stray) < MAX_SUGGESTED else ""
        stray[name] = f"belongs to no roster student{hint}; not read"
    return stray


def _closest_ids(stem: str, ids: Mapping[str, str]) -> str:
    """The hint ` (did you mean s005?)` naming the roster ids nearest `stem`, all of them when
    several are equally near (s05 is as near to s005 as to s015): never a confident wrong
    guess."""
    matcher = difflib.SequenceMatcher(b=stem[:100])
    scored = []
    for i in ids:
        matcher.set_seq1(i)
        if matcher.real_quick_ratio() >= 0.6 and matcher.quick_ratio() >= 0.6:
            scored.append((matcher.ratio(), i))
    best = max((r for r, _ in scored), default=0.0)
    if best < 0.6:
        return ""
    nearest = sorted(ids[i] for r, i in scored if r == best)
    if len(nearest) > 3:
        return ""
    shown = nearest[0] if len(nearest) == 1 else ", ".join(nearest[:-1]) + " or " + nearest[-1]
    return f" (did you mean {shown}?)"


def meant_for(student_id: str, stray: Mapping[str, str]) -> list[str]:
    """The stray files whose name is this student's id with another suffix (`s005.txt`)."""
    return [n for n in stray if n.split(".", 1)[0].lower() == student_id.lower()]


def read_sheet(
    path: Path,
    student_id: str,
    problem_count: int,
    keys: Mapping[int, Sequence[str]] | None = None,
    content: tuple[bytes, str] | None = None,
) -> Sheet:
    """Read and validate an answer sheet, never raising over its content. `keys[k]` are the
    part keys of problem k; a key the problem does not have is reported as a warning, with
    the closest valid key (a misspelled `lagrangain` must not silently read as "not answered").
    `content`: what `read_regular_file(path)` gave another process (a Dask worker does not
    share the grading machine's files, so the parent reads them and sends the bytes)."""
    data, reason = read_regular_file(path) if content is None else content
    if reason:
        return _bad(path, "", reason)
    return sheet_from_bytes(path, data, student_id, problem_count, keys)


def sheet_from_bytes(
    path: Path,
    data: bytes,
    student_id: str,
    problem_count: int,
    keys: Mapping[int, Sequence[str]] | None = None,
) -> Sheet:
    """`read_sheet` on bytes in hand (`path` names the file and its format by its suffix): what
    a writer of sheets reads its text back with before it writes it."""
    digest = hashlib.sha256(data).hexdigest()
    if not data.strip():
        return _bad(path, digest, "the file is empty")
    if b"\x00" in data:
        return _bad(path, digest, "the file is binary, not a text answer sheet")
    form = "json" if path.suffix.lower() == ".json" else "toml"
    load = untrusted.load_json if form == "json" else untrusted.load_toml
    primed: list[str] = []  # the answers whose quotes `quote_primes` placed
    try:
        text = untrusted.decode(data, "the file")
        try:
            raw = load(text, "the answer sheet")
        except UnreadableInput as first:
            # \dot, \sin, \alpha in a "…" string, or a prime in a '…' one: what the format
            # cannot read voids the whole sheet; read it as meant, with a note per answer, when
            # that makes the sheet readable (otherwise the first error stands)
            fixed, primed = quote_primes(text) if form == "toml" else (text, [])
            fixed, found = escape_unknown(fixed, form)
            if not found and not primed:
                raise
            try:
                raw = load(fixed, "the answer sheet")
            except UnreadableInput:
                raise first from None
            text = fixed
    except UnreadableInput as error:
        reason = str(error)
        if "Unescaped '\\'" in reason:  # a backslash the recovery could not place
            reason += (
                "; LaTeX in an answer belongs in single quotes, where a backslash stays a "
                "backslash: eom = '\\ddot{x} = 0'"
            )
        return _bad(path, digest, reason)
    if not isinstance(raw, dict):
        return _bad(path, digest, "the answer sheet must be a table of problems")
    sheet = _structure(path, digest, raw, student_id, problem_count, keys or {})
    if primed:
        sheet = replace(sheet, warnings=(*sheet.warnings, *map(quote_warning, primed)))
    return _repair_escapes(sheet, text)


def _repair_escapes(sheet: Sheet, raw: str) -> Sheet:
    """Each answer whose LaTeX a string escape ate (`\\theta` read as a tab and "heta"), or held
    one the format cannot read (`\\dot`, marked by `escape_unknown`), read as meant where it
    can be, with one warning per answer (lagrade.grading.latex_escapes)."""
    warnings = list(sheet.warnings)
    answers: dict[int, dict[str, Any]] = {}
    for index, table in sheet.answers.items():
        answers[index] = {}
        for key, value in table.items():
            items = value if isinstance(value, list) else [value]
            if not all(isinstance(v, str) for v in items):
                answers[index][key] = value
                continue
            fixed, restored, kept, unknown = [], [], [], []
            for item in items:
                item, u = unmark(item)
                text, r, k = repair_escapes(item, raw)
                fixed.append(text)
                restored += r
                kept += k
                unknown += u
            answers[index][key] = fixed if isinstance(value, list) else fixed[0]
            if restored or kept or unknown:
                where = f"[problem{index}] {untrusted.bounded(key, 60)}"
                warnings.append(escape_warning(where, restored, kept, unknown))
    return replace(sheet, answers=answers, warnings=tuple(warnings))


def feed_digest(digest: Any, path: Path) -> None:
    """Feed what a result depends on into `digest` (a hashlib object): a regular file's bytes,
    streamed whatever their size, or for anything else its kind, without following a link or
    opening a device (a rerun then sees a link or a folder replaced by a file as a change)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError as error:
        digest.update(f"<unopenable {error.errno}>".encode())
        return
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        digest.update(f"<not a regular file {stat.S_IFMT(mode)}>".encode())
        return
    with os.fdopen(fd, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            digest.update(chunk)


def _is_regular(path: Path) -> bool:
    try:
        return stat.S_ISREG(path.lstat().st_mode)
    except OSError:
        return False


def read_regular_file(path: Path) -> tuple[bytes, str]:
    """The bytes of `path` when it is a regular file of at most MAX_SHEET_BYTES, else why not.
    A symbolic link is refused, not followed (it could point at any file the grader can read),
    and a fifo or device is never opened for reading (it could block forever)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError as error:
        if error.errno == errno.ELOOP or path.is_symlink():
            return b"", "the submission is a symbolic link; hand in the file itself"
        return b"", f"the file cannot be read ({error.strerror or error})"
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            kind = "a folder" if stat.S_ISDIR(info.st_mode) else "not a regular file"
            return b"", f"the submission is {kind}; hand in the answer sheet file itself"
        if info.st_size > MAX_SHEET_BYTES:
            return b"", (
                f"the file is {info.st_size / 1e6:.1f} MB; an answer sheet may be at most "
                f"{MAX_SHEET_BYTES // 1024} KiB"
            )
        with os.fdopen(fd, "rb", closefd=False) as f:
            data = f.read(MAX_SHEET_BYTES + 1)
    except OSError as error:
        return b"", f"the file cannot be read ({error.strerror or error})"
    finally:
        os.close(fd)
    if len(data) > MAX_SHEET_BYTES:  # grew while being read
        return b"", f"the file is larger than {MAX_SHEET_BYTES // 1024} KiB"
    return data, ""


def _structure(
    path: Path,
    digest: str,
    raw: dict,
    student_id: str,
    problem_count: int,
    keys: Mapping[int, Sequence[str]],
) -> Sheet:
    warnings = []
    declared = raw.get("student_id")
    other_id = None
    if declared is not None and str(declared).lower() != student_id.lower():
        other_id = untrusted.bounded(str(declared), 60)
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
        if index in keys:
            warnings += _unknown_keys(index, answers[index], keys[index])
    extra = sorted(
        k
        for k in raw
        if k.startswith("problem") and k not in {f"problem{i}" for i in range(1, problem_count + 1)}
    )
    if extra:
        warnings.append(f"ignored tables that the assignment does not have: {', '.join(extra)}")
    return Sheet(path, digest, answers, "", tuple(warnings), other_id)


def _unknown_keys(index: int, answers: Mapping[str, Any], valid: Sequence[str]) -> list[str]:
    """A warning per key of [problem<index>] that names no part, with the closest valid key
    (at most MAX_KEY_WARNINGS of them: a sheet of ten thousand made-up keys gets a count)."""
    unknown = [k for k in answers if k not in valid]
    out = []
    for key in unknown[:MAX_KEY_WARNINGS]:
        shown = untrusted.bounded(key, 60)
        close = difflib.get_close_matches(key[:100].lower(), list(valid), n=1, cutoff=0.6)
        if close and close[0] not in answers:
            text = (
                f"[problem{index}] has no part {shown!r}: did you mean {close[0]!r}? That "
                f"answer was not graded, and {close[0]!r} counts as not answered."
            )
        elif close:
            text = f"[problem{index}] has no part {shown!r} (did you mean {close[0]!r}?); "
            text += "that answer was not graded."
        else:
            text = f"[problem{index}] has no part {shown!r}; that answer was not graded "
            text += f"(its parts are {', '.join(valid)})."
        out.append(text)
    if len(unknown) > MAX_KEY_WARNINGS:
        out.append(f"[problem{index}]: {len(unknown) - MAX_KEY_WARNINGS} more unknown keys")
    return out


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
