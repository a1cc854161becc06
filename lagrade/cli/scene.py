"""`lagrade scene check FILE` and `lagrade scene new NAME`: an instructor's own scene files
(the format: docs/scenes.md; the work: `lagrade.assign.scene_check`)."""

from __future__ import annotations

import argparse
from pathlib import Path


def scene_check(args: argparse.Namespace) -> int:
    from lagrade.assign import check_scene_file
    from lagrade.judge import deriving

    # the whole check is the scene's derivation (in every presentation): one limit for it
    with deriving(f"scene file {args.file}"):
        report = check_scene_file(args.file, args.figure)
    print(report.text)
    if report.failures:
        print(f"\n{len(report.failures)} check(s) failed; see above")
        return 1
    return 0


def scene_new(args: argparse.Namespace) -> int:
    from lagrade.assign import new_scene_file

    path = new_scene_file(args.name, args.out)
    print(f"wrote {path}: edit it, then run `lagrade scene check {path}` (format: docs/scenes.md)")
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    scene = commands.add_parser(
        "scene",
        help="write and check scene files of your own (docs/scenes.md)",
        description="A scene file declares one system in TOML (coordinates, parameters, bodies, "
        "potential, constraints); lagrade derives the rest. Format: docs/scenes.md.",
    )
    actions = scene.add_subparsers(dest="scene_command", metavar="ACTION", required=True)
    check = actions.add_parser(
        "check",
        help="validate a scene file, print its derived solution, check its quantities, draw it",
        description="Read FILE (every problem at once, exit status 2), check it in each "
        "presentation, print the five-step solution, check every quantity against the "
        "derived motion (exit status 1 when one fails) and draw the figure.",
        epilog="example: lagrade scene check examples/scenes/parabola.toml --figure parabola.svg",
    )
    check.add_argument("file", type=Path, metavar="FILE.toml")
    check.add_argument(
        "--figure", type=Path, default=None, help="where to draw the figure (default: ID.svg here)"
    )
    check.set_defaults(run=scene_check)
    new = actions.add_parser(
        "new",
        help="write a commented template NAME.toml",
        epilog="example: lagrade scene new my_pendulum",
    )
    new.add_argument("name", help="the scene's id and file name (letters, digits, _ and -)")
    new.add_argument("--out", type=Path, default=None, help="folder to write it in (default: here)")
    new.set_defaults(run=scene_new)
