"""Batch grading speed: 1,000 synthetic submissions of 3 problems × 6 parts, graded with
`--jobs 2` and with `--jobs 1` in the same run (target: under 60 s with 2 jobs on 2 cores).

Run: python benchmarks/bench_grade.py [--students N]

The class is generated once (not timed) with the demo's synthetic answer sheets (correct
answers in varied notation, common mistakes, blanks); each grading run starts from an empty
output folder, so nothing is reused.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

from lagrade.assign import generate
from lagrade.cli.demo_class import write_submissions
from lagrade.grading.batch import grade

ASSIGNMENT = """\
title = "Grading benchmark"
points = 1

[[problems]]
scene = "wedge"
parts = ["dof", "lagrangian", "eom", "momenta", "cyclic", "conserved"]

[[problems]]
scene = "hoop"
parts = ["dof", "T", "V", "lagrangian", "eom", "conserved"]

[[problems]]
scene = "kepler"
parts = ["lagrangian", "eom", "momenta", "cyclic", "conserved",
         { quantity = "circular_angular_velocity" }]
"""


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--students", type=int, default=1000)
    args = parser.parse_args()
    root = Path(tempfile.mkdtemp(prefix="lagrade-bench-grade-"))
    (root / "assignment.toml").write_text(ASSIGNMENT)
    rows = ["id,name"] + [f"b{i:04d},Student {i}" for i in range(args.students)]
    (root / "roster.csv").write_text("\n".join(rows) + "\n")
    t0 = time.perf_counter()
    generate(root / "assignment.toml", root / "roster.csv", 5, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    write_submissions(root / "subs", manifest, malformed=None, missing=None)
    print(
        f"class of {args.students} generated in {time.perf_counter() - t0:.1f} s (not timed below)"
    )
    figures = {}
    for jobs in (2, 1):
        t0 = time.perf_counter()
        summary = grade(
            root / "out" / "manifest.json", root / "subs", root / f"grades-{jobs}", jobs=jobs
        )
        seconds = time.perf_counter() - t0
        figures[jobs] = seconds
        print(
            f"--jobs {jobs}: {seconds:6.1f} s for {len(summary.results)} submissions "
            f"({len(summary.results) / seconds:.1f} submissions/s); statuses {summary.counts}"
        )
    print(f"speed-up of 2 jobs over 1: {figures[1] / figures[2]:.2f}×; target: --jobs 2 under 60 s")


if __name__ == "__main__":
    main()
