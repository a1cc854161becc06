"""`lagrade bank list` and `lagrade bank show SCENE`: the scenes and their derived solutions."""

from __future__ import annotations

import argparse


def bank_list(args: argparse.Namespace) -> int:
    from lagrade.bank import get_scene, scene_ids

    for sid in scene_ids():
        scene = get_scene(sid)
        coords = ", ".join(scene.coordinates)
        print(f"{sid:22} {scene.title}  [{coords}]")
    return 0


def bank_show(args: argparse.Namespace) -> int:
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


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    bank = commands.add_parser("bank", help="browse the problem bank")
    bank_commands = bank.add_subparsers(dest="bank_command", metavar="ACTION", required=True)
    listing = bank_commands.add_parser("list", help="list every scene id with its title")
    listing.set_defaults(run=bank_list)
    show = bank_commands.add_parser("show", help="show a scene's full derived solution")
    show.add_argument("scene", help="scene id (see `lagrade bank list`)")
    show.add_argument(
        "--seed", type=int, default=None, help="variant seed (default: the declared form)"
    )
    show.add_argument("--format", choices=("text", "latex", "json"), default="text")
    show.set_defaults(run=bank_show)
