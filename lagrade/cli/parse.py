"""`lagrade parse TEXT`: how an answer is read — the plain echo, LaTeX with dots over derivatives,
the symbols found — or the error with a caret under its position."""

from __future__ import annotations

import argparse


def preview_command(
    text: str,
    coordinates: list[str],
    parameters: list[str],
    latex: bool | None,
    allow_primes: bool = False,
) -> tuple[int, str]:
    """(exit status, text to print) for `lagrade parse TEXT --coordinates … --parameters …`.

    Parameters named on the command line have no declared domain; they are taken as positive
    (masses, lengths, g), which is what sympy's assumptions then know about them. Exit status 0
    with the preview, or 1 with the error message, the answer and a caret under the problem.
    A malformed vocabulary (a coordinate name that is not a name) raises RequestError.
    """
    from lagrade.errors import ParseError
    from lagrade.mechanics import DDOT, DOT
    from lagrade.notation import Vocabulary, parse_answer

    vocabulary = Vocabulary.from_names(coordinates, list(parameters), allow_primes=allow_primes)
    try:
        parsed = parse_answer(text, vocabulary, latex=latex)
    except ParseError as error:
        unknown = error.message.startswith("Unknown symbol")
        flags = "\nDeclare every name with --coordinates or --parameters (e.g. --parameters m,g,R)."
        return 1, str(error) + (flags if unknown else "")
    lines = [
        f"Interpreted as: {parsed.plain()}",
        f"LaTeX:          {parsed.latex()}",
        f"Symbols found:  {', '.join(sorted(parsed.symbols)) or '(none)'}",
    ]
    for name in coordinates:
        if not any(s in parsed.symbols for s in (name, name + DOT, name + DDOT)):
            lines.append(f"Warning: the coordinate {name} does not appear (nor its velocity).")
    lines += [f"Warning: {w}" for w in parsed.warnings]
    return 0, "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    status, text = preview_command(
        args.text,
        _split(args.coordinates),
        _split(args.parameters),
        latex=True if args.latex else None,
        allow_primes=args.allow_primes,
    )
    print(text)
    return status


def _split(csv: str) -> list[str]:
    return [s.strip() for s in csv.split(",") if s.strip()]


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
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
    parse.add_argument(
        "--allow-primes", action="store_true", help="read x' as x_dot without a note"
    )
    parse.set_defaults(run=run)
