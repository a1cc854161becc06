"""The tree the parser builds: plain Python data whose only sympy objects are the question's own
symbols. The grammar makes it, `build` turns it into sympy and `echo` prints it back."""

from __future__ import annotations

from typing import NamedTuple


class Node(NamedTuple):
    """kind: num (value (p, q), extra: written as an integer), sym (value: Symbol), pi,
    add/mul (value: list of nodes), inv (1/value, inside mul), neg, pow (value ^ extra),
    call (value: function name, extra: (argument, integer power or None)), ddt (the total time
    derivative of value, extra: (order, the time symbol, the question's jets))."""

    kind: str
    start: int
    end: int
    value: object = None
    extra: object = None
