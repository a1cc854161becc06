"""Time to derive every scene of the bank, cold: L, momenta, Euler–Lagrange equations, cyclic
coordinates (the issue's target: all scenes together under 2 s on one core).

Run: python benchmarks/bench_derive.py [--repeat N]

Each repeat runs in a fresh interpreter, so nothing is cached between repeats (sympy's own caches
included); the figure reported is the median over repeats of the total, and the per-scene split
of the median run. Accelerations (the expensive, only-when-asked step) are timed separately.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys

CHILD = r"""
import json, time
t0 = time.perf_counter()
from lagrade.bank import get_scene, scene_ids
import_s = time.perf_counter() - t0
per_scene, accel = {}, {}
start = time.perf_counter()
for sid in scene_ids():
    s0 = time.perf_counter()
    v = get_scene(sid).default
    system = v.system
    system.generalized_momenta, system.euler_lagrange, system.cyclic_coordinates
    per_scene[sid] = time.perf_counter() - s0
total = time.perf_counter() - start
if ACCEL:
    for sid in scene_ids():
        s0 = time.perf_counter()
        get_scene(sid).default.system.accelerations
        accel[sid] = time.perf_counter() - s0
print(json.dumps({"import": import_s, "total": total, "per_scene": per_scene, "accel": accel}))
"""


def run_once(accelerations: bool) -> dict:
    code = CHILD.replace("ACCEL", "True" if accelerations else "False")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeat", type=int, default=5, help="fresh-interpreter runs (default 5)")
    args = parser.parse_args()
    runs = [run_once(accelerations=(i == 0)) for i in range(args.repeat)]
    totals = [r["total"] for r in runs]
    median_run = sorted(runs, key=lambda r: r["total"])[len(runs) // 2]
    print(f"{'scene':24} {'L, p, EOM, cyclic (ms)':>24} {'accelerations (ms)':>20}")
    for sid, seconds in median_run["per_scene"].items():
        print(
            f"{sid:24} {seconds * 1e3:24.1f} {runs[0]['accel'].get(sid, float('nan')) * 1e3:20.1f}"
        )
    print(f"\nscenes: {len(median_run['per_scene'])}")
    print(
        f"all scenes, cold (median of {len(runs)} fresh runs): {statistics.median(totals):.3f} s "
        f"(min {min(totals):.3f}, max {max(totals):.3f}); target < 2 s"
    )
    print(
        "import of lagrade.bank: "
        f"{statistics.median(r['import'] for r in runs):.3f} s (not included)"
    )


if __name__ == "__main__":
    main()
