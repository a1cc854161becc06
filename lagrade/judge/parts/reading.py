"""Reading a part's answer: the items `lagrade.judge.parts.items` split it into, each parsed by
the project parser in the question's vocabulary, labels (`p_x = …`, `L = …`) dropped, lists of
names read in any spelling, and the student's own L for follow-through."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Any

import sympy as sp

from lagrade.errors import ParseError, RequestError, UnsupportedExpression
from lagrade.judge.compiled import Compiled
from lagrade.judge.evaluate import compile_tree
from lagrade.judge.parts.ambiguity import note_ambiguous
from lagrade.judge.parts.items import single_text
from lagrade.judge.problem import Problem, parser
from lagrade.judge.verdict import unreadable_line
from lagrade.notation import NameRead, plain
from lagrade.recent import Recent


class Side:
    """One side of an answer as the parser read it: its tree, and its sympy form, built on first
    use (with the question's own symbols)."""

    __slots__ = ("node", "_make", "_expr")

    def __init__(self, node: Any, make: Callable[[], sp.Expr]):
        self.node = node
        self._make = make
        self._expr: sp.Expr | None = None

    @property
    def expr(self) -> sp.Expr:
        if self._expr is None:
            self._expr = self._make()
        return self._expr

    @property
    def label(self) -> str | None:
        """The name of the side when it is a single symbol (`p_x` in `p_x = …`)."""
        value = self.node.value if self.node.kind == "sym" else None
        return value.name if getattr(value, "is_Symbol", False) else None


_ZERO_SIDE: Any = object()  # the right side of a bare expression read as an equation


class Read:
    """One parsed answer item: lhs (a label symbol or an expression), rhs, and the echo. Read from
    the parser's tree, the checks compile it (`compiled`) and see its symbols (`symbols`)
    without sympy, which is built (`lhs`, `rhs`, `expr`) only where a step needs algebra: a
    diagnosis, a hint, a number worked out exactly."""

    __slots__ = ("_lhs", "_rhs", "echo", "_rename", "_compiled", "_expr")
    __slots__ += ("_symbols", "parsed")

    def __init__(
        self, lhs: Any, rhs: Any, echo: Any, rename: Mapping | None = None, parsed: Any = None
    ):
        self._lhs, self._rhs, self.echo = lhs, rhs, echo
        self._rename = rename or {}
        #: The parser's reading of the whole item (`lagrade.notation.Parsed`), whose typeset
        #: form a preview shows; None for sympy objects from Python callers.
        self.parsed = parsed
        self._compiled: Compiled | None = None
        self._expr: sp.Expr | None = None
        self._symbols: frozenset | None = None

    @staticmethod
    def _sympy(side: Any) -> sp.Expr | None:
        if side is _ZERO_SIDE:
            return sp.S.Zero
        return side.expr if isinstance(side, Side) else side

    @property
    def lhs(self) -> sp.Expr:
        return self._sympy(self._lhs)  # type: ignore[return-value]

    @property
    def rhs(self) -> sp.Expr | None:
        return self._sympy(self._rhs)

    @property
    def has_rhs(self) -> bool:
        return self._rhs is not None

    @property
    def expr(self) -> sp.Expr:
        if self._expr is None:
            self._expr = self.lhs if self._rhs is None else self.lhs - self.rhs
        return self._expr

    @staticmethod
    def _label(side: Any) -> str | None:
        if isinstance(side, Side):
            return side.label
        return side.name if isinstance(side, sp.Symbol) else None

    @property
    def label(self) -> str | None:
        """The name on the left when the left side is a single symbol (a label, p_x = …)."""
        return self._label(self._lhs)

    @property
    def rhs_label(self) -> str | None:
        return self._label(self._rhs) if self._rhs is not _ZERO_SIDE else None

    def only_lhs(self) -> Read:
        """The left side alone, with this item's echo."""
        return Read(self._lhs, None, self.echo, self._rename, self.parsed)

    def only_rhs(self) -> Read:
        """The right side alone, with this item's echo."""
        return Read(self._rhs, None, self.echo, self._rename, self.parsed)

    def _sides(self) -> list[tuple[Any, int]] | None:
        """(node, sign) of each side read from the tree; None when a side is sympy's."""
        sides = []
        for side, sign in ((self._lhs, 1), (self._rhs, -1)):
            if side is None or side is _ZERO_SIDE:
                continue
            if not isinstance(side, Side):
                return None
            sides.append((side.node, sign))
        return sides

    @property
    def compiled(self) -> Compiled:
        """The item (lhs − rhs) compiled by its top-level terms: from the tree when it was read
        from one (its sympy form built only if something asks for `expr`), else from its sympy
        form. Every decision and every number the feedback quotes reads this one program."""
        if self._compiled is None:
            sides = self._sides()
            program = compile_tree(sides, self._rename) if sides else None
            if program is None:
                self._compiled = Compiled.of(self.expr)
            else:
                self._compiled = Compiled(lambda: self.expr, program)
        return self._compiled

    @property
    def symbols(self) -> frozenset:
        """The symbols the item holds (the question's own)."""
        if self._symbols is None:
            sides = self._sides()
            if sides is None:
                self._symbols = frozenset(self.expr.free_symbols)
            else:
                found: set = set()
                for node, _sign in sides:
                    _collect(node, found)
                self._symbols = frozenset(self._rename.get(s, s) for s in found)
        return self._symbols


def _collect(node: Any, found: set) -> None:
    """The symbols of a tree (the declared imaginary unit is a number)."""
    kind = node.kind
    if kind == "sym":
        if getattr(node.value, "is_Symbol", False):
            found.add(node.value)
    elif kind in ("add", "mul"):
        for child in node.value:
            _collect(child, found)
    elif kind in ("neg", "inv"):
        _collect(node.value, found)
    elif kind == "pow":
        _collect(node.value, found)
        _collect(node.extra, found)
    elif kind == "call":
        argument = node.extra[0]
        for a in (argument,) if hasattr(argument, "kind") else argument:
            _collect(a, found)
    elif kind == "ddt":  # never unbuilt (the parser's screen), but its symbols are these
        _collect(node.value, found)


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
            unreadable_line(k + 1, e.error)
            for k, e in enumerate(self.entries)
            if isinstance(e, Unreadable)
        ]


def read_lines(items: Sequence[Any], reader: Callable[[Any], Read | list[Read]]) -> Lines:
    """The one place a list of answer lines is parsed: each item (`items.list_items`) by
    `reader`, a line that does not parse set aside as Unreadable so that the others are still
    judged. When no line reads at all, the parser's error is raised (the part is `invalid`, as
    for a one-line answer)."""
    entries: list[Read | Unreadable] = []
    for item in items:
        try:
            got = reader(item)
        except ParseError as error:
            entries.append(Unreadable(item if isinstance(item, str) else str(item), error))
            note_ambiguous(item, error)  # judged under its readings by `run_checker`
            continue
        entries.extend(got if isinstance(got, list) else [got])
    lines = Lines(tuple(entries))
    bad = lines.unreadable
    if bad and not lines.reads:
        if len(bad) == 1:
            raise bad[0].error
        raise ParseError("No line of this answer can be read.\n" + "\n".join(lines.feedback()))
    return lines


def line_label(problem: Problem, text: str) -> str | None:
    """The `name` of a line written `name = …`, in the spelling the parser reads it (`ℓ` is l,
    `p_θ` p_theta, `ℒ` L): a label is a name whatever its letters. Read from the raw text, so
    that it serves a line that does not parse too (to tell which quantity it was meant to
    give); None when the text before `=` is no single name."""
    m = _LABEL.match(text)
    if m is None:
        return None
    name = m.group(1)
    if _ASCII_NAME.match(name):
        return name
    try:
        (got,) = parser().read_names(name, problem.vocabulary())
    except (ParseError, ValueError):
        return None
    return got.name if got.order == 0 and _ASCII_NAME.match(got.name) else None


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
    latex = getattr(item, "latex", None)
    memo = _parses.get()
    if memo is None:
        return read_parsed(problem, parse[mode](item, vocab, latex=latex))
    key = (id(vocab), mode, str(item), latex)
    if key not in memo:
        try:
            memo[key] = parse[mode](item, vocab, latex=latex)
        except ParseError as error:
            memo[key] = error
    found = memo[key]
    if isinstance(found, ParseError):
        raise found
    return read_parsed(problem, found)


#: The parser's results for one request, by (vocabulary, mode, text, LaTeX flag), while
#: `parsed_once` runs: the driver reads an answer for its reading's key and the checker reads
#: it again, and the second reading is the first one's parse (the notes are added again by
#: `read_parsed`, which runs each time).
_parses: ContextVar[dict | None] = ContextVar("parses", default=None)


@contextmanager
def parsed_once() -> Iterator[None]:
    """Parse each text once while the block runs (one request's reading and judging)."""
    token = _parses.set({})
    try:
        yield
    finally:
        _parses.reset(token)


def read_names(problem: Problem, items: Sequence[Any], expected: str) -> list[NameRead]:
    """The names a list answer gives (coordinates, cyclic coordinates), each in any spelling the
    grammar reads (θ, \\theta, theta; θ₁, theta1, theta_1; θ̇, thetadot), through the parser's
    own lexicon. A name the question does not know is returned without a symbol; an item that
    is not names fails with `expected`."""
    names: list[NameRead] = []
    for item in items:
        if isinstance(item, sp.Symbol):  # from Python callers and tests, never student text
            text = item.name
        elif isinstance(item, str):
            text = item
        else:
            raise RequestError(f"an answer item must be a string, got {type(item).__name__}")
        names += parser().read_names(
            text, problem.vocabulary(), latex=getattr(item, "latex", None), expected=expected
        )
    return names


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
    mine = problem.parser_symbols_are_mine
    tree = parsed.tree
    if tree is not None:  # left unbuilt: sides that build their sympy form on demand
        canonical = (lambda e: e) if mine else problem.canonical
        lhs = Side(tree.lhs, lambda: canonical(parsed.lhs))
        rhs = (
            Side(tree.rhs, lambda: canonical(parsed.rhs))
            if tree.rhs is not None
            else (_ZERO_SIDE if tree.equation else None)
        )
        return Read(lhs, rhs, parsed.plain(), None if mine else problem.renaming, parsed)
    if mine:
        return Read(parsed.lhs, parsed.rhs, parsed.plain(), parsed=parsed)
    rhs = None if parsed.rhs is None else problem.canonical(parsed.rhs)
    return Read(problem.canonical(parsed.lhs), rhs, parsed.plain(), parsed=parsed)


#: `name =` at the start of a line, the name in any script (ℓ, p_θ, L_z, θ₁); `line_label` reads
#: it in the parser's spelling.
_LABEL = re.compile(r"^\s*([^\W\d][\w\u0300-\u036f]*)\s*=(?!=)")
_ASCII_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
#: A label with its arguments, as textbooks write it: `L(theta, theta_dot) = …`.
_LABEL_WITH_ARGUMENTS = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*\([^()=]*\)\s*=")
#: Names a student writes for an arbitrary additive constant (`L = T - V + const`).
ADDITIVE_CONSTANTS = ("const", "constant")


def read_labelled(problem: Problem, item: Any, extra_labels: Sequence[str] = ()) -> Read:
    """An expression that may be written `name = expression` (p_x = …, h = …, L = …): the name
    is dropped. `expression = const` is accepted too."""
    labels = [n for n in [*extra_labels, *ADDITIVE_CONSTANTS] if n not in problem.by_name]
    if isinstance(item, str):
        called = _LABEL_WITH_ARGUMENTS.match(item)
        if called and called.group(1) in extra_labels:
            # `L(theta, theta_dot) = …` is `L = …`, its arguments blanked so carets stay put
            name = called.group(1)
            item = name + " " * (called.end() - len(name) - 1) + "=" + item[called.end() :]
        name = line_label(problem, item)
        if name is not None and name not in problem.by_name and name not in labels:
            labels.append(name)
    got = read(problem, item, labels)
    if not got.has_rhs:
        return got
    if got.label is not None:  # a name for the quantity (h = …, even when h is a parameter:
        return got.only_rhs()  # "parameter = expression" says nothing)
    if got.rhs_label in ADDITIVE_CONSTANTS:
        return got.only_lhs()
    raise not_labelled(item)


def without_additive_constant(problem: Problem, got: Read) -> Read:
    """`got` with an arbitrary additive constant (`+ const`) set to zero, for the parts defined
    up to one (a Lagrangian, a potential): it changes no motion. A `const` that is not simply
    added (`const*x`) is left, and the evaluator says it has no value. The item's symbols (from
    its tree) tell whether there is one; only then is its sympy form built."""
    if not any(name in str(got.echo) for name in ADDITIVE_CONSTANTS):  # the usual case, at once
        return got
    constants = [
        symbol
        for symbol in got.symbols
        if str(symbol) in ADDITIVE_CONSTANTS and str(symbol) not in problem.by_name
    ]
    if not constants:
        return got
    expr = got.expr
    for symbol in constants:
        slope = expr.diff(symbol)
        if slope != 0 and not slope.free_symbols:
            expr = expr.subs(symbol, 0)
    return got if expr is got.expr else Read(expr, None, got.echo, parsed=got.parsed)


def not_labelled(item: Any) -> ParseError:
    text = item if isinstance(item, str) else str(item)
    return ParseError(
        "Write this answer as an expression, or as name = expression.", (0, len(text)), text
    )


def read_single(problem: Problem, answer: Any, part: str, label: str) -> Read:
    """The answer of a one-expression part (`items.single_text`), `label = …` allowed."""
    return read_labelled(problem, single_text(answer, part), (label,))


def own_lagrangian(problem: Problem, given: Mapping | None) -> Compiled | None:
    """The student's own L from `given`, compiled, when it parses (follow-through is best
    effort). None for a scene with dissipation or given forces: its motion is not the own L's
    alone, and an own L's motion would "conserve" what the damped motion does not.

    Read once per text and question structure (the vocabulary it is read with): every part
    of a sheet that follows through (equations, momenta, cyclic, conserved, …) reads the
    same L."""
    if not given or "lagrangian" not in given:
        return None
    if problem.variant is not None and problem.variant.scene.nonconservative:
        return None
    text = given["lagrangian"]
    if not isinstance(text, str):
        return _own_lagrangian(problem, text)
    kept = problem.shared.setdefault("_own_lagrangians", Recent(OWN_LAGRANGIANS_KEPT))
    return kept.made(text, lambda: _own_lagrangian(problem, text))


#: Own Lagrangians kept per question structure: a class's, read once for all their parts.
OWN_LAGRANGIANS_KEPT = 1_024


def _own_lagrangian(problem: Problem, text: Any) -> Compiled | None:
    try:
        with reading_notes():  # the notes belong to the lagrangian part, not to this one
            got = read_single(problem, text, "lagrangian", "L")
            own = got.compiled
    except (ParseError, RequestError, UnsupportedExpression):
        return None
    return None if has_acceleration(problem, own) else own


def has_acceleration(problem: Problem, expr: sp.Expr | Compiled | Read) -> bool:
    symbols = expr.symbols if isinstance(expr, Compiled | Read) else expr.free_symbols
    return any(j.ddot in symbols for j in problem.jets)
