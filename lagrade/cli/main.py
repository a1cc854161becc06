"""The `lagrade` command: parse arguments, make one library call, print, exit.

Exit status: 0 success; 1 the answer or request was judged invalid/incorrect where the command
says so (see each command's help); 2 a usage or input error (`Kind: message` on stderr).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

from lagrade.errors import LagradeError

EPILOG = """examples:
  lagrade bank list
  lagrade bank show wedge --seed 3 --format json
  lagrade parse "1/2 m R^2 thetadot^2 + m g R cos(theta)" --coordinates theta --parameters m,g,R
  lagrade check --scene wedge --part cyclic --answer x_M
  lagrade generate examples/assignment.toml --roster examples/roster.csv --seed 2025 --out ps3
  lagrade grade ps3/manifest.json submissions/ --jobs 2
  lagrade demo
"""


def _bank_list(args: argparse.Namespace) -> int:
    from lagrade.bank import get_scene, scene_ids

    for sid in scene_ids():
        scene = get_scene(sid)
        coords = ", ".join(scene.coordinates)
        print(f"{sid:22} {scene.title}  [{coords}]")
    return 0


def _bank_show(args: argparse.Namespace) -> int:
    from lagrade.assign import solution as export
    from lagrade.bank import get_scene

    scene = get_scene(args.scene)
    variant = scene.default if args.seed is None else scene.variant(args.seed)
    render = {
        "text": export.solution_text,
        "json": export.solution_json,
        "latex": export.solution_latex,
    }
    print(render[args.format](variant))
    return 0


def _parse(args: argparse.Namespace) -> int:
    from lagrade.cli.parse import preview_command

    status, text = preview_command(
        args.text,
        _split(args.coordinates),
        _split(args.parameters),
        latex=True if args.latex else None,
        allow_primes=args.allow_primes,
    )
    print(text)
    return status


def _generate(args: argparse.Namespace) -> int:
    from lagrade.assign.generate import generate
    from lagrade.cli.progress import ProgressBar
    from lagrade.judge.verify import verify_variant

    with ProgressBar() as bar:
        result = generate(
            args.assignment,
            args.roster,
            args.seed,
            args.out,
            formats=args.formats,
            templates_dir=args.templates,
            force=args.force,
            progress=bar,
            verify=None if args.no_verify else verify_variant,
        )
    for warning in result.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    print(f"wrote {result.files} files for {result.students} students to {result.out_dir}")
    return 0


def _check(args: argparse.Namespace) -> int:
    from lagrade.judge.check import run_check_command

    status, text = run_check_command(args)
    if text:
        print(text)
    return status


def _grade(args: argparse.Namespace) -> int:
    from lagrade.cli.progress import ProgressBar
    from lagrade.grading.batch import grade

    with ProgressBar() as bar:
        summary = grade(
            args.manifest,
            args.submissions,
            args.out,
            jobs=args.jobs,
            part_time_limit=args.part_time_limit,
            progress=bar,
        )
    counts = ", ".join(f"{k} {v}" for k, v in summary.counts.items() if v)
    print(f"{len(summary.results)} students: {counts} ({summary.reused} unchanged, reused)")
    print(f"gradebook: {summary.out_dir / 'gradebook.csv'}")
    print(f"summary:   {summary.out_dir / 'summary.md'}")
    return 0 if summary.all_graded else 1


def _demo(args: argparse.Namespace) -> int:
    from lagrade.cli.demo import run_demo, summary_table
    from lagrade.cli.progress import ProgressBar

    with ProgressBar() as bar:
        summary, where = run_demo(args.folder, jobs=args.jobs, progress=bar)
    print(summary_table(summary))
    print()
    for label, path in where.items():
        print(f"{label + ':':13} {path}")
    # The demo plants a missing and a malformed submission on purpose: success is that every
    # student has a row and nothing else went wrong.
    return 0 if summary.counts["timeout"] + summary.counts["error"] == 0 else 1


def _split(csv: str) -> list[str]:
    return [s.strip() for s in csv.split(",") if s.strip()]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="lagrade",
        description="Generate and grade problem sets in Lagrangian mechanics.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    bank = commands.add_parser("bank", help="browse the problem bank")
    bank_commands = bank.add_subparsers(dest="bank_command", metavar="ACTION", required=True)
    listing = bank_commands.add_parser("list", help="list every scene id with its title")
    listing.set_defaults(run=_bank_list)
    show = bank_commands.add_parser("show", help="show a scene's full derived solution")
    show.add_argument("scene", help="scene id (see `lagrade bank list`)")
    show.add_argument(
        "--seed", type=int, default=None, help="variant seed (default: the declared form)"
    )
    show.add_argument("--format", choices=("text", "latex", "json"), default="text")
    show.set_defaults(run=_bank_show)

    parse = commands.add_parser(
        "parse",
        help="show how an answer is read (the 'interpreted as' preview)",
        description="Parse TEXT as a student answer and print what it was read as, or the error "
        "with a caret under its position. Parameters named here are taken as positive.",
    )
    parse.add_argument("text", help="the answer, plain text or LaTeX")
    parse.add_argument(
        "--coordinates", default="", help="comma-separated coordinates, e.g. theta,phi"
    )
    parse.add_argument("--parameters", default="", help="comma-separated parameters, e.g. m,g,R")
    parse.add_argument(
        "--latex", action="store_true", help="read TEXT as LaTeX (default: auto-detect)"
    )
    parse.add_argument("--allow-primes", action="store_true", help="read x' as x_dot")
    parse.set_defaults(run=_parse)

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
        default="md,html,tex",
        help="comma list of md,html,tex,pdf (default md,html,tex)",
    )
    generate.add_argument("--templates", type=Path, default=None, help="folder of *.j2 overrides")
    generate.add_argument("--force", action="store_true", help="replace an existing output folder")
    generate.add_argument(
        "--no-verify", action="store_true", help="skip grading each key before writing (faster)"
    )
    generate.set_defaults(run=_generate)

    from lagrade.judge.check import add_check_arguments

    check = commands.add_parser(
        "check",
        help="judge one answer, or a JSON-lines file of requests",
        description="Judge an answer against a bank scene (--scene), an ad-hoc Lagrangian "
        "(--lagrangian with --coordinates and --parameters) or a reference expression "
        "(--expression). Exit 0 when correct (or when a --batch ran to its end), 1 otherwise.",
        epilog="examples:\n  lagrade check --scene wedge --part cyclic --answer x_M\n"
        '  lagrade check --scene hoop --part eom --answer "theta_ddot = omega^2 sin(theta) '
        'cos(theta) - g/R sin(theta)"\n  lagrade check --batch requests.jsonl --out results.jsonl',
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_check_arguments(check)
    check.set_defaults(run=_check)

    grade = commands.add_parser(
        "grade",
        help="grade a folder of answer sheets: gradebook, feedback, results.json, summary",
        description="Grade every roster student's answer sheet (SUBMISSIONS/<id>.toml or .json) "
        "against the manifest. Every student gets a row; a rerun reuses unchanged results. "
        "Exit 0 when every student was graded, 1 when some are missing, invalid, timed out or "
        "failed (their rows say why).",
        epilog="example: lagrade grade ps3/manifest.json submissions/ --out grades --jobs 2",
    )
    grade.add_argument("manifest", type=Path, metavar="DIR/manifest.json")
    grade.add_argument("submissions", type=Path, metavar="SUBMISSIONS")
    grade.add_argument("--out", type=Path, default=None, help="output folder (default DIR/grades)")
    grade.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel")
    grade.add_argument(
        "--part-time-limit",
        type=float,
        default=2.0,
        help="seconds allowed per answer part (default 2)",
    )
    grade.set_defaults(run=_grade)

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
    demo.set_defaults(run=_demo)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the `lagrade` console script."""
    args = build_parser().parse_args(argv)
    run: Callable[[argparse.Namespace], int] = args.run
    try:
        return run(args)
    except LagradeError as error:
        print(f"{type(error).__name__}: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
