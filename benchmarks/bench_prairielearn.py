"""Every bank scene's PrairieLearn question through PrairieLearn's real Python worker.

    LAGRADE_PRAIRIELEARN=/path/to/PrairieLearn \
    LAGRADE_PRAIRIELEARN_PYTHON=/path/to/python-with-its-dependencies \
    python benchmarks/bench_prairielearn.py [--scenes kepler,wedge] [--pages DIR]

One assignment asks each scene every part it can be asked (and its quantities); it is exported
with `lagrade export prairielearn` into a temporary course (questions/ and the vendored lagrade in
serverFilesCourse/: the worker's Python has no lagrade installed). Each question then goes
through the phases as PrairieLearn's Node side drives them (`tests/prairielearn_node.py`):
generate, prepare, render of the three panels, PrairieLearn's question test (correct, incorrect,
invalid), and submissions that probe this issue's faults: HTML in every answer (no tag of it may
reach the rendered page or a popover), a readable first line with an unreadable second in every
multi-line part (format errors, not graded), a wrong answer in every part (each feedback sentence
must be in the rendered submission panel). Prints the figures, and with --pages writes each
question's rendered panels as HTML pages to look at in a browser.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from lagrade.bank import scene_ids  # noqa: E402
from lagrade.grading.prairielearn import export_prairielearn  # noqa: E402
from tests.prairielearn_node import Node, checkout  # noqa: E402
from tests.prairielearn_probe import assignment_text, new_figures, probe  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenes", default="", help="comma-separated scene ids (default: all)")
    parser.add_argument("--pages", type=Path, default=None, help="write rendered panels here")
    args = parser.parse_args()
    pl = checkout()
    if pl is None:
        print("skipped: set LAGRADE_PRAIRIELEARN to a PrairieLearn checkout")
        return 0
    scenes = [s for s in args.scenes.split(",") if s] or list(scene_ids())
    figures = new_figures()
    faults: dict[str, list[str]] = {}
    with tempfile.TemporaryDirectory() as scratch:
        course = Path(scratch) / "course"
        (Path(scratch) / "a.toml").write_text(assignment_text(scenes), encoding="utf-8")
        folders = export_prairielearn(Path(scratch) / "a.toml", 2025, course)
        if args.pages:
            args.pages.mkdir(parents=True, exist_ok=True)
        node = Node.real(pl, course)
        print(f"PrairieLearn worker: {node.python}; mustache: {node.mustache.engine}")
        try:
            for folder in folders:
                question = node.question(folder.name)
                try:
                    found = probe(question, figures, args.pages)
                except Exception as error:  # a course issue: the question is broken
                    found = [f"{type(error).__name__}: {error}"]
                found += question.issues
                faults[folder.name] = found
                print(f"{folder.name}: {'ok' if not found else '; '.join(found)[:400]}")
        finally:
            node.close()
        times = defaultdict(list)
        for file, fcn, seconds in node.worker.calls:
            if fcn not in ("ping", "restart"):
                times[f"{'elements' if file == 'question.html' else 'server.py'} {fcn}"].append(
                    seconds
                )
    print(f"\n{len(folders)} questions, {sum(1 for f in faults.values() if not f)} without a fault")
    print(json.dumps(figures, indent=1))
    print("seconds per call (median, max, calls):")
    for name, values in sorted(times.items()):
        print(f"  {name:24} {statistics.median(values):6.2f} {max(values):6.2f} {len(values):5}")
    return 0 if not any(faults.values()) else 1


if __name__ == "__main__":
    raise SystemExit(main())
