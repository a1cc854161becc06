"""What the parser understood, shown back to the student: a plain echo with explicit * and ^,
LaTeX with dots over derivatives, the symbols found — or the error with its caret.

`preview_command` is the body of `lagrade parse`; the CLI only wires arguments to it.
"""

from __future__ import annotations

import sympy as sp

from lagrade.mechanics.lagrange import DDOT, DOT


def render_plain(expr: sp.Expr) -> str:
    """sympy's own order, with ^ for powers: 'R^2*m*theta_ddot - R*g*m*sin(theta)'."""
    return sp.sstr(expr).replace("**", "^")


def _latex_name(name: str) -> str:
    """theta_dot → \\dot{\\theta}; x_M_ddot → \\ddot{x}_{M}; x_M → x_{M}."""
    accent = None
    for suffix, command in ((DDOT, "ddot"), (DOT, "dot")):
        if name.endswith(suffix) and len(name) > len(suffix):
            name, accent = name[: -len(suffix)], command
            break
    head, _, subscript = name.partition("_")
    body = sp.latex(sp.Symbol(head))
    if accent:
        body = f"\\{accent}{{{body}}}"
    if subscript:
        body += "_{" + sp.latex(sp.Symbol(subscript)) + "}"
    return body


def render_latex(expr: sp.Expr) -> str:
    """LaTeX with \\dot/\\ddot over velocities and accelerations and \\cdot for products."""
    names = {s: _latex_name(s.name) for s in expr.free_symbols if isinstance(s, sp.Symbol)}
    return sp.latex(expr, symbol_names=names, mul_symbol="dot")


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
    from lagrade.notation.parse import Vocabulary, parse_answer

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
