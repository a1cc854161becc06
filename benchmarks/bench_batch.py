"""Judging speed end to end on a cold batch like a grading script's, in one run.

The batch (`batch_corpus.py`): every bank scene given ad hoc as {"lagrangian", "coordinates",
"parameters"} under three renamings of its coordinates, plus about 220 closed-form `expression`
problems — about 300 distinct problems × 6 answers, right and wrong, in several notations.

Timed, each from a cold start, on the same request file:
  lagrade --jobs 1    `python -m lagrade check --batch` in a fresh process, one worker
  lagrade --jobs 2    the same with two workers
  baseline            the same command from another lagrade tree (`--baseline PATH`, e.g. a
                      worktree of the previous commit), one worker; skipped without the flag
  sympy reference     a straightforward judge in this process: answers read by lagrade's own
                      parser (student text never reaches sympify), then `simplify(a - b) == 0`
                      for expressions and momenta, sympy's `euler_equations` for Lagrangians,
                      `solve` for the accelerations of equations of motion and of conserved
                      quantities; `--reference-limit` seconds per request (SIGALRM)

Each command runs `--repeat` times from cold, interleaved; the median wall time is reported.
Reported per run: wall time, requests/s, the share of preparation (`prepare_ms` over the time
spent in the worker), p99 of the per-request time the results report, peak RSS of the largest
process. The results of the baseline are compared with this tree's (verdicts, and every field but
the timings); the reference judge's verdicts are compared with lagrade's for information.

Usage: python benchmarks/bench_batch.py [--baseline PATH] [--reference-limit S] [--no-reference]
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from batch_corpus import Request, build_batch  # noqa: E402

TIMINGS = ("ms", "prepare_ms")

_MEASURE = """
import resource, subprocess, sys, time
start = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)
wall = time.perf_counter() - start
print(wall, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
"""


def run_cli(tree: Path, requests: Path, out: Path, jobs: int) -> tuple[float, float]:
    """(wall seconds, peak RSS in MiB of the largest process) of one `check --batch` run,
    measured by a small parent process of its own so that runs do not share a maximum."""
    command = [sys.executable, "-m", "lagrade", "check", "--batch", str(requests)]
    command += ["--out", str(out), "--jobs", str(jobs)]
    env = {**os.environ, "PYTHONPATH": str(tree)}
    done = subprocess.run(
        [sys.executable, "-c", _MEASURE, *command],
        env=env,
        cwd=requests.parent,  # not this tree: `python -m` would import lagrade from the cwd
        capture_output=True,
        text=True,
        check=True,
    )
    wall, rss_kib = done.stdout.split()
    return float(wall), int(rss_kib) / 1024


def percentile(xs: list[float], p: float) -> float:
    s = sorted(xs)
    return s[min(len(s) - 1, int(round(p / 100 * (len(s) - 1))))] if s else float("nan")


def summarise(label: str, results: list[dict], wall: float, rss: float) -> dict:
    ms = [r.get("ms", 0.0) for r in results]
    prep = [r.get("prepare_ms") for r in results]
    has_prep = all(p is not None for p in prep)
    per_request = [m + (p or 0.0) for m, p in zip(ms, prep, strict=True)]
    return {
        "label": label,
        "wall": wall,
        "rps": len(results) / wall,
        "prep_share": (sum(prep) / (sum(ms) + sum(prep))) if has_prep else None,
        "prep_s": sum(prep) / 1e3 if has_prep else None,
        "work_s": (sum(ms) + (sum(prep) if has_prep else 0.0)) / 1e3,
        "p99": percentile(per_request, 99),
        "rss": rss,
        "has_prep": has_prep,
    }


# --- the sympy reference judge --------------------------------------------------------------------


class _Late(Exception):
    pass


def _ring(signum, frame):
    raise _Late


def reference_verdict(request: Request, cache: dict) -> str:
    """correct | incorrect | invalid for one request, by plain sympy."""
    import sympy as sp
    from sympy.calculus.euler import euler_equations

    from lagrade.errors import LagradeError
    from lagrade.judge.problem import build_problem
    from lagrade.mechanics.lagrange import t
    from lagrade.notation import parse_answer, parse_equations

    body = request.body
    key = json.dumps(body["problem"], sort_keys=True)
    if key not in cache:
        cache[key] = {"problem": build_problem(body["problem"])}
    entry = cache[key]
    problem = entry["problem"]
    part, answer = body["part"], body["answer"]
    jets = problem.jets
    try:
        if part == "expression":
            got = parse_answer(answer, problem.vocabulary()).expr
            return _yes(sp.simplify(got - problem.expression) == 0)
        L = problem.lagrangian
        if part == "cyclic":
            truth = {j.name for j in jets if sp.diff(L, j.q) == 0}
            said = {s.strip() for s in answer.split(",") if s.strip() and s.strip() != "none"}
            return _yes(said == truth)
        if "functions" not in entry:
            fs = [sp.Function(j.name)(t) for j in jets]
            to_t = {}
            for j, f in zip(jets, fs, strict=True):
                to_t |= {j.q: f, j.dot: f.diff(t), j.ddot: f.diff(t, 2)}
            entry["functions"], entry["to_t"] = fs, to_t
        fs, to_t = entry["functions"], entry["to_t"]

        def el(lagrangian):
            return [e.lhs for e in euler_equations(lagrangian.xreplace(to_t), fs, t)]

        if part == "lagrangian":
            got = parse_answer(answer, problem.vocabulary()).expr
            Ea, Eb = el(got), el(L)
            c = sp.simplify(Ea[0] / Eb[0])
            if c == 0 or c.has(t):
                return "incorrect"
            return _yes(all(sp.simplify(a - c * b) == 0 for a, b in zip(Ea, Eb, strict=True)))
        if part == "momenta":
            labels = [f"p_{j.name}" for j in jets]
            said = parse_equations(answer, problem.vocabulary(labels))
            got = {str(p.lhs): p.rhs for p in said}
            return _yes(
                all(
                    sp.simplify(got.get(f"p_{j.name}", sp.nan) - sp.diff(L, j.dot)) == 0
                    for j in jets
                )
            )
        if "accelerations" not in entry:
            rows = [sp.expand(e) for e in el(L)]
            acc = sp.solve(rows, [f.diff(t, 2) for f in fs], dict=True)
            entry["accelerations"] = acc[0] if acc else None
        acc = entry["accelerations"]
        if acc is None:
            return "invalid"
        if part == "eom":
            said = [p.expr.xreplace(to_t) for p in parse_equations(answer, problem.vocabulary())]
            mine = sp.solve(said, [f.diff(t, 2) for f in fs], dict=True)
            if len(mine) != 1:
                return "incorrect"
            return _yes(all(sp.simplify(mine[0].get(k, sp.nan) - v) == 0 for k, v in acc.items()))
        if part == "conserved":
            items = [answer] if isinstance(answer, str) else answer
            for text in items:
                Q = parse_answer(text, problem.vocabulary()).expr.xreplace(to_t)
                dQ = Q.diff(t).subs(acc)
                if sp.simplify(dQ) != 0 or not Q.has(*fs):
                    return "incorrect"
            return "correct"
    except LagradeError:
        return "invalid"
    return "invalid"


def _yes(flag) -> str:
    return "correct" if bool(flag) else "incorrect"


def run_reference(requests: list[Request], limit: float) -> tuple[float, list[str], int]:
    """(wall seconds, verdicts, how many ran out of time) of the reference judge."""
    cache: dict = {}
    verdicts = []
    late = 0
    previous = signal.signal(signal.SIGALRM, _ring)
    start = time.perf_counter()
    try:
        for r in requests:
            signal.setitimer(signal.ITIMER_REAL, limit)
            try:
                verdicts.append(reference_verdict(r, cache))
            except _Late:
                verdicts.append("timeout")
                late += 1
            except Exception:  # noqa: BLE001 - sympy failing is a verdict of its own
                verdicts.append("error")
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
    finally:
        signal.signal(signal.SIGALRM, previous)
    return time.perf_counter() - start, verdicts, late


# --- the report ----------------------------------------------------------------------------------


def _strip(r: dict) -> dict:
    return {k: v for k, v in r.items() if k not in TIMINGS}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", type=Path, help="another lagrade tree to time (optional)")
    parser.add_argument("--reference-limit", type=float, default=2.0, help="seconds per request")
    parser.add_argument("--no-reference", action="store_true", help="skip the sympy reference")
    parser.add_argument("--seed", type=int, default=13)
    parser.add_argument(
        "--repeat", type=int, default=3, help="cold runs of each command (the median is shown)"
    )
    args = parser.parse_args()

    t0 = time.perf_counter()
    requests = build_batch(args.seed)
    problems = {json.dumps(r.body["problem"], sort_keys=True) for r in requests}
    parts: dict[str, int] = {}
    for r in requests:
        parts[r.body["part"]] = parts.get(r.body["part"], 0) + 1
    print(
        f"batch: {len(requests)} requests over {len(problems)} distinct problems "
        f"(built in {time.perf_counter() - t0:.1f} s)\n  parts: "
        + ", ".join(f"{k} {v}" for k, v in sorted(parts.items()))
    )
    rows = []
    results: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory(prefix="lagrade-bench-batch-") as tmp:
        path = Path(tmp) / "requests.jsonl"
        path.write_text(
            "".join(json.dumps({"id": i, **r.body}) + "\n" for i, r in enumerate(requests))
        )
        runs = [("lagrade --jobs 1", ROOT, 1), ("lagrade --jobs 2", ROOT, 2)]
        if args.baseline:
            runs.append(("baseline --jobs 1", args.baseline.resolve(), 1))
        walls: dict[str, list[tuple[float, float]]] = {label: [] for label, _t, _j in runs}
        for round_ in range(args.repeat):  # interleaved, so that a busy moment hits all alike
            for label, tree, jobs in runs:
                out = Path(tmp) / f"out-{jobs}-{len(walls[label])}-{label[0]}.jsonl"
                walls[label].append(run_cli(tree, path, out, jobs))
                if round_ == 0:
                    results[label] = [json.loads(line) for line in out.read_text().splitlines()]
                print(f"  ran {label}: {walls[label][-1][0]:.2f} s")
        for label, _tree, _jobs in runs:
            wall = statistics.median(w for w, _rss in walls[label])
            rss = max(r for _w, r in walls[label])
            rows.append(summarise(label, results[label], wall, rss))
    ref = None
    if not args.no_reference:
        wall, verdicts, late = run_reference(requests, args.reference_limit)
        ref = (wall, verdicts, late)
        print(f"  ran the sympy reference: {wall:.1f} s ({late} ran out of time)")

    print(
        f"\n{'run':20} {'wall s':>8} {'req/s':>8} {'prep share':>11} {'p99 ms':>8} "
        f"{'peak RSS MiB':>13}"
    )
    for row in rows:
        share = f"{100 * row['prep_share']:.0f} %" if row["prep_share"] is not None else "hidden"
        print(
            f"{row['label']:20} {row['wall']:8.2f} {row['rps']:8.0f} {share:>11} "
            f"{row['p99']:8.1f} {row['rss']:13.0f}"
        )
    if ref is not None:
        print(
            f"{'sympy reference':20} {ref[0]:8.2f} {len(requests) / ref[0]:8.0f} "
            f"{'-':>11} {'-':>8} {'-':>13}"
        )
    one = rows[0]
    print(
        f"\nlagrade --jobs 1: preparation {one['prep_s']:.2f} s of {one['work_s']:.2f} s spent in "
        "the worker (the rest of the wall time: start-up, reading, the pipe)"
    )
    print(f"--jobs 2 / --jobs 1 speed-up: {rows[0]['wall'] / rows[1]['wall']:.2f}×")
    ours = results["lagrade --jobs 1"]
    two = results["lagrade --jobs 2"]
    print(
        "--jobs 2 results equal to --jobs 1 (all fields but timings): "
        f"{sum(_strip(a) == _strip(b) for a, b in zip(ours, two, strict=True))} of {len(ours)}"
    )
    if args.baseline:
        base_row = rows[2]
        base = results["baseline --jobs 1"]
        verdicts = sum(a["verdict"] != b["verdict"] for a, b in zip(ours, base, strict=True))
        fields = sum(_strip(a) != _strip(b) for a, b in zip(ours, base, strict=True))
        print(
            f"speed-up over the baseline, one worker: {base_row['wall'] / one['wall']:.2f}× end "
            f"to end; with --jobs 2: {base_row['wall'] / rows[1]['wall']:.2f}×"
        )
        print(f"verdict changes against the baseline: {verdicts}; results differing: {fields}")
    if ref is not None:
        agree = sum(v == r["verdict"] for v, r in zip(ref[1], ours, strict=True))
        print(
            f"speed-up over the sympy reference: {ref[0] / one['wall']:.1f}× (--jobs 1); "
            f"its verdicts agree with lagrade's on {agree} of {len(ours)}"
        )


if __name__ == "__main__":
    main()
