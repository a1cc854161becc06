"""Memory of a long grading run: 3,000 synthetic submissions of `bench_grade.py`'s assignment
(3 problems × 6 parts), with the resident set of the parent and of each worker sampled every few
hundred submissions (from the progress callback, via /proc/<pid>/status VmRSS).

Target (issue 14): after warm-up, the parent's RSS and the largest worker's stay within 20 % of
their value at the warm-up sample. The warm-up sample is the first one taken once a tenth of the
class is graded (the parent has derived every question by then, and each worker has filled its
caches); a worker replaced mid-run (`Limits.recycle`) shows as a new pid.

Run: python benchmarks/bench_grade_memory.py [--students N] [--jobs J] [--every K]
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench_grade import ASSIGNMENT  # noqa: E402
from rss import tree_rss  # noqa: E402

import lagrade  # noqa: E402
from lagrade.assign import generate  # noqa: E402
from lagrade.cli.demo_class import write_submissions  # noqa: E402
from lagrade.grading.batch import grade  # noqa: E402

FLAT = 0.20


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--students", type=int, default=3000)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--every", type=int, default=250, help="sample every K submissions")
    args = parser.parse_args()
    root = Path(tempfile.mkdtemp(prefix="lagrade-bench-memory-"))
    (root / "assignment.toml").write_text(ASSIGNMENT)
    rows = ["id,name"] + [f"m{i:04d},Student {i}" for i in range(args.students)]
    (root / "roster.csv").write_text("\n".join(rows) + "\n")
    t0 = time.perf_counter()
    generate(root / "assignment.toml", root / "roster.csv", 5, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    write_submissions(root / "subs", manifest, malformed=None, missing=None)
    print(
        f"class of {args.students} generated in {time.perf_counter() - t0:.0f} s (not timed); "
        f"lagrade from {Path(lagrade.__file__).parent}"
    )

    samples: list[tuple[int, float, int, dict[int, int]]] = []
    start = time.perf_counter()

    def sample(done: int, total: int, _student: str) -> None:
        if done % args.every == 0 or done == total:
            parent, children = tree_rss(os.getpid())
            samples.append((done, time.perf_counter() - start, parent, children))

    summary = grade(
        root / "out" / "manifest.json", root / "subs", root / "grades", jobs=args.jobs,
        progress=sample,
    )  # fmt: skip
    seconds = time.perf_counter() - start
    print(
        f"--jobs {args.jobs}: {len(summary.results)} submissions in {seconds:.0f} s; "
        f"statuses {summary.counts}"
    )
    print(f"{'graded':>7} {'s':>6} {'parent MB':>10} {'largest worker MB':>18}  workers (pid: MB)")
    for done, at, parent, children in samples:
        workers = ", ".join(f"{pid}: {kb / 1024:.0f}" for pid, kb in sorted(children.items()))
        largest = max(children.values(), default=0) / 1024
        print(f"{done:>7} {at:>6.0f} {parent / 1024:>10.0f} {largest:>18.0f}  {workers}")
    report_flatness(samples, args.students)


def report_flatness(samples, students: int) -> None:
    warm = next((s for s in samples if s[0] >= students / 10), None)
    if warm is None or warm is samples[-1]:
        print("too few samples after warm-up to judge; lower --every")
        return
    after = samples[samples.index(warm) :]
    for name, value in (
        ("parent", lambda s: s[2]),
        ("largest worker", lambda s: max(s[3].values(), default=0)),
    ):
        base = value(warm)
        peak, last = max(value(s) for s in after), value(after[-1])
        growth = (peak - base) / base if base else float("inf")
        verdict = "flat" if growth <= FLAT else "NOT flat"
        print(
            f"{name}: {base / 1024:.0f} MB at {warm[0]} graded, peak {peak / 1024:.0f} MB, "
            f"last {last / 1024:.0f} MB: {growth:+.0%} after warm-up ({verdict} within "
            f"{FLAT:.0%})"
        )


if __name__ == "__main__":
    main()
