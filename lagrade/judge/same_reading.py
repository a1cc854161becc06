"""The content of an answer's reading as a key, so that the driver can give an answer spelled
another way (spaces, `*` left out, `^` for `**`, θ for theta, LaTeX) the verdict of one read
the same way before, without judging it again.

The key holds everything the verdict of a part in `SAME_READING_PARTS` is a function of, for a
given question, part and `given`: each item's sides as the parser's tree (without positions),
its plain echo (the `interpreted` a verdict shows, and what feedback quotes: "Equation 2
(…)"), and the parser's notes in order (a wrong answer's feedback ends with them). The
checkers of these parts read the answer with the same reader (`read.READERS`) and see nothing
else of its text, so two answers with one key get one verdict, field for field.

`expression` is keyed only where its checker reads nothing of the text beside the reader
(`expression.judged_by_its_reading`: no `=`, no number with a unit, no degree sign).

Left out (no key, judged as before): the other parts, whose checkers read the raw text
beside the reader (`transformation`: its remark; `dof`, names, the oscillation parts), an
`expression` answer with a number and its unit, a degree sign or a value after `=`, an
answer with an unreadable line (the parser's message quotes the text and its caret), an item
whose reading was built as a sympy form (a time derivative, an additive constant), a tree
over `MAX_KEY_NODES` nodes and an answer over `MAX_KEYED_CHARS` characters.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import sympy as sp

from lagrade.errors import LagradeError
from lagrade.judge.parts.expression import judged_by_its_reading
from lagrade.judge.parts.reading import _ZERO_SIDE, Lines, Read, Side, reading_notes
from lagrade.judge.problem import Problem
from lagrade.judge.read import READERS

#: Parts whose checker judges the reader's result and nothing else of the answer's text.
SAME_READING_PARTS = frozenset(
    {
        "lagrangian",
        "T",
        "V",
        "eom",
        "momenta",
        "conserved",
        "hamiltonian",
        "hamilton_equations",
        "expression",
    }
)
#: The most tree nodes one key may hold: keying stays a fraction of the reading it follows.
MAX_KEY_NODES = 4_096
#: The most characters of answer text read for a key. On a miss the checker reads the answer
#: again, so a key costs one more reading; beyond this (far beyond a student's answer, within
#: the parser's limits) it is not worth that reading.
MAX_KEYED_CHARS = 4_000


class _NoKey(Exception):
    """The reading holds something the key cannot say exactly."""


def reading_key(problem: Problem, part: str, answer: Any) -> str | None:
    """The key of `answer`'s reading to `part` of `problem` (see the module's docstring), or
    None when the part or the reading has none. A student's text never raises here: what
    does not read has no key, and the checker says why."""
    if part not in SAME_READING_PARTS or _characters(answer) > MAX_KEYED_CHARS:
        return None
    if part == "expression" and not judged_by_its_reading(problem, answer):
        return None
    with reading_notes() as notes:
        try:
            got = READERS[part](problem, answer)
        except LagradeError:
            return None
    if part == "expression":  # a list of one item: the answer has no `=`
        if len(got) != 1:
            return None
        got = got[0]
    out: list[str] = []
    symbols: dict[Any, int] = {}
    try:
        _item(got, _Walk(out, symbols))
    except _NoKey:
        return None
    out += [_text("w", note) for note in notes]
    out += [_symbol(symbol) for symbol in symbols]  # in the order first met: canonical
    return "".join(out)


class _Walk:
    """Where a key is written: its tokens, the symbols met (each written once, at the end,
    and named by its number in the tree) and the nodes left to the budget."""

    __slots__ = ("out", "symbols", "left")

    def __init__(self, out: list[str], symbols: dict[Any, int]):
        self.out, self.symbols, self.left = out, symbols, MAX_KEY_NODES


def _characters(answer: Any) -> int:
    if isinstance(answer, str):
        return len(answer)
    if isinstance(answer, list | tuple):
        return sum(len(a) if isinstance(a, str) else MAX_KEYED_CHARS + 1 for a in answer)
    return MAX_KEYED_CHARS + 1  # no text: a caller's object, not keyed


def _item(got: Any, walk: _Walk) -> None:
    out = walk.out
    if isinstance(got, Lines):
        out.append(f"L{len(got.entries)}[")
        for entry in got.entries:
            if not isinstance(entry, Read):  # an unreadable line: its message quotes the text
                raise _NoKey
            _read(entry, walk)
        out.append("]")
    elif isinstance(got, Read):
        _read(got, walk)
    else:
        raise _NoKey


def _read(got: Read, walk: _Walk) -> None:
    out = walk.out
    out.append("R")
    for side in (got._lhs, got._rhs):  # the sides as read (Read keeps them private)
        if side is None:
            out.append("N")
        elif side is _ZERO_SIDE:
            out.append("Z")
        elif isinstance(side, Side):
            out.append("T")
            _tree(side.node, walk)
        else:  # a sympy form (built at once): not keyed
            raise _NoKey
    out.append(_text("E", str(got.echo)))


def _tree(root: Any, walk: _Walk) -> None:
    """The tree in a prefix code without its positions, one token per node: iterative, so that
    no tree is too deep for it."""
    out, symbols = walk.out, walk.symbols
    stack: list[Any] = [root]
    while stack:
        node = stack.pop()
        if isinstance(node, str):
            out.append(node)
            continue
        walk.left -= 1
        if walk.left < 0:
            raise _NoKey
        kind = node.kind
        if kind == "num":
            p, q = node.value
            if not (type(p) is int and type(q) is int and type(node.extra) is bool):
                raise _NoKey
            out.append(f"n{p}/{q}{'i' if node.extra else 'r'};")
        elif kind == "sym":
            if not isinstance(node.value, sp.Basic):  # a symbol, or the declared imaginary unit
                raise _NoKey
            out.append(f"s{symbols.setdefault(node.value, len(symbols))};")
        elif kind == "pi":
            out.append("p")
        elif kind in ("add", "mul"):
            children = list(node.value)
            out.append(f"{kind[0]}{len(children)}(")
            stack.append(")")
            stack.extend(reversed(children))
        elif kind in ("neg", "inv"):
            out.append(f"{kind[0]}(")
            stack += [")", node.value]
        elif kind == "pow":
            out.append("^(")
            stack += [")", node.extra, node.value]
        elif kind == "call":
            argument, power = node.extra
            # one argument is a Node (itself a tuple), several a tuple of Nodes
            arguments = [argument] if hasattr(argument, "kind") else list(argument)
            if not (isinstance(node.value, str) and (power is None or type(power) is int)):
                raise _NoKey
            out.append(_text("f", node.value) + f"{power}:{len(arguments)}(")
            stack.append(")")
            stack.extend(reversed(arguments))
        else:  # a time derivative is built at once; anything else is no reading we key
            raise _NoKey


@lru_cache(maxsize=1_024)  # a question has a few dozen symbols; srepr costs microseconds
def _symbol(value: sp.Basic) -> str:
    """A symbol (or the declared imaginary unit) exactly: its name and assumptions."""
    return _text("s", sp.srepr(value))


def _text(tag: str, text: str) -> str:
    """A length-prefixed string: no text can end it early or run into the next token."""
    return f"{tag}{len(text)}:{text}"
