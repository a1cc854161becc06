"""What a sheet in the student's own coordinates costs: building the reference in their
coordinates (relating their map to the statement's, carrying the potential over, deriving L and
the sample points) and judging the later parts against it, side by side with the same parts of a
sheet in the statement's coordinates, per scene.

Run: python benchmarks/bench_own_coordinates.py [--repeat N]

Each scene runs in a fresh interpreter per repeat (nothing cached between repeats, sympy's own
caches included). In it the statement's question is prepared first, as `lagrade grade` does
before it forks its workers (not timed); then, timed: (1) a sheet in the statement's coordinates,
its seven later parts (lagrangian, T, V, eom, momenta, cyclic, conserved) judged with its
transformation and L as `given`; (2) the first sheet with a map in other coordinates: building
the reference in them; (3) its seven later parts, each part's preparation in the student's
coordinates included. The answers are each side's key (right answers), judged by `run_checker`
directly, so the verdict memory of `check` plays no part. Figures are medians over repeats.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys

#: A student's map in other coordinates per scene (the conventions of the tests).
MAPS = {
    "incline_pendulum": [
        "x_block = -s cos(alpha)", "y_block = -s sin(alpha)",
        "x_bob = -s cos(alpha) - l sin(phi)", "y_bob = -s sin(alpha) - l cos(phi)",
    ],
    "wedge": [
        "x_wedge = x_M", "y_wedge = 0",
        "x_block = x_M + h/tan(alpha) - q cos(alpha)", "y_block = q sin(alpha)",
    ],
    "coupled_oscillators": ["x_block1 = x_1", "y_block1 = 0", "x_block2 = x_2", "y_block2 = 0"],
    "spring_pendulum": ["x_bob = r cos(theta)", "y_bob = -r sin(theta)"],
    "two_body_spring": [
        "x_mass1 = X", "y_mass1 = Y", "x_mass2 = X + r cos(theta)", "y_mass2 = Y + r sin(theta)",
    ],
    "kepler": ["x_planet = -r sin(theta)", "y_planet = r cos(theta)"],
    "charged_particle": ["x_particle = -x", "y_particle = y", "z_particle = z"],
    "sliding_ladder": [
        "x_ladder = l cos(theta)/2", "y_ladder = l sin(theta)/2", "phi_ladder = pi/2 - theta",
    ],
    "double_pendulum": [
        "x_bob1 = l_1 sin(theta_1)", "y_bob1 = -l_1 cos(theta_1)",
        "x_bob2 = l_1 sin(theta_1) + l_2 sin(theta_1 + theta_2)",
        "y_bob2 = -l_1 cos(theta_1) - l_2 cos(theta_1 + theta_2)",
    ],
}  # fmt: skip

CHILD = r"""
import json, sys, time
from lagrade.judge.driver import cached_problem, prepare
from lagrade.judge.key import key_answer
from lagrade.judge.parts import run_checker
from lagrade.judge.parts.own_coordinates import chosen_coordinates

LATER = ["lagrangian", "T", "V", "eom", "momenta", "cyclic", "conserved"]
scene, lines = sys.argv[1], json.loads(sys.argv[2])
problem = cached_problem({"scene": scene})
for part in LATER + ["transformation"]:
    prepare(problem, part, diagnosis=True)

def sheet(variant, transformation):
    given = {"transformation": transformation, "lagrangian": key_answer(variant, "lagrangian")}
    return {part: key_answer(variant, part) for part in LATER}, given

def judged(problem, answers, given):
    start = time.perf_counter()
    verdicts = [run_checker(problem, part, answers[part], given) for part in LATER]
    assert all(v.status == "correct" for v in verdicts), [v.feedback for v in verdicts]
    return time.perf_counter() - start

answers, given = sheet(problem.variant, key_answer(problem.variant, "transformation"))
statement = judged(problem, answers, given)
start = time.perf_counter()
choice = chosen_coordinates(problem, lines)
build = time.perf_counter() - start
assert choice.kind == "own", choice
answers, given = sheet(choice.problem.variant, lines)
own = judged(problem, answers, given)
print(json.dumps({"statement": statement, "build": build, "own": own}))
"""


def run_once(scene: str, lines: list[str]) -> dict:
    out = subprocess.run(
        [sys.executable, "-c", CHILD, scene, json.dumps(lines)],
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(out.stdout)


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeat", type=int, default=3, help="fresh-interpreter runs (default 3)")
    args = parser.parse_args()
    print(
        f"{'scene':22} {'statement sheet':>16} {'build (own)':>12} {'own sheet':>10} "
        f"{'own total':>10}   (ms, 7 later parts)"
    )
    totals = []
    for scene, lines in MAPS.items():
        runs = [run_once(scene, lines) for _ in range(args.repeat)]
        median = {k: statistics.median(r[k] for r in runs) * 1e3 for k in runs[0]}
        total = median["build"] + median["own"]
        totals.append((scene, total, median["statement"]))
        print(
            f"{scene:22} {median['statement']:16.0f} {median['build']:12.0f} "
            f"{median['own']:10.0f} {total:10.0f}"
        )
    worst = max(totals, key=lambda x: x[1])
    print(
        f"\nper sheet in the student's coordinates (build + 7 parts): median "
        f"{statistics.median(t for _, t, _ in totals):.0f} ms, worst {worst[1]:.0f} ms "
        f"({worst[0]}); in the statement's: median "
        f"{statistics.median(s for _, _, s in totals):.0f} ms"
    )


if __name__ == "__main__":
    main()
