"""Many answers to few questions, end to end: a class's answers to 5 bank questions (issue 29's
"10,000 answers to 5 bank questions"), through `python -m lagrade check --batch` from a cold
start, for this tree and optionally a baseline tree, side by side in one run.

The answers are the labelled corpus of tests/grading/corpus.py for 5 bank scenes (every part:
rewrites, single-term mutations, right and wrong), cycled to the requested count; each copy is
spelled differently (spaces around operators, `*` written or left out where that reads the
same), so that no answer is a repeat the judge could look up instead of judging — as students'
answers differ in spelling more often than in substance.

Reported per tree: wall time (median of `--repeat` cold runs, interleaved), requests/s, and the
median and p99 of the per-request time the results report (`ms`, in the worker: reading,
judging, feedback). The verdicts of the two trees are compared.

Usage: python benchmarks/bench_many_answers.py [--baseline PATH] [--count 10000] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from bench_batch import percentile, run_cli  # noqa: E402

from tests.grading.corpus import corpus  # noqa: E402

SCENES = ("simple_pendulum", "atwood", "hoop", "spring_pendulum", "wedge")


def respelled(text: str, rnd: random.Random) -> str:
    """The same answer spelled another way: spaces around + and -, and a `*` between two
    names written as a space. Each change keeps the reading (a name never fuses with another:
    `m*g` becomes `m g`, never `mg`)."""
    out = []
    for k, c in enumerate(text):
        if c in "+-=" and k > 0 and rnd.random() < 0.5:
            out.append(f" {c} ")
        elif (
            c == "*"
            and 0 < k < len(text) - 1
            and text[k - 1].isalnum()
            and text[k + 1].isalpha()
            and text[k + 1 : k + 2] != "*"
            and text[k - 1 : k] != "*"
            and rnd.random() < 0.5
        ):
            out.append(" ")
        else:
            out.append(c)
    return "".join(out)


def build(count: int, seed: int) -> list[dict]:
    from lagrade.bank.registry import scene_ids

    assert set(SCENES) <= set(scene_ids()), "a scene of SCENES left the bank"
    items = list(corpus(SCENES, per_part=12))
    rnd = random.Random(seed)
    requests, seen = [], set()
    k = 0
    while len(requests) < count:
        item = items[k % len(items)]
        k += 1
        answer = item.answer
        if k > len(items):
            answer = (
                respelled(answer, rnd)
                if isinstance(answer, str)
                else [respelled(line, rnd) for line in answer]
            )
        key = (json.dumps(item.problem, sort_keys=True), item.part, json.dumps(answer))
        if key in seen:
            if k > 50 * count:
                break
            continue
        seen.add(key)
        requests.append({"problem": item.problem, "part": item.part, "answer": answer})
    return requests


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", type=Path, help="another lagrade tree to time (optional)")
    parser.add_argument("--count", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--seed", type=int, default=29)
    args = parser.parse_args()
    requests = build(args.count, args.seed)
    problems = {json.dumps(r["problem"], sort_keys=True) for r in requests}
    print(f"{len(requests)} requests to {len(problems)} questions (every part)")
    runs = [("lagrade", ROOT)] + ([("baseline", args.baseline.resolve())] if args.baseline else [])
    walls: dict[str, list[float]] = {label: [] for label, _tree in runs}
    results: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory(prefix="lagrade-bench-many-") as tmp:
        path = Path(tmp) / "requests.jsonl"
        path.write_text("".join(json.dumps({"id": i, **r}) + "\n" for i, r in enumerate(requests)))
        for round_ in range(args.repeat):
            for label, tree in runs:
                out = Path(tmp) / f"out-{label}-{round_}.jsonl"
                walls[label].append(run_cli(tree, path, out, 1)[0])
                if round_ == 0:
                    results[label] = [json.loads(line) for line in out.read_text().splitlines()]
                print(f"  ran {label}: {walls[label][-1]:.2f} s")
    print(f"\n{'run':10} {'wall s':>8} {'req/s':>8} {'median ms':>10} {'p99 ms':>8}")
    for label, _tree in runs:
        wall = statistics.median(walls[label])
        ms = [r["ms"] for r in results[label] if "ms" in r]
        print(
            f"{label:10} {wall:8.2f} {len(requests) / wall:8.0f} {statistics.median(ms):10.3f} "
            f"{percentile(ms, 99):8.2f}"
        )
    if "baseline" in results:
        ours, theirs = results["lagrade"], results["baseline"]
        same = sum(a["verdict"] == b["verdict"] for a, b in zip(ours, theirs, strict=True))
        print(f"\nverdicts equal to the baseline's: {same} of {len(ours)}")
        speedup = statistics.median(walls["baseline"]) / statistics.median(walls["lagrade"])
        print(f"end-to-end speed-up over the baseline: {speedup:.2f}×")


if __name__ == "__main__":
    main()
