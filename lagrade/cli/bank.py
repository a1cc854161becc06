"""`lagrade bank list [PATH…]` and `lagrade bank show SCENE`: scenes and their derived solutions;
a scene is a bank id or a scene file, and `list` takes files and folders of them too."""

from __future__ import annotations

import argparse


def bank_list(args: argparse.Namespace) -> int:
    from lagrade.bank import list_scenes

    rows, problems = list_scenes(args.paths)
    for sid, title, coordinates in rows:
        print(f"{sid:22} {title}  [{', '.join(coordinates)}]")
    if problems:
        from lagrade.errors import LagradeError

        raise LagradeError("\n".join(problems))
    return 0


def bank_show(args: argparse.Namespace) -> int:
    from lagrade.assign import solution as export
    from lagrade.bank import find_scene
    from lagrade.judge import deriving

    render = {
        "text": export.solution_text,
        "json": export.solution_json,
        "latex": export.solution_latex,
    }
    with deriving(f"scene {args.scene}"):  # a scene file is text from outside: the same limits
        scene = find_scene(args.scene)
        variant = scene.default if args.seed is None else scene.variant(args.seed)
        shown = render[args.format](variant)
    print(shown)
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    bank = commands.add_parser("bank", help="browse the problem bank and your scene files")
    bank_commands = bank.add_subparsers(dest="bank_command", metavar="ACTION", required=True)
    listing = bank_commands.add_parser(
        "list",
        help="list scenes with their titles: the bank, or the scene files and folders given",
        epilog="example: lagrade bank list examples/scenes wedge",
    )
    listing.add_argument(
        "paths", nargs="*", metavar="PATH", help="scene files, folders of them, or bank ids"
    )
    listing.set_defaults(run=bank_list)
    show = bank_commands.add_parser("show", help="show a scene's full derived solution")
    show.add_argument("scene", help="a bank id (see `lagrade bank list`) or a scene file")
    show.add_argument(
        "--seed", type=int, default=None, help="variant seed (default: the declared form)"
    )
    show.add_argument("--format", choices=("text", "latex", "json"), default="text")
    show.set_defaults(run=bank_show)
