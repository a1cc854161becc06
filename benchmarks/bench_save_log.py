"""What the log of saves costs a save, side by side in one run: the answer page's save as it was
(the sheet written atomically, the one before it copied to `.previous/`), and as it is (the
sheet written inside a transaction that appends it to the SQLite log), with the log's commit
synced to disk (`synchronous = FULL`, the default: a save the page reported survives a power
cut) and, for comparison, with `synchronous = NORMAL` (WAL's usual setting: consistent after a
power cut, but the last saves may be gone).

Run: python benchmarks/bench_save_log.py [--saves 200] [--threads 1,8]

Each configuration writes `--saves` saves of a realistic sheet (four answers, ~600 bytes) per
thread, each thread its own student, into a fresh folder on the same disk; it reports the
median and p99 milliseconds per save and saves per second over all threads.
"""

from __future__ import annotations

import argparse
import contextlib
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPOSITORY))

import lagrade.grading.atomic as atomic  # noqa: E402
import lagrade.grading.savelog as savelog  # noqa: E402
from lagrade.grading.answer_page.sheets import save_sheet, sheet_text  # noqa: E402
from lagrade.grading.submission import find_submission, read_regular_file  # noqa: E402

MANIFEST = {
    "assignment": {"title": "Benchmark"},
    "problems": [
        {"index": 1, "parts": [{"key": k} for k in ("dof", "lagrangian", "eom", "momenta")]}
    ],
}


def answers(k: int) -> dict[int, dict[str, str]]:
    return {
        1: {
            "dof": "1",
            "lagrangian": f"1/2 m l^2 theta_dot^2 + m g l cos(theta) + 0*{k}",
            "eom": "m l^2 theta_ddot + m g l sin(theta) = 0\n" * 3,
            "momenta": r"p_\theta = m l^{2} \dot{\theta}",
        }
    }


def old_save(folder: Path, student_id: str, text: str) -> None:
    """The save before the log (lagrade 2ec3f8e): copy the sheet to .previous/, write the new."""
    existing, _ = find_submission(folder, student_id)
    if existing is not None:
        data, reason = read_regular_file(existing)
        if not reason:
            atomic.write_bytes(folder / ".previous" / existing.name, data)
    atomic.write_text(folder / f"{student_id}.toml", text)


@contextlib.contextmanager
def synchronous(mode: str):
    """The log's connections with `PRAGMA synchronous = mode` instead of FULL."""
    real = savelog.SaveLog._connect

    @contextlib.contextmanager
    def connect(self):
        with real(self) as conn:
            conn.execute(f"PRAGMA synchronous = {mode}")
            yield conn

    savelog.SaveLog._connect = connect
    try:
        yield
    finally:
        savelog.SaveLog._connect = real


def run(kind: str, threads: int, saves: int) -> list[float]:
    times: list[float] = []
    lock = threading.Lock()
    with tempfile.TemporaryDirectory(dir=REPOSITORY / "build") as tmp:
        folder = Path(tmp)
        log = savelog.SaveLog(savelog.log_path(folder)) if kind != "before the log" else None

        def student(n: int) -> None:
            who = {"id": f"s{n:03d}", "name": f"Student {n}"}
            mine = []
            for k in range(saves):
                given = answers(k)
                start = time.perf_counter()
                text = sheet_text(MANIFEST, who, given)
                if log is None:
                    old_save(folder, who["id"], text)
                else:
                    ns = savelog.now_ns()
                    save_sheet(log, folder, who["id"], text, answers=given, saved_ns=ns)
                mine.append(time.perf_counter() - start)
            with lock:
                times.extend(mine)

        workers = [threading.Thread(target=student, args=(n,)) for n in range(threads)]
        start = time.perf_counter()
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        times.append(-(time.perf_counter() - start))  # the wall time, marked negative
    return times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--saves", type=int, default=200, help="saves per thread")
    parser.add_argument("--threads", default="1,8", help="concurrent students, e.g. 1,8")
    args = parser.parse_args()
    (REPOSITORY / "build").mkdir(exist_ok=True)
    print(f"{'save':<34} {'threads':>7} {'median ms':>10} {'p99 ms':>8} {'saves/s':>8}")
    for threads in (int(t) for t in args.threads.split(",")):
        for kind in ("before the log", "log, synchronous FULL", "log, synchronous NORMAL"):
            mode = kind.rsplit(" ", 1)[-1]
            with synchronous(mode) if mode == "NORMAL" else contextlib.nullcontext():
                measured = run(kind, threads, args.saves)
            wall = -min(measured)
            times = sorted(t for t in measured if t >= 0)
            p99 = times[min(len(times) - 1, round(0.99 * (len(times) - 1)))]
            print(
                f"{kind:<34} {threads:>7} {statistics.median(times) * 1e3:>10.2f} "
                f"{p99 * 1e3:>8.2f} {len(times) / wall:>8.0f}",
                flush=True,
            )


if __name__ == "__main__":
    main()
