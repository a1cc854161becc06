"""`lagrade export prairielearn`: an assignment as PrairieLearn questions, one folder per
problem (the format and what `server.py` does: `lagrade.grading.prairielearn`)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from lagrade.errors import AssignmentError


def run(args: argparse.Namespace) -> int:
    from lagrade.grading.manifest import carried_scene_texts
    from lagrade.grading.prairielearn import export_prairielearn, info_json

    source, seed, texts = Path(args.source), args.seed, None
    if source.suffix == ".json":  # a manifest: its assignment copy, seed and scene files
        try:
            manifest = json.loads(source.read_text(encoding="utf-8"))
            source = source.parent / manifest["assignment"]["file"]
            seed = manifest["seed"] if seed is None else seed
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise AssignmentError(f"{args.source} is not a lagrade manifest ({error})") from None
        texts = carried_scene_texts(manifest)
    if seed is None:
        raise AssignmentError("give --seed (or export from a manifest.json, which has one)")
    folders = export_prairielearn(source, seed, args.out, args.scenes, texts)
    for folder in folders:
        print(f"{folder}  ({info_json(folder)['title']})")
    print(
        f"{len(folders)} PrairieLearn questions in {args.out}; copy them into your course's "
        "questions/ folder (lagrade must be installed in the course's Python environment)"
    )
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    export = commands.add_parser(
        "export",
        help="export an assignment to another system (prairielearn)",
        description="Write one PrairieLearn question folder per problem (info.json, "
        "question.html, server.py): variants drawn from the bank by PrairieLearn's seed, "
        "unreadable answers returned without costing an attempt, parts graded by lagrade.",
        epilog="example: lagrade export prairielearn examples/assignment.toml --seed 2025 "
        "--out pl-questions",
    )
    export.add_argument("system", choices=("prairielearn",), help="the target system")
    export.add_argument("source", metavar="ASSIGNMENT.toml|manifest.json")
    export.add_argument("--seed", type=int, default=None, help="the assignment seed")
    export.add_argument("--out", type=Path, required=True, help="folder for the questions")
    export.add_argument(
        "--scenes", type=Path, default=None, help="folder of scene files the assignment names by id"
    )
    export.set_defaults(run=run)
