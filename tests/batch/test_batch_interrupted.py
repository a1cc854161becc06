"""A grading run stopped half-way (Ctrl-C, or killed outright) leaves no partial output file,
and a rerun completes the work, reusing what was finished."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest


def grade_command(workspace: Path) -> list[str]:
    """`lagrade grade` on the workspace's class, as a separate process."""
    return [
        sys.executable,
        "-m",
        "lagrade",
        "grade",
        str(workspace / "out" / "manifest.json"),
        str(workspace / "submissions"),
        "--out",
        str(workspace / "grades"),
    ]


def start(workspace: Path) -> subprocess.Popen:
    return subprocess.Popen(
        grade_command(workspace) + ["--jobs", "1"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def wait_for_results(
    folder: Path, count: int, process: subprocess.Popen, limit: float = 120
) -> int:
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        done = len(list(folder.glob("*.json"))) if folder.exists() else 0
        if done >= count or process.poll() is not None:
            return done
        time.sleep(0.02)
    raise AssertionError("grading made no progress")


def assert_no_partial_files(out: Path) -> None:
    for path in out.rglob("*"):
        if path.is_file() and not path.name.endswith(".tmp"):
            if path.suffix == ".json":
                json.loads(path.read_text())  # a torn write would not parse
            assert path.stat().st_size > 0, path


def children(pid: int) -> list[int]:
    """The processes whose parent is `pid` (Linux /proc)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_bytes()
            except OSError:
                continue
            if int(stat.rsplit(b")", 1)[1].split()[1]) == pid:
                found.append(int(entry.name))
    return found


def assert_gone(pids: list[int], limit: float = 10.0) -> None:
    deadline = time.monotonic() + limit
    alive = pids
    while alive and time.monotonic() < deadline:
        alive = [p for p in alive if Path(f"/proc/{p}").exists() and not _zombie(p)]
        time.sleep(0.1)
    assert not alive, f"workers still running after their parent stopped: {alive}"


def _zombie(pid: int) -> bool:
    try:
        return b") Z " in Path(f"/proc/{pid}/stat").read_bytes()
    except OSError:
        return True


@pytest.mark.parametrize("how", [signal.SIGINT, signal.SIGKILL], ids=["ctrl-c", "kill"])
def test_rerun_completes_an_interrupted_run(workspace, how):
    process = start(workspace)
    students = workspace / "grades" / "students"
    done = wait_for_results(students, 1, process)
    workers = children(process.pid)
    process.send_signal(how)
    process.wait(30)
    assert_gone(workers)  # a killed parent's workers do not live on as orphans
    # a fast run can finish all 12 between the first result and the signal
    if done >= 12 or (process.returncode == 0 and len(list(students.glob("*.json"))) >= 12):
        pytest.skip("the run finished before it could be interrupted")
    assert_no_partial_files(workspace / "grades")
    if how == signal.SIGINT:
        assert process.returncode == 130
        assert not list((workspace / "grades").rglob("*.tmp"))
    finished = len(list(students.glob("*.json")))
    assert finished < 12

    rerun = subprocess.run(
        grade_command(workspace),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert rerun.returncode == 0, rerun.stderr
    assert f"({finished} unchanged, reused)" in rerun.stdout
    assert len(list(students.glob("*.json"))) == 12
    assert not list((workspace / "grades").rglob("*.tmp"))
    assert_no_partial_files(workspace / "grades")
