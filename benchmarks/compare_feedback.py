"""Feedback stays as good as before: run the same corpora through two copies of lagrade (this tree
and a baseline checkout, e.g. a worktree of the previous commit) and compare every result field
but the timings — verdict, score, feedback, interpreted, method, witness, follow-through and the
mistakes named.

Corpora:
  grading   the labelled corpus of tests/grading/corpus.py with bench_check's extra requests
            (every part of every scene: rewrites and single-term mutations)
  batch     the cold batch of bench_batch.py (ad-hoc Lagrangians under renamed coordinates,
            expression problems; right and wrong answers in several notations)
  demo      `lagrade demo`: a class of 30 generated, answered and graded; every per-student
            result file is compared

Each copy runs as its own `python -m lagrade` process with PYTHONPATH set to its tree, so the
two never share a module. Exit status 0 when nothing differs.

Usage: python benchmarks/compare_feedback.py --baseline PATH [--corpora grading,batch,demo]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

#: Result fields that measure time, not judgement.
TIMINGS = {"ms", "prepare_ms", "graded_at", "seconds", "elapsed"}


def _run(tree: Path, args: list[str], cwd: Path) -> float:
    env = {**os.environ, "PYTHONPATH": str(tree)}
    start = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "lagrade", *args],
        env=env,
        cwd=cwd,
        check=True,
        stdout=subprocess.DEVNULL,
    )
    return time.perf_counter() - start


def _strip(value):
    if isinstance(value, dict):
        return {k: _strip(v) for k, v in value.items() if k not in TIMINGS}
    if isinstance(value, list):
        return [_strip(v) for v in value]
    return value


def grading_requests() -> list[dict]:
    from bench_check import extra_items

    from tests.grading.corpus import corpus

    items = list(corpus(per_part=12)) + extra_items()
    return [{"problem": it.problem, "part": it.part, "answer": it.answer} for it in items]


def batch_requests() -> list[dict]:
    from batch_corpus import build_batch

    return [r.body for r in build_batch()]


def compare_batch(name: str, requests: list[dict], trees: dict[str, Path], work: Path) -> int:
    """Both trees' `check --batch` results on the same requests; the number of differences."""
    path = work / f"{name}.jsonl"
    path.write_text("".join(json.dumps({"id": i, **r}) + "\n" for i, r in enumerate(requests)))
    results = {}
    for label, tree in trees.items():
        out = work / f"{name}-{label}.jsonl"
        seconds = _run(tree, ["check", "--batch", str(path), "--out", str(out)], work)
        results[label] = [json.loads(line) for line in out.read_text().splitlines()]
        print(f"  {name}: {label} ran {len(requests)} requests in {seconds:.1f} s")
    return _report(name, results["new"], results["baseline"], requests)


def compare_demo(trees: dict[str, Path], work: Path) -> int:
    """Both trees' `lagrade demo` per-student results, part by part; the number of parts that
    changed. A part whose feedback differs only in the numbers it quotes (another point, other
    values) is counted apart from one whose words changed."""
    files = {}
    for label, tree in trees.items():
        folder = work / f"demo-{label}"
        seconds = _run(tree, ["demo", str(folder), "--jobs", "2"], work)
        grades = folder / "grades" / "students"
        files[label] = {p.name: p for p in sorted(grades.glob("*.json"))}
        print(f"  demo: {label} ran in {seconds:.1f} s ({len(files[label])} students' results)")
    differ = 0
    if set(files["new"]) != set(files["baseline"]):
        print(f"  demo: different result files: {set(files['new']) ^ set(files['baseline'])}")
        differ += 1
    verdicts, changed, numbers_only, only = 0, [], [], set()
    for rel in sorted(set(files["new"]) & set(files["baseline"])):
        a = _strip(json.loads(files["new"][rel].read_text()))
        b = _strip(json.loads(files["baseline"][rel].read_text()))
        parts_a, parts_b = _parts(a), _parts(b)
        for key in sorted(set(parts_a) & set(parts_b)):
            pa, pb = parts_a[key], parts_b[key]
            only |= set(pa) ^ set(pb)  # a field one version writes and the other does not
            verdicts += pa.get("verdict") != pb.get("verdict")
            keys = sorted(k for k in set(pa) & set(pb) if pa.get(k) != pb.get(k))
            if not keys:
                continue
            if keys == ["feedback"] and _numbers_out(pa["feedback"]) == _numbers_out(
                pb["feedback"]
            ):
                numbers_only.append((rel, key, pa, pb))
            else:
                changed.append((rel, key, pa, pb))
        rest_a = {k: v for k, v in a.items() if k != "problems"}
        rest_b = {k: v for k, v in b.items() if k != "problems"}
        if rest_a != rest_b or set(parts_a) != set(parts_b):
            changed.append((rel, "(sheet)", rest_a, rest_b))
    if only:
        print(f"  demo: fields written by one version only: {sorted(only)}")
    for rel, key, pa, pb in numbers_only:
        print(f"  demo: {rel} {key}: quoted numbers only")
        print(f"      new:      {pa['feedback']!r}\n      baseline: {pb['feedback']!r}")
    for rel, key, pa, pb in changed[:8]:
        keys = sorted(k for k in set(pa) & set(pb) if pa.get(k) != pb.get(k))
        print(f"  demo: {rel} {key}: {keys}")
        for k in keys:
            print(f"      new:      {pa.get(k)!r}\n      baseline: {pb.get(k)!r}")
    print(
        f"  demo: {len(files['new'])} students' results; verdict changes {verdicts}; parts "
        f"whose feedback quotes other numbers {len(numbers_only)}; other parts changed "
        f"{len(changed)}"
    )
    return differ + verdicts + len(changed) + len(numbers_only)


def _numbers_out(feedback: list[str]) -> list[str]:
    """Feedback with every number (and a sign before it) replaced by #."""
    return [re.sub(r"[−-]?\d+(?:\.\d+)?(?:e[−-]?\d+)?", "#", f) for f in feedback]


def _parts(result: dict) -> dict[str, dict]:
    """A student's graded parts by "problem/part key"."""
    return {
        f"{p.get('index')}/{part.get('key')}": part
        for p in result.get("problems", [])
        for part in p.get("parts", [])
    }


def _report(name: str, new: list[dict], old: list[dict], requests: list[dict]) -> int:
    assert len(new) == len(old), (len(new), len(old))
    verdicts = sum(a["verdict"] != b["verdict"] for a, b in zip(new, old, strict=True))
    differ = [
        (i, a, b) for i, (a, b) in enumerate(zip(new, old, strict=True)) if _strip(a) != _strip(b)
    ]
    named = sum(a.get("mistakes") != b.get("mistakes") for _i, a, b in differ)
    mistakes = sum(bool(b.get("mistakes")) for b in old)
    print(
        f"  {name}: {len(new)} results; verdict changes {verdicts}; any field changed "
        f"{len(differ)}; mistakes named differently {named} (baseline names {mistakes})"
    )
    fields: dict[str, int] = {}
    for _i, a, b in differ:
        for k in set(a) | set(b):
            if k not in TIMINGS and a.get(k) != b.get(k):
                fields[k] = fields.get(k, 0) + 1
    if fields:
        print(f"  {name}: fields changed (results): {dict(sorted(fields.items()))}")
    for i, a, b in differ[:5]:
        keys = [k for k in set(a) | set(b) if k not in TIMINGS and a.get(k) != b.get(k)]
        print(f"    request {i} ({requests[i]['part']}): {keys}")
        for k in keys:
            print(f"      new:      {a.get(k)!r}\n      baseline: {b.get(k)!r}")
    return len(differ)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", required=True, type=Path, help="the other lagrade tree")
    parser.add_argument("--corpora", default="grading,batch,demo")
    args = parser.parse_args()
    trees = {"new": ROOT, "baseline": args.baseline.resolve()}
    chosen = args.corpora.split(",")
    differences = 0
    with tempfile.TemporaryDirectory(prefix="lagrade-compare-") as tmp:
        work = Path(tmp)
        if "grading" in chosen:
            differences += compare_batch("grading", grading_requests(), trees, work)
        if "batch" in chosen:
            differences += compare_batch("batch", batch_requests(), trees, work)
        if "demo" in chosen:
            differences += compare_demo(trees, work)
    print(f"differences: {differences}")
    sys.exit(1 if differences else 0)


if __name__ == "__main__":
    main()
