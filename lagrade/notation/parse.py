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
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import sympy as sp

from lagrade.errors import ParseError
from lagrade.notation.build import build, check_finite
from lagrade.notation.echo import echo as _echo
from lagrade.notation.grammar import Parser
from lagrade.notation.latex import translate
from lagrade.notation.lexer import Source, normalise
from lagrade.notation.limits import MAX_LENGTH, MAX_TOTAL_LENGTH
from lagrade.notation.parsed import Parsed, Tree
from lagrade.notation.screen import needs_sympy
from lagrade.notation.vocabulary import Vocabulary

__all__ = [
    "NameRead",
    "Parsed",
    "ParseError",
    "Vocabulary",
    "is_latex",
    "parse_answer",
    "parse_equation",
    "parse_equations",
    "parse_expression",
    "read_names",
    "split_equations",
]


def is_latex(text: str) -> bool:
    """Auto-detection: a backslash, $…$ delimiters, or a braced power x^{2} mean LaTeX."""
    stripped = text.strip()
    return "\\" in text or "^{" in text or (stripped.startswith("$") and stripped.endswith("$"))


def _check_length(src: Source) -> None:
    """Refuse an answer over MAX_LENGTH characters before anything reads it."""
    if len(src.text) > MAX_LENGTH:
        src.fail(
            f"The answer is too long ({len(src.text)} characters; the limit is {MAX_LENGTH}).",
            MAX_LENGTH,
            len(src.text),
        )


def _parse_source(src: Source, vocabulary: Vocabulary, latex: bool | None, mode: str) -> Parsed:
    """Text → tokens → tree → sympy, then the finiteness check and the echo."""
    _check_length(src)
    lexicon = vocabulary._lexicon
    src = normalise(src)
    latex = bool(latex or (latex is None and is_latex(src.text)))
    if latex:
        src = translate(src, keep_e="e" in lexicon.table, names=lexicon.table)
    parser = Parser(src, lexicon)
    # a run of declared single letters (\frac{GMm}{r}, GM) is their product, with a note
    parser.tokens = parser.split_letter_runs(parser.tokens, latex)
    lhs_node, rhs_node = parser.parse_answer(mode)
    shown = _echo(lhs_node, src.text)
    if rhs_node is not None:
        shown += " = " + _echo(rhs_node, src.text)
    elif mode == "equation":
        shown += " = 0"
    found = frozenset(parser.found)
    imaginary = lexicon.imaginary_unit is not None
    if not needs_sympy((lhs_node, rhs_node), imaginary):  # sympy would refuse nothing: later
        tree = Tree(lhs_node, rhs_node, mode == "equation")
        return Parsed.unbuilt(
            src.original,
            tree,
            found,
            parser.warnings,
            shown,
            lambda node: build(node, src),
            src.text,
        )
    lhs = build(lhs_node, src)
    rhs = build(rhs_node, src) if rhs_node is not None else None
    if mode == "equation" and rhs is None:
        rhs = sp.S.Zero
    for side, node in ((lhs, lhs_node), (rhs, rhs_node)):
        if side is not None:
            check_finite(side, node, src, imaginary=imaginary)
    sides = Tree(lhs_node, rhs_node, mode == "equation")
    return Parsed(
        src.original, lhs, rhs, found, tuple(parser.warnings), shown, sides=sides, text=src.text
    )


def _guarded(
    src: Source,
    vocabulary: Vocabulary,
    latex: bool | None,
    mode: str,
    read: Callable = _parse_source,
):
    """The one boundary: only ParseError leaves, whatever happened inside."""
    if not isinstance(vocabulary, Vocabulary):
        raise TypeError(f"vocabulary must be a Vocabulary, not {type(vocabulary).__name__}")
    try:
        return read(src, vocabulary, latex, mode)
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
        mode = latex if latex is not None else is_latex(whole)
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


# --- lists of names --------------------------------------------------------------------------


@dataclass(frozen=True)
class NameRead:
    """One name of a list of names (the coordinates, the cyclic ones) as the grammar reads it,
    in whatever spelling it was typed: `name` is its canonical spelling (θ, \\theta and theta
    give "theta"; θ₁ and theta1 give "theta_1"; θ̇ and thetadot give "theta_dot"), `symbol` the
    question's symbol (None for a name the question does not know), `coordinate` the
    coordinate it is, or is the velocity (`order` 1) or acceleration (`order` 2) of, and `span`
    where it stands in `source`, the text as typed."""

    name: str
    symbol: sp.Symbol | None
    coordinate: str | None
    order: int
    span: tuple[int, int]
    source: str


def _read_name_source(src: Source, vocabulary: Vocabulary, latex: bool | None, expected: str):
    """Text → names: the same normalisation, LaTeX translation, tokens and lexicon as an
    expression, but every token must be a name; anything else fails with `expected`."""
    _check_length(src)
    lexicon = vocabulary._lexicon
    src = normalise(src)
    if latex or (latex is None and is_latex(src.text)):
        src = translate(src, keep_e="e" in lexicon.table, names=lexicon.table)
    rules = Parser(src, lexicon)
    tokens = rules.tokens[:-1]
    of_t = {k + d for k, tok in enumerate(tokens) for d in (1, 2, 3) if _of_t(tokens, k)}
    names = []
    for k, tok in enumerate(tokens):
        if k in of_t:  # theta(t) is theta
            continue
        if tok.kind != "name":
            src.fail(expected, tok.start, tok.end)
        entry = lexicon.table.get(tok.text)
        span = src.locate(tok.start, tok.end)
        if entry is None or entry.kind == "pi" or entry.value is sp.I:
            names.append(NameRead(tok.text, None, None, tok.marks, span, src.original))
            continue
        rules.lookup(tok)  # primes where the question does not allow them fail here
        order = entry.order + tok.marks + tok.primes
        jet = entry.jet
        if jet is None:
            names.append(NameRead(entry.value.name, entry.value, None, order, span, src.original))
            continue
        symbol = rules.derivative(entry, order, tok.start, tok.end).value
        names.append(NameRead(symbol.name, symbol, jet.name, order, span, src.original))
    if not names:
        src.fail("The answer is empty.", 0, len(src.text))
    return tuple(names)


def _of_t(tokens, k: int) -> bool:
    """Whether the name at k is followed by `(t)`, without a space (theta(t))."""
    following = [tok.text for tok in tokens[k + 1 : k + 4]]
    return tokens[k].kind == "name" and following == ["(", "t", ")"] and not tokens[k + 1].spaced


def read_names(
    text: str,
    vocabulary: Vocabulary,
    *,
    latex: bool | None = None,
    expected: str = "Write names only here, as in theta, phi.",
) -> tuple[NameRead, ...]:
    """The names in `text` (separated by spaces), each in its canonical spelling and with the
    question's symbol when the question knows it; a name the question does not know is read,
    not refused (saying which names are wrong is the checker's). Anything but names fails with
    `expected` and a caret."""
    src = _source(text)
    return _guarded(src, vocabulary, latex, expected, _read_name_source)
