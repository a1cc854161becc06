"""`lagrade serve`, over HTTP against a live server: private links, the preview, saving the
sheet `lagrade grade` reads (every version in the log of saves), refusals, and a clean stop."""

from __future__ import annotations

import csv
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from lagrade.grading.answer_page.tokens import load_or_create_secret, student_token
from lagrade.grading.savelog import SaveLog, log_path
from lagrade.grading.submission import read_sheet, sheet_from_bytes
from tests.serve.conftest import generate_class, get, post, start_server, stop_server


def test_links_are_per_student_and_private(served):
    assert set(served.links) == {"s001", "s002", "s003"}
    tokens = {url.rsplit("/", 1)[1] for url in served.links.values()}
    assert len(tokens) == 3 and all(len(t) == 32 for t in tokens)
    for student_id, name in (("s001", "Ada Lovelace"), ("s002", "Emmy Noether")):
        status, page = get(served.url(student_id))
        assert status == 200
        assert name in page
        others = {"Ada Lovelace", "Emmy Noether", "Lise Meitner"} - {name}
        assert not any(other in page for other in others)


def test_wrong_or_missing_token_is_404_without_data(served):
    token = served.url("s001").rsplit("/", 1)[1]
    wrong = token[:-1] + ("a" if token[-1] != "a" else "b")
    for url in (
        f"{served.base}/s/{wrong}",
        f"{served.base}/s/",
        f"{served.base}/s/s001",
        f"{served.base}/manifest.json",
        f"{served.base}/s/{wrong}/handout",
    ):
        status, body = get(url)
        assert status == 404, url
        assert body == "Not found."
    status, body = post(f"{served.base}/s/{wrong}/save", {"answers": {"1": {"dof": "1"}}})
    assert status == 404 and body == "Not found."
    status, body = post(
        f"{served.base}/s/{wrong}/preview", {"problem": 1, "key": "dof", "text": "1"}
    )
    assert status == 404
    assert (
        not (served.sheets / "s001.toml").exists()
        or "dof = '1'" not in (served.sheets / "s001.toml").read_text()
    )


def test_preview_shows_the_reading_as_mathml(served):
    url = served.url("s002") + "/preview"
    status, result = post(
        url, {"problem": 1, "key": "lagrangian", "text": "1/2 m l^2 theta_dot^2 + m g l cos(theta)"}
    )
    assert status == 200 and result["status"] == "read"
    (line,) = result["lines"]
    assert line["plain"].startswith("1/2*m*l^2*theta_dot^2")
    assert line["mathml"].startswith("<math") and "<mover" in line["mathml"]  # θ with a dot
    # typeset in the student's order with every product dotted (issue 29), not sympy's g·l·m…
    dot = "<mo>&#183;</mo>"
    assert line["mathml"].index("<mfrac>") < line["mathml"].index("<mi>g</mi>")
    assert f"<mi>m</mi>{dot}<mi>g</mi>{dot}<mi>l</mi>{dot}<mrow><mi>cos</mi>" in line["mathml"]
    status, result = post(url, {"problem": 1, "key": "lagrangian", "text": r"\frac{1}{2} m"})
    assert result["status"] == "read"
    status, result = post(url, {"problem": 1, "key": "lagrangian", "text": "m (g"})
    assert result["status"] == "unreadable"
    assert "never closed" in result["message"] and "^" in result["message"]
    status, result = post(url, {"problem": 1, "key": "eom", "text": "theta_ddot = 0\nm +* 2"})
    assert result["status"] == "read" and len(result["lines"]) == 1
    assert "Line 2 could not be read" in result["message"]
    status, result = post(url, {"problem": 1, "key": "lagrangian", "text": "  "})
    assert result == {"status": "empty", "lines": [], "message": "", "warnings": []}


def test_preview_never_tells_right_from_wrong(served):
    url = served.url("s002") + "/preview"
    _, right = post(url, {"problem": 1, "key": "dof", "text": "1"})
    _, wrong = post(url, {"problem": 1, "key": "dof", "text": "7"})
    assert set(right) == set(wrong) == {"status", "lines", "message", "warnings"}
    assert right["status"] == wrong["status"] == "read"


def test_save_writes_the_sheet_grade_reads_and_logs_every_version(served):
    url = served.url("s003") + "/save"
    first = {"1": {"dof": "1", "lagrangian": r"\frac{1}{2} m l^2 \dot{\theta}^2", "eom": ""}}
    status, reply = post(url, {"answers": first})
    assert status == 200 and reply["status"] == "saved" and reply["file"] == "s003.toml"
    second = {
        "1": {
            "dof": "1",
            "lagrangian": "m l^2 theta_dot^2/2 + m g l cos(theta)",
            "eom": "m l^2 theta_ddot = -m g l sin(theta)\nx'' = 0",
            "momenta": "p_theta = m l^2 theta_dot",
        }
    }
    status, reply = post(url, {"answers": second})
    assert status == 200
    keys = {1: ["dof", "lagrangian", "eom", "momenta"]}
    sheet = read_sheet(served.sheets / "s003.toml", "s003", 1, keys)
    assert sheet.readable and not sheet.warnings
    assert sheet.answers[1]["lagrangian"] == second["1"]["lagrangian"]
    assert sheet.answers[1]["eom"].splitlines() == second["1"]["eom"].splitlines()
    logged = SaveLog(log_path(served.sheets), create=False).saves("s003")
    assert logged[-1].sheet == (served.sheets / "s003.toml").read_bytes()
    previous = sheet_from_bytes(Path("s003.toml"), logged[-2].sheet, "s003", 1, keys)
    assert previous.answers[1]["lagrangian"] == first["1"]["lagrangian"]  # backslashes kept
    assert "eom" not in previous.answers[1]  # a blank field is not written
    assert logged[-2].answers == {"1": {k: v for k, v in first["1"].items() if v}}
    assert not (served.sheets / ".previous").exists()  # the log holds every version


def test_bad_requests_are_refused_and_write_nothing(served):
    url = served.url("s002") + "/save"
    for body in (
        b"[[[[",
        b"\xff\xfe",
        {"answers": {"9": {"dof": "1"}}},
        {"answers": {"1": {"doff": "1"}}},
        {"answers": {"1": {"dof": 3}}},
        {"answers": "x"},
        [1, 2],
        b"x" * 600_000,
    ):
        status, reply = post(url, body)
        assert status == 400, body
        assert reply["status"] == "error" and reply["message"]
    assert not (served.sheets / "s002.toml").exists()


def test_saves_of_many_students_at_once_never_mix(tmp_path, served):
    """Each of 3 students saves 20 times from 3 threads at once: every sheet on disk is one
    of that student's own saves, whole, and the log holds all 60 of each, the last one the
    sheet on disk."""
    errors = []
    log = SaveLog(log_path(served.sheets), create=False) if served.sheets.exists() else None
    before = {s: len(log.saves(s)) if log else 0 for s in served.links}

    def hammer(student_id: str, thread: int) -> None:
        for k in range(20):
            text = f"{student_id} {thread} {k}"
            status, _ = post(
                served.url(student_id) + "/save",
                {"answers": {"1": {"lagrangian": f"m*g*l  # {text}"}}},
            )
            if status != 200:
                errors.append(status)

    threads = [threading.Thread(target=hammer, args=(s, t)) for s in served.links for t in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for student_id in served.links:
        text = (served.sheets / f"{student_id}.toml").read_text()
        assert f'student_id = "{student_id}"' in text
        others = set(served.links) - {student_id}
        assert not any(f"# {o} " in text for o in others)
        rows = SaveLog(log_path(served.sheets), create=False).saves(student_id)
        assert len(rows) - before[student_id] == 60
        assert rows[-1].sheet == (served.sheets / f"{student_id}.toml").read_bytes()
        assert all(f"# {student_id} " in r.answers["1"]["lagrangian"] for r in rows[-60:])


def test_port_in_use_is_one_clear_error(served, tmp_path):
    port = int(served.base.rsplit(":", 1)[1])
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            "from lagrade.cli.main import entry; entry()",
            "serve",
            str(served.manifest),
            "--submissions",
            str(tmp_path),
            "--port",
            str(port),
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert result.returncode == 3
    assert f"cannot listen on 127.0.0.1:{port}" in result.stderr
    assert "Traceback" not in result.stderr


def test_feedback_on_save_with_a_limit_of_attempts(tmp_path):
    manifest = generate_class(tmp_path, "[answer_page]\nfeedback = true\nattempts = 1\n")
    server = start_server(tmp_path, manifest)
    try:
        url = server.url("s001") + "/save"
        status, reply = post(url, {"answers": {"1": {"dof": "1", "lagrangian": "m g l"}}})
        assert status == 200 and reply["attempts_left"] == 0
        parts = reply["feedback"]["parts"]
        assert parts["1/dof"]["verdict"] == "correct"
        assert parts["1/lagrangian"]["verdict"] == "incorrect" and parts["1/lagrangian"]["feedback"]
        assert parts["1/eom"]["feedback"] == ["Not answered."]
        status, reply = post(url, {"answers": {"1": {"dof": "2"}}})
        assert status == 200 and reply["feedback"] is None and reply["attempts_left"] == 0
        assert "dof = '2'" in (server.sheets / "s001.toml").read_text()  # saved all the same
    finally:
        assert stop_server(server) == 0


@pytest.mark.parametrize("how", [signal.SIGTERM, signal.SIGINT], ids=["sigterm", "ctrl-c"])
def test_a_signal_stops_the_server_cleanly(tmp_path, how):
    manifest = generate_class(tmp_path)
    server = start_server(tmp_path, manifest)
    start = time.monotonic()
    server.process.send_signal(how)
    status = server.process.wait(timeout=30)
    assert time.monotonic() - start < 15
    assert status == 0  # documented: stopping is a server's normal end, not an interruption
    output = server.output.read_text()
    assert "Stopped" in output and "Traceback" not in output
    assert "interrupted" not in output and "error" not in output, output
    port = int(server.base.rsplit(":", 1)[1])
    with socket.socket() as sock:  # the port is free again
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(("127.0.0.1", port))


def test_links_are_stable_for_the_same_secret(served, tmp_path):
    rows = list(csv.DictReader((served.root / "links.csv").open()))
    secret = load_or_create_secret(served.manifest.parent / ".lagrade-serve-secret")
    for row in rows:
        assert row["url"].endswith("/s/" + student_token(secret, row["id"]))
    other = load_or_create_secret(tmp_path / "other-secret")
    assert student_token(other, "s001") != student_token(secret, "s001")


def test_a_signal_before_uvicorn_listens_still_stops_the_server_cleanly(tmp_path):
    """The race CI met: SIGTERM right after "listening on" but before uvicorn had put in its
    own handlers, which left a half-built event loop and a traceback. Here the signal is
    raised at exactly that moment, every time."""
    uvicorn = pytest.importorskip("uvicorn")
    if not hasattr(uvicorn.Config, "get_loop_factory"):  # uvicorn < 0.36 builds its loop elsewhere
        pytest.skip("this uvicorn has no loop factory to raise the signal in")
    manifest = generate_class(tmp_path)
    starter = (
        "import asyncio, signal, uvicorn\n"
        "def loop():\n"  # the stop lands while asyncio.run builds its event loop
        "    signal.raise_signal(signal.SIGTERM)\n"
        "    return asyncio.new_event_loop()\n"
        "uvicorn.Config.get_loop_factory = lambda self: loop\n"
        "from lagrade.cli.main import entry; entry()\n"
    )
    command = [sys.executable, "-c", starter, "serve", str(manifest)]
    command += ["--submissions", str(tmp_path / "sheets"), "--port", "0", "--jobs", "1"]
    done = subprocess.run(command, capture_output=True, text=True, timeout=120)
    output = done.stdout + done.stderr
    assert done.returncode == 0, output
    assert "Stopped" in output and "Traceback" not in output and "never awaited" not in output
