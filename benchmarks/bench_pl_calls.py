"""CPU per PrairieLearn call: generate, parse and grade of exported lagrade questions, each call
in a fresh process, as PrairieLearn's worker makes it, and cold.

PrairieLearn runs a question's server.py in a worker forked from its zygote (`zygote.py`, in
`apps/prairielearn/python/`), which imports before it forks ("Pre-load commonly used modules",
checked at PrairieLearn 88fb8556a7): numpy, matplotlib, scikit-learn (which imports scipy) and
its own `prairielearn` package, whose `conversion_utils` imports sympy. It puts the course's
serverFilesCourse/ on sys.path, so server.py runs the vendored lagrade with its shipped
bytecode. Each call here is one fresh process that does the same, then measures:

  zygote   numpy, sympy, matplotlib and scipy imported first, as the zygote has them (not
           counted: the zygote paid for them once, before any request)
  cold     nothing imported first: what a call costs where no process has them loaded

CPU is the call's process and the judging workers it forks (parse and grade judge in a
killable worker), from loading server.py to the call's return. The calls are checked: the key
scores 1 and parses without a format error, a wrong submission (every answer with `+ 1` added)
scores below 1.

Usage: python benchmarks/bench_pl_calls.py [--scenes simple_pendulum,wedge] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from lagrade.grading.prairielearn import export_prairielearn  # noqa: E402

#: What PrairieLearn's zygote imports before forking a worker, among what a lagrade question
#: uses (its other preloads, lxml, nltk, pint, chevron, pandas, are not lagrade's).
ZYGOTE_PRELOADS = "numpy, sympy, matplotlib, scipy, scipy.linalg, scipy.optimize"

_CALL = r"""
import json, os, sys, time, importlib.util
question, phase, course, data_path, preload = sys.argv[1:6]
if preload == "zygote":
    import {preloads}
    import matplotlib
    matplotlib.use("PDF")  # as zygote.py sets it
sys.path.insert(0, os.path.join(course, "serverFilesCourse"))  # as PrairieLearn does
t0, c0 = time.process_time(), os.times()
spec = importlib.util.spec_from_file_location("server", os.path.join(question, "server.py"))
server = importlib.util.module_from_spec(spec)
spec.loader.exec_module(server)
data = json.load(open(data_path))
getattr(server, phase)(data)
c1 = os.times()
import lagrade
assert "serverFilesCourse" in lagrade.__file__, lagrade.__file__  # the vendored copy ran
workers = c1.children_user + c1.children_system - c0.children_user - c0.children_system
print(json.dumps({"cpu": time.process_time() - t0 + workers, "data": data}))
""".replace("{preloads}", ZYGOTE_PRELOADS)


def call(question: Path, phase: str, course: Path, data: dict, preload: str) -> tuple[float, dict]:
    """(CPU seconds, data after the call) of one call in a fresh process."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(data, f)
    done = subprocess.run(
        [sys.executable, "-c", _CALL, str(question), phase, str(course), f.name, preload],
        capture_output=True,
        text=True,
        cwd=str(question),
    )
    Path(f.name).unlink()
    if done.returncode:
        raise SystemExit(f"{question.name} {phase} ({preload}): {done.stderr[-2000:]}")
    found = json.loads(done.stdout.splitlines()[-1])
    return found["cpu"], found["data"]


def submission(data: dict, answers: dict) -> dict:
    """The data of a parse or grade call with `answers` submitted (PrairieLearn's keys)."""
    return {
        **data,
        "submitted_answers": dict(answers),
        "raw_submitted_answers": dict(answers),
        "format_errors": {},
        "partial_scores": {},
        "score": 0,
        "feedback": {},
        "gradable": True,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenes", default="simple_pendulum,wedge")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    scenes = [s for s in args.scenes.split(",") if s]
    problems = "\n".join(
        f'[[problems]]\nscene = "{s}"\nparts = ["dof", "lagrangian", "eom", "momenta"]\n'
        for s in scenes
    )
    times: dict[tuple[str, str], list[float]] = {}
    faults: list[str] = []
    with tempfile.TemporaryDirectory() as scratch:
        assignment = Path(scratch) / "a.toml"
        assignment.write_text(f'title = "Per call"\npoints = 1\n\n{problems}', encoding="utf-8")
        course = Path(scratch) / "course"
        folders = export_prairielearn(assignment, 2025, course)
        for _ in range(args.repeat):  # interleaved: the two ways side by side in every round
            for folder in folders:
                for preload in ("zygote", "cold"):
                    new = {"params": {}, "correct_answers": {}, "variant_seed": 7, "options": {}}
                    cpu, generated = call(folder, "generate", course, new, preload)
                    times.setdefault(("generate", preload), []).append(cpu)
                    key = generated["correct_answers"]
                    wrong = {k: f"{v} + 1" for k, v in key.items()}
                    for phase, answers in (("parse", key), ("grade", key), ("grade", wrong)):
                        asked = submission(generated, answers)
                        cpu, after = call(folder, phase, course, asked, preload)
                        label = phase if answers is key else "grade (wrong)"
                        times.setdefault((label, preload), []).append(cpu)
                        if phase == "parse" and after["format_errors"]:
                            faults.append(f"{folder.name}: the key has format errors")
                        if phase == "grade" and (after["score"] == 1) != (answers is key):
                            faults.append(f"{folder.name}: {label} scored {after['score']}")
    print(f"{len(folders)} questions ({', '.join(scenes)}), {args.repeat} rounds; CPU per call:")
    print(f"  {'call':16}{'zygote (median)':>18}{'cold (median)':>16}{'calls':>7}")
    for label in ("generate", "parse", "grade", "grade (wrong)"):
        zygote, cold = times[(label, "zygote")], times[(label, "cold")]
        print(
            f"  {label:16}{statistics.median(zygote):16.3f} s"
            f"{statistics.median(cold):14.3f} s{len(zygote):7}"
        )
    for fault in sorted(set(faults)):
        print("FAULT:", fault)
    return 1 if faults else 0


if __name__ == "__main__":
    raise SystemExit(main())
