"""Evaluate: expressions compiled once into straight-line programs (`program`: from sympy;
`tree`: from the parser's tree, without sympy) and run on whole arrays of sample points — in
float64, complex128, mpmath at 50 digits (`backends`) or hyper-dual numbers for derivatives
(`hyperdual`). Nothing here prints an expression to source or executes it: only a whitelist of
node types compiles."""

from lagrade.errors import UnsupportedExpression
from lagrade.judge.evaluate.backends import (
    COMPLEX,
    FLOAT,
    MP,
    MP_COMPLEX,
    MP_DIGITS,
    apply,
    extreme,
    finite_in_mp,
    run,
)
from lagrade.judge.evaluate.hyperdual import HyperDual, run_hyperdual
from lagrade.judge.evaluate.program import (
    PI,
    Constant,
    E,
    I,
    Named,
    Program,
    Real,
    compile_program,
    top_terms,
)
from lagrade.judge.evaluate.tree import compile_tree

__all__ = [
    "COMPLEX",
    "Constant",
    "E",
    "FLOAT",
    "HyperDual",
    "I",
    "MP",
    "MP_COMPLEX",
    "MP_DIGITS",
    "Named",
    "PI",
    "Program",
    "Real",
    "UnsupportedExpression",
    "apply",
    "compile_program",
    "compile_tree",
    "extreme",
    "finite_in_mp",
    "run",
    "run_hyperdual",
    "top_terms",
]
