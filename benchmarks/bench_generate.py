"""Time `lagrade generate` for a large class: 300 students x the 4 problems of
examples/assignment.toml, in Markdown, HTML and LaTeX (no PDF). Target: under 30 s on one core.

    python benchmarks/bench_generate.py [--students 300] [--formats md,html,tex]
"""

from __future__ import annotations

import argparse
import csv
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from lagrade.assign import generate  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=300)
    parser.add_argument("--formats", default="md,html,tex")
    parser.add_argument("--assignment", default=str(ROOT / "examples" / "assignment.toml"))
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="lagrade-bench-"))
    try:
        roster = work / "roster.csv"
        with roster.open("w", newline="", encoding="utf-8") as f:
            writer = csv.writer(f)
            writer.writerow(["id", "name", "email", "section"])
            for i in range(args.students):
                writer.writerow([f"s{i:04d}", f"Student {i}", f"s{i}@example.edu", "AB"[i % 2]])
        start = time.perf_counter()
        result = generate(args.assignment, roster, 2025, work / "out", args.formats)
        elapsed = time.perf_counter() - start
        size = sum(p.stat().st_size for p in (work / "out").rglob("*") if p.is_file())
        print(
            f"{result.students} students, {result.files} files, {size / 1e6:.1f} MB, "
            f"formats {args.formats}: {elapsed:.2f} s "
            f"({1000 * elapsed / result.students:.1f} ms per student)"
        )
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
