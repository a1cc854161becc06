"""Reading a part's answer: items of a list answer, each parsed by the project parser in the
question's vocabulary, labels (`p_x = …`, `L = …`) dropped, and the student's own L for
follow-through."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Any

import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.judge.compiled import Compiled
from lagrade.judge.problem import Problem, parser
from lagrade.notation.parse import split_equations
from lagrade.notation.printer import plain


@dataclass(frozen=True)
class Read:
    """One parsed answer item: lhs (a label symbol or an expression), rhs, and the echo."""

    lhs: sp.Expr
    rhs: sp.Expr | None
    echo: str

    @property
    def expr(self) -> sp.Expr:
        return self.lhs if self.rhs is None else self.lhs - self.rhs


def items_of(answer: Any, part: str) -> list[Any]:
    if isinstance(answer, str | sp.Basic):
        return [answer]
    if isinstance(answer, Sequence) and not isinstance(answer, str | bytes):
        return list(answer)
    raise RequestError(f"the answer to {part!r} must be a string or a list of strings")


@dataclass(frozen=True)
class Unreadable:
    """One line of a multi-line answer that does not parse: its text and the parser's error."""

    text: str
    error: ParseError


@dataclass(frozen=True)
class Lines:
    """A multi-line answer read line by line: `entries` in order, each a Read or, for a line
    that does not parse, an Unreadable (a line read as several equations gives several Reads).
    An unreadable line counts like a wrong one; its echo is "" (nothing was read)."""

    entries: tuple[Read | Unreadable, ...]

    @property
    def reads(self) -> list[Read]:
        return [e for e in self.entries if isinstance(e, Read)]

    @property
    def unreadable(self) -> list[Unreadable]:
        return [e for e in self.entries if isinstance(e, Unreadable)]

    @property
    def echoes(self) -> list[str]:
        return [e.echo if isinstance(e, Read) else "" for e in self.entries]

    def feedback(self) -> list[str]:
        """One sentence per unreadable line, naming it (1-based, as in `interpreted`) and
        carrying the parser's message with its caret."""
        return [
            f"Line {k + 1} could not be read: {e.error}"
            for k, e in enumerate(self.entries)
            if isinstance(e, Unreadable)
        ]


def read_lines(items: Sequence[Any], reader: Callable[[Any], Read | list[Read]]) -> Lines:
    """The one place a list of answer lines is parsed: each line by `reader`, a line that does
    not parse set aside as Unreadable so that the others are still judged. When no line reads
    at all, the parser's error is raised (the part is `invalid`, as for a one-line answer)."""
    entries: list[Read | Unreadable] = []
    for item in _pieces(items):
        try:
            got = reader(item)
        except ParseError as error:
            entries.append(Unreadable(item if isinstance(item, str) else str(item), error))
            continue
        entries.extend(got if isinstance(got, list) else [got])
    lines = Lines(tuple(entries))
    bad = lines.unreadable
    if bad and not lines.reads:
        if len(bad) == 1:
            raise bad[0].error
        raise ParseError("No line of this answer can be read.\n" + "\n".join(lines.feedback()))
    return lines


def _pieces(items: Sequence[Any]) -> list[Any]:
    """Each item split where the parser splits equations (newline, ';', LaTeX '\\\\'), so that
    one unreadable equation in `a = 0; b +* 2 = 0` does not hide the one that reads."""
    return [
        piece
        for item in items
        for piece in (split_equations(item) if isinstance(item, str) else [item])
    ]


def line_label(text: str) -> str | None:
    """The `name` of a line written `name = …`, read from its raw text (for a line that does
    not parse, to tell which quantity it was meant to give)."""
    m = _LABEL.match(text)
    return m.group(1) if m else None


def read(problem: Problem, item: Any, labels: Sequence[str] = (), mode: str = "answer") -> Read:
    """Parse one answer item with the project parser; sympy objects (from Python callers and
    tests, never from student text) pass through."""
    if isinstance(item, sp.Equality):
        return Read(problem.canonical(item.lhs), problem.canonical(item.rhs), plain(item))
    if isinstance(item, sp.Basic):
        return Read(problem.canonical(sp.S(item)), None, plain(item))
    if not isinstance(item, str):
        raise RequestError(f"an answer item must be a string, got {type(item).__name__}")
    p = parser()
    vocab = problem.vocabulary(labels)
    parse = {
        "answer": p.parse_answer,
        "equation": p.parse_equation,
        "expression": p.parse_expression,
    }
    return read_parsed(problem, parse[mode](item, vocab))


_notes: ContextVar[list[str] | None] = ContextVar("reading_notes", default=None)


@contextmanager
def reading_notes() -> Iterator[list[str]]:
    """Collect, while the block runs, what the parser says about how the answer was read
    (`k/m x` read as (k/m)·x, log read as ln), so that the verdict can say it too: a reading
    the student did not intend is then visible in the feedback, not only in a preview."""
    token = _notes.set([])
    try:
        yield _notes.get()  # type: ignore[misc]
    finally:
        _notes.reset(token)


def read_parsed(problem: Problem, parsed) -> Read:
    notes = _notes.get()
    if notes is not None:
        notes += [w for w in parsed.warnings if w not in notes]
    if problem.parser_symbols_are_mine:
        return Read(parsed.lhs, parsed.rhs, parsed.plain())
    rhs = None if parsed.rhs is None else problem.canonical(parsed.rhs)
    return Read(problem.canonical(parsed.lhs), rhs, parsed.plain())


_LABEL = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=")


def read_labelled(problem: Problem, item: Any, extra_labels: Sequence[str] = ()) -> Read:
    """An expression that may be written `name = expression` (p_x = …, h = …, L = …): the name
    is dropped. `expression = const` is accepted too."""
    labels = [n for n in [*extra_labels, "const", "constant"] if n not in problem.by_name]
    if isinstance(item, str):
        m = _LABEL.match(item)
        if m and m.group(1) not in problem.by_name and m.group(1) not in labels:
            labels.append(m.group(1))
    got = read(problem, item, labels)
    if got.rhs is None:
        return got
    if isinstance(got.lhs, sp.Symbol):  # a name for the quantity (h = …, even when h is a
        return Read(got.rhs, None, got.echo)  # parameter: "parameter = expression" says nothing)
    if isinstance(got.rhs, sp.Symbol) and str(got.rhs) in ("const", "constant"):
        return Read(got.lhs, None, got.echo)
    raise not_labelled(item)


def not_labelled(item: Any) -> ParseError:
    text = item if isinstance(item, str) else str(item)
    return ParseError(
        "Write this answer as an expression, or as name = expression.", (0, len(text)), text
    )


def read_single(problem: Problem, answer: Any, part: str, label: str) -> Read:
    items = items_of(answer, part)
    if len(items) != 1:
        raise RequestError(f"the answer to {part!r} is a single expression")
    return read_labelled(problem, items[0], (label,))


def own_lagrangian(problem: Problem, given: Mapping | None) -> sp.Expr | None:
    """The student's own L from `given`, when it parses (follow-through is best effort)."""
    if not given or "lagrangian" not in given:
        return None
    try:
        with reading_notes():  # the notes belong to the lagrangian part, not to this one
            expr = read_labelled(problem, given["lagrangian"], ("L",)).expr
    except (ParseError, RequestError):
        return None
    return None if has_acceleration(problem, expr) else expr


NONE_WORDS = {"none", "no", "-", "", "∅", "nothing"}


def has_acceleration(problem: Problem, expr: sp.Expr | Compiled) -> bool:
    symbols = expr.symbols if isinstance(expr, Compiled) else expr.free_symbols
    return any(j.ddot in symbols for j in problem.jets)
