"""`lagrade parse`: what the parser understood, shown back — a plain echo with explicit * and ^,
LaTeX with dots over derivatives, the symbols found — or the error with its caret."""

from __future__ import annotations

from lagrade.errors import ParseError
from lagrade.mechanics.lagrange import DDOT, DOT
from lagrade.notation import Vocabulary, parse_answer


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
    vocabulary = Vocabulary.from_names(coordinates, list(parameters), allow_primes=allow_primes)
    try:
        parsed = parse_answer(text, vocabulary, latex=latex)
    except ParseError as error:
        return 1, str(error)
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
