"""Accuracy and speed of `lagrade check --batch` on the systems corpus: graded answers on 43
mechanical systems from public sources nobody here wrote (benchmarks/corpus/systems.jsonl).

1. Recomputes every label without lagrade (benchmarks/corpus/verify_systems.py, numbers only;
   --skip-verify skips it); a label that does not verify stops the run.
2. Writes the cases as `check --batch` requests and runs them through the command itself
   (`python -m lagrade check --batch … --out … --jobs N`), timing the whole run.
3. Prints the wrong verdicts by class — false accepts by the class of mistake, false rejects by
   the form of the right answer, right answers the parser could not read (with its message),
   wrong answers that were not judged incorrect — per part, and the median and p99 of the
   per-request `ms` (judging the answer) and of `ms + prepare_ms` (with the question's share).

Usage: python benchmarks/bench_systems.py [--jobs 1] [--skip-verify] [--list]
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus.verify_systems import load, verify_case  # noqa: E402


def _requests(records: list[dict]) -> str:
    lines = []
    for r in records:
        request = {"id": r["id"], **r["request"]}
        lines.append(json.dumps(request, ensure_ascii=False))
    return "\n".join(lines) + "\n"


def run_batch(records: list[dict], jobs: int) -> tuple[list[dict], float]:
    """The results of `lagrade check --batch` on the records, in order, and the wall time."""
    with tempfile.TemporaryDirectory() as tmp:
        requests, results = Path(tmp) / "requests.jsonl", Path(tmp) / "results.jsonl"
        requests.write_text(_requests(records), encoding="utf-8")
        command = [sys.executable, "-m", "lagrade", "check", "--batch", str(requests)]
        command += ["--out", str(results), "--jobs", str(jobs)]
        start = time.perf_counter()
        subprocess.run(command, check=True, cwd=ROOT)
        wall = time.perf_counter() - start
        out = [json.loads(line) for line in results.read_text(encoding="utf-8").splitlines()]
    if [o.get("id") for o in out] != [r["id"] for r in records]:
        raise SystemExit("the results do not answer the requests one for one, in order")
    return out, wall


def _message(result: dict) -> str:
    """The parser's message of an unreadable answer, without the position (so alike ones group):
    the first line's message, or the first unreadable line's."""
    lines = "\n".join(result.get("feedback") or [""]).splitlines()
    for line in lines:
        if "could not be read: " in line:
            return re.sub(r" at position \d+", "", line.split("could not be read: ", 1)[1])
    return re.sub(r" at position \d+", "", lines[0] if lines else "")


def _percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def report(records: list[dict], results: list[dict], wall: float, listing: bool) -> int:
    wrong = 0
    false_accepts: Counter = Counter()
    false_rejects: Counter = Counter()
    unreadable: list[tuple[str, str]] = []
    not_judged: Counter = Counter()
    by_part: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for record, result in zip(records, results, strict=True):
        part, label, verdict = record["request"]["part"], record["label"], result["verdict"]
        by_part[part][0] += 1
        if verdict == label:
            continue
        wrong += 1
        by_part[part][1] += 1
        if label == "incorrect" and verdict == "correct":
            false_accepts[record["mistake"]] += 1
        elif label == "incorrect":
            not_judged[verdict] += 1
        elif verdict == "invalid":
            unreadable.append((record["id"], _message(result)))
        else:
            false_rejects[f"{record['notation']}/{record['form']}"] += 1
        if listing:
            print(f"  {record['id']}: label {label}, lagrade {verdict}")
    n = len(records)
    systems = len({r["system"] for r in records})
    print(
        f"systems corpus: {n} cases on {systems} systems, {wrong} wrong verdicts "
        f"({100 * (n - wrong) / n:.1f} % right)"
    )
    for part, (count, bad) in sorted(by_part.items()):
        print(f"  {part:<11} {count:4d} cases, {bad:3d} wrong")
    print(f"false accepts (wrong answers marked correct): {sum(false_accepts.values())}")
    for mistake, count in false_accepts.most_common():
        print(f"  {mistake}: {count}")
    print(f"false rejects (right answers marked incorrect): {sum(false_rejects.values())}")
    for form, count in false_rejects.most_common():
        print(f"  {form}: {count}")
    print(f"right answers not read (invalid): {len(unreadable)}")
    messages = Counter(m for _, m in unreadable)
    for message, count in messages.most_common():
        print(f"  {count} × {message}")
    print(f"wrong answers not judged incorrect: {sum(not_judged.values())} {dict(not_judged)}")
    ms = [r["ms"] for r in results]
    total = [r["ms"] + r.get("prepare_ms", 0.0) for r in results]
    print(
        f"ms per request (judging): median {statistics.median(ms):.2f}, "
        f"p99 {_percentile(ms, 0.99):.1f}"
    )
    print(
        f"ms per request (with the question's preparation): median "
        f"{statistics.median(total):.2f}, p99 {_percentile(total, 0.99):.1f}"
    )
    print(
        f"wall time of the batch: {wall:.1f} s ({n / wall:.0f} requests/s, "
        f"process start and imports included)"
    )
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--skip-verify", action="store_true")
    parser.add_argument("--list", action="store_true", help="list every wrong verdict")
    args = parser.parse_args()
    records = load()
    if not args.skip_verify:
        start = time.perf_counter()
        bad = [r["id"] for r in records if not verify_case(r, proofs=False).agrees]
        print(
            f"labels recomputed without lagrade: {len(records) - len(bad)}/{len(records)} "
            f"agree ({time.perf_counter() - start:.0f} s)"
        )
        if bad:
            print("labels that do not verify: " + ", ".join(bad))
            return 1
    results, wall = run_batch(records, args.jobs)
    return report(records, results, wall, args.list)


if __name__ == "__main__":
    raise SystemExit(main())
