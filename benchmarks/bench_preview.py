"""The answer page's preview reads, never judges: a preview of a wrong Lagrangian costs what a
preview of a right one does (issue 34). Rows, interleaved in one run, in this process:

  preview right L   the page's preview of the key's L
  preview wrong L   the page's preview of a wrong L (the key with ½ dropped on a term)
  judge wrong L     the same wrong L judged by the one driver (what the preview used to run:
                    the whole grader, mistake catalogue included), for scale

Each answer is spelled differently every round (a term + 0*k added) so that no cache answers.

Run: python benchmarks/bench_preview.py [--rounds N]
"""

from __future__ import annotations

import argparse
import statistics
import time

from lagrade.bank.registry import get_scene
from lagrade.grading.answer_page.preview import preview
from lagrade.grading.student import part_spec
from lagrade.judge.driver import judge
from lagrade.judge.key import key_answer

ENTRY = {"scene": "wedge", "seed": 3}
PART = {"key": "lagrangian", "part": "lagrangian", "points": 1, "quantity": None}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=60)
    args = parser.parse_args()
    key = key_answer(get_scene("wedge").variant(ENTRY["seed"]), "lagrangian")
    wrong = key.replace("/2", "", 1)  # the ½ dropped on the first kinetic term
    assert wrong != key
    spec = part_spec(ENTRY, PART)
    rows: dict[str, list[float]] = {"preview right L": [], "preview wrong L": []}
    rows["judge wrong L"] = []
    preview(ENTRY, PART, key)  # the question built once, as the page's workers keep it
    for k in range(args.rounds):
        salt = f" + 0*{k + 2}"
        for name, run, text in (
            ("preview right L", lambda t: preview(ENTRY, PART, t), key + salt),
            ("preview wrong L", lambda t: preview(ENTRY, PART, t), wrong + salt),
            ("judge wrong L", lambda t: judge(spec, "lagrangian", t), wrong + salt),
        ):
            start = time.perf_counter()
            run(text)
            rows[name].append((time.perf_counter() - start) * 1e3)
    base = statistics.median(rows["preview right L"])
    print(f"{'row':<18}{'median ms':>11}{'p90 ms':>9}{'× right':>9}")
    for name, times in rows.items():
        times.sort()
        median, p90 = statistics.median(times), times[int(0.9 * (len(times) - 1))]
        print(f"{name:<18}{median:>11.2f}{p90:>9.2f}{median / base:>9.2f}")


if __name__ == "__main__":
    main()
