"""Student answers → sympy, safely: the public functions, and `_guarded`, the one boundary that
lets only `ParseError` out whatever the input.

Student text never reaches eval, exec, sympify, parse_expr or sympy's LaTeX parsers. It is
normalised and tokenized (`lagrade.notation.lexer`), LaTeX is first translated into the plain
grammar (`lagrade.notation.latex`), the recursive-descent `grammar.Parser` builds a small tree of
plain Python data (`lagrade.notation.nodes`), size limits are checked on that tree, and only then
does `build` turn it into sympy through the one whitelist table `build.SYMPY_CONSTRUCTORS`.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import sympy as sp

from lagrade.errors import ParseError
from lagrade.notation.build import build, check_finite
from lagrade.notation.echo import echo as _echo
from lagrade.notation.grammar import Parser
from lagrade.notation.latex import translate
from lagrade.notation.lexer import Source, normalise
from lagrade.notation.limits import MAX_LENGTH, MAX_TOTAL_LENGTH
from lagrade.notation.parsed import Parsed
from lagrade.notation.vocabulary import Vocabulary

__all__ = [
    "Parsed",
    "ParseError",
    "Vocabulary",
    "parse_answer",
    "parse_equation",
    "parse_equations",
    "parse_expression",
    "split_equations",
]


def _is_latex(text: str) -> bool:
    """Auto-detection: a backslash, $…$ delimiters, or a braced power x^{2} mean LaTeX."""
    stripped = text.strip()
    return "\\" in text or "^{" in text or (stripped.startswith("$") and stripped.endswith("$"))


def _parse_source(src: Source, vocabulary: Vocabulary, latex: bool | None, mode: str) -> Parsed:
    """Text → tokens → tree → sympy, then the finiteness check and the echo."""
    if len(src.text) > MAX_LENGTH:
        src.fail(
            f"The answer is too long ({len(src.text)} characters; the limit is {MAX_LENGTH}).",
            MAX_LENGTH,
            len(src.text),
        )
    lexicon = vocabulary._lexicon
    src = normalise(src)
    if latex or (latex is None and _is_latex(src.text)):
        src = translate(src, keep_e="e" in lexicon.table)
    parser = Parser(src, lexicon)
    lhs_node, rhs_node = parser.parse_answer(mode)
    lhs = build(lhs_node, src)
    rhs = build(rhs_node, src) if rhs_node is not None else None
    if mode == "equation" and rhs is None:
        rhs = sp.S.Zero
    for side, node in ((lhs, lhs_node), (rhs, rhs_node)):
        if side is not None:
            check_finite(side, node, src, imaginary=lexicon.imaginary_unit is not None)
    shown = _echo(lhs_node, src.text)
    if rhs is not None:
        shown += " = " + (_echo(rhs_node, src.text) if rhs_node is not None else "0")
    return Parsed(src.original, lhs, rhs, frozenset(parser.found), tuple(parser.warnings), shown)


def _guarded(src: Source, vocabulary: Vocabulary, latex: bool | None, mode: str) -> Parsed:
    """The one boundary: only ParseError leaves, whatever happened inside."""
    if not isinstance(vocabulary, Vocabulary):
        raise TypeError(f"vocabulary must be a Vocabulary, not {type(vocabulary).__name__}")
    try:
        return _parse_source(src, vocabulary, latex, mode)
    except ParseError:
        raise
    except RecursionError:
        src.fail("The answer is nested too deeply.", 0, len(src.text))
    except Exception:  # an internal error must not crash a batch; the cause stays chained
        src.fail("Could not read this answer (internal error).", 0, len(src.text))


def _source(text: object) -> Source:
    if not isinstance(text, str):
        Source("", "").fail(f"The answer must be text, not {type(text).__name__}.", 0, 0)
    return Source(text, text)


def parse_expression(text: str, vocabulary: Vocabulary, *, latex: bool | None = None) -> Parsed:
    """An expression (a Lagrangian, a momentum); an '=' is an error. `latex=None` reads the text
    as LaTeX when it contains a backslash."""
    return _guarded(_source(text), vocabulary, latex, "expression")


def parse_equation(text: str, vocabulary: Vocabulary, *, latex: bool | None = None) -> Parsed:
    """An equation lhs = rhs; a bare expression means expression = 0 (rhs is 0)."""
    return _guarded(_source(text), vocabulary, latex, "equation")


def parse_answer(text: str, vocabulary: Vocabulary, *, latex: bool | None = None) -> Parsed:
    """An expression or an equation, whichever was written (rhs is None without '=')."""
    return _guarded(_source(text), vocabulary, latex, "answer")


_SEPARATORS = re.compile(r"\n|(?<!\\);|\\\\")


def split_equations(text: str) -> list[str]:
    """The pieces `parse_equations` reads one equation from (lines, ';' or LaTeX '\\\\'), so
    that a caller can read each on its own and keep the ones that parse."""
    return [piece for piece in _SEPARATORS.split(text) if piece.strip()]


def parse_equations(
    text: str | Sequence[str], vocabulary: Vocabulary, *, latex: bool | None = None
) -> list[Parsed]:
    """A list of equations: one per line or separated by ';' (or LaTeX '\\\\'); a list of strings
    may hold several lines each. Errors point into the text they came from."""
    texts = (
        [text] if isinstance(text, str) else list(text) if isinstance(text, Sequence) else [text]
    )
    results: list[Parsed] = []
    for whole in texts:
        src = _source(whole)
        if len(whole) > MAX_TOTAL_LENGTH:
            src.fail(
                f"The answer is too long ({len(whole)} characters; "
                f"the limit is {MAX_TOTAL_LENGTH}).",
                MAX_TOTAL_LENGTH,
                len(whole),
            )
        mode = latex if latex is not None else _is_latex(whole)
        start = 0
        for match in [*_SEPARATORS.finditer(whole), None]:
            end = match.start() if match else len(whole)
            piece = whole[start:end]
            if piece.strip():
                segment = Source(whole, piece, offset=start)
                results.append(_guarded(segment, vocabulary, mode, "equation"))
            start = match.end() if match else end
    if not results:
        _source(texts[0] if texts and isinstance(texts[0], str) else "").fail(
            "The answer is empty.", 0, 0
        )
    return results
