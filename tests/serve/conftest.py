"""A small generated class and a live `lagrade serve` on a free port, started the way an
instructor starts it (the console command in a process of its own)."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request
from dataclasses import dataclass
from pathlib import Path

import pytest

from lagrade.cli.main import main

ASSIGNMENT = """\
title = "Answer page test"
course = "PHYS 201"
points = 1
{top}

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "eom", "momenta"]
points = { lagrangian = 2 }
{extra}
"""

REPOSITORY = Path(__file__).resolve().parents[2]  # where `tests.planted` is importable from
ROSTER = "id,name\ns001,Ada Lovelace\ns002,Emmy Noether\ns003,Lise Meitner\n"


@dataclass
class Served:
    root: Path
    manifest: Path
    sheets: Path
    links: dict[str, str]  # id → url
    base: str
    process: subprocess.Popen
    output: Path

    def url(self, student_id: str) -> str:
        return self.links[student_id]


def generate_class(root: Path, extra: str = "", top: str = "", assignment: str = "") -> Path:
    """A class of three from ASSIGNMENT (`top`: top-level keys such as `due`; `extra`: tables
    after the problem), or from the whole `assignment` text given."""
    text = assignment or ASSIGNMENT.replace("{extra}", extra).replace("{top}", top)
    (root / "assignment.toml").write_text(text)
    (root / "roster.csv").write_text(ROSTER)
    status = main(
        [
            "generate",
            str(root / "assignment.toml"),
            "--roster",
            str(root / "roster.csv"),
            "--seed",
            "11",
            "--out",
            str(root / "ps"),
            "--formats",
            "md",
        ]
    )
    assert status == 0
    return root / "ps" / "manifest.json"


def start_server(root: Path, manifest: Path, *extra: str, planted: bool = False) -> Served:
    """`lagrade serve` in a process of its own; `planted`: with the checker of
    `tests/planted.py`, which spins in C on an answer holding its marker."""
    sheets, links = root / "sheets", root / "links.csv"
    output = root / "server.out"
    process = subprocess.Popen(
        [
            sys.executable,
            "-c",
            ("import tests.planted as p; p.install(); " if planted else "")
            + "from lagrade.cli.main import entry; entry()",
            "serve",
            str(manifest),
            "--submissions",
            str(sheets),
            "--links",
            str(links),
            "--port",
            "0",
            "--jobs",
            "1",
            *extra,
        ],
        stdout=open(output, "w"),
        stderr=subprocess.STDOUT,
        env={**os.environ, "PYTHONUNBUFFERED": "1", "PYTHONPATH": str(REPOSITORY)},
    )
    deadline = time.monotonic() + 60
    base = ""
    while time.monotonic() < deadline and not base:
        if process.poll() is not None:
            raise AssertionError("the server stopped:\n" + output.read_text())
        for line in output.read_text().splitlines():
            if "listening on " in line:
                base = line.split("listening on ")[1].split()[0].rstrip("/")
        time.sleep(0.1)
    assert base, output.read_text()
    rows = list(csv.DictReader(links.open()))
    served = Served(
        root, manifest, sheets, {r["id"]: r["url"] for r in rows}, base, process, output
    )
    # the first preview starts a worker process: wait until one answers
    post(served.url("s001") + "/preview", {"problem": 1, "key": "dof", "text": "1"}, timeout=120)
    return served


def stop_server(served: Served) -> int:
    if served.process.poll() is None:
        served.process.send_signal(signal.SIGTERM)
    return served.process.wait(timeout=30)


def post(url: str, body, timeout: float = 30) -> tuple[int, dict | str]:
    data = body if isinstance(body, bytes) else json.dumps(body).encode()
    request = urllib.request.Request(url, data=data, method="POST")
    request.add_header("Content-Type", "application/json")
    return _open(request, timeout)


def get(url: str, timeout: float = 30) -> tuple[int, str]:
    return _open(urllib.request.Request(url), timeout)


def _open(request, timeout):
    try:
        with urllib.request.urlopen(request, timeout=timeout) as response:
            text = response.read().decode()
            status = response.status
            kind = response.headers.get("Content-Type", "")
    except urllib.error.HTTPError as error:
        text, status, kind = (
            error.read().decode(),
            error.code,
            error.headers.get("Content-Type", ""),
        )
    return status, (json.loads(text) if "json" in kind else text)


@pytest.fixture(scope="session")
def served(tmp_path_factory):
    root = tmp_path_factory.mktemp("serve")
    manifest = generate_class(root)
    server = start_server(root, manifest)
    yield server
    stop_server(server)
