"""`--dask`: `grade` and `check --batch` on a Dask cluster give what they give on one machine.

The demo class graded both ways gives byte-identical outputs (every file but the output
folder's lock, which holds the run's process id); a batch of requests checked both ways gives
the same result lines but for the timings (`ms`, `prepare_ms`: the time each answer took, which
differs from run to run by nature). A Dask worker killed mid-run costs nothing: its chunk runs
again and every student and request still has its one result. A part held in C code is killed
at its limit + grace inside a Dask worker as on one machine, and costs only itself.

These tests need the optional extra (`pip install 'lagrade[dask]'`) and skip, saying so,
without it; `.ci/run` installs it. The refusals that do not need Dask are in
tests/cli/test_dask_refusals.py."""

from __future__ import annotations

import json
import os
import random
import shutil
import signal
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip(
    "distributed", reason="needs Dask's distributed scheduler: pip install 'lagrade[dask]'"
)

from distributed import Client, LocalCluster  # noqa: E402

from lagrade.cli.demo_class import run_demo  # noqa: E402
from lagrade.cli.main import main  # noqa: E402
from lagrade.grading.batch import grade  # noqa: E402
from lagrade.grading.manifest import student_variant  # noqa: E402
from lagrade.judge.key import key_answer  # noqa: E402
from tests.planted import HANG  # noqa: E402

from .test_killed_part import _replace_answer  # noqa: E402

TIMINGS = ("ms", "prepare_ms")


def _files(folder: Path) -> dict[str, bytes]:
    """Every output file of a grading run by its path inside the folder, but the lock (the
    run's process id)."""
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and p.name != ".lagrade.lock"
    }


@pytest.fixture(scope="module")
def cluster():
    """A cluster of two Dask workers of one thread each on this machine, for the tests that
    join a running cluster (tcp://) and kill its workers; its nannies restart a killed one."""
    with (
        LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as running,
        Client(running) as client,
    ):
        yield running.scheduler_address, client


def _all_workers_back(client: Client) -> None:
    client.wait_for_workers(2, timeout=60)


@pytest.fixture(scope="module")
def demo(tmp_path_factory) -> Path:
    """`lagrade demo`'s class of 30 (graded there on this machine, `--jobs 2`)."""
    root = tmp_path_factory.mktemp("dask-demo")
    run_demo(root / "demo", jobs=2)
    return root / "demo"


def test_the_demo_class_grades_byte_identical_with_dask_local(demo, capsys):
    out = demo.parent / "grades-dask"
    status = main(
        [
            "grade",
            str(demo / "assignment" / "manifest.json"),
            str(demo / "submissions"),
            "--out",
            str(out),
            "--dask",
            "local",
            "--jobs",
            "2",
        ]
    )
    assert status == 1  # the demo plants a missing and a malformed sheet
    here, there = _files(demo / "grades"), _files(out)
    assert len(here) > 100 and sorted(here) == sorted(there)
    assert [name for name in here if here[name] != there[name]] == []
    summary = json.loads((out / "students" / "s001.json").read_text())
    assert summary["status"] == "graded"


def test_a_dask_worker_killed_mid_grade_costs_no_student(demo, cluster):
    """SIGKILL to a Dask worker process while it judges a chunk: the nanny starts another, the
    scheduler runs the chunk again, and every student has the result of the run without Dask."""
    address, client = cluster
    _all_workers_back(client)
    killed = []

    def kill_a_busy_worker(done: int, total: int, student_id: str) -> None:
        if killed or done < 3:
            return
        busy = [w for w, keys in client.processing().items() if keys]
        if busy:
            pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
            os.kill(pid, signal.SIGKILL)
            killed.append((pid, done))

    out = demo.parent / "grades-killed"
    summary = grade(
        demo / "assignment" / "manifest.json",
        demo / "submissions",
        out,
        dask=address,
        progress=kill_a_busy_worker,
    )
    assert killed and killed[0][1] < 30, "no worker was killed while it had a chunk"
    assert len(summary.results) == 30
    here, there = _files(demo / "grades"), _files(out)
    assert sorted(here) == sorted(there)
    assert [name for name in here if here[name] != there[name]] == []
    _all_workers_back(client)


def _requests() -> list[bytes]:
    """A batch like a grading script's: key answers and slips for several bank scenes and seeds,
    answers repeated, unreadable lines, a request whose time limit strikes, shuffled so that a
    question's requests are scattered (a chunk of one question then holds lines far apart, and
    an unreadable line must still be named by its own number)."""
    rng = random.Random(29)
    lines = []
    for scene in ("simple_pendulum", "hoop", "wedge", "atwood", "kepler"):
        for seed in (1, 2, 3):
            variant = student_variant(scene, seed)
            for part in ("dof", "lagrangian", "eom", "momenta", "cyclic", "conserved"):
                answer = key_answer(variant, part)
                request = {"problem": {"scene": scene, "seed": seed}, "part": part}
                lines.append({**request, "answer": answer})
                if part == "lagrangian":
                    lines.append({**request, "answer": f"2*({answer}) + 1"})  # right
                    lines.append({**request, "answer": f"-({answer})"})  # V - T
                    lines.append({**request, "answer": answer.replace("+", "-", 1)})  # a slip
                    lines.append({**request, "answer": f"({answer}) + zz"})  # unknown name
                if part == "dof":
                    lines.append({**request, "answer": "7"})
    slow = {"problem": {"scene": "double_pendulum"}, "part": "conserved", "time_limit": 1e-4}
    lines.append({**slow, "answer": ["+".join(f"sin(theta_1)^{k}" for k in range(1, 40))]})
    rng.shuffle(lines)
    records = [json.dumps({"id": k, **r}).encode() for k, r in enumerate(lines)]
    records[7:7] = [b"{not json", b"", b'{"id": "u", "answer": "\xff"}']
    records[40:40] = [b'{"id": "p", "problem": {"scene": "wedge"}, "part": "zzz", "answer": "1"}']
    return records


def _check(tmp_path: Path, name: str, *flags: str) -> list[dict]:
    requests = tmp_path / "requests.jsonl"
    if not requests.exists():
        requests.write_bytes(b"\n".join(_requests()) + b"\n")
    out = tmp_path / f"{name}.jsonl"
    assert main(["check", "--batch", str(requests), "--out", str(out), *flags]) == 0
    return [json.loads(line) for line in out.read_text().splitlines()]


def _untimed(results: list[dict]) -> list[dict]:
    return [{k: v for k, v in r.items() if k not in TIMINGS} for r in results]


def test_check_batch_gives_the_same_results_with_dask_local(tmp_path):
    here = _check(tmp_path, "here", "--jobs", "2")
    there = _check(tmp_path, "there", "--dask", "local", "--jobs", "2")
    assert len(here) == len(_requests()) - 1  # the blank line has none
    assert _untimed(here) == _untimed(there)
    verdicts = {r["verdict"] for r in there}
    assert verdicts == {"correct", "incorrect", "invalid", "timeout"}
    unreadable = next(r for r in there if "not UTF-8" in "".join(r["feedback"]))
    assert "line 10 " in unreadable["feedback"][0]


def test_a_dask_worker_killed_mid_check_batch_costs_no_request(tmp_path, cluster):
    address, client = cluster
    _all_workers_back(client)
    here = _check(tmp_path, "here")
    killed = []
    finished = threading.Event()

    def kill_a_busy_worker() -> None:
        while not finished.is_set():
            busy = [w for w, keys in client.processing().items() if keys]
            if busy:
                pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
                os.kill(pid, signal.SIGKILL)
                killed.append(pid)
                return
            time.sleep(0.02)

    killer = threading.Thread(target=kill_a_busy_worker)
    killer.start()
    try:
        there = _check(tmp_path, "there", "--dask", address)
    finally:
        finished.set()
        killer.join()
    assert killed, "no worker was killed while it had a chunk"
    assert _untimed(here) == _untimed(there)
    _all_workers_back(client)


def test_a_part_held_in_c_is_killed_inside_a_dask_worker_and_costs_only_itself(
    tmp_path, demo, cluster
):
    """The kill rule of tests/batch/test_killed_part.py, inside Dask workers: the planted
    checker spins in one C call for a sheet's `eom` answer holding HANG; that part alone is
    `timeout`, the rest of the sheet is graded, as on one machine."""
    address, client = cluster
    _all_workers_back(client)

    def plant() -> None:
        import tests.planted as planted

        planted.install()

    client.run(plant)
    try:
        subs = tmp_path / "subs"
        shutil.copytree(demo / "submissions", subs)
        _replace_answer(subs / "s002.toml", 1, "eom", HANG)
        start = time.monotonic()
        summary = grade(demo / "assignment" / "manifest.json", subs, tmp_path / "out", dask=address)
        seconds = time.monotonic() - start
    finally:
        client.restart()  # the workers forget the plant
    result = json.loads((tmp_path / "out" / "students" / "s002.json").read_text())
    parts = {f"{p['index']}/{q['key']}": q for p in result["problems"] for q in p["parts"]}
    assert parts["1/eom"]["verdict"] == "timeout"
    assert result["status"] == "timeout" and "problem 1 eom" in result["reason"]
    assert [k for k, q in parts.items() if q["verdict"] == "timeout"] == ["1/eom"]
    before = json.loads((demo / "grades" / "students" / "s002.json").read_text())
    others = {f"{p['index']}/{q['key']}": q for p in before["problems"] for q in p["parts"]}
    assert {k: q for k, q in parts.items() if k != "1/eom"} == {
        k: q for k, q in others.items() if k != "1/eom"
    }
    assert summary.counts["graded"] == 27 and summary.counts["timeout"] == 1
    assert seconds < 60


def test_an_unreachable_scheduler_is_one_line_and_exit_2(tmp_path, monkeypatch, capsys):
    import lagrade.grading.cluster.connect as connect

    monkeypatch.setattr(connect, "CONNECT_SECONDS", 1.0)
    requests = tmp_path / "requests.jsonl"
    requests.write_bytes(b"\n".join(_requests()[:3]) + b"\n")
    argv = ["check", "--batch", str(requests), "--out", str(tmp_path / "out.jsonl")]
    assert main([*argv, "--dask", "tcp://127.0.0.1:9"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("lagrade: error: cannot reach the Dask scheduler at tcp://127.0.0.1:9")
    assert err.count("\n") == 1 and not (tmp_path / "out.jsonl").exists()


def test_a_worker_running_another_lagrade_stops_the_run(tmp_path, cluster, monkeypatch, capsys):
    """The workers must run the version the parent runs (a result records its grader's version,
    and a rerun reuses it on that word): a worker that does not says so, and nothing is written."""
    import lagrade.assign

    address, client = cluster
    _all_workers_back(client)
    # the parent reads the version at the assign layer's door, as every other layer does
    monkeypatch.setattr(lagrade.assign, "project_version", lambda: "0.0.0+other")
    requests = tmp_path / "requests.jsonl"
    requests.write_bytes(b"\n".join(_requests()[:3]) + b"\n")
    argv = ["check", "--batch", str(requests), "--out", str(tmp_path / "out.jsonl")]
    assert main([*argv, "--dask", address]) == 2
    err = capsys.readouterr().err
    assert "this run lagrade 0.0.0+other: install the same lagrade on every worker" in err
    assert err.count("\n") == 1 and not (tmp_path / "out.jsonl").exists()
