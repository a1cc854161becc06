"""Throughput on a Dask cluster against this machine's own pool, side by side in one run.

Two workloads: the cold batch of `batch_corpus.py` through `lagrade check --batch`, and the class
of `bench_grade.py` (`--students` synthetic sheets of 3 problems × 6 parts) through
`lagrade grade`. Each runs, as a fresh command from a cold start:

  local --jobs 1, 2                  this machine's killable pool, no Dask
  dask local --jobs W (W = 1, 2, 4)  `--dask local`: a LocalCluster of W one-thread workers
                                     started by the command (its start-up is in the time)
  running cluster, W workers         `--dask tcp://…`: a LocalCluster started beforehand, its
                                     workers restarted and lagrade imported in each before every
                                     run (not timed), as a cluster that is already up

interleaved (`--repeat` rounds; the median wall time is shown), with requests or sheets per
second. Every run's results are compared with `local --jobs 1`'s: the batch's result lines all
fields but the timings (`ms`, `prepare_ms`), the class's output files byte for byte (all but
the lock file). This machine has 2 cores, so 4 workers share them: the figures say what the
Dask path costs here, not what a cluster of several machines gains.

`--study` instead times the choices `lagrade.grading.cluster.chunks` makes, on a running
cluster of 2 workers: chunks per thread 1, 4, 16, with the requests or sheets grouped by
question or left in file order, on the batch as written (grouped by problem) and shuffled.

Run: python benchmarks/bench_dask.py [--students N] [--repeat R] [--study]
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

TIMINGS = ("ms", "prepare_ms")
WORKERS = (1, 2, 4)


_MEASURE = """
import resource, subprocess, sys, time
start = time.perf_counter()
done = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
wall = time.perf_counter() - start
use = resource.getrusage(resource.RUSAGE_CHILDREN)
print(done.returncode, wall, use.ru_utime + use.ru_stime)
sys.stderr.write(done.stderr)
"""


def _lagrade(*arguments: str, cwd: Path) -> tuple[float, float]:
    """(wall seconds, CPU seconds of the command and every process it started) of one
    `python -m lagrade …` command (exit 0 or 1: 1 is a class not all graded), measured by a
    small parent of its own. The machine is shared, so the CPU seconds are the steadier
    figure of the work done; the wall time is what a user waits."""
    done = subprocess.run(
        [sys.executable, "-c", _MEASURE, sys.executable, "-m", "lagrade", *arguments],
        cwd=cwd,  # not this tree: `python -m` would import lagrade from the cwd
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        capture_output=True,
        text=True,
        check=True,
    )
    status, wall, cpu = done.stdout.split()
    if int(status) not in (0, 1):
        raise RuntimeError(f"lagrade {' '.join(arguments)} failed: {done.stderr}")
    return float(wall), float(cpu)


def _cpu_seconds() -> float:
    """CPU seconds of this process (a Dask worker), the children it has reaped and those alive
    (its judging pool)."""
    import psutil

    me = psutil.Process()
    times = me.cpu_times()
    total = times.user + times.system + times.children_user + times.children_system
    for child in me.children(recursive=True):
        try:
            times = child.cpu_times()
        except psutil.NoSuchProcess:
            continue
        total += times.user + times.system
    return total


def _files(folder: Path) -> dict[str, bytes]:
    return {
        p.relative_to(folder).as_posix(): p.read_bytes()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and p.name != ".lagrade.lock"
    }


def _untimed(path: Path) -> list[dict]:
    lines = path.read_text().splitlines()
    return [{k: v for k, v in json.loads(line).items() if k not in TIMINGS} for line in lines]


def _write_batch(folder: Path, seed: int) -> tuple[Path, Path, int]:
    from batch_corpus import build_batch

    requests = build_batch(seed)
    lines = [json.dumps({"id": i, **r.body}) + "\n" for i, r in enumerate(requests)]
    in_order = folder / "requests.jsonl"
    in_order.write_text("".join(lines))
    random.Random(seed).shuffle(lines)
    shuffled = folder / "requests-shuffled.jsonl"
    shuffled.write_text("".join(lines))
    return in_order, shuffled, len(lines)


def _write_class(folder: Path, students: int) -> tuple[Path, Path]:
    from bench_grade import ASSIGNMENT

    from lagrade.assign import generate
    from lagrade.cli.demo_class import write_submissions

    folder.mkdir(parents=True, exist_ok=True)
    (folder / "assignment.toml").write_text(ASSIGNMENT)
    rows = ["id,name"] + [f"b{i:04d},Student {i}" for i in range(students)]
    (folder / "roster.csv").write_text("\n".join(rows) + "\n")
    generate(folder / "assignment.toml", folder / "roster.csv", 5, folder / "out", formats=("md",))
    manifest = json.loads((folder / "out" / "manifest.json").read_text())
    write_submissions(folder / "subs", manifest, malformed=None, missing=None)
    return folder / "out" / "manifest.json", folder / "subs"


class Running:
    """A LocalCluster of `workers` one-thread workers, up before the runs it serves; `ready()`
    restarts its workers and imports lagrade in each, so that every run meets a cluster whose
    workers are up but have judged nothing."""

    def __init__(self, workers: int) -> None:
        from distributed import Client, LocalCluster

        self.workers = workers
        self.cluster = LocalCluster(
            n_workers=workers, threads_per_worker=1, dashboard_address=":0", silence_logs=40
        )
        self.client = Client(self.cluster)
        self.address = self.cluster.scheduler_address

    def ready(self) -> None:
        self.client.restart()
        self.client.wait_for_workers(self.workers)
        for module in ("lagrade.grading.cluster.on_worker", "lagrade.grading.student"):
            self.client.run(importlib.import_module, module)
        self.since = self._total()

    def cpu(self) -> float:
        """CPU seconds of the workers and their judging processes since `ready`."""
        return self._total() - self.since

    def _total(self) -> float:
        return sum(self.client.run(_cpu_seconds).values())

    def close(self) -> None:
        self.client.close()
        self.cluster.close()


def main_table(args: argparse.Namespace, tmp: Path) -> None:
    requests, _shuffled, count = _write_batch(tmp, args.seed)
    t0 = time.perf_counter()
    manifest, subs = _write_class(tmp / "class", args.students)
    print(
        f"batch: {count} requests; class: {args.students} sheets (generated in "
        f"{time.perf_counter() - t0:.0f} s, not timed)"
    )
    runs: list[tuple[str, list[str], Running | None]] = [
        ("local --jobs 1", ["--jobs", "1"], None),
        ("local --jobs 2", ["--jobs", "2"], None),
    ]
    runs += [
        (f"dask local --jobs {w}", ["--dask", "local", "--jobs", str(w)], None) for w in WORKERS
    ]
    clusters = [Running(w) for w in WORKERS]
    runs += [(f"running cluster, {c.workers} workers", ["--dask", c.address], c) for c in clusters]
    figures: dict[tuple[str, str], list[tuple[float, float]]] = {}
    same: dict[tuple[str, str], bool] = {}
    try:
        for round_ in range(args.repeat):  # interleaved, so that a busy moment hits all alike
            for k, (label, flags, running) in enumerate(runs):
                for work in ("batch", "class"):
                    if running is not None:
                        running.ready()
                    if work == "batch":
                        out = tmp / f"results-{k}-{round_}.jsonl"
                        command = ("check", "--batch", str(requests), "--out", str(out))
                    else:
                        out = tmp / f"grades-{k}-{round_}"
                        command = ("grade", str(manifest), str(subs), "--out", str(out))
                    wall, cpu = _lagrade(*command, *flags, cwd=tmp)
                    if running is not None:
                        cpu += running.cpu()
                    figures.setdefault((label, work), []).append((wall, cpu))
                    first = tmp / (
                        f"results-0-{round_}.jsonl" if work == "batch" else f"grades-0-{round_}"
                    )
                    if work == "batch":
                        same[label, work] = same.get((label, work), True) and _untimed(
                            out
                        ) == _untimed(first)
                    else:
                        same[label, work] = same.get((label, work), True) and _files(out) == _files(
                            first
                        )
                    print(
                        f"  ran {label:30} {work:5}: {wall:6.1f} s wall, {cpu:6.1f} s CPU",
                        flush=True,
                    )
    finally:
        for running in clusters:
            running.close()
    print(
        f"\nmedians of {args.repeat} rounds; {count} requests, {args.students} sheets\n"
        f"{'run':30} {'batch s':>8} {'CPU s':>6} {'req/s':>6} {'same':>5}   "
        f"{'class s':>8} {'CPU s':>6} {'sheets/s':>8} {'same':>5}"
    )
    for label, *_ in runs:
        cells = []
        for work, items in (("batch", count), ("class", args.students)):
            wall = statistics.median(w for w, _c in figures[label, work])
            cpu = statistics.median(c for _w, c in figures[label, work])
            rate = f"{items / wall:{6 if work == 'batch' else 8}.1f}"
            cells.append(f"{wall:8.1f} {cpu:6.1f} {rate} {_yes(same[label, work]):>5}")
        print(f"{label:30} " + "   ".join(cells))
    print(
        "\nsame: in every round, the batch's result lines equal local --jobs 1's in every field "
        "but ms and prepare_ms; the class's output files byte-identical to local --jobs 1's"
    )


def _yes(flag: bool) -> str:
    return "yes" if flag else "NO"


def study(args: argparse.Namespace, tmp: Path) -> None:
    """Chunks per thread and grouping, timed in this process against a running cluster of 2
    workers, interleaved over `--repeat` rounds."""
    import lagrade.grading.cluster.checking as checking
    import lagrade.grading.cluster.chunks as chunks
    import lagrade.grading.cluster.grading as grading
    from lagrade.cli.check import check_batch_file
    from lagrade.grading.batch import grade

    requests, shuffled, count = _write_batch(tmp, args.seed)
    manifest, subs = _write_class(tmp / "class", args.students)
    running = Running(2)
    grouped = (checking._question, grading._questions_of)
    settings = [(per, group) for per in (1, 4, 16) for group in (True, False)]
    figures: dict[tuple, list[tuple[float, float]]] = {}
    try:
        for round_ in range(args.repeat):
            for per, group in settings:
                chunks.CHUNKS_PER_THREAD = per
                checking._question = grouped[0] if group else (lambda record: "")
                grading._questions_of = grouped[1] if group else (lambda item: "")
                for work in ("batch", "shuffled", "class"):
                    running.ready()
                    start = time.perf_counter()
                    if work == "class":
                        out = tmp / f"study-{per}-{group}-{round_}"
                        grade(manifest, subs, out, dask=running.address)
                    else:
                        path = requests if work == "batch" else shuffled
                        check_batch_file(path, tmp / "study.jsonl", dask=running.address)
                    wall = time.perf_counter() - start
                    cpu = running.cpu()
                    figures.setdefault((per, group, work), []).append((wall, cpu))
                    print(
                        f"  chunks per thread {per:2}, grouped {_yes(group):3}, {work:8}: "
                        f"{wall:6.1f} s wall, {cpu:6.1f} s CPU of the workers",
                        flush=True,
                    )
    finally:
        running.close()
    print(
        f"\nrunning cluster of 2 workers, medians of {args.repeat} rounds; {count} requests "
        f"(as written: grouped by problem; and shuffled), {args.students} sheets\n"
        f"{'chunks/thread':>13} {'grouped':>8}   {'batch s':>7} {'CPU s':>6}   "
        f"{'shuffled s':>10} {'CPU s':>6}   {'class s':>7} {'CPU s':>6}"
    )
    for per, group in settings:
        cells = []
        for work in ("batch", "shuffled", "class"):
            wall = statistics.median(w for w, _c in figures[per, group, work])
            cpu = statistics.median(c for _w, c in figures[per, group, work])
            cells.append(f"{wall:{10 if work == 'shuffled' else 7}.1f} {cpu:6.1f}")
        print(f"{per:13} {_yes(group):>8}   " + "   ".join(cells))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=300)
    parser.add_argument("--repeat", type=int, default=2, help="rounds (the median is shown)")
    parser.add_argument("--seed", type=int, default=13)
    parser.add_argument("--study", action="store_true", help="time the chunking choices instead")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="lagrade-bench-dask-") as tmp:
        (study if args.study else main_table)(args, Path(tmp))


if __name__ == "__main__":
    main()
