"""`lagrade generate`: handouts, keys, answer sheets and a manifest for a roster."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def run(args: argparse.Namespace) -> int:
    from lagrade.assign import generate
    from lagrade.cli.progress import ProgressBar
    from lagrade.judge import deriving, verify_variant

    with ProgressBar() as bar:
        result = generate(
            args.assignment,
            args.roster,
            args.seed,
            args.out,
            **({"formats": args.formats} if args.formats else {}),
            templates_dir=args.templates,
            force=args.force,
            progress=bar,
            verify=None if args.no_verify else verify_variant,
            scenes_dir=args.scenes,
            within=deriving,
        )
    for warning in result.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    print(f"wrote {result.files} files for {result.students} students to {result.out_dir}")
    if result.unwritten:
        count = sum(len(kinds) for kinds in result.unwritten.values())
        print(
            f"{count} files of {len(result.unwritten)} students were not made (the warnings say "
            'why; manifest.json lists them under "unwritten")',
            file=sys.stderr,
        )
        return 1
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    generate = commands.add_parser(
        "generate",
        help="handouts, answer keys, answer sheets and a manifest for a roster",
        description="Generate one variant per student of every problem in ASSIGNMENT.toml: "
        "handouts with figures, answer keys, blank answer sheets and manifest.json. Every "
        "variant's key is checked by the grader before anything is written.",
        epilog="example: lagrade generate examples/assignment.toml --roster examples/roster.csv "
        "--seed 2025 --out ps3 --formats md,html,tex,pdf",
    )
    generate.add_argument("assignment", type=Path, metavar="ASSIGNMENT.toml")
    generate.add_argument("--roster", type=Path, required=True, help="CSV with columns id and name")
    generate.add_argument("--seed", type=int, required=True, help="fixes every student's variant")
    generate.add_argument("--out", type=Path, required=True, help="output folder (must not exist)")
    generate.add_argument(
        "--formats",
        default=None,
        help="comma list of md,html,tex,pdf (default md,html,tex: Markdown and HTML, and the "
        "LaTeX source; pdf compiles it where TeX Live is installed)",
    )
    generate.add_argument("--templates", type=Path, default=None, help="folder of *.j2 overrides")
    generate.add_argument(
        "--scenes",
        type=Path,
        default=None,
        help='folder of scene files the assignment names by id (scene = "parabola")',
    )
    generate.add_argument("--force", action="store_true", help="replace an existing output folder")
    generate.add_argument(
        "--no-verify", action="store_true", help="skip grading each key before writing (faster)"
    )
    generate.set_defaults(run=run)
