"""Layer 1: student text → sympy, safely. Our own lexer and grammar (and a small LaTeX subset)
build sympy objects through one whitelist; nothing here calls eval, sympify or parse_expr.
Failures are `ParseError`s with a position and a caret."""

from __future__ import annotations

from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "COMMANDS": "lagrade.notation.latex",
    "fold": "lagrade.notation.screen",
    "FUNCTIONS": "lagrade.notation.build",
    "GREEK": "lagrade.notation.lexer",
    "is_latex": "lagrade.notation.parse",
    "key_answer": "lagrade.notation.keys",
    "MAX_TOTAL_LENGTH": "lagrade.notation.limits",
    "name_latex": "lagrade.notation.printer",
    "NameRead": "lagrade.notation.parse",
    "parse": "lagrade.notation.parse",  # the module
    "parse_answer": "lagrade.notation.parse",
    "parse_equation": "lagrade.notation.parse",
    "parse_equations": "lagrade.notation.parse",
    "parse_expression": "lagrade.notation.parse",
    "Parsed": "lagrade.notation.parsed",
    "plain": "lagrade.notation.printer",
    "printer": "lagrade.notation.printer",  # the module
    "symbol_names": "lagrade.notation.printer",
    "Vocabulary": "lagrade.notation.vocabulary",
}
#: The modules exported as a whole.
_MODULES = {"parse", "printer"}

__all__ = [
    "COMMANDS",
    "fold",
    "FUNCTIONS",
    "GREEK",
    "is_latex",
    "key_answer",
    "MAX_TOTAL_LENGTH",
    "name_latex",
    "NameRead",
    "parse",
    "parse_answer",
    "parse_equation",
    "parse_equations",
    "parse_expression",
    "Parsed",
    "plain",
    "printer",
    "symbol_names",
    "Vocabulary",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
