"""`lagrade export prairielearn|gradescope`: an assignment for another system. PrairieLearn:
one question folder per problem (`lagrade.grading.prairielearn`); Gradescope: an autograder zip
that grades each upload with lagrade (`lagrade.grading.gradescope`)."""

from __future__ import annotations

import argparse
from pathlib import Path

import lagrade.untrusted as untrusted
from lagrade.errors import AssignmentError, LagradeError


def run(args: argparse.Namespace) -> int:
    if args.system == "gradescope":
        return _gradescope(args)
    from lagrade.grading import (
        QUESTIONS,
        SERVER_FILES,
        carried_scene_texts,
        export_prairielearn,
        info_json,
        vendored_folder,
    )

    source, seed, texts = Path(args.source), args.seed, None
    if source.suffix == ".json":  # a manifest: its assignment copy, seed and scene files
        try:
            what = str(args.source)
            manifest = untrusted.load_json(untrusted.decode(source.read_bytes(), what), what)
            source = source.parent / manifest["assignment"]["file"]
            seed = manifest["seed"] if seed is None else seed
        except (OSError, LagradeError, KeyError, TypeError) as error:
            raise AssignmentError(f"{args.source} is not a lagrade manifest ({error})") from None
        texts = carried_scene_texts(manifest)
    if seed is None:
        raise AssignmentError("give --seed (or export from a manifest.json, which has one)")
    folders = export_prairielearn(source, seed, args.out, args.scenes, texts)
    for folder in folders:
        print(f"{folder}  ({info_json(folder)['title']})")
    lagrade = vendored_folder(args.out)
    print(
        f"{len(folders)} PrairieLearn questions in {args.out / QUESTIONS}, and the lagrade they "
        f"run in {lagrade}.\nCopy both into your course (nothing to install):\n"
        f"  {args.out / QUESTIONS}/*  ->  COURSE/{QUESTIONS}/\n"
        f"  {lagrade}  ->  COURSE/{SERVER_FILES}/{lagrade.name}\n"
        f"(or give the course's folder as --out)."
    )
    return 0


def _gradescope(args: argparse.Namespace) -> int:
    from lagrade.grading import export_gradescope

    out = export_gradescope(Path(args.source), args.out, trust_sheet=args.trust_sheet)
    print(
        f"{out}: Gradescope autograder (setup.sh, run_autograder, the lagrade wheel, the "
        "manifest); upload it under Configure Autograder (README.txt inside says more)"
    )
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    export = commands.add_parser(
        "export",
        help="export an assignment to another system (prairielearn, gradescope)",
        description="prairielearn: one question folder per problem (info.json,\n"
        "question.html, server.py) in OUT/questions/, and the lagrade they run in\n"
        "OUT/serverFilesCourse/ (PrairieLearn installs nothing): variants drawn from the bank\n"
        "by PrairieLearn's seed, unreadable answers returned without costing an attempt,\n"
        "parts graded by lagrade. OUT may be the course's own folder.\n"
        "gradescope: an autograder zip (--out autograder.zip) that grades each student's\n"
        "uploaded answer sheet against their own variant, as `lagrade grade` does (give it\n"
        "the manifest.json). The student is the Gradescope account's, found in the roster\n"
        "by email, then by Gradescope's student ID; an account on no roster row, or a sheet\n"
        "naming another student, scores 0 with a sentence (--trust-sheet: take the sheet's\n"
        "student_id when the account matches no roster row).",
        epilog="examples:\n"
        "  lagrade export prairielearn examples/assignment.toml --seed 2025 --out pl-course\n"
        "  lagrade export gradescope ps3/manifest.json --out autograder.zip",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    export.add_argument("system", choices=("prairielearn", "gradescope"), help="the target system")
    export.add_argument("source", metavar="ASSIGNMENT.toml|manifest.json")
    export.add_argument("--seed", type=int, default=None, help="the assignment seed")
    export.add_argument(
        "--out",
        type=Path,
        required=True,
        help="the course folder to write questions/ and serverFilesCourse/ into (prairielearn), "
        "or the zip to write (gradescope)",
    )
    export.add_argument(
        "--scenes",
        type=Path,
        default=None,
        help="folder of scene files the assignment names by id (prairielearn)",
    )
    export.add_argument(
        "--trust-sheet",
        action="store_true",
        help="gradescope: when a Gradescope account matches no roster student (by email or "
        "student ID), grade the student the uploaded sheet's student_id names",
    )
    export.set_defaults(run=run)
