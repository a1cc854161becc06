"""Layer 1: student text → sympy, safely. Our own lexer and grammar (and a small LaTeX subset)
build sympy objects through one whitelist; nothing here calls eval, sympify or parse_expr.
Failures are `ParseError`s with a position and a caret."""

from lagrade.notation.parse import (
    Parsed,
    Vocabulary,
    parse_answer,
    parse_equation,
    parse_equations,
    parse_expression,
)

__all__ = [
    "Parsed",
    "Vocabulary",
    "parse_answer",
    "parse_equation",
    "parse_equations",
    "parse_expression",
]
