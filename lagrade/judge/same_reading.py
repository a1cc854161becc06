"""The content of an answer's reading as a key, so that the driver can give an answer spelled
another way (spaces, `*` left out, `^` for `**`, θ for theta, LaTeX) the verdict of one read
the same way before, without judging it again.

The key holds everything the verdict of a part in `SAME_READING_PARTS` is a function of, for a
given question, part and `given`: each item's sides as the parser's tree (without positions),
its plain echo (the `interpreted` a verdict shows, and what feedback quotes: "Equation 2
(…)"), and the parser's notes in order (a wrong answer's feedback ends with them). The
checkers of these parts read the answer with the same reader (`read.READERS`) and see nothing
else of its text, so two answers with one key get one verdict, field for field.

Left out (no key, judged as before): the other parts, whose checkers read the raw text
beside the reader (`expression`: a unit or a degree sign; `transformation`: its remark;
`dof`, names, the oscillation parts), an answer with an unreadable line (the parser's message
quotes the text and its caret), an item whose reading was built as a sympy form (a time
derivative, an additive constant), and a tree over `MAX_KEY_NODES` nodes.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import sympy as sp

from lagrade.errors import LagradeError
from lagrade.judge.parts.reading import _ZERO_SIDE, Lines, Read, Side, reading_notes
from lagrade.judge.problem import Problem
from lagrade.judge.read import READERS

#: Parts whose checker judges the reader's result and nothing else of the answer's text.
SAME_READING_PARTS = frozenset(
    {"lagrangian", "T", "V", "eom", "momenta", "conserved", "hamiltonian", "hamilton_equations"}
)
#: The most tree nodes one key may hold: keying stays a fraction of the reading it follows.
MAX_KEY_NODES = 4_096


class _NoKey(Exception):
    """The reading holds something the key cannot say exactly."""


def reading_key(problem: Problem, part: str, answer: Any) -> str | None:
    """The key of `answer`'s reading to `part` of `problem` (see the module's docstring), or
    None when the part or the reading has none. A student's text never raises here: what
    does not read has no key, and the checker says why."""
    if part not in SAME_READING_PARTS:
        return None
    with reading_notes() as notes:
        try:
            got = READERS[part](problem, answer)
        except LagradeError:
            return None
    out: list[str] = []
    try:
        _item(got, out, [MAX_KEY_NODES])
    except _NoKey:
        return None
    for note in notes:
        out.append(_text("w", note))
    return "".join(out)


def _item(got: Any, out: list[str], budget: list[int]) -> None:
    if isinstance(got, Lines):
        out.append(f"L{len(got.entries)}[")
        for entry in got.entries:
            if not isinstance(entry, Read):  # an unreadable line: its message quotes the text
                raise _NoKey
            _read(entry, out, budget)
        out.append("]")
    elif isinstance(got, Read):
        _read(got, out, budget)
    else:
        raise _NoKey


def _read(got: Read, out: list[str], budget: list[int]) -> None:
    out.append("R")
    for side in (got._lhs, got._rhs):  # the sides as read (Read keeps them private)
        if side is None:
            out.append("N")
        elif side is _ZERO_SIDE:
            out.append("Z")
        elif isinstance(side, Side):
            out.append("T")
            _tree(side.node, out, budget)
        else:  # a sympy form (built at once): not keyed
            raise _NoKey
    out.append(_text("E", str(got.echo)))


def _tree(root: Any, out: list[str], budget: list[int]) -> None:
    """The tree in a prefix code without its positions, one token per node: iterative, so that
    no tree is too deep for it."""
    stack: list[Any] = [root]
    while stack:
        node = stack.pop()
        if isinstance(node, str):
            out.append(node)
            continue
        budget[0] -= 1
        if budget[0] < 0:
            raise _NoKey
        kind = node.kind
        if kind == "num":
            p, q = node.value
            if not (type(p) is int and type(q) is int and type(node.extra) is bool):
                raise _NoKey
            out.append(f"n{p}/{q}{'i' if node.extra else 'r'};")
        elif kind == "sym":
            out.append(_symbol(node.value))
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


def _symbol(value: Any) -> str:
    """A symbol (or the declared imaginary unit) exactly: its name and assumptions."""
    if not isinstance(value, sp.Basic):
        raise _NoKey
    return _srepr(value)


@lru_cache(maxsize=1_024)  # a question has a few dozen symbols; srepr costs microseconds
def _srepr(value: sp.Basic) -> str:
    return _text("s", sp.srepr(value))


def _text(tag: str, text: str) -> str:
    """A length-prefixed string: no text can end it early or run into the next token."""
    return f"{tag}{len(text)}:{text}"
