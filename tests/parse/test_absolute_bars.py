"""|x| is read as abs(x), as docs/notation.md promises: bars nest, a bar after a factor opens a
new absolute value only outside bars, and an unclosed bar says where it opened."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.errors import ParseError
from lagrade.notation.parse import Vocabulary, parse_answer

VOCAB = Vocabulary.from_names(["x", "q"], {"m": "positive"})


@pytest.mark.parametrize(
    ("text", "echo"),
    [
        ("|x| + m", "abs(x) + m"),
        ("m |x - q|", "m*abs(x - q)"),
        ("||x| - m|", "abs(abs(x) - m)"),
        ("|x| |q|", "abs(x)*abs(q)"),
        ("|sin x|", "abs(sin(x))"),
        ("m + |x|", "m + abs(x)"),  # after an operator, outside bars, '|' opens (was refused)
        ("m*|x| - |q|/m", "m*abs(x) - abs(q)/m"),
    ],
)
def test_bars_read_as_abs(text, echo):
    parsed = parse_answer(text, VOCAB)
    assert parsed.plain() == echo
    assert parsed.expr.has(sp.Abs)


@pytest.mark.parametrize(
    ("text", "message"),
    [("|x", "Missing '|': the '|' at position 1 is never closed."), ("||", "answer ended")],
)
def test_unclosed_bars_say_where(text, message):
    with pytest.raises(ParseError, match=message.replace("|", r"\|").replace("(", r"\(")):
        parse_answer(text, VOCAB)
