"""`lagrade demo`: the whole job end to end on a synthetic class — generate an assignment from
the bank for 30 students, write their submissions (correct answers in varied notation, common
mistakes, blank parts, a malformed file, a missing one), grade them, and summarise. The class
itself is `lagrade.cli.demo_class`, imported when the command runs (start-up stays light)."""

from __future__ import annotations

import argparse
from pathlib import Path

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
    """Where the class could go from here: the three ways into instructors' systems."""
    manifest = folder / "assignment" / "manifest.json"
    return "\n".join(
        [
            "",
            "Next, with this class:",
            f"  answer pages:  lagrade serve {manifest} --submissions {folder}/submissions "
            f"--links {folder}/links.csv",
            f"  PrairieLearn:  lagrade export prairielearn {manifest} --out {folder}/pl-questions",
            f"  Canvas/Moodle: lagrade grade {manifest} {folder}/submissions --export canvas",
            "",
            "Your own system: `lagrade scene new my_system` writes a scene file to fill in, and",
            "  docs/scenes.md (in lagrade's source) walks from there to a graded class.",
        ]
    )


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    demo = commands.add_parser(
        "demo",
        help="generate, submit and grade a synthetic class of 30 end to end",
        description="In FOLDER: write a demo assignment and a roster of 30, generate handouts "
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
    demo.add_argument("--jobs", type=int, default=2, help="submissions graded in parallel")
    demo.set_defaults(run=run)
