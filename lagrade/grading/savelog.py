"""The answer page's log of saves: every save appended to a SQLite database beside the sheets
(`SHEETS/.lagrade-saves.sqlite3`), with the student, the instant, the answers as sent, the
sheet's exact bytes and their SHA-256, so that "I saved it before the deadline" can be checked
and `lagrade grade --as-of TIME` grades the last save before a time, byte for byte.

The embedded default (Python's own sqlite3): WAL journal, `synchronous = FULL` (a save the page
reported is on disk), one transaction per save that holds the sheet's write too — the row is
committed only when the sheet is written, and a sheet whose row cannot be committed is put back
— so the log and the folder never disagree about a save the student was told of. Concurrent
saves (other students, other server processes) wait for each other (`BEGIN IMMEDIATE`, a busy
timeout), never interleave.

    saves     id, student, saved_at (UTC, ISO 8601), saved_ns, origin ('page', or 'found': a
              sheet the page did not write, logged before a save replaced it, dated by its
              modification time), late, token (the page's attempt token), answers (JSON), file,
              sheet (bytes), sha256
    gradings  save_id, graded_at, feedback (JSON): a graded save, one per attempt spent
"""

from __future__ import annotations

import contextlib
import dataclasses
import datetime as dt
import hashlib
import json
import os
import sqlite3
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

from lagrade.errors import OutputError, RequestError
from lagrade.grading.instants import from_ns, to_ns, utc_text

LOG_NAME = ".lagrade-saves.sqlite3"
#: The schema's version (`PRAGMA user_version`); a log of another version is refused.
VERSION = 1
_BUSY_SECONDS = 30.0
_SCHEMA = """
CREATE TABLE IF NOT EXISTS saves (
    id INTEGER PRIMARY KEY AUTOINCREMENT,
    student TEXT NOT NULL,
    saved_at TEXT NOT NULL,
    saved_ns INTEGER NOT NULL,
    origin TEXT NOT NULL CHECK (origin IN ('page', 'found')),
    late INTEGER NOT NULL DEFAULT 0,
    token TEXT,
    answers TEXT,
    file TEXT NOT NULL,
    sheet BLOB NOT NULL,
    sha256 TEXT NOT NULL,
    UNIQUE (student, token)
);
CREATE INDEX IF NOT EXISTS saves_by_time ON saves (student, saved_ns, id);
CREATE TABLE IF NOT EXISTS gradings (
    save_id INTEGER PRIMARY KEY REFERENCES saves (id),
    graded_at TEXT NOT NULL,
    feedback TEXT NOT NULL
);
"""


@dataclasses.dataclass(frozen=True)
class Save:
    """One row of the log."""

    id: int
    student: str
    saved_at: dt.datetime
    origin: str
    late: bool
    token: str | None
    answers: dict[str, dict[str, str]] | None
    file: str
    sheet: bytes
    sha256: str


def log_path(sheets: Path) -> Path:
    """Where the log of the sheets folder `sheets` is."""
    return Path(sheets) / LOG_NAME


def canonical_answers(answers: Mapping[Any, Mapping[str, str]]) -> str:
    """The answers as the log stores them: JSON, problems and keys sorted, blank answers left
    out (they are not in the sheet either), the rest as sent; equal answers, equal text."""
    kept = {
        str(index): {k: v for k, v in sorted(table.items()) if v.strip()}
        for index, table in answers.items()
    }
    return json.dumps(
        {i: t for i, t in sorted(kept.items(), key=lambda kv: int(kv[0])) if t},
        ensure_ascii=False,
    )


class SaveLog:
    """The log of one sheets folder. Each call opens its own connection: calls come from the
    server's threads, and a connection is cheap next to the fsync of a commit."""

    def __init__(self, path: Path, *, create: bool = True) -> None:
        """The log at `path`, made when absent; with `create=False` (a reader such as `grade
        --as-of`) it must exist already, and nothing is made."""
        self.path = Path(path)
        self.create = create
        if not create and not self.path.is_file():
            raise RequestError(
                f"there is no log of saves at {self.path} (the answer page, `lagrade serve`, "
                "writes it beside the sheets it saves)"
            )
        with self._connect() as conn:
            if create:
                _create(conn, self.path)
            else:
                _check(conn, self.path)

    # --- connections ------------------------------------------------------------------------
    @contextlib.contextmanager
    def _connect(self) -> Iterator[sqlite3.Connection]:
        try:
            # never made by a reader (mode=rw); the WAL's index beside it is, as SQLite needs
            mode = "rwc" if self.create else "rw"
            conn = sqlite3.connect(
                f"{self.path.resolve().as_uri()}?mode={mode}",
                uri=True,
                timeout=_BUSY_SECONDS,
                isolation_level=None,
            )
        except sqlite3.Error as error:
            raise OutputError(f"cannot open the log of saves {self.path}: {error}") from None
        try:
            conn.execute("PRAGMA synchronous = FULL")
            yield conn
        except sqlite3.DatabaseError as error:
            raise OutputError(f"the log of saves {self.path} failed: {error}") from None
        finally:
            conn.close()

    # --- writing ----------------------------------------------------------------------------
    def record(
        self,
        student: str,
        file: str,
        sheet: bytes,
        *,
        answers: Mapping[Any, Mapping[str, str]],
        token: str | None,
        late: bool,
        saved_ns: int,
        write: Callable[[], Callable[[], None]],
    ) -> Save:
        """Append a page save and write its sheet in one transaction: `write()` writes the
        sheet and returns how to undo that (put the replaced sheet back), which is called if
        the row cannot be committed. A failure of either leaves neither."""
        digest = hashlib.sha256(sheet).hexdigest()
        saved_at = from_ns(saved_ns)
        stored = canonical_answers(answers)
        with self._connect() as conn:
            conn.execute("BEGIN IMMEDIATE")
            try:
                cursor = conn.execute(
                    "INSERT INTO saves (student, saved_at, saved_ns, origin, late, token, "
                    "answers, file, sheet, sha256) VALUES (?, ?, ?, 'page', ?, ?, ?, ?, ?, ?)",
                    (
                        student,
                        utc_text(saved_at),
                        saved_ns,
                        int(late),
                        token,
                        stored,
                        file,
                        sheet,
                        digest,
                    ),
                )
                undo = write()
            except BaseException:
                conn.execute("ROLLBACK")
                raise
            try:
                conn.execute("COMMIT")
            except BaseException:
                undo()
                with contextlib.suppress(sqlite3.Error):
                    conn.execute("ROLLBACK")
                raise
            row_id = cursor.lastrowid
        kept = json.loads(stored)
        return Save(row_id, student, saved_at, "page", late, token, kept, file, sheet, digest)

    def keep_found(self, student: str, file: str, sheet: bytes, modified_ns: int) -> bool:
        """Log a sheet found on disk that is not the student's last logged one (a sheet from
        before the log, or one put in the folder by hand) before a save replaces it, dated by
        its modification time. True when a row was added."""
        digest = hashlib.sha256(sheet).hexdigest()
        with self._connect() as conn:
            conn.execute("BEGIN IMMEDIATE")
            try:
                last = conn.execute(
                    "SELECT sha256 FROM saves WHERE student = ? ORDER BY id DESC LIMIT 1",
                    (student,),
                ).fetchone()
                if last is not None and last[0] == digest:
                    conn.execute("COMMIT")
                    return False
                conn.execute(
                    "INSERT INTO saves (student, saved_at, saved_ns, origin, file, sheet, "
                    "sha256) VALUES (?, ?, ?, 'found', ?, ?, ?)",
                    (student, utc_text(from_ns(modified_ns)), modified_ns, file, sheet, digest),
                )
                conn.execute("COMMIT")
            except BaseException:
                with contextlib.suppress(sqlite3.Error):
                    conn.execute("ROLLBACK")
                raise
        return True

    def record_grading(self, save_id: int, feedback: Mapping[str, Any]) -> None:
        """Note that save `save_id` was graded (an attempt spent) and what the page showed."""
        with self._connect() as conn:
            conn.execute(
                "INSERT OR IGNORE INTO gradings (save_id, graded_at, feedback) VALUES (?, ?, ?)",
                (save_id, utc_text(dt.datetime.now(dt.UTC)), json.dumps(feedback)),
            )

    # --- reading ----------------------------------------------------------------------------
    def by_token(self, student: str, token: str) -> Save | None:
        """The student's save made with the page's attempt token `token`, if any."""
        with self._connect() as conn:
            row = conn.execute(
                f"SELECT {_COLUMNS} FROM saves WHERE student = ? AND token = ?", (student, token)
            ).fetchone()
        return None if row is None else _save(row)

    def grading_of(self, save_id: int) -> dict[str, Any] | None:
        """The feedback shown for save `save_id` when it was graded, else None."""
        with self._connect() as conn:
            row = conn.execute(
                "SELECT feedback FROM gradings WHERE save_id = ?", (save_id,)
            ).fetchone()
        return None if row is None else json.loads(row[0])

    def last_graded(self, student: str) -> tuple[str, dict[str, Any]] | None:
        """The answers (canonical JSON) and feedback of the student's last graded save."""
        with self._connect() as conn:
            row = conn.execute(
                "SELECT s.answers, g.feedback FROM gradings g JOIN saves s ON s.id = g.save_id "
                "WHERE s.student = ? ORDER BY g.save_id DESC LIMIT 1",
                (student,),
            ).fetchone()
        return None if row is None else (row[0], json.loads(row[1]))

    def attempts_used(self, student: str) -> int:
        """How many of the student's saves were graded (attempts spent)."""
        with self._connect() as conn:
            (count,) = conn.execute(
                "SELECT count(*) FROM gradings g JOIN saves s ON s.id = g.save_id "
                "WHERE s.student = ?",
                (student,),
            ).fetchone()
        return int(count)

    def saves(self, student: str | None = None) -> list[Save]:
        """Every row, in the order they were appended (of one student, when given)."""
        query = f"SELECT {_COLUMNS} FROM saves"
        args: tuple = ()
        if student is not None:
            query, args = query + " WHERE student = ?", (student,)
        with self._connect() as conn:
            return [_save(row) for row in conn.execute(query + " ORDER BY id", args)]

    def last_before(self, students: Iterable[str], moment: dt.datetime) -> dict[str, Save]:
        """Each student's last save at or before `moment` (by its time, then its order in
        the log); a student with none is left out."""
        limit = to_ns(moment)
        out: dict[str, Save] = {}
        with self._connect() as conn:
            for student in students:
                row = conn.execute(
                    f"SELECT {_COLUMNS} FROM saves WHERE student = ? AND saved_ns <= ? "
                    "ORDER BY saved_ns DESC, id DESC LIMIT 1",
                    (student, limit),
                ).fetchone()
                if row is not None:
                    out[student] = _save(row)
        return out

    def holds(self, student: str, sha256: str) -> bool:
        """Whether the log has a save of the student with these bytes."""
        with self._connect() as conn:
            row = conn.execute(
                "SELECT 1 FROM saves WHERE student = ? AND sha256 = ? LIMIT 1", (student, sha256)
            ).fetchone()
        return row is not None


_COLUMNS = "id, student, saved_ns, origin, late, token, answers, file, sheet, sha256"


def _save(row: tuple) -> Save:
    rid, student, saved_ns, origin, late, token, answers, file, sheet, digest = row
    return Save(
        rid,
        student,
        from_ns(saved_ns),
        origin,
        bool(late),
        token,
        None if answers is None else json.loads(answers),
        file,
        bytes(sheet),
        digest,
    )


def _create(conn: sqlite3.Connection, path: Path) -> None:
    """The tables, in WAL mode; a file that is not this log (another program's database,
    another version) is refused rather than written into."""
    (version,) = conn.execute("PRAGMA user_version").fetchone()
    tables = {r[0] for r in conn.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    if version != 0 or tables - {"sqlite_sequence"}:
        _check(conn, path)
        return
    conn.execute("PRAGMA journal_mode = WAL")
    conn.executescript(_SCHEMA)
    conn.execute(f"PRAGMA user_version = {VERSION}")


def _check(conn: sqlite3.Connection, path: Path) -> None:
    (version,) = conn.execute("PRAGMA user_version").fetchone()
    if version != VERSION:
        raise RequestError(
            f"{path} is not a log of saves this lagrade can use (schema version {version}, "
            f"expected {VERSION}); move it away to start a new log"
        )


def now_ns() -> int:
    """The server's clock, in nanoseconds after the epoch, at microsecond resolution (what the
    log stores, so that a save's instant compares exactly)."""
    return time.time_ns() // 1000 * 1000


def modified_ns(path: Path) -> int:
    """A file's modification time, at the log's resolution."""
    return os.lstat(path).st_mtime_ns // 1000 * 1000


def sheets_as_of(
    sheets: Path, student_ids: Iterable[str], moment: dt.datetime, into: Path
) -> dict[str, Save]:
    """Write into `into` each student's sheet as it stood at `moment`, byte for byte: the last
    save of the log at or before it, or a sheet in `sheets` the log does not hold (one never
    replaced by a save) when its modification time is at or before it and after that save.
    Returns what was written, by student; a student with neither is left out."""
    from lagrade.grading.submission import SUFFIXES, find_submission, read_regular_file

    log = SaveLog(log_path(sheets), create=False)
    ids = list(student_ids)
    chosen = log.last_before(ids, moment)
    limit = to_ns(moment)
    for student in ids:
        path, _ = find_submission(Path(sheets), student)
        if path is None:
            continue
        data, reason = read_regular_file(path)
        digest = hashlib.sha256(data).hexdigest()
        if reason or log.holds(student, digest):
            continue
        when = modified_ns(path)
        last = chosen.get(student)
        if when <= limit and (last is None or when > to_ns(last.saved_at)):
            chosen[student] = Save(
                0, student, from_ns(when), "found", False, None, None, path.name, data, digest
            )
    Path(into).mkdir(parents=True, exist_ok=True)
    for student, save in chosen.items():
        sheet_names = {student.lower() + suffix for suffix in SUFFIXES}
        name = save.file if save.file.lower() in sheet_names else f"{student}.toml"
        (Path(into) / name).write_bytes(save.sheet)
    return chosen
