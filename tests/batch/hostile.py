"""Helpers for the hostile-input tests: run `lagrade` as a user would, in a child process (so a
crash, a traceback on stderr or a stray file is seen as the user would see it), read its outputs
strictly, and snapshot a folder tree to prove that nothing was written outside `--out`."""

from __future__ import annotations

import csv
import hashlib
import io
import json
import os
import subprocess
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import lagrade

#: The source tree under test (the worktree a test run imports `lagrade` from).
SOURCE = Path(lagrade.__file__).resolve().parent.parent

#: A bank question that every process derives in a few milliseconds.
PENDULUM = {"scene": "simple_pendulum", "seed": 1}
#: An ad-hoc question whose coordinate is called `theta` whatever the seed.
AD_HOC = {
    "lagrangian": "m*l^2*theta_dot^2/2 + m*g*l*cos(theta)",
    "coordinates": ["theta"],
    "parameters": {"m": "positive", "g": "positive", "l": "positive"},
}
EXPRESSION = {"expression": "m*g*cos(theta)", "parameters": {"m": "positive", "theta": "(0, 1)"}}


def command(*args: Any) -> list[str]:
    """`python -m lagrade ARGS`; run it from outside a source tree, or `-m` imports that one."""
    return [sys.executable, "-m", "lagrade", *map(str, args)]


#: The environment of a child: the tree under test, and no .pyc files written into it.
ENV = {**os.environ, "PYTHONPATH": str(SOURCE), "PYTHONDONTWRITEBYTECODE": "1"}


def run_lagrade(
    *args: Any, cwd: Path, timeout: float = 300, preexec_fn: Callable[[], None] | None = None
) -> subprocess.CompletedProcess[bytes]:
    """`python -m lagrade ARGS` on the tree under test; stdout and stderr as bytes."""
    return subprocess.run(
        command(*args),
        cwd=cwd,
        env=ENV,
        capture_output=True,
        timeout=timeout,
        preexec_fn=preexec_fn,
    )


def no_traceback(proc: subprocess.CompletedProcess[bytes]) -> None:
    stderr = proc.stderr.decode("utf-8", "replace")
    assert "Traceback" not in stderr, stderr[-3000:]


def request(request_id: Any, answer: Any, part: str = "dof", problem: Any = None) -> bytes:
    """One request line as UTF-8 JSON (non-ASCII characters written raw)."""
    body = {"id": request_id, "problem": problem or PENDULUM, "part": part, "answer": answer}
    return json.dumps(body, ensure_ascii=False).encode("utf-8")


def run_batch(
    folder: Path, records: Sequence[bytes], *extra: str
) -> tuple[subprocess.CompletedProcess[bytes], list[dict[str, Any]]]:
    """Write `records` joined by b"\\n" to a requests file, run `check --batch` on it and return
    the process and the result lines (read strictly: UTF-8, split on \\n only, JSON each)."""
    requests, results = folder / "requests.jsonl", folder / "results.jsonl"
    requests.write_bytes(b"\n".join(records) + b"\n")
    results.unlink(missing_ok=True)
    proc = run_lagrade("check", "--batch", requests, "--out", results, *extra, cwd=folder)
    return proc, (read_results(results) if results.exists() else [])


def _not_json(constant: str) -> None:
    raise ValueError(f"{constant} is not JSON (RFC 8259)")


def read_results(path: Path) -> list[dict[str, Any]]:
    """Result lines, read strictly: UTF-8 (a lone surrogate or bad byte raises), split on \\n
    only, and JSON as RFC 8259 has it (NaN and Infinity, which Python writes, refused)."""
    text = path.read_bytes().decode("utf-8")
    lines = text.split("\n")
    assert lines[-1] == "", "the results file does not end with a newline"
    return [json.loads(line, parse_constant=_not_json) for line in lines[:-1]]


def records_of(data: bytes) -> list[bytes]:
    """The request lines of a file: split on b"\\n" only, blank ones (ASCII spaces) left out."""
    return [r for r in data.split(b"\n") if r.strip(b" \t\r")]


def gradebook(out: Path) -> list[dict[str, str]]:
    """gradebook.csv's rows (read strictly as UTF-8)."""
    text = (out / "gradebook.csv").read_bytes().decode("utf-8")
    return list(csv.DictReader(io.StringIO(text, newline="")))


def tree(folder: Path, skip: Path | None = None) -> dict[str, str]:
    """Every entry under `folder` (not following links), `skip`'s subtree left out: its kind and
    content hash, or a link's target."""
    found = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        here = Path(dirpath)
        if skip is not None and (here == skip or skip in here.parents):
            dirnames[:] = []
            continue
        for name in dirnames + filenames:
            path = here / name
            if path == skip:
                continue
            rel = str(path.relative_to(folder))
            if path.is_symlink():
                found[rel] = "link:" + os.readlink(path)
            elif path.is_dir():
                found[rel] = "dir"
            elif path.is_file():
                found[rel] = hashlib.sha256(path.read_bytes()).hexdigest()
            else:
                found[rel] = "special"
    return found


def undecodable(out: Path) -> list[str]:
    """Output files (all but the PNG chart) that are not valid UTF-8."""
    bad = []
    for path in out.rglob("*"):
        if path.is_file() and path.suffix != ".png":
            try:
                path.read_bytes().decode("utf-8")
            except UnicodeDecodeError:
                bad.append(str(path.relative_to(out)))
    return bad
