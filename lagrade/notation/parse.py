"""Student answers → sympy, safely: our own grammar, declared symbols only, clear errors.

Student text never reaches eval, exec, sympify, parse_expr or sympy's LaTeX parsers. It is
normalised and tokenized (`grader.lexer`), LaTeX is first translated into the plain grammar
(`grader.latex`), a recursive-descent `Parser` whose methods are the rules of notation.md builds
a small tree of plain Python data, size limits are checked on that tree, and only then does
`_build` turn it into sympy through the one whitelist table `SYMPY_CONSTRUCTORS`.

Whatever the input, the public functions return a `Parsed` or raise `ParseError`.

    answer  := sum [ '=' sum ]
    sum     := ['+'|'-'] term (('+'|'-') term)*
    term    := unary ( ('*'|'/') unary | <juxtaposition> power )*
    unary   := '-' unary | power
    power   := atom [ ('^'|'**') unary ]            -- right-associative: 2^3^2 = 2^9
    atom    := number | '(' sum ')' | call | diff | name
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple, NoReturn

import sympy as sp

from lagrade.errors import ParseError, RequestError
from lagrade.mechanics import lagrange as mechanics
from lagrade.mechanics.domains import Domain
from lagrade.notation.echo import echo as _echo
from lagrade.notation.latex import translate
from lagrade.notation.lexer import Source, Token, normalise, read_number, tokenize
from lagrade.notation.printer import as_typed, render_latex

__all__ = [
    "Parsed",
    "ParseError",
    "Vocabulary",
    "parse_answer",
    "parse_equation",
    "parse_equations",
    "parse_expression",
]

#: The only door from the parser to sympy: tree node kinds and function names → constructors.
SYMPY_CONSTRUCTORS: dict[str, Callable[..., sp.Expr]] = {
    "add": sp.Add,
    "mul": sp.Mul,
    "pow": sp.Pow,
    "integer": sp.Integer,
    "rational": sp.Rational,
    "pi": lambda: sp.pi,
    "sin": sp.sin,
    "cos": sp.cos,
    "tan": sp.tan,
    "sec": sp.sec,
    "csc": sp.csc,
    "cot": sp.cot,
    "sinh": sp.sinh,
    "cosh": sp.cosh,
    "tanh": sp.tanh,
    "asin": sp.asin,
    "acos": sp.acos,
    "atan": sp.atan,
    "arcsin": sp.asin,
    "arccos": sp.acos,
    "arctan": sp.atan,
    "exp": sp.exp,
    "ln": sp.log,
    "log": sp.log,  # the natural logarithm, as in physics texts (a warning says so)
    "sqrt": sp.sqrt,
    "abs": sp.Abs,
}
FUNCTIONS = frozenset(SYMPY_CONSTRUCTORS) - {"add", "mul", "pow", "integer", "rational", "pi"}
_TRIG = frozenset(("sin", "cos", "tan", "sec", "csc", "cot", "sinh", "cosh", "tanh"))

# Limits against denial of service, all checked before sympy sees anything big.
MAX_LENGTH = 2_000  # characters per answer
MAX_TOTAL_LENGTH = 20_000  # characters in a list of equations
MAX_DEPTH = 50  # nesting of brackets, signs and powers
MAX_NODES = 2_000  # tree nodes per answer
MAX_EXPONENT = 100  # |numeric exponent|
MAX_NUMBER_BITS = 4_000  # size of an exact number produced by a power

_NOT_FINITE = "The answer is not a finite real expression."
_BAD_VALUES = (sp.zoo, sp.nan, sp.oo, -sp.oo, sp.I)
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_VELOCITY_SUFFIX = re.compile(r"(.+?)_?(d?dot)\Z")


# --- what a question lets a student write ------------------------------------------------------


class _Entry(NamedTuple):
    kind: str  # "sym" or "pi"
    value: sp.Expr
    jet: mechanics.Jet | None
    order: int  # 0 coordinate or plain symbol, 1 velocity, 2 acceleration


def _digit_variants(name: str) -> set[str]:
    """m1 ↔ m_1, theta12 ↔ theta_12: digit subscripts with or without the underscore."""
    return {name, re.sub(r"_(?=[0-9])", "", name), re.sub(r"(?<=[A-Za-z])(?=[0-9])", "_", name)}


@dataclass(frozen=True)
class Vocabulary:
    """What a question lets a student write: its coordinates (each with velocity and
    acceleration), its parameters as the very sympy symbols of the reference, extra labels
    (p_theta, L, h, …) and whether primes mean time derivatives."""

    coordinates: tuple[str, ...]
    parameters: Mapping[str, sp.Symbol]
    labels: tuple[str, ...] = ()
    allow_primes: bool = False

    def __post_init__(self) -> None:
        object.__setattr__(self, "coordinates", tuple(self.coordinates))
        object.__setattr__(self, "parameters", dict(self.parameters))
        object.__setattr__(self, "labels", tuple(self.labels))
        problems = []
        names = list(self.coordinates) + list(self.parameters) + list(self.labels)
        for name in names:
            if not isinstance(name, str) or not _NAME.match(name):
                problems.append(
                    f"{name!r} is not a name (letters, digits and _, starting with a letter)"
                )
        for name, symbol in self.parameters.items():
            if not isinstance(symbol, sp.Symbol):
                problems.append(f"parameter {name!r} must map to a sympy Symbol, not {symbol!r}")
        jet_names = [f"{c}{suffix}" for c in self.coordinates for suffix in ("", "_dot", "_ddot")]
        seen: set[str] = set()
        for name in jet_names + list(self.parameters) + list(self.labels):
            if name in seen:
                problems.append(f"{name!r} is declared twice")
            seen.add(name)
        if problems:
            raise RequestError("vocabulary is not valid: " + "; ".join(problems))

    def __hash__(self) -> int:
        return hash(
            (self.coordinates, tuple(self.parameters.items()), self.labels, self.allow_primes)
        )

    @classmethod
    def from_variant(
        cls, variant, labels: Iterable[str] = (), *, allow_primes: bool = False
    ) -> Vocabulary:
        """The vocabulary of a scene variant (`problem_bank.scene.SceneVariant`)."""
        return cls(
            tuple(variant.coordinates), dict(variant.parameter_symbols), tuple(labels), allow_primes
        )

    @classmethod
    def from_names(
        cls,
        coordinates: Iterable[str],
        parameters: Mapping[str, str | Domain] | Iterable[str],
        labels: Iterable[str] = (),
        *,
        allow_primes: bool = False,
    ) -> Vocabulary:
        """From names alone; parameter domains as strings ('positive', '(0, pi/2)'), and bare
        parameter names are positive (masses, lengths, g)."""
        if isinstance(parameters, Mapping):
            symbols = {
                name: Domain.parse(domain).symbol(name) for name, domain in parameters.items()
            }
        else:
            symbols = {name: Domain.parse("positive").symbol(name) for name in parameters}
        return cls(tuple(coordinates), symbols, tuple(labels), allow_primes)

    @cached_property
    def _lexicon(self) -> _Lexicon:
        return _Lexicon(self)


class _Lexicon:
    """Every spelling a vocabulary accepts, resolved once per Vocabulary."""

    def __init__(self, vocabulary: Vocabulary):
        self.allow_primes = vocabulary.allow_primes
        self.jets = [mechanics.jet(c) for c in vocabulary.coordinates]
        self.coordinates = vocabulary.coordinates
        exact: dict[str, _Entry] = {}
        for j in self.jets:
            exact[j.name] = _Entry("sym", j.q, j, 0)
            exact[j.dot.name] = _Entry("sym", j.dot, j, 1)
            exact[j.ddot.name] = _Entry("sym", j.ddot, j, 2)
        for name, symbol in vocabulary.parameters.items():
            exact[name] = _Entry("sym", symbol, None, 0)
        for name in vocabulary.labels:
            exact[name] = _Entry("sym", sp.Symbol(name, real=True), None, 0)
        table = dict(exact)
        for j in self.jets:
            for v in _digit_variants(j.name):
                table.setdefault(v, exact[j.name])
                for suffix, order in (("dot", 1), ("_dot", 1), ("ddot", 2), ("_ddot", 2)):
                    table.setdefault(
                        v + suffix, _Entry("sym", (j.q, j.dot, j.ddot)[order], j, order)
                    )
        for name in list(vocabulary.parameters) + list(vocabulary.labels):
            for v in _digit_variants(name):
                table.setdefault(v, exact[name])
        table.setdefault("t", _Entry("sym", mechanics.t, None, 0))
        table.setdefault("pi", _Entry("pi", sp.pi, None, 0))
        self.table = table
        self.longest = max(len(k) for k in table)
        allowed = list(vocabulary.parameters)
        for j in self.jets:
            allowed += [j.name, j.dot.name, j.ddot.name]
        allowed += list(vocabulary.labels) + ["t"]
        self.allowed = ", ".join(allowed)

    def is_function(self, name: str) -> bool:
        return name in FUNCTIONS and name not in self.table

    def split(self, name: str) -> list[str] | None:
        """Fewest declared names that spell `name` (mgl → m, g, l), or None."""
        if len(name) > 64:
            return None
        best: list[list[str] | None] = [None] * (len(name) + 1)
        best[0] = []
        for i in range(len(name)):
            if best[i] is None:
                continue
            for k in range(i + 1, min(len(name), i + self.longest) + 1):
                piece = name[i:k]
                if piece in self.table:
                    candidate = best[i] + [piece]  # type: ignore[operator]
                    if best[k] is None or len(candidate) < len(best[k]):  # type: ignore[arg-type]
                        best[k] = candidate
        found = best[len(name)]
        return found if found is not None and len(found) > 1 else None


# --- the result ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class Parsed:
    """A parsed answer: an expression (rhs None) or an equation lhs = rhs, the names found, and
    warnings about readings the student may want to check."""

    source: str
    lhs: sp.Expr
    rhs: sp.Expr | None
    symbols: frozenset[str]
    warnings: tuple[str, ...] = ()
    echo: str = ""  # the plain reading, written from the parse tree (see grader.echo)

    @property
    def expr(self) -> sp.Expr:
        """The expression, or lhs − rhs for an equation (which then means expr = 0)."""
        return self.lhs if self.rhs is None else self.lhs - self.rhs

    @property
    def is_equation(self) -> bool:
        return self.rhs is not None

    def plain(self) -> str:
        """Echo with explicit * and ^ in the student's order, e.g.
        'm*R^2*theta_ddot - m*g*R*sin(theta) = 0'."""
        if self.echo:
            return self.echo
        if self.rhs is None:
            return as_typed(self.lhs)
        return f"{as_typed(self.lhs)} = {as_typed(self.rhs)}"

    def latex(self) -> str:
        """LaTeX with dots over derivatives (\\dot{\\theta}, \\ddot{x}_{M}) and \\cdot products."""
        if self.rhs is None:
            return render_latex(self.lhs)
        return f"{render_latex(self.lhs)} = {render_latex(self.rhs)}"


# --- the tree the parser builds (plain Python data, no sympy) ---------------------------------


class Node(NamedTuple):
    """kind: num (value (p, q), extra: written as an integer), sym (value: Symbol), pi,
    add/mul (value: list of nodes), inv (1/value, inside mul), neg, pow (value ^ extra),
    call (value: function name, extra: (argument, integer power or None))."""

    kind: str
    start: int
    end: int
    value: object = None
    extra: object = None


_TERM_END = frozenset(("+", "-", ")", "=", ",", ";"))


class Parser:
    """Recursive descent over the tokens of one answer; one method per grammar rule."""

    def __init__(self, src: Source, lexicon: _Lexicon):
        self.src = src
        self.text = src.text
        self.lexicon = lexicon
        self.tokens = tokenize(src)
        self.pos = 0
        self.depth = 0
        self.nodes = 0
        self.found: set[str] = set()
        self.warnings: list[str] = []

    # --- helpers ------------------------------------------------------------------------------
    def fail(self, message: str, start: int, end: int, hint: str | None = None) -> NoReturn:
        self.src.fail(message, start, end, hint)

    def peek(self, ahead: int = 0) -> Token:
        index = self.pos + ahead
        return self.tokens[index] if index < len(self.tokens) else self.tokens[-1]

    def next(self) -> Token:
        tok = self.tokens[self.pos]
        self.pos += 1
        return tok

    def node(
        self, kind: str, start: int, end: int, value: object = None, extra: object = None
    ) -> Node:
        self.nodes += 1
        if self.nodes > MAX_NODES:
            self.fail(f"The answer is too complex (more than {MAX_NODES} parts).", start, end)
        return Node(kind, start, end, value, extra)

    def enter(self, tok: Token) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(
                f"The answer is nested too deeply (more than {MAX_DEPTH} levels).",
                tok.start,
                tok.end,
            )

    def column(self, index: int) -> int:
        """1-based position in the student's text, for messages."""
        return self.src.locate(index, index + 1)[0] + 1

    def missing_close(self, opening: Token) -> str:
        return f"Missing ')': the '(' at position {self.column(opening.start)} is never closed."

    def operand_after(self, op: Token) -> None:
        """After an operator, something must follow."""
        tok = self.peek()
        if tok.kind == "end":
            self.fail(
                f"The answer ends with '{op.text}'; something is missing after it.",
                op.start,
                op.end,
            )
        if tok.kind == "op" and tok.text not in ("(", "-"):
            self.fail(
                f"Expected a term after '{op.text}' but found '{tok.text}'.", op.start, tok.end
            )

    def unexpected(self, tok: Token) -> NoReturn:
        if tok.kind == "end":
            self.fail("Expected a term but the answer ended.", tok.start, tok.end)
        if tok.text == ")":
            self.fail("Unmatched ')'.", tok.start, tok.end)
        if tok.text == "=":
            self.fail("Something is missing before '='.", tok.start, tok.end)
        if tok.text == ";":
            self.fail(
                "Only one answer is expected here; put each equation on its own line.",
                tok.start,
                tok.end,
            )
        if tok.text == ",":
            self.fail("Unexpected ','.", tok.start, tok.end)
        if self.pos == 0:
            self.fail(
                f"The answer starts with '{tok.text}'; something is missing before it.",
                tok.start,
                tok.end,
            )
        self.fail(f"Unexpected '{tok.text}'.", tok.start, tok.end)

    # --- grammar ------------------------------------------------------------------------------
    def parse_answer(self, mode: str) -> tuple[Node, Node | None]:
        """answer := sum ['=' sum]; mode 'expression' forbids the '='."""
        self.check_leibniz()
        if self.peek().kind == "end":
            self.fail("The answer is empty.", 0, len(self.text))
        lhs = self.parse_sum()
        rhs = None
        tok = self.peek()
        if tok.text == "=":
            if mode == "expression":
                self.fail(
                    "Expected an expression, not an equation; "
                    "write only the expression, without '='.",
                    tok.start,
                    tok.end,
                )
            self.next()
            if self.peek().kind == "end":
                self.fail(
                    "The answer ends with '='; write what it equals (0 if nothing).",
                    tok.start,
                    tok.end,
                )
            rhs = self.parse_sum()
            tok = self.peek()
            if tok.text == "=":
                self.fail("Use a single '=' for an equation.", tok.start, tok.end)
        if tok.kind != "end":
            self.unexpected(tok)
        return lhs, rhs

    def parse_sum(self) -> Node:
        """sum := ['+'|'-'] term (('+'|'-') term)*"""
        first = self.peek()
        terms = []
        negative = False
        if first.text in ("+", "-"):
            self.next()
            self.operand_after(first)
            negative = first.text == "-"
        term = self.parse_term()
        terms.append(self.node("neg", first.start, term.end, term) if negative else term)
        while self.peek().text in ("+", "-"):
            op = self.next()
            self.operand_after(op)
            term = self.parse_term()
            terms.append(self.node("neg", op.start, term.end, term) if op.text == "-" else term)
        if len(terms) == 1:
            return terms[0]
        return self.node("add", terms[0].start, terms[-1].end, terms)

    def parse_term(self) -> Node:
        """term := unary ( ('*'|'/') unary | <juxtaposition> power )*"""
        first = self.parse_unary()
        factors = [first]
        after_division = False
        while True:
            tok = self.peek()
            if tok.text in ("*", "/"):
                self.next()
                self.operand_after(tok)
                factor = self.parse_unary()
                if tok.text == "*":
                    factors.append(factor)
                    after_division = False
                else:
                    factors.append(self.node("inv", factor.start, factor.end, factor))
                    after_division = True
            elif tok.kind in ("num", "name") or tok.text == "(":
                if tok.kind == "num" and self.tokens[self.pos - 1].kind == "num":
                    a, b = self.tokens[self.pos - 1].text, tok.text
                    if not tok.spaced:
                        start = self.tokens[self.pos - 1].start
                        self.fail(f"Cannot read the number '{a}{b}'.", start, tok.end)
                    self.fail(
                        f"Two numbers side by side; write {a}{b} or {a}*{b}.",
                        self.tokens[self.pos - 1].start,
                        tok.end,
                    )
                if after_division and not self.is_integer_fraction(factors):
                    self.ambiguous_division(first.start, factors[-1])
                factors.append(self.parse_power())
                after_division = False
            else:
                break
        if len(factors) == 1:
            return first
        return self.node("mul", first.start, factors[-1].end, factors)

    @staticmethod
    def is_integer_fraction(factors: list[Node]) -> bool:
        """1/2 m v^2: an integer over an integer may be followed by more factors."""
        if len(factors) != 2:
            return False
        top, bottom = factors[0], factors[1].value
        return top.kind == "num" and top.extra and bottom.kind == "num" and bottom.extra  # type: ignore[union-attr]

    def ambiguous_division(self, term_start: int, divisor: Node) -> NoReturn:
        following = self.parse_power()
        left = self.text[term_start : divisor.start].rstrip().rstrip("/").rstrip()
        under = self.text[divisor.start : divisor.end]
        after = self.text[following.start : following.end]
        self.fail(
            f"Ambiguous division: write {left}/({under}*{after}) or ({left}/{under})*{after}.",
            term_start,
            following.end,
        )

    def parse_unary(self) -> Node:
        """unary := '-' unary | power"""
        tok = self.peek()
        self.enter(tok)
        if tok.text == "-":
            self.next()
            self.operand_after(tok)
            operand = self.parse_unary()
            result = self.node("neg", tok.start, operand.end, operand)
        else:
            result = self.parse_power()
        self.depth -= 1
        return result

    def parse_power(self) -> Node:
        """power := atom [('^'|'**') unary], right-associative."""
        base = self.parse_atom()
        tok = self.peek()
        if tok.text not in ("^", "**"):
            return base
        self.next()
        self.operand_after(tok)
        exponent = self.parse_unary()
        literal = exponent.value if exponent.kind == "num" else None
        if exponent.kind == "neg" and exponent.value.kind == "num":  # type: ignore[union-attr]
            literal = exponent.value.value  # type: ignore[union-attr]
        if literal is not None and abs(literal[0]) > MAX_EXPONENT * literal[1]:  # type: ignore[index]
            self.fail(
                f"Exponent too large: at most {MAX_EXPONENT} in absolute value.",
                exponent.start,
                exponent.end,
            )
        return self.node("pow", base.start, exponent.end, base, exponent)

    def parse_atom(self) -> Node:
        """atom := number | '(' sum ')' | call | diff | name"""
        tok = self.peek()
        if tok.kind == "num":
            self.next()
            p, q, whole = read_number(tok, self.src)
            return self.node("num", tok.start, tok.end, (p, q), whole)
        if tok.text == "(":
            return self.parse_group()
        if tok.kind == "name":
            if tok.text == "diff" and "diff" not in self.lexicon.table:
                return self.parse_diff()
            if self.lexicon.is_function(tok.text):
                return self.parse_call()
            self.next()
            return self.parse_name(tok)
        self.unexpected(tok)

    def parse_group(self) -> Node:
        """'(' sum ')'"""
        opening = self.next()
        self.enter(opening)
        tok = self.peek()
        if tok.text == ")":
            self.fail("Empty brackets '()'.", opening.start, tok.end)
        if tok.kind == "end":
            self.fail(
                f"Missing ')': the '(' at position {self.column(opening.start)} is never closed.",
                opening.start,
                opening.end,
            )
        inner = self.parse_sum()
        closing = self.peek()
        if closing.text != ")":
            if closing.kind == "end":
                self.fail(
                    self.missing_close(opening),
                    opening.start,
                    opening.end,
                )
            self.unexpected(closing)
        self.next()
        self.depth -= 1
        return inner._replace(start=opening.start, end=closing.end)

    def parse_call(self) -> Node:
        """call := FUNC ['^' INTEGER] ('(' sum ')' | simple_arg)"""
        tok = self.next()
        name = tok.text
        if tok.marks or tok.primes:
            self.fail(
                f"'{name}' is a function; it cannot carry a dot or a prime.", tok.start, tok.end
            )
        if name == "log":
            self.warn("log is read as the natural logarithm ln.")
        power = None
        if self.peek().text in ("^", "**"):
            op = self.next()
            nxt = self.peek()
            if nxt.kind == "num" and nxt.text.isdigit() and 0 < int(nxt.text) <= MAX_EXPONENT:
                power = int(nxt.text)
                self.next()
            elif nxt.text == "-" or (nxt.text == "(" and self.peek(1).text == "-"):
                fix = f"a{name}(x) or 1/{name}(x)" if name in _TRIG else f"1/{name}(x)"
                self.fail(f"{name}^-1 is ambiguous; write {fix}.", tok.start, nxt.end)
            else:
                self.fail(
                    f"After '{name}^' write a whole number, as in {name}^2(x), "
                    f"or put the power after the argument: {name}(x)^n.",
                    op.start,
                    nxt.end,
                )
        nxt = self.peek()
        if nxt.text == "(":
            argument = self.parse_group()
        elif (
            nxt.kind in ("name", "num")
            and not self.lexicon.is_function(nxt.text)
            and nxt.text != "diff"
        ):
            argument = self.parse_simple_argument()
            self.check_bare_argument(tok, power, argument)
        elif nxt.kind == "end":
            self.fail(f"Expected '(' after '{name}' but the answer ended.", tok.start, tok.end)
        else:
            self.fail(
                f"Write the argument of '{name}' in brackets, as in {name}(x).", tok.start, nxt.end
            )
        return self.node("call", tok.start, argument.end, name, (argument, power))

    def parse_simple_argument(self) -> Node:
        tok = self.next()
        if tok.kind == "num":
            p, q, whole = read_number(tok, self.src)
            return self.node("num", tok.start, tok.end, (p, q), whole)
        return self.parse_name(tok)

    def check_bare_argument(self, function: Token, power: int | None, argument: Node) -> None:
        """`sin theta` must end its term or be followed by another function: `sin omega t`,
        `sin 2 theta`, `cos theta^2` are ambiguous."""
        tok = self.peek()
        if tok.kind == "end" or tok.text in _TERM_END:
            return
        if tok.kind == "name" and self.lexicon.is_function(tok.text):
            return
        if (
            tok.text == "*"
            and self.peek(1).kind == "name"
            and self.lexicon.is_function(self.peek(1).text)
        ):
            return
        name = function.text + (f"^{power}" if power else "")
        arg = self.text[argument.start : argument.end]
        if tok.text in ("^", "**"):
            self.next()
            self.operand_after(tok)
            following = self.parse_unary()
            rest = self.text[tok.start : following.end]
            fix = f"{name}({arg}{rest}) or {name}({arg}){rest}"
        elif tok.text in ("*", "/"):
            self.next()
            self.operand_after(tok)
            following = self.parse_power()
            rest = tok.text + self.text[following.start : following.end]
            fix = f"{name}({arg}{rest}) or {name}({arg}){rest}"
        else:
            following = self.parse_power()
            rest = self.text[following.start : following.end]
            fix = f"{name}({arg}*{rest}) or {name}({arg})*{rest}"
        self.fail(
            f"Ambiguous '{function.text}' without brackets: write {fix}.",
            function.start,
            following.end,
        )

    def parse_diff(self) -> Node:
        """diff := 'diff' '(' name ',' 't' [',' INTEGER] ')'"""
        tok = self.next()
        if self.peek().text != "(":
            self.fail("Write diff(x, t) with brackets.", tok.start, tok.end)
        opening = self.next()
        target = self.peek()
        if target.kind != "name":
            self.fail(
                "diff(...) takes a coordinate and t, as in diff(theta, t).", tok.start, target.end
            )
        self.next()
        self.skip_of_t()
        comma = self.peek()
        if comma.text != ",":
            if comma.text == ")":
                self.fail(
                    f"diff(...) needs the variable t: write diff({target.text}, t).",
                    tok.start,
                    comma.end,
                )
            self.fail(
                "diff(...) takes a single coordinate, as in diff(theta, t).",
                target.start,
                comma.end,
            )
        self.next()
        var = self.peek()
        if not (var.kind == "name" and var.text == "t" and not var.marks and not var.primes):
            self.fail("diff(...) is only allowed with respect to t.", var.start, var.end)
        self.next()
        order = 1
        if self.peek().text == ",":
            self.next()
            n = self.peek()
            if not (n.kind == "num" and n.text in ("1", "2")):
                self.fail("The order in diff(x, t, n) must be 1 or 2.", n.start, n.end)
            order = int(n.text)
            self.next()
        closing = self.peek()
        if closing.text != ")":
            if closing.kind == "end":
                self.fail(
                    self.missing_close(opening),
                    opening.start,
                    opening.end,
                )
            self.fail("Expected ')' to close diff(...).", closing.start, closing.end)
        self.next()
        entry = self.lookup(target)
        if entry.jet is None:
            self.not_a_coordinate(target.text, target)
        return self.derivative(entry, entry.order + target.marks + order, tok.start, closing.end)

    def followed_by_of_t(self) -> bool:
        """'(t)' right after a name, without a space: theta(t)."""
        opening = self.peek()
        return (
            opening.text == "("
            and not opening.spaced
            and self.peek(1).text == "t"
            and self.peek(2).text == ")"
        )

    def skip_of_t(self) -> bool:
        """Consume '(t)' after a coordinate (theta(t) is theta)."""
        if self.followed_by_of_t():
            self.pos += 3
            return True
        return False

    # --- names --------------------------------------------------------------------------------
    def lookup(self, tok: Token) -> _Entry:
        entry = self.lexicon.table.get(tok.text)
        if entry is None:
            self.unknown(tok)
        if tok.primes and not self.lexicon.allow_primes:
            base = entry.jet.name if entry.jet is not None else tok.text
            if entry.order + tok.marks + tok.primes == 1:
                fix = f"write {base}dot for d{base}/dt"
            else:
                fix = f"write {base}ddot for the second derivative"
            self.fail(f"Primes are ambiguous in mechanics; {fix}.", tok.start, tok.end)
        return entry

    def parse_name(self, tok: Token) -> Node:
        entry = self.lookup(tok)
        extra = tok.marks + tok.primes
        if extra and entry.jet is None:
            self.not_a_coordinate(tok.text, tok)
        if entry.kind == "pi":
            return self.node("pi", tok.start, tok.end)
        if extra:
            return self.derivative(entry, entry.order + extra, tok.start, tok.end)
        end = tok.end
        if self.followed_by_of_t():
            if entry.jet is None:
                self.fail(
                    f"'{tok.text}(t)' reads as a function of time, but {tok.text} is not a "
                    f"coordinate; write {tok.text}*t for a product.",
                    tok.start,
                    self.peek(2).end,
                )
            end = self.peek(2).end
            self.skip_of_t()
            self.warn(f"{tok.text}(t) is read as {tok.text}.")
        self.found.add(entry.value.name)  # type: ignore[attr-defined]
        return self.node("sym", tok.start, end, entry.value)

    def derivative(self, entry: _Entry, order: int, start: int, end: int) -> Node:
        jet = entry.jet
        assert jet is not None
        if order > 2:
            self.fail(
                "Only velocities and accelerations exist here: "
                f"that is a derivative of order {order} of {jet.name}.",
                start,
                end,
            )
        symbol = (jet.q, jet.dot, jet.ddot)[order]
        self.found.add(symbol.name)
        return self.node("sym", start, end, symbol)

    def not_a_coordinate(self, name: str, tok: Token) -> NoReturn:
        coordinates = ", ".join(self.lexicon.coordinates) or "none"
        self.fail(
            f"'{name}' is not a coordinate of this problem (coordinates: {coordinates}).",
            tok.start,
            tok.end,
        )

    def unknown(self, tok: Token) -> NoReturn:
        name = tok.text
        velocity = _VELOCITY_SUFFIX.match(name)
        if velocity and name not in ("ddot", "_dot", "_ddot"):
            stem = velocity.group(1).rstrip("_")
            entry = self.lexicon.table.get(stem)
            if stem and (entry is None or entry.jet is None) and not self.lexicon.split(name):
                self.not_a_coordinate(stem, tok)
        parts = self.lexicon.split(name)
        if parts:
            self.fail(
                f"Unknown symbol '{name}'. Did you mean {'*'.join(parts)}? "
                "Separate variables with * or a space.",
                tok.start,
                tok.end,
            )
        for function in sorted(FUNCTIONS, key=len, reverse=True):
            rest = name[len(function) :]
            if name.startswith(function) and rest:
                inner = (
                    rest if rest in self.lexicon.table else "*".join(self.lexicon.split(rest) or ())
                )
                if inner:
                    self.fail(
                        f"Unknown symbol '{name}'. Did you mean {function}({inner})?",
                        tok.start,
                        tok.end,
                    )
        hint = None
        if name == "e":
            hint = "e is not Euler's number here; write exp(x) for the exponential."
        elif name in ("I", "E"):
            hint = f"{name} means something only when the question declares it."
        self.fail(
            f"Unknown symbol '{name}'. Allowed: {self.lexicon.allowed}.", tok.start, tok.end, hint
        )

    def check_leibniz(self) -> None:
        """dx/dt, d/dt(...), dtheta/dt, d^2x/dt^2: rejected before names are looked up."""
        table = self.lexicon.table
        tokens = self.tokens
        for i, tok in enumerate(tokens):
            if tok.kind != "name" or tok.text in table:
                continue
            leibniz = (
                (tok.text == "dt" and i > 0 and tokens[i - 1].text == "/")
                or (tok.text == "d" and tokens[i + 1].text == "/")
                or (
                    tok.text == "d"
                    and i > 0
                    and tokens[i - 1].text == "/"
                    and tokens[i + 1].text == "t"
                )
            )
            if not leibniz:
                continue
            what = "x"
            for k in [*range(i - 1, max(-1, i - 6), -1), *range(i + 1, min(len(tokens), i + 6))]:
                candidate = tokens[k].text
                entry = table.get(candidate[1:]) if candidate.startswith("d") else None
                if entry is None:
                    entry = table.get(candidate)
                if entry is not None and entry.jet is not None:
                    what = entry.jet.name
                    break
            start = tokens[i - 2].start if i >= 2 and tokens[i - 1].text == "/" else tok.start
            end = tok.end
            if tok.text == "d" and tokens[i + 1].text == "/":
                end = tokens[i + 2].end
            self.fail(
                f"Leibniz notation is not supported; write {what}dot or diff({what}, t).",
                start,
                end,
            )

    def warn(self, message: str) -> None:
        if message not in self.warnings:
            self.warnings.append(message)


# --- tree → sympy, through the whitelist only ---------------------------------------------------


def _build(node: Node, src: Source) -> sp.Expr:
    kind = node.kind
    make = SYMPY_CONSTRUCTORS
    if kind == "sym":
        return node.value  # type: ignore[return-value]
    if kind == "num":
        p, q = node.value  # type: ignore[misc]
        return make["integer"](p) if q == 1 else make["rational"](p, q)
    if kind == "add":
        return make["add"](*[_build(term, src) for term in node.value])  # type: ignore[union-attr]
    if kind == "mul":
        return make["mul"](*[_factor(f, src) for f in node.value])  # type: ignore[union-attr]
    if kind == "neg":
        inner = node.value
        if inner.kind == "mul":  # type: ignore[union-attr]
            return make["mul"](sp.S.NegativeOne, *[_factor(f, src) for f in inner.value])  # type: ignore[union-attr]
        return make["mul"](sp.S.NegativeOne, _build(inner, src))  # type: ignore[arg-type]
    if kind == "pow":
        return _power(_build(node.value, src), _build(node.extra, src), node, src)  # type: ignore[arg-type]
    if kind == "call":
        argument, power = node.extra  # type: ignore[misc]
        result = make[node.value](_build(argument, src))  # type: ignore[index]
        return result if power is None else make["pow"](result, make["integer"](power))
    if kind == "pi":
        return make["pi"]()
    raise AssertionError(f"unknown node kind {kind!r}")


def _factor(node: Node, src: Source) -> sp.Expr:
    if node.kind == "inv":
        return _power(_build(node.value, src), sp.S.NegativeOne, node, src)  # type: ignore[arg-type]
    return _build(node, src)


def _power(base: sp.Expr, exponent: sp.Expr, node: Node, src: Source) -> sp.Expr:
    """base^exponent, refusing numbers too large to compute and roots of negative numbers."""
    if exponent.is_Rational:
        if abs(exponent) > MAX_EXPONENT:
            src.fail(
                f"Exponent too large: at most {MAX_EXPONENT} in absolute value.",
                node.start,
                node.end,
            )
        if base.is_Rational:
            if exponent.is_Integer:
                bits = max(abs(base.p).bit_length(), base.q.bit_length()) * abs(int(exponent))
                if bits > MAX_NUMBER_BITS:
                    src.fail(
                        "This power gives a number too large to work with.", node.start, node.end
                    )
            elif base.is_negative:
                src.fail(_NOT_FINITE, node.start, node.end)
    return SYMPY_CONSTRUCTORS["pow"](base, exponent)


# --- the public functions -----------------------------------------------------------------------


def _is_latex(text: str) -> bool:
    """Auto-detection: a backslash, $…$ delimiters, or a braced power x^{2} mean LaTeX."""
    stripped = text.strip()
    return "\\" in text or "^{" in text or (stripped.startswith("$") and stripped.endswith("$"))


def _parse_source(src: Source, vocabulary: Vocabulary, latex: bool | None, mode: str) -> Parsed:
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
    lhs = _build(lhs_node, src)
    rhs = _build(rhs_node, src) if rhs_node is not None else None
    if mode == "equation" and rhs is None:
        rhs = sp.S.Zero
    for side, node in ((lhs, lhs_node), (rhs, rhs_node)):
        if side is not None and side.has(*_BAD_VALUES):
            start, end = (node.start, node.end) if node is not None else (0, len(src.text))
            src.fail(_NOT_FINITE, start, end)
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
