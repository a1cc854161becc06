"""Speed and accuracy of answer checking, through the batch path of `lagrade check --batch`.

1. Builds ≥ 1,000 labelled requests of every part from every scene of the bank (the corpus of
   tests/grading/corpus.py: rewrites and single-term mutations, labels verified at 50 digits
   independently of the grader; plus dof, cyclic, T, V, transformation requests).
2. Runs them through `lagrade.judge.check.run_batch` — the code behind `lagrade check --batch` — in
   one worker process, and reports median and p99 time per request and requests per second.
3. Runs the expression-level pairs of the same corpus (L, T, V, momenta, expressions) through
   `sympy.simplify(a - b) == 0` and `Expr.equals`, each in a killable worker with a per-check time
   limit, on a stratified subset (simplify is slow), and reports each method's wrong verdicts
   and two speed ratios: against lagrade's whole request (batch round trip: parsing, judging,
   feedback, the pipe) and against lagrade on parsed answers (simplify's own footing: it is
   given sympy expressions).

Usage: python benchmarks/bench_check.py [--subset N] [--limit SECONDS] [--per-part K]
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import random
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import sympy as sp  # noqa: E402

from lagrade.bank.registry import get_scene, scene_ids  # noqa: E402
from lagrade.judge.check import check_pool, run_batch  # noqa: E402
from lagrade.notation.printer import plain  # noqa: E402
from tests.grading.corpus import Item, corpus, expected_status  # noqa: E402


def extra_items() -> list[Item]:
    """dof, cyclic, T, V and transformation requests (right and wrong) for every scene."""
    items = []
    for sid in scene_ids():
        v = get_scene(sid).default
        spec = {"scene": sid}
        items.append(Item(spec, "dof", str(v.dof), "correct", "right"))
        items.append(Item(spec, "dof", str(v.dof + 1), "incorrect", "off_by_one"))
        cyc = list(v.system.cyclic_coordinates)
        items.append(Item(spec, "cyclic", cyc or "none", "correct", "right"))
        wrong = [c for c in v.coordinates if c not in cyc][:1] + cyc[1:]
        items.append(
            Item(
                spec,
                "cyclic",
                wrong or "none",
                "incorrect" if wrong != cyc else "correct",
                "swapped",
            )
        )
        T, V = v.kinetic_energy, v.potential_energy
        items.append(Item(spec, "T", plain(sp.factor(T)), "correct", "factored", (sp.factor(T), T)))
        items.append(Item(spec, "T", plain(2 * T), "incorrect", "double", (2 * T, T)))
        items.append(Item(spec, "V", plain(V), "correct", "right", (V, V)))
        if V != 0:
            items.append(Item(spec, "V", plain(-V + 1), "incorrect", "sign", (-V + 1, V)))
        tr = [f"{k} = {plain(e)}" for k, e in v.transformation.items()]
        items.append(Item(spec, "transformation", tr, "correct", "right"))
    return items


def run_ours(items: list[Item]) -> tuple[list[float], list[dict], float]:
    lines = []
    for i, it in enumerate(items):
        lines.append(
            json.dumps({"id": i, "problem": it.problem, "part": it.part, "answer": it.answer})
        )
    times, results = [], []
    with check_pool() as pool:
        start = time.perf_counter()
        last = start
        for result in run_batch(lines, pool=pool):
            now = time.perf_counter()
            times.append((now - last) * 1e3)
            last = now
            results.append(result)
        total = time.perf_counter() - start
    return times, results, total


def _method_worker(conn) -> None:
    while True:
        job = conn.recv()
        if job is None:
            return
        method, a, b = job
        start = time.perf_counter()
        try:
            if method == "simplify":
                answer = sp.simplify(a - b) == 0
            else:
                answer = a.equals(b)
        except Exception:  # noqa: BLE001 - a method that fails has no verdict
            answer = None
        conn.send((answer, (time.perf_counter() - start) * 1e3))


class MethodRunner:
    """simplify / equals in a worker that is killed at the time limit."""

    def __init__(self, limit: float):
        self.limit = limit
        self.ctx = mp.get_context("fork")
        self._start()

    def _start(self):
        self.conn, child = self.ctx.Pipe()
        self.proc = self.ctx.Process(target=_method_worker, args=(child,), daemon=True)
        self.proc.start()

    def run(self, method: str, a, b):
        self.conn.send((method, a, b))
        if self.conn.poll(self.limit):
            return self.conn.recv()
        self.proc.kill()
        self.proc.join()
        self._start()
        return "timeout", self.limit * 1e3

    def close(self):
        self.conn.send(None)
        self.proc.join(2)


def judged_without_parsing(items: list[Item]) -> list[float]:
    """ms per request for `check_request` in this process with the parser memoised: a first
    pass parses (and derives each question), the timed second pass gets the same Parsed objects
    back, so the time is the judging and the feedback alone — simplify's footing, which also
    starts from parsed expressions. Everything else is the production code path, but for the
    memory of decided answers, which is off here: the second pass would only look them up."""
    import importlib

    from lagrade.notation import parse

    check_module = importlib.import_module("lagrade.judge.check")
    check_request = check_module.check_request
    kept_verdicts = check_module._VERDICT_CACHE_SIZE
    check_module._VERDICT_CACHE_SIZE = 0
    check_module._verdicts.clear()

    names = ("parse_answer", "parse_equation", "parse_expression", "parse_equations")
    originals = {name: getattr(parse, name) for name in names}
    for name, function in originals.items():
        memo: dict = {}

        def memoised(text, vocabulary, *, latex=None, _f=function, _memo=memo):
            key = (json.dumps(text), id(vocabulary), latex)
            if key not in _memo:
                _memo[key] = _f(text, vocabulary, latex=latex)
            return _memo[key]

        setattr(parse, name, memoised)
    try:
        requests = [{"problem": it.problem, "part": it.part, "answer": it.answer} for it in items]
        for request in requests:
            check_request(request)
        out = []
        for request in requests:
            start = time.perf_counter()
            check_request(request)
            out.append((time.perf_counter() - start) * 1e3)
        return out
    finally:
        check_module._VERDICT_CACHE_SIZE = kept_verdicts
        for name, function in originals.items():
            setattr(parse, name, function)


def percentile(xs: list[float], p: float) -> float:
    s = sorted(xs)
    return s[min(len(s) - 1, int(round(p / 100 * (len(s) - 1))))]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--subset", type=int, default=150, help="pairs run through simplify/equals")
    parser.add_argument(
        "--limit", type=float, default=2.0, help="seconds per simplify/equals check"
    )
    parser.add_argument("--per-part", type=int, default=12, help="mutations per part and scene")
    args = parser.parse_args()

    t0 = time.perf_counter()
    items = list(corpus(per_part=args.per_part)) + extra_items()
    print(
        f"corpus: {len(items)} labelled requests from {len(scene_ids())} scenes "
        f"(labels verified at 50 digits, built in {time.perf_counter() - t0:.1f} s)"
    )
    parts: dict[str, int] = {}
    for it in items:
        parts[it.part] = parts.get(it.part, 0) + 1
    print("  parts: " + ", ".join(f"{k} {v}" for k, v in sorted(parts.items())))

    times, results, total = run_ours(items)
    wrong = [
        (it, r) for it, r in zip(items, results, strict=True) if r["verdict"] != expected_status(it)
    ]
    worker_ms = [r["ms"] for r in results]
    first_touch = {}
    for i, it in enumerate(items):
        first_touch.setdefault(json.dumps([it.problem, it.part], sort_keys=True), i)
    steady = [t for i, t in enumerate(times) if i not in set(first_touch.values())]
    print("\nlagrade check --batch (one worker process, round trip per request incl. parsing):")
    print(f"  requests        {len(items)}")
    print(
        f"  median          {statistics.median(times):.2f} ms   (judging alone: "
        f"{statistics.median(worker_ms):.2f} ms)"
    )
    print(
        f"  p99             {percentile(times, 99):.2f} ms   (excluding the {len(first_touch)} "
        f"first requests per question, which derive it: {percentile(steady, 99):.2f} ms)"
    )
    print(
        f"  throughput      {len(items) / total:.0f} requests/s  ({total:.1f} s in all, "
        "including deriving each question once)"
    )
    print(f"  wrong verdicts  {len(wrong)} of {len(items)}")
    for it, r in wrong[:10]:
        print(f"    {it.problem} {it.part} {it.kind} label={it.label} got={r['verdict']}")

    pairs = [(i, it) for i, it in enumerate(items) if it.pair is not None]
    rng = random.Random(0)
    by_part: dict[str, list] = {}
    for i, it in pairs:
        by_part.setdefault(it.part, []).append((i, it))
    subset = []
    for _part, group in sorted(by_part.items()):
        share = max(1, round(args.subset * len(group) / len(pairs)))
        subset += rng.sample(group, min(share, len(group)))
    print(
        f"\nsympy on {len(subset)} of the {len(pairs)} expression-level pairs (stratified by part; "
        f"time limit {args.limit:g} s per check; the same pairs as above):"
    )
    ours_ms = [times[i] for i, _ in subset]
    ours_wrong = sum(results[i]["verdict"] != expected_status(it) for i, it in subset)
    judged_ms = judged_without_parsing([it for _i, it in subset])
    runner = MethodRunner(args.limit)
    report = {}
    for method in ("simplify", "equals"):
        ms, wrong_n, undecided = [], 0, 0
        for _i, it in subset:
            a, b = it.pair
            verdict, t = runner.run(method, a, b)
            ms.append(t)
            if verdict in (None, "timeout"):
                undecided += 1
                wrong_n += 1  # no verdict where one is needed counts as wrong
                continue
            truth = expected_status(it) == "correct"
            wrong_n += bool(verdict) != truth
        report[method] = (ms, wrong_n, undecided)
    runner.close()
    print(f"  {'method':10} {'median ms':>10} {'total s':>9} {'wrong':>6} {'no verdict':>11}")
    print(
        f"  {'lagrade':10} {statistics.median(ours_ms):10.2f} {sum(ours_ms) / 1e3:9.2f} "
        f"{ours_wrong:6d} {0:11d}"
    )
    print(
        f"  {'lagrade*':10} {statistics.median(judged_ms):10.2f} {sum(judged_ms) / 1e3:9.2f}"
        "      -           -   (* the same requests in-process with parsing memoised: "
        "judging + feedback, no parsing, no pipe)"
    )
    for method, (ms, wrong_n, undecided) in report.items():
        print(
            f"  {method:10} {statistics.median(ms):10.2f} {sum(ms) / 1e3:9.2f} {wrong_n:6d} "
            f"{undecided:11d}"
        )
    rewrites = [k for k, (_i, it) in enumerate(subset) if expected_status(it) == "correct"]
    for method, (ms, _w, _u) in report.items():
        print(
            f"  speed ratio {method}/lagrade: median "
            f"{statistics.median(ms) / statistics.median(ours_ms):.1f}× (batch round trip), "
            f"{statistics.median(ms) / statistics.median(judged_ms):.1f}× (parsed answers, "
            "like simplify's input); total "
            f"{sum(ms) / sum(ours_ms):.1f}×; on the {len(rewrites)} correct rewrites only: total "
            f"{sum(ms[k] for k in rewrites) / sum(ours_ms[k] for k in rewrites):.1f}×"
        )
    print(
        "\n(simplify(a - b) == 0 and equals compare L literally, so a right L that differs by a "
        "constant,\n a total derivative or a factor counts as 'different' for them: those are "
        "among their wrong verdicts.)"
    )


if __name__ == "__main__":
    main()
