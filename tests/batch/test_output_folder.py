"""The output folder belongs to one run at a time; another process's temp files are never
touched; and a fault of the machine (full disk, read-only folder) is its own exit status with
one readable line, distinct from a normal run with missing students."""

from __future__ import annotations

import errno
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

import lagrade.grading.atomic as atomic
from lagrade.cli.main import (
    EXIT_BAD_INPUT,
    EXIT_BUSY,
    EXIT_ENVIRONMENT,
    EXIT_NOT_ALL_PASSED,
    EXIT_OK,
    main,
)


def grade_args(workspace: Path, *extra: str) -> list[str]:
    return [
        "grade",
        str(workspace / "out" / "manifest.json"),
        str(workspace / "submissions"),
        "--out",
        str(workspace / "grades"),
        *extra,
    ]


def test_a_second_run_on_the_same_folder_is_refused_with_its_own_status(workspace, capsys):
    # Another process holds the folder (as a running `lagrade grade` would).
    holder = subprocess.Popen(
        [
            sys.executable,
            "-c",
            "import sys, time, lagrade.grading.atomic as a\n"
            "with a.hold_folder(sys.argv[1]):\n"
            "    print('held', flush=True); time.sleep(60)\n",
            str(workspace / "grades"),
        ],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert holder.stdout.readline().strip() == "held"
        assert main(grade_args(workspace)) == EXIT_BUSY
        err = capsys.readouterr().err
        assert f"pid {holder.pid}" in err and "Traceback" not in err
        assert not (workspace / "grades" / "gradebook.csv").exists()
    finally:
        holder.kill()
        holder.wait()
    # Once the holder is gone (killed, not even cleanly), the folder is free again.
    assert main(grade_args(workspace)) == EXIT_OK


def test_the_lock_is_not_held_by_forked_children(tmp_path):
    """Workers are forked while the parent holds the folder; a killed parent's orphans must not
    keep the next run out (flock would: its lock is shared with every forked child)."""
    with atomic.hold_folder(tmp_path):
        pid = os.fork()
        if pid == 0:  # the child: sleep as a worker would, holding the parent's descriptors
            time.sleep(3)
            os._exit(0)
    try:
        with atomic.hold_folder(tmp_path):  # parent released; the live child must not block it
            pass
    finally:
        os.kill(pid, 9)
        os.waitpid(pid, 0)


def test_temp_files_of_a_live_run_are_left_alone(workspace):
    grades = workspace / "grades"
    grades.mkdir()
    live = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        theirs = grades / f".gradebook.csv.{live.pid}.abc123.tmp"
        foreign = grades / ".notes.tmp"  # not ours at all
        dead = grades / ".summary.md.999999999.xyz.tmp"  # no process has that pid
        for path in (theirs, foreign, dead):
            path.write_text("half-written")
        assert main(grade_args(workspace)) == EXIT_OK
        assert theirs.read_text() == "half-written"
        assert foreign.exists()
        assert not dead.exists()
    finally:
        live.kill()
        live.wait()


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EROFS, errno.EACCES])
def test_a_disk_fault_is_an_environment_fault(workspace, monkeypatch, capsys, code):
    real_replace = os.replace

    def failing_replace(src, dst):
        if str(dst).endswith("gradebook.csv"):
            raise OSError(code, os.strerror(code))
        return real_replace(src, dst)

    monkeypatch.setattr(os, "replace", failing_replace)
    assert main(grade_args(workspace)) == EXIT_ENVIRONMENT
    err = capsys.readouterr().err
    assert os.strerror(code) in err and "gradebook.csv" in err
    assert "Traceback" not in err
    assert not list((workspace / "grades").glob(".gradebook.csv.*.tmp"))


def test_exit_statuses_are_distinct(workspace, capsys):
    """0 all graded, 1 graded with a student missing, 2 bad input; each documented in --help."""
    assert main(grade_args(workspace)) == EXIT_OK
    next(iter(sorted((workspace / "submissions").iterdir()))).unlink()
    assert main(grade_args(workspace)) == EXIT_NOT_ALL_PASSED
    (workspace / "out" / "manifest.json").write_text("{not json")
    assert main(grade_args(workspace)) == EXIT_BAD_INPUT
    assert len({EXIT_OK, EXIT_NOT_ALL_PASSED, EXIT_BAD_INPUT, EXIT_ENVIRONMENT, EXIT_BUSY}) == 5
    with pytest.raises(SystemExit):
        main(["--help"])
    help_text = capsys.readouterr().out
    for status in ("0 success", "1 done", "2 bad input", "3 environment fault", "4 the output"):
        assert status in " ".join(help_text.split())


def test_ids_that_are_paths_never_leave_the_output_folder(workspace, capsys):
    manifest_path = workspace / "out" / "manifest.json"
    manifest = json.loads(manifest_path.read_text())
    manifest["students"][0]["id"] = "../../escaped"
    manifest_path.write_text(json.dumps(manifest))
    before = set(workspace.parent.rglob("*"))
    assert main(grade_args(workspace)) == EXIT_BAD_INPUT
    assert "cannot name a file" in capsys.readouterr().err
    assert set(workspace.parent.rglob("*")) - before <= set(workspace.rglob("*"))


def test_an_interrupt_inside_mkstemp_leaves_no_temp_file(tmp_path, monkeypatch):
    """Ctrl-C can strike after mkstemp has made the file but before `writing` knows its name;
    the run's hold on the folder removes what it left (seen once in the interrupted-run test)."""
    real_mkstemp = atomic.tempfile.mkstemp

    def interrupted(*args, **kwargs):
        fd, name = real_mkstemp(*args, **kwargs)
        os.close(fd)
        raise KeyboardInterrupt

    monkeypatch.setattr(atomic.tempfile, "mkstemp", interrupted)
    with pytest.raises(KeyboardInterrupt), atomic.hold_folder(tmp_path):
        atomic.write_text(tmp_path / "students" / "s01.json", "{}")
    assert not list(tmp_path.rglob("*.tmp"))
