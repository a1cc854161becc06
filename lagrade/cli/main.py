"""The `lagrade` command: parse arguments, make one library call, print, exit.

Exit status, the same for every command (documented in `lagrade --help` and the README):
  0    success
  1    done, but not everything passed: an answer judged not correct (`check`), students
       missing, invalid or timed out (`grade`), a PDF that could not be made (`generate`)
  2    bad input or usage: a malformed file, request, option or scene id
  3    environment fault: the disk is full, a folder is read-only or not ours to write
  4    the output folder is in use by another lagrade run
  130  interrupted (Ctrl-C or SIGTERM); `serve` exits 0 when stopped, its normal end
"""

from __future__ import annotations

import argparse
import signal
import sys
from collections.abc import Callable, Sequence
from typing import NoReturn

from lagrade.cli.terminal import guarded
from lagrade.errors import LagradeError, OutputBusy, OutputError

EXIT_OK, EXIT_NOT_ALL_PASSED, EXIT_BAD_INPUT, EXIT_ENVIRONMENT, EXIT_BUSY = 0, 1, 2, 3, 4
EXIT_INTERRUPTED = 130

EPILOG = """examples:
  lagrade bank list
  lagrade bank show wedge --seed 3 --format json
  lagrade scene check examples/scenes/parabola.toml
  lagrade parse "1/2 m R^2 thetadot^2 + m g R cos(theta)" --coordinates theta --parameters m,g,R
  lagrade check --scene wedge --part cyclic --answer x_M
  lagrade generate examples/assignment.toml --roster examples/roster.csv --seed 2025 --out ps3
  lagrade grade ps3/manifest.json submissions/ --jobs 2
  lagrade export prairielearn ps3/manifest.json --out pl-questions
  lagrade serve ps3/manifest.json --submissions ps3-sheets --links ps3-links.csv
  lagrade demo

exit status: 0 success; 1 done, but an answer was not correct or students are missing or
invalid; 2 bad input or usage; 3 environment fault (disk full, read-only folder); 4 the output
folder is in use by another run; 130 interrupted (serve: 0, stopping is its normal end).
"""


class OneLineParser(argparse.ArgumentParser):
    """argparse, with a usage error on one line as the README promises (`lagrade: error: …`),
    naming the command's --help instead of printing its whole usage block."""

    def error(self, message: str) -> NoReturn:
        print(f"lagrade: error: {message} (see '{self.prog} --help')", file=sys.stderr)
        sys.exit(EXIT_BAD_INPUT)


def build_parser() -> argparse.ArgumentParser:
    parser = OneLineParser(
        prog="lagrade",
        description="Generate and grade problem sets in Lagrangian mechanics.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action=_VersionAction, help="print lagrade's version and exit")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    # Each command module registers itself; imported here so that `import lagrade.cli.main`
    # stays cheap (the modules load what their command needs).
    from lagrade.cli import bank, check, demo, export, generate, grade, parse, scene, serve

    for command in (bank, scene, parse, generate, check, grade, export, serve, demo):
        command.add_parser(commands)
    return parser


class _VersionAction(argparse.Action):
    """`--version`: the installed distribution's version (pyproject.toml's, read back from its
    metadata only when asked, so building the command line stays cheap)."""

    def __init__(self, option_strings: Sequence[str], dest: str, **kwargs: object) -> None:
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, **kwargs)

    def __call__(self, parser: argparse.ArgumentParser, *_args: object) -> NoReturn:
        from importlib.metadata import PackageNotFoundError, version

        try:
            number = version("lagrade")
        except PackageNotFoundError:  # run from a source tree that was never installed
            number = "(not installed)"
        print(f"lagrade {number}")
        parser.exit()


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the `lagrade` console script: every outcome is an exit status and, on
    failure, one line on stderr (never a traceback for anything a user can cause)."""
    with guarded():  # control characters in anything printed are shown as escapes
        return _main(argv)


def _main(argv: Sequence[str] | None) -> int:
    try:
        args = build_parser().parse_args(argv)
        run: Callable[[argparse.Namespace], int] = args.run
        return run(args)
    except OutputBusy as error:
        return _fail(error, EXIT_BUSY)
    except OutputError as error:
        return _fail(error, EXIT_ENVIRONMENT)
    except LagradeError as error:
        return _fail(error, EXIT_BAD_INPUT)
    except OSError as error:  # a fault of the machine, not of the input: say which file
        where = f" ({error.filename})" if error.filename else ""
        return _fail(f"{error.strerror or error}{where}", EXIT_ENVIRONMENT)
    except KeyboardInterrupt:
        print("lagrade: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


def _fail(error: object, status: int) -> int:
    print(f"lagrade: error: {error}", file=sys.stderr)
    return status


def _interrupt(_signum: int, _frame: object) -> None:
    raise KeyboardInterrupt


def entry() -> None:
    """The console script: `main`, with an interrupt during start-up (importing the commands)
    reported like any other, never as a traceback; SIGTERM (a scheduler's stop) is handled
    like Ctrl-C, so a stopped run removes its temporary files too."""
    signal.signal(signal.SIGTERM, _interrupt)
    try:
        status = main()
    except KeyboardInterrupt:
        print("lagrade: interrupted", file=sys.stderr)
        status = EXIT_INTERRUPTED
    sys.exit(status)


if __name__ == "__main__":
    entry()
