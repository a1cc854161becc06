"""The parser's footing: a cursor over one answer's tokens (`peek`, `next`), the node counter and
depth gauge that enforce the size limits, and the messages for a token in the wrong place.
`fail` is how every rule reports a student's mistake."""

from __future__ import annotations

from typing import NoReturn

from lagrade.notation.lexer import Source, Token, tokenize
from lagrade.notation.limits import MAX_DEPTH, MAX_NODES
from lagrade.notation.nodes import Node
from lagrade.notation.vocabulary import Lexicon

_new = tuple.__new__


class TokenStream:
    """The tokens of one answer and the position in them, with what the grammar's rules share:
    the names found, the warnings, and the limits on size and nesting."""

    def __init__(self, src: Source, lexicon: Lexicon):
        self.src = src
        self.text = src.text
        self.lexicon = lexicon
        self.tokens = tokenize(src)
        self.pos = 0
        self.depth = 0
        self.bars = 0  # absolute-value bars open around the current position
        self.nodes = 0
        self.extremum_arguments = 0  # arguments of Max and Min so far (limits.py)
        self.found: set[str] = set()
        self.warnings: list[str] = list(src.notes)

    def fail(
        self,
        message: str,
        start: int,
        end: int,
        hint: str | None = None,
        readings: tuple[tuple[str, str], ...] = (),
    ) -> NoReturn:
        """A student's mistake at characters start…end of the text being read."""
        self.src.fail(message, start, end, hint, readings)

    def peek(self, ahead: int = 0) -> Token:
        """The token `ahead` places on, or the end token past it. The rules read the current
        token as `self.tokens[self.pos]` where they are hot: `pos` never passes the end token,
        which no rule consumes."""
        try:
            return self.tokens[self.pos + ahead]
        except IndexError:
            return self.tokens[-1]

    def next(self) -> Token:
        tok = self.tokens[self.pos]
        self.pos += 1
        return tok

    def node(
        self, kind: str, start: int, end: int, value: object = None, extra: object = None
    ) -> Node:
        """A new tree node, counted against MAX_NODES (made with `tuple.__new__`, which skips the
        Python-level `Node.__new__`: the parser makes one per atom and operator)."""
        self.nodes += 1
        if self.nodes > MAX_NODES:
            self.fail(f"The answer is too complex (more than {MAX_NODES} parts).", start, end)
        return _new(Node, (kind, start, end, value, extra))

    def enter(self, tok: Token) -> None:
        """One level deeper (a bracket, a sign, an exponent), counted against MAX_DEPTH; the
        rule that enters also leaves (`self.depth -= 1`)."""
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
        """After an operator, something must follow: a term, a bracket, a sign, or outside
        bars a '|' that opens an absolute value (`m + |x|`)."""
        tok = self.peek()
        if tok.kind == "end":
            self.fail(
                f"The answer ends with '{op.text}'; something is missing after it.",
                op.start,
                op.end,
            )
        if (
            tok.kind == "op"
            and tok.text not in ("(", "-")
            and not (tok.text == "|" and not self.bars)
        ):
            self.fail(
                f"Expected a term after '{op.text}' but found '{tok.text}'.", op.start, tok.end
            )

    def unexpected(self, tok: Token) -> NoReturn:
        """The message for a token no rule can take here, in the student's words."""
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

    def warn(self, message: str) -> None:
        """A reading the student may want to check; each message once."""
        if message not in self.warnings:
            self.warnings.append(message)
