"""Speed against accuracy of every expression-equivalence method, over the labelled corpus:
pairs.jsonl (the bank's rewrites and mutations, and hand-written hard cases, real-valued
semantics) and external.jsonl (cases from public sources nobody here wrote: instructors'
vocabulary, principal branches, SI scale; labels by complex arithmetic).

Run:  python benchmarks/bench_methods.py [--limit 2] [--methods NAME ...] [--every K]
Writes docs/methods.csv and, when matplotlib is installed (pip install -e ".[charts]"),
docs/methods.png and docs/methods.svg.

Each method runs in its own forked worker process (fresh sympy caches, so no method profits from
another's work), which decides the corpus pairs one at a time; a check that takes longer than
--limit seconds is killed with SIGKILL (C-level work included), counted as a timeout, and a new
worker takes over. Times are measured inside the worker around `decide` alone (parsing is done
once, before). First every label is verified again by benchmarks/corpus/verify_labels.py and,
for the external cases, verify_external.py (--skip-verify skips that); a label that does not
verify stops the run. A method's error rate counts every check that did not end in the right
verdict: false accepts, false rejects, undecided (None or an exception) and timeouts.
"""

from __future__ import annotations

import argparse
import csv
import math
import multiprocessing as mp
import os
import signal
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus import verify_external, verify_labels  # noqa: E402
from benchmarks.corpus.corpus import EXTERNAL, ParsedPair, load  # noqa: E402
from benchmarks.methods import DEFAULT_NAME, Method, all_methods  # noqa: E402

DOCS = ROOT / "docs"
_FORK = mp.get_context("fork")


@dataclass
class Result:
    """One method over the corpus."""

    method: str
    checks: int
    times: list[float]
    false_accepts: list[str]
    false_rejects: list[str]
    undecided: list[str]
    timeouts: list[str]

    @property
    def wrong(self) -> int:
        return (
            len(self.false_accepts)
            + len(self.false_rejects)
            + len(self.undecided)
            + len(self.timeouts)
        )

    @property
    def error_rate(self) -> float:
        return self.wrong / self.checks

    @property
    def median(self) -> float:
        return statistics.median(self.times)

    @property
    def p99(self) -> float:
        ordered = sorted(self.times)
        return ordered[min(len(ordered) - 1, math.ceil(0.99 * len(ordered)) - 1)]


def _worker(conn, method: Method, pairs: list[ParsedPair]) -> None:
    """Decide the pairs the parent names, one at a time, reporting (verdict, seconds, error)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    while True:
        index = conn.recv()
        if index is None:
            return
        p = pairs[index]
        start = time.perf_counter()
        try:
            verdict, error = method.decide(p.answer, p.reference, p.domains), ""
        except Exception as exc:  # noqa: BLE001 - an exception is an undecided check, reported
            verdict, error = None, f"{type(exc).__name__}: {exc}"
        conn.send((verdict, time.perf_counter() - start, error))


class Worker:
    """A forked worker for one method, replaced after a kill."""

    def __init__(self, method: Method, pairs: list[ParsedPair]):
        self.method, self.pairs = method, pairs
        self._start()

    def _start(self) -> None:
        self.conn, child = _FORK.Pipe()
        self.process = _FORK.Process(
            target=_worker, args=(child, self.method, self.pairs), daemon=True
        )
        self.process.start()
        child.close()

    def decide(self, index: int, limit: float):
        """(verdict, seconds, error) or None after a timeout (the worker is killed and replaced)."""
        self.conn.send(index)
        if self.conn.poll(limit):
            try:
                return self.conn.recv()
            except EOFError:  # the worker died (memory, a crash in C): undecided, start afresh
                self._restart()
                return None, limit, "worker died"
        self._restart()
        return None

    def _restart(self) -> None:
        os.kill(self.process.pid, signal.SIGKILL)
        self.process.join()
        self.conn.close()
        self._start()

    def close(self) -> None:
        try:
            self.conn.send(None)
        except (BrokenPipeError, OSError):
            pass
        self.process.join(5)
        if self.process.is_alive():
            os.kill(self.process.pid, signal.SIGKILL)
            self.process.join()


def run_method(method: Method, pairs: list[ParsedPair], limit: float) -> Result:
    result = Result(method.name, len(pairs), [], [], [], [], [])
    worker = Worker(method, pairs)
    worker.decide(0, 10 * limit)  # warm-up, untimed: lazy imports and first-call setup
    try:
        for i, p in enumerate(pairs):
            got = worker.decide(i, limit)
            if got is None:
                result.timeouts.append(p.id)
                result.times.append(limit)
                continue
            verdict, seconds, _error = got
            result.times.append(seconds)
            if verdict is None:
                result.undecided.append(p.id)
            elif verdict and not p.label:
                result.false_accepts.append(p.id)
            elif not verdict and p.label:
                result.false_rejects.append(p.id)
    finally:
        worker.close()
    return result


def write_csv(results: list[Result], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(
            [
                "method",
                "checks",
                "median_ms",
                "p99_ms",
                "false_accepts",
                "false_rejects",
                "undecided",
                "timeouts",
                "error_rate",
                "pareto",
                "default",
            ]
        )
        front = pareto_front(results)
        for r in results:
            w.writerow(
                [
                    r.method,
                    r.checks,
                    f"{r.median * 1e3:.3f}",
                    f"{r.p99 * 1e3:.3f}",
                    len(r.false_accepts),
                    len(r.false_rejects),
                    len(r.undecided),
                    len(r.timeouts),
                    f"{r.error_rate:.4f}",
                    int(r.method in front),
                    int(r.method == DEFAULT_NAME),
                ]
            )


def pareto_front(results: list[Result]) -> list[str]:
    """Methods that no other method beats on both median time and error rate."""
    front = []
    for r in results:
        dominated = any(
            (o.median <= r.median and o.error_rate <= r.error_rate)
            and (o.median < r.median or o.error_rate < r.error_rate)
            for o in results
        )
        if not dominated:
            front.append(r.method)
    return front


def chart(results: list[Result], stem: Path) -> bool:
    """Time per check (log) against error rate, Pareto front drawn, default marked."""
    try:
        import matplotlib  # noqa: PLC0415
    except ImportError:
        print(
            "matplotlib is not installed: no chart drawn. Install the optional extra with\n"
            '    pip install -e ".[charts]"\nand run this benchmark again.'
        )
        return False
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "lagrade-methods"
    import matplotlib.pyplot as plt  # noqa: PLC0415

    fig, ax = plt.subplots(figsize=(10, 6.5), dpi=120)
    front = set(pareto_front(results))
    families = {
        "float": "tab:blue",
        "mp": "tab:purple",
        "structural": "tab:gray",
        "simplify": "tab:red",
        "equals": "tab:orange",
        "exact": "tab:green",
        "webwork": "tab:brown",
        "numbas": "tab:pink",
        "hybrid": "black",
    }
    labels: list[tuple[float, float, str]] = []
    for r in results:
        family = next((k for k in families if r.method.startswith(k)), "float")
        x, y = r.median * 1e3, 100 * r.error_rate
        marker = "*" if r.method == DEFAULT_NAME else ("D" if r.method in front else "o")
        size = 220 if r.method == DEFAULT_NAME else 46
        ax.scatter(
            [x],
            [y],
            s=size,
            marker=marker,
            color=families[family],
            zorder=3,
            edgecolors="black" if r.method in front else "none",
            linewidths=0.8,
        )
        if not r.method.startswith("float") or r.method in front:
            labels.append((x, y, r.method + (" (default)" if r.method == DEFAULT_NAME else "")))
    pts = sorted((r.median * 1e3, 100 * r.error_rate) for r in results if r.method in front)
    if pts:
        xs, ys = [pts[0][0]], [pts[0][1]]
        for px, py in pts[1:]:
            xs += [px, px]
            ys += [ys[-1], py]
        ax.plot(xs, ys, color="tab:green", lw=1.2, ls="--", zorder=2, label="Pareto front")
    floats = [r for r in results if r.method.startswith("float")]
    if floats:
        ax.scatter(
            [], [], color=families["float"], s=46, label="float64, 1–50 points, rtol 1e-3/1e-6/1e-9"
        )
    ax.scatter([], [], marker="*", s=150, color="black", label=f"default ({DEFAULT_NAME})")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=1.0, linscale=0.6)  # 0 % stays on the chart
    ax.set_ylim(bottom=-0.3)
    ax.set_xlabel("median time per check (ms, log scale)")
    ax.set_ylabel(
        "wrong verdicts (% of pairs: false accepts + false rejects + undecided + timeouts)"
    )
    n = results[0].checks if results else 0
    ax.set_title(f"Expression equivalence: speed against accuracy ({n} labelled pairs)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    _place_labels(fig, ax, labels)
    fig.savefig(stem.with_suffix(".png"), metadata={"Software": None})
    fig.savefig(stem.with_suffix(".svg"), metadata={"Date": None, "Creator": None})
    plt.close(fig)
    return True


def _place_labels(fig, ax, labels: list[tuple[float, float, str]], size: float = 8) -> None:
    """Each method's name beside its point, moved down a line at a time while it would cover a
    name already placed (points of nearly equal speed and accuracy stack their names)."""
    px_per_pt = fig.dpi / 72
    height, char = (size + 2) * px_per_pt, 0.55 * size * px_per_pt
    placed: list[tuple[float, float, float, float]] = []  # boxes in display pixels
    for x, y, text in sorted(labels, key=lambda item: -item[1]):
        ax_x, ax_y = ax.transData.transform((x, y))
        left, width = ax_x + 6 * px_per_pt, char * len(text)
        dy = 4 * px_per_pt
        for _ in range(12):
            bottom = ax_y + dy
            if not any(
                left < bx + bw and bx < left + width and bottom < by + bh and by < bottom + height
                for bx, by, bw, bh in placed
            ):
                break
            dy -= height
        placed.append((left, ax_y + dy, width, height))
        ax.annotate(
            text, (x, y), textcoords="offset points", xytext=(6, dy / px_per_pt), fontsize=size
        )


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--limit", type=float, default=2.0, help="seconds per check (default 2)")
    parser.add_argument("--methods", nargs="*", help="only these methods (names as in the CSV)")
    parser.add_argument("--every", type=int, default=1, help="every K-th pair only (a quick run)")
    parser.add_argument("--out", type=Path, default=DOCS / "methods.csv", help="CSV path")
    parser.add_argument("--skip-verify", action="store_true", help="do not re-verify the labels")
    parser.add_argument(
        "--corpus",
        choices=("all", "own", "external"),
        default="all",
        help="which pairs: ours (pairs.jsonl), the external cases, or both (default)",
    )
    args = parser.parse_args()
    own = load()[:: args.every] if args.corpus != "external" else []
    external = load(EXTERNAL)[:: args.every] if args.corpus != "own" else []
    pairs = own + external
    if not args.skip_verify:
        t0 = time.perf_counter()
        checks = [verify_labels.check(p) for p in own]
        bad = [c.id for c in checks if not c.ok]
        bad += [p.id for p in external if not verify_external.label_holds(p)]
        print(f"external labels verified (complex arithmetic): {len(external)} pairs")
        proved = sum(c.proof.startswith("proved") for c in checks if c.label)
        print(
            f"labels verified independently: {len(checks) - len(bad)}/{len(checks)} at 60 points "
            f"(60, then 150 digits); {proved}/{sum(c.label for c in checks)} true pairs proved "
            f"exactly ({time.perf_counter() - t0:.0f} s)"
        )
        if bad:
            print("labels that do not verify: " + ", ".join(bad))
            return 1
    methods = [m for m in all_methods() if not args.methods or m.name in args.methods]
    print(f"{len(methods)} methods × {len(pairs)} pairs, limit {args.limit:g} s per check")
    results = []
    start = time.perf_counter()
    for m in methods:
        t0 = time.perf_counter()
        r = run_method(m, pairs, args.limit)
        results.append(r)
        print(
            f"{r.method:24} median {r.median * 1e3:9.3f} ms  p99 {r.p99 * 1e3:9.3f} ms  "
            f"FA {len(r.false_accepts):3}  FR {len(r.false_rejects):3}  "
            f"undecided {len(r.undecided):3}  "
            f"timeouts {len(r.timeouts):3}  ({time.perf_counter() - t0:.0f} s)",
            flush=True,
        )
        for label, ids in (
            ("false accept", r.false_accepts),
            ("false reject", r.false_rejects),
            ("timeout", r.timeouts),
        ):
            hard = [i for i in ids if i.startswith(("hard/", "external/"))]
            if hard:
                print(f"    {label}: " + ", ".join(hard))
    write_csv(results, args.out)
    print(f"wrote {args.out.relative_to(ROOT) if args.out.is_relative_to(ROOT) else args.out}")
    if chart(results, args.out.with_suffix("")):
        print(f"wrote {args.out.with_suffix('.png').name} and {args.out.with_suffix('.svg').name}")
    print(f"Pareto front: {', '.join(pareto_front(results))}")
    print(f"total {time.perf_counter() - start:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
