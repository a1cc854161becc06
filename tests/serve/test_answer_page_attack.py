"""The answer page under attack: answers whose check holds a worker in C code (where no alarm
reaches: the planted checker of `tests/planted.py`) are killed at the limit + grace, one
student has one item in the workers at a time, and a bystander's preview is answered at once
while two students attack."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest

from lagrade.cli.main import main
from lagrade.grading.answer_page.preview import PREVIEW_TIME_LIMIT
from lagrade.grading.answer_page.saving import SAVE_PART_TIME_LIMIT
from lagrade.judge.clocks import GRACE
from tests.planted import HANG
from tests.serve.conftest import ROSTER, post, start_server, stop_server

ASSIGNMENT = """\
title = "Answer page under attack"
points = 1

[[problems]]
scene = "wedge"
parts = ["dof", "lagrangian", { quantity = "block_acceleration" }]
"""
#: Slack over the limit + grace for the round trip and a loaded machine.
SLACK = 2.5


def _slow(student: str) -> dict:
    return {"problem": 1, "key": "block_acceleration", "text": HANG}


@pytest.fixture(scope="module")
def attacked(tmp_path_factory):
    root = tmp_path_factory.mktemp("attack")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    (root / "roster.csv").write_text(ROSTER)
    args = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    assert main([*args, "--seed", "5", "--out", str(root / "ps"), "--formats", "md"]) == 0
    server = start_server(root, root / "ps" / "manifest.json", planted=True)  # --jobs 1
    yield server
    stop_server(server)


def _timed_post(url: str, body: dict) -> tuple[float, int, dict]:
    start = time.monotonic()
    status, reply = post(url, body, timeout=120)
    return time.monotonic() - start, status, reply


def test_two_attackers_do_not_hold_a_bystanders_preview(attacked):
    stop = threading.Event()
    replies: list[tuple[str, float, dict]] = []

    def attack(student: str) -> None:  # a slow preview again as soon as one is answered
        while not stop.is_set():
            elapsed, _, reply = _timed_post(attacked.url(student) + "/preview", _slow(student))
            replies.append((student, elapsed, reply))

    attackers = [threading.Thread(target=attack, args=(s,)) for s in ("s001", "s002")]
    for thread in attackers:
        thread.start()
    try:
        time.sleep(1.0)  # both attacks are in the workers now
        bystander = []
        for text in ("1", "2", "m*g*h"):
            key = "dof" if text != "m*g*h" else "lagrangian"
            elapsed, status, reply = _timed_post(
                attacked.url("s003") + "/preview", {"problem": 1, "key": key, "text": text}
            )
            assert status == 200 and reply["status"] == "read", reply
            bystander.append(elapsed)
            time.sleep(0.5)
        time.sleep(PREVIEW_TIME_LIMIT + GRACE)  # let each attacker's first preview end
    finally:
        stop.set()
        for thread in attackers:
            thread.join()
    assert max(bystander) < 1.0, bystander
    assert {student for student, _, _ in replies} == {"s001", "s002"}
    for _student, elapsed, reply in replies:
        assert reply["status"] == "timeout"
        assert reply["message"] == "Reading this answer took too long."
        assert elapsed < PREVIEW_TIME_LIMIT + GRACE + SLACK, elapsed


def test_one_student_has_one_item_in_the_workers(attacked):
    """While a student's slow preview runs, their next previews wait in their own lane; a newer
    preview of the same field replaces the one waiting (answered `superseded`)."""
    results: dict[str, tuple[float, dict]] = {}

    def ask(name: str, body: dict) -> None:
        elapsed, _, reply = _timed_post(attacked.url("s002") + "/preview", body)
        results[name] = (elapsed, reply)

    slow = threading.Thread(target=ask, args=("slow", _slow("s002")))
    slow.start()
    time.sleep(0.5)
    first = threading.Thread(target=ask, args=("first", {"problem": 1, "key": "dof", "text": "1"}))
    first.start()
    time.sleep(0.3)
    second = {"problem": 1, "key": "dof", "text": "2"}
    newest = threading.Thread(target=ask, args=("newest", second))
    newest.start()
    for thread in (slow, first, newest):
        thread.join()
    assert results["slow"][1]["status"] == "timeout"
    assert results["first"][1] == {
        "status": "superseded",
        "lines": [],
        "message": "",
        "warnings": [],
    }
    assert results["first"][0] < 1.0  # answered when replaced, not when the lane frees
    assert results["newest"][1]["status"] == "read"
    assert results["newest"][1]["lines"][0]["plain"] == "2"
    # it waited for the slow one: the student's own lane, not a third worker
    assert results["newest"][0] > PREVIEW_TIME_LIMIT - 1.0


def _descendants(pid: int) -> list[int]:
    """Every process below `pid` (Linux /proc)."""
    parents: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            ppid = int(stat.rsplit(")", 1)[1].split()[1])
            parents.setdefault(ppid, []).append(int(entry.name))
    found, todo = [], [pid]
    while todo:
        children = parents.get(todo.pop(), [])
        found += children
        todo += children
    return found


def test_the_pages_workers_have_a_memory_limit(attacked):
    limits = []
    for pid in _descendants(attacked.process.pid):
        try:
            text = Path(f"/proc/{pid}/limits").read_text()
        except OSError:
            continue
        line = next(ln for ln in text.splitlines() if ln.startswith("Max address space"))
        limits.append(line.split()[3])
    assert "unlimited" in limits  # the host, which judges nothing
    assert any(value != "unlimited" for value in limits)  # its workers


def test_a_graded_save_killed_in_one_part_keeps_the_others(tmp_path):
    root = tmp_path
    (root / "assignment.toml").write_text(ASSIGNMENT + "\n[answer_page]\nfeedback = true\n")
    (root / "roster.csv").write_text(ROSTER)
    args = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    assert main([*args, "--seed", "5", "--out", str(root / "ps"), "--formats", "md"]) == 0
    server = start_server(root, root / "ps" / "manifest.json", planted=True)
    try:
        answers = {"dof": "2", "lagrangian": "m*g*h", "block_acceleration": HANG}
        elapsed, status, reply = _timed_post(
            server.url("s001") + "/save", {"answers": {"1": answers}}
        )
    finally:
        stop_server(server)
    assert status == 200 and reply["status"] == "saved"
    parts = reply["feedback"]["parts"]
    assert parts["1/block_acceleration"]["verdict"] == "timeout"
    assert parts["1/dof"]["verdict"] == "correct" and parts["1/dof"]["points"] == 1
    assert parts["1/lagrangian"]["verdict"] == "incorrect" and parts["1/lagrangian"]["feedback"]
    # the part's limit and grace, and a fresh worker for the rest (on c5b4539: the whole hold)
    assert elapsed < SAVE_PART_TIME_LIMIT + GRACE + 2 * SLACK, elapsed
