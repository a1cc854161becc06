"""Where the judging loop of a cold batch spends its CPU time, phase by phase, for one or more
lagrade trees side by side (each in its own process, interleaved).

The batch is bench_batch's (`batch_corpus.build_batch`). Each tree's process imports lagrade,
then judges every request in order in that one process (`check_request`, as a `--jobs 1` worker
does, with the catalogue built whole for a question-part of many answers as `run_batch` marks
it), while a CPU-time sampler (ITIMER_PROF, every `--interval` ms) looks at the Python stack.
A sample goes to the phase of the outermost lagrade module on the stack that names one:

  diagnosis   the mistake catalogue: catalogue, mutations, keepers, lazylist, matching,
              fingerprints (mutants built, differentiated, compiled; a wrong answer matched)
  decision    deciding by residuals: decision, rows, equivalence, exact, derivatives, adaptive
  reference   the reference and its points: problem, sampling, mechanics (sympy derivations)
  reading     reading answers: notation, parts/reading, parts/items
  other       everything else in the loop (checkers' glue, caches, verdicts)

Usage: python benchmarks/phases.py [TREE ...] [--repeat N] [--interval MS] [--limit N]
       [--corpus batch|grading|variants|class]
(no TREE: this tree). Each tree runs with its own interpreter when it has a .venv.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

PHASES = {
    "diagnosis": (
        "lagrade/judge/catalogue.py",
        "lagrade/judge/mutations.py",
        "lagrade/judge/keepers.py",
        "lagrade/judge/lazylist.py",
        "lagrade/judge/matching.py",
        "lagrade/judge/fingerprints.py",
        "lagrade/judge/row_fingerprints.py",
    ),
    "decision": (
        "lagrade/judge/decision.py",
        "lagrade/judge/rows.py",
        "lagrade/judge/equivalence.py",
        "lagrade/judge/exact.py",
        "lagrade/judge/derivatives.py",
        "lagrade/judge/adaptive.py",
    ),
    "reference": (
        "lagrade/judge/problem.py",
        "lagrade/judge/sampling.py",
        "lagrade/judge/reference.py",
        "lagrade/mechanics/",
        "lagrade/bank/",
    ),
    "reading": (
        "lagrade/notation/",
        "lagrade/judge/parts/reading.py",
        "lagrade/judge/parts/items.py",
    ),
}
ORDER = ("diagnosis", "decision", "reference", "reading", "other")

# The child: judge the batch in-process under a stack sampler; print the samples per phase.
_CHILD = r"""
import json, resource, signal, sys, time
sys.path.insert(0, sys.argv[1] + "/benchmarks")
PHASES = json.loads(sys.argv[2])
interval = float(sys.argv[3]) / 1e3
limit = int(sys.argv[4])
corpus = sys.argv[5]
if corpus == "class":
    # bench_grade's class, generated (not sampled); the loop below grades each sheet with
    # grade_student, as `lagrade grade`'s worker does after its warm-up
    import tempfile
    from pathlib import Path
    from bench_grade import ASSIGNMENT
    from lagrade.assign import generate
    from lagrade.cli.demo_class import write_submissions
    import lagrade.grading.batch as batch
    root = Path(tempfile.mkdtemp(prefix="lagrade-phases-"))
    (root / "assignment.toml").write_text(ASSIGNMENT)
    roster = ["id,name"] + [f"b{i:04d},Student {i}" for i in range(limit or 60)]
    (root / "roster.csv").write_text("\n".join(roster) + "\n")
    generate(root / "assignment.toml", root / "roster.csv", 5, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    write_submissions(root / "subs", manifest, malformed=None, missing=None)
    held = {}
    def keep(manifest, rubric, tasks, jobs, limits):
        held.update(manifest=manifest, rubric=rubric, tasks=tasks)
        batch.forget_problems()
        batch.warm_up(manifest)
        return iter(())
    batch._judged_here = keep
    try:
        batch.grade(root / "out" / "manifest.json", root / "subs", root / "grades", jobs=1)
    except Exception:
        pass  # no outcomes came back: the summary has nothing to write
    from lagrade.grading.student import grade_student
    def judge_one(task):
        result = grade_student(held["manifest"], held["rubric"], task[1])
        return json.dumps(result, sort_keys=True, default=str)
    work = [(i, task) for i, task in enumerate(held["tasks"])]
    limit = 0
elif corpus in ("grading", "variants"):
    from compare_feedback import grading_requests
    bodies = grading_requests()
if corpus == "variants":
    # a class: each scene request asked of one of 8 students' variants whose presentation is
    # the declared one (the corpus's answers use the declared names), in turn
    from lagrade.bank import get_scene
    seeds = {}
    def student_seeds(sid):
        if sid not in seeds:
            scene = get_scene(sid)
            declared = (scene.default.names, scene.default.options)
            shown = lambda v: (v.names, v.options)
            found = [k for k in range(1, 400) if shown(scene.variant(k)) == declared]
            seeds[sid] = found[:8]
        return seeds[sid]
    turned = []
    for i, b in enumerate(bodies):
        problem = b.get("problem")
        plain_scene = isinstance(problem, dict) and "scene" in problem
        if plain_scene and "seed" not in problem and "scene_text" not in problem:
            choices = student_seeds(problem["scene"])
            if choices:
                b = {**b, "problem": {**problem, "seed": choices[i % len(choices)]}}
        turned.append(b)
    bodies = turned
else:
    from batch_corpus import build_batch
    bodies = [r.body for r in build_batch(13)]
if corpus != "class":
    import importlib; check = importlib.import_module("lagrade.judge.check")
    bodies = bodies[: limit or None]
    work = [(i, ({k: v for k, v in b.items() if k != "id"}, 2.0)) for i, b in enumerate(bodies)]
    work = check._diagnose_early(work)
    def judge_one(item):
        verdict = check.check_request({"id": 0, **item[0]}, item[1], *(item[2:]))
        return json.dumps(verdict.to_dict(timings=False), sort_keys=True, default=str)

cache = {}
counts = {k: 0 for k in list(PHASES) + ["other"]}

def phase_of(code):
    name = code.co_filename
    hit = cache.get(name)
    if hit is None:
        hit = ""
        for phase, paths in PHASES.items():
            if any(p in name for p in paths):
                hit = phase
                break
        cache[name] = hit
    return hit

def sample(signum, frame):
    found = "other"
    f = frame
    while f is not None:  # innermost to outermost: the last match is the outermost
        p = phase_of(f.f_code)
        if p:
            found = p
        f = f.f_back
    counts[found] += 1

signal.signal(signal.SIGPROF, sample)
cpu0 = time.process_time()
signal.setitimer(signal.ITIMER_PROF, interval, interval)
verdicts = []
for _, item in work:
    try:
        verdicts.append(judge_one(item))
    except Exception as error:  # named, so that a broken loop cannot pass for equal verdicts
        verdicts.append(f"raised {type(error).__name__}: {error}")
signal.setitimer(signal.ITIMER_PROF, 0, 0)
cpu = time.process_time() - cpu0
print(json.dumps({"counts": counts, "cpu": cpu, "n": len(work), "verdicts": verdicts}))
"""


def interpreter(tree: Path) -> str:
    own = tree / ".venv" / "bin" / "python"
    return str(own) if own.exists() else sys.executable


def run(tree: Path, interval: float, limit: int, corpus: str) -> dict:
    env = {**os.environ, "PYTHONPATH": str(tree)}
    done = subprocess.run(
        [
            interpreter(tree),
            "-c",
            _CHILD,
            str(ROOT),
            json.dumps(PHASES),
            str(interval),
            str(limit),
            corpus,
        ],
        env=env,
        cwd="/",
        capture_output=True,
        text=True,
    )
    if done.returncode:
        raise SystemExit(f"{tree}: {done.stderr[-3000:]}")
    return json.loads(done.stdout.splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("trees", nargs="*", type=Path)
    parser.add_argument("--repeat", type=int, default=1, help="runs per tree (interleaved)")
    parser.add_argument("--interval", type=float, default=1.0, help="sampling period, ms")
    parser.add_argument("--limit", type=int, default=0, help="only the first N requests")
    parser.add_argument(
        "--corpus",
        choices=("batch", "grading", "variants", "class"),
        default="batch",
        help="bench_batch's cold batch, compare_feedback's grading corpus, that corpus "
        "asked of 8 students' variants per scene (one question per student), or "
        "bench_grade's class of --limit students (default 60) graded sheet by sheet",
    )
    args = parser.parse_args()
    trees = [t.resolve() for t in args.trees] or [ROOT]
    runs: dict[Path, list[dict]] = {t: [] for t in trees}
    for _ in range(args.repeat):
        for tree in trees:
            runs[tree].append(run(tree, args.interval, args.limit, args.corpus))
    header = f"{'phase':12}" + "".join(f"{str(t)[-24:]:>34}" for t in trees)
    print(header)
    rows = {}
    for tree in trees:
        rs = runs[tree]
        cpu = sorted(r["cpu"] for r in rs)[len(rs) // 2]
        counts = {k: sum(r["counts"][k] for r in rs) for k in ORDER}
        total = sum(counts.values()) or 1
        rows[tree] = {k: (counts[k] / total, counts[k] / total * cpu) for k in ORDER}
        rows[tree]["cpu"] = cpu
    for k in ORDER:
        print(
            f"{k:12}"
            + "".join(f"{rows[t][k][1]:>22.2f} s {100 * rows[t][k][0]:>6.1f} %" for t in trees)
        )
    print(f"{'total CPU':12}" + "".join(f"{rows[t]['cpu']:>22.2f} s {'':>8}" for t in trees))
    n = runs[trees[0]][0]["n"]
    print(f"requests: {n}")
    if len(trees) > 1:
        base = runs[trees[0]][0]["verdicts"]
        for tree in trees[1:]:
            other = runs[tree][0]["verdicts"]
            changed = sum(a != b for a, b in zip(base, other, strict=True))
            print(f"result changes {trees[0].name} → {tree.name}: {changed} (all but timings)")
    for tree in trees:
        raised = sum(v.startswith("raised ") for v in runs[tree][0]["verdicts"])
        if raised:
            print(
                f"{tree.name}: {raised} requests raised (the first: "
                f"{next(v for v in runs[tree][0]['verdicts'] if v.startswith('raised '))[:200]})"
            )


if __name__ == "__main__":
    main()
