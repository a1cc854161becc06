"""`lagrade demo`: the whole job end to end on a synthetic class — generate an assignment from
the bank for 30 students, write their submissions (correct answers in varied notation, common
mistakes, blank parts, a malformed file, a missing one), grade them, and summarise. The class
itself is `lagrade.cli.demo_class`, imported when the command runs (start-up stays light)."""

from __future__ import annotations

import argparse
import shlex
import shutil
import sys
from pathlib import Path

from lagrade.cli.arguments import count
from lagrade.cli.grade import summary_table


def run(args: argparse.Namespace) -> int:
    from lagrade.cli.demo_class import run_demo
    from lagrade.cli.progress import ProgressBar

    with ProgressBar() as bar:
        summary, where = run_demo(args.folder, jobs=args.jobs, progress=bar)
    print(summary_table(summary))
    print()
    for label, path in where.items():
        print(f"{label + ':':13} {path}")
    print(_next_steps(where["submissions"].parent))
    # The demo plants a missing and a malformed submission on purpose: success is that every
    # student has a row and nothing else went wrong.
    return 0 if summary.counts["timeout"] + summary.counts["error"] == 0 else 1


def _next_steps(folder: Path) -> str:
    """Where the class could go from here: the three ways into instructors' systems, each a
    command that runs as printed (see `how_to_run`)."""
    manifest = folder / "assignment" / "manifest.json"
    lagrade = how_to_run()
    return "\n".join(
        [
            "",
            "Next, with this class:",
            f"  answer pages:  {lagrade} serve {manifest} --submissions {folder}/submissions "
            f"--links {folder}/links.csv",
            f"  PrairieLearn:  {lagrade} export prairielearn {manifest} "
            f"--out {folder}/pl-questions",
            f"  Canvas/Moodle: {lagrade} grade {manifest} {folder}/submissions --export canvas",
            f"  your own system: {lagrade} scene new my_system",
            "(a scene file to fill in; docs/scenes.md in lagrade's source walks from there to a "
            "graded class)",
        ]
    )


def how_to_run() -> str:
    """How to run this same lagrade again from this shell: `lagrade` when that name on PATH
    is this installation (an activated venv), otherwise the path it was started by
    (`.venv/bin/lagrade` right after the README's quick start, before `. .venv/bin/activate`),
    or `python -m lagrade` with this interpreter."""
    started = Path(sys.argv[0])
    on_path = shutil.which("lagrade")
    if started.name == "lagrade" and started.is_file():
        if on_path and Path(on_path).resolve() == started.resolve():
            return "lagrade"
        return shlex.quote(str(started))
    return f"{shlex.quote(sys.executable)} -m lagrade"


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    demo = commands.add_parser(
        "demo",
        help="generate, submit and grade a synthetic class of 30 end to end",
        description="In DIR: write a demo assignment and a roster of 30, generate handouts "
        "and keys, write synthetic submissions (varied notation, common mistakes, blank parts, "
        "one malformed file, one missing), grade them and print the results.",
    )
    demo.add_argument(
        "folder",
        type=Path,
        nargs="?",
        default=Path("lagrade-demo"),
        metavar="DIR",
        help="where to work (default ./lagrade-demo)",
    )
    demo.add_argument("--jobs", type=count, default=2, help="submissions graded in parallel")
    demo.set_defaults(run=run)
