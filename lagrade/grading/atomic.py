"""Atomic file output: write to a temporary file beside the target, then rename over it, so a
reader (or an interrupted run: Ctrl-C, a kill) never sees a half-written file. And the lock that
lets one run at a time write into an output folder.

No fsync: the guarantee is against the process being stopped, which is what a grading run
meets; flushing every file to the platter would cost more than grading it (measured: the
per-student outputs of a batch took longer than the grading with an fsync per file).

A temporary file's name carries the pid of the run that made it (`.name.<pid>.<random>.tmp`):
the run removes its own on failure, and a later run removes only those whose run has died, so
no run ever deletes a file that another live process is writing.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import json
import os
import re
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from lagrade.errors import OutputBusy, OutputError

LOCK_NAME = ".lagrade.lock"
_TEMPORARY = re.compile(r"^\..+\.(\d+)\.[^.]+\.tmp$")


@contextlib.contextmanager
def writing(path: Path) -> Iterator[Any]:
    """A binary file to stream into that appears at `path` only when the block ends normally
    (write_bytes for output too large to hold in memory at once)."""
    path = Path(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(
            prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=path.parent
        )
    except OSError as error:
        raise OutputError(_cannot_write(path, error)) from None
    try:
        with os.fdopen(fd, "wb") as f:
            yield f
        os.replace(tmp, path)
    except BaseException as error:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        if isinstance(error, OSError):
            raise OutputError(_cannot_write(path, error)) from None
        raise


def write_bytes(path: Path, data: bytes) -> None:
    """Write `data` to `path` atomically (same-folder temp file, then os.replace). A full disk,
    a read-only folder or a missing permission raises OutputError naming the file."""
    with writing(path) as f:
        f.write(data)


def write_text(path: Path, text: str) -> None:
    """Write text as UTF-8 (`encode_text`)."""
    write_bytes(path, encode_text(text))


def encode_text(text: str) -> bytes:
    """Text as `write_text` writes it: UTF-8. A lone surrogate cannot be UTF-8: the readers refuse
    them, and should one come through anyway it is written as its escape (`\\udc80`), never a
    crash."""
    return text.encode("utf-8", errors="backslashreplace")


def write_json(path: Path, data: Any) -> None:
    write_text(path, json.dumps(data, indent=2, ensure_ascii=False, sort_keys=True) + "\n")


def remove_stale_temporaries(folder: Path) -> int:
    """Delete the temp files that runs which have since died left in `folder`; returns how many.
    A temp file of a live process, or one not named by this module, is left alone."""
    count = 0
    for leftover in Path(folder).rglob(".*.tmp"):
        match = _TEMPORARY.match(leftover.name)
        if match is None or _alive(int(match.group(1))):
            continue
        leftover.unlink(missing_ok=True)
        count += 1
    return count


@contextlib.contextmanager
def hold_folder(folder: Path) -> Iterator[None]:
    """Hold `folder` for this run: a second run that asks while this one writes gets
    OutputBusy at once (never a wait, never two runs interleaving their files). The lock is a
    POSIX record lock (lockf): it ends with the process however the process ends, and unlike
    flock it is not inherited by forked workers, which may outlive a killed parent briefly."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd = os.open(folder / LOCK_NAME, os.O_RDWR | os.O_CREAT, 0o644)
    except OSError as error:
        raise OutputError(_cannot_write(folder, error)) from None
    try:
        try:
            fcntl.lockf(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as error:
            if error.errno not in (errno.EACCES, errno.EAGAIN):
                raise OutputError(_cannot_write(folder, error)) from None
            holder = os.pread(fd, 32, 0).decode("ascii", "replace").strip() or "another"
            raise OutputBusy(
                f"another lagrade run (pid {holder}) is writing to {folder}; wait for it to "
                "finish or choose another output folder"
            ) from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        yield
    finally:
        try:
            _remove_own_temporaries(folder)
        finally:
            os.close(fd)


def _remove_own_temporaries(folder: Path) -> None:
    """Delete the temp files this process left in `folder`: an interrupt that strikes between
    a temp file's creation and its rename (inside mkstemp, say) leaves one that `writing`
    never learnt the name of."""
    mine = str(os.getpid())
    for leftover in Path(folder).rglob(".*.tmp"):
        match = _TEMPORARY.match(leftover.name)
        if match is not None and match.group(1) == mine:
            with contextlib.suppress(OSError):
                leftover.unlink()


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OverflowError:
        return False  # no process has a pid that large
    except PermissionError:
        return True  # another user's process
    return True


def _cannot_write(path: Path, error: OSError) -> str:
    reason = error.strerror or str(error)
    return f"cannot write {path}: {reason}"
