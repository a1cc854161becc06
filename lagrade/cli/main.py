"""The `lagrade` command: parse arguments, make one library call, print, exit.

Exit status: 0 success; 1 the answer or request was judged invalid/incorrect where the command
says so (see each command's help); 2 a usage or input error (`Kind: message` on stderr).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence

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


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="lagrade",
        description="Generate and grade problem sets in Lagrangian mechanics.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    # Each command module registers itself; imported here so that `import lagrade.cli.main`
    # stays cheap (the modules load what their command needs).
    from lagrade.cli import bank, check, demo, generate, grade, parse

    for command in (bank, parse, generate, check, grade, demo):
        command.add_parser(commands)
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
