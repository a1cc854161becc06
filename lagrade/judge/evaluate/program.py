"""Straight-line programs: what every evaluator of the judge runs (float64, complex, mpmath, exact
fractions, numbers modulo a prime, hyper-dual numbers), and the compiler that makes one from
sympy expressions (a reference derived by the mechanics layer, a mutant of the catalogue).
Student text is compiled by `tree`, straight from the parser's tree, without sympy.

Why not `lambdify`: it prints the expression to Python source and executes it, which the project
forbids for anything derived from student text. Here a whitelist of node types is walked once
into a list of instructions; anything else (an undefined function, a Derivative) is rejected
with a clear message.

Instructions, each referring to earlier ones by index:

    ("in", symbol)            an input (a sympy Symbol: the key of the points' arrays)
    ("const", value, float)   a constant: a Fraction, a `Real` or one of PI, E, I; and its float
    ("add", (i, j, …))        a sum;  ("mul", (i, j, …)) a product
    ("powi", i, n)            an integer power;  ("powc", i, exponent) a constant power
    ("powe", i, j)            i ** j for a variable exponent: exp(j log i)
    ("fn", name, i)           sin, cos, …, abs, sign (names in FUNCTIONS)
    ("atan2", y, x)           the angle of (x, y);  ("max" | "min", (i, j, …)) the extremes
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from lagrade.errors import UnsupportedExpression

#: The functions of one argument the evaluators know, by instruction name.
FUNCTIONS = frozenset(
    {
        "sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "sinh", "cosh",
        "tanh", "asinh", "acosh", "atanh", "exp", "log", "abs", "sign",
    }
)  # fmt: skip


class Named(NamedTuple):
    """π, Euler's number or the imaginary unit: constants without an exact rational value."""

    name: str

    def __repr__(self) -> str:
        return self.name


PI = Named("pi")
E = Named("E")
I = Named("I")  # noqa: E741 - the imaginary unit's own name


class Real(NamedTuple):
    """A binary floating-point constant as sympy holds it (mpmath's raw tuple), read at the
    working precision of the evaluator that uses it (a sympy Float of a reference)."""

    mpf: tuple

    def __float__(self) -> float:
        import mpmath

        return float(mpmath.mpf(self.mpf))


Constant = Fraction | Real | Named


@dataclass(frozen=True)
class Program:
    """Straight-line code for several expressions: instructions in dependency order, each shared
    subtree once; `outputs` are the instructions whose values are the results."""

    code: tuple[tuple, ...]
    outputs: tuple[int, ...]
    symbols: frozenset

    def joined(self, other: Program) -> Program:
        """One program computing this one's outputs, then `other`'s (an answer and its
        reference run together)."""
        shift = len(self.code)
        return Program(
            self.code + tuple(shifted(instr, shift) for instr in other.code),
            self.outputs + tuple(k + shift for k in other.outputs),
            self.symbols | other.symbols,
        )

    def single(self, k: int) -> Program:
        """The program of output k alone (dead instructions are harmless)."""
        return Program(self.code, (self.outputs[k],), self.symbols)


def shifted(instr: tuple, by: int) -> tuple:
    """An instruction with the indices it refers to moved by `by`."""
    op = instr[0]
    if op in ("in", "const"):
        return instr
    if op in ("add", "mul", "max", "min"):
        return (op, tuple(k + by for k in instr[1]))
    if op in ("powi", "powc"):
        return (op, instr[1] + by, instr[2])
    if op in ("powe", "atan2"):
        return (op, instr[1] + by, instr[2] + by)
    return (op, instr[1], instr[2] + by)  # fn


def as_float(value: Constant) -> np.float64 | np.complex128:
    """A constant as a numpy number, so that float arithmetic on it follows IEEE rules (0 ** -1
    is inf, not ZeroDivisionError) and a number beyond float range is ±inf, not
    OverflowError."""
    if value is I:
        return np.complex128(1j)
    if value is PI:
        return np.float64(np.pi)
    if value is E:
        return np.float64(np.e)
    try:
        return np.float64(float(value))
    except OverflowError:
        return np.float64(np.inf if value > 0 else -np.inf)


def constant(value: Constant) -> tuple:
    return ("const", value, as_float(value))


def is_integer(value: Any) -> bool:
    return isinstance(value, Fraction) and value.denominator == 1


# --- from sympy -----------------------------------------------------------------------------------


def compile_program(exprs: Sequence) -> Program:
    """Compile `exprs` (sympy expressions over the whitelist) into one Program whose outputs are
    the expressions in order."""
    import sympy as sp

    functions = _sympy_functions()
    code: list[tuple] = []
    index: dict = {}
    symbols: set = set()

    def emit(node) -> int:
        found = index.get(node)
        if found is not None:
            return found
        instr = _instruction(sp, functions, node, emit, symbols)
        code.append(instr)
        index[node] = len(code) - 1
        return len(code) - 1

    outputs = tuple(emit(sp.S(e) if isinstance(e, int | float) else e) for e in exprs)
    return Program(tuple(code), outputs, frozenset(symbols))


_FUNCTION_TABLE: dict = {}


def _sympy_functions() -> dict:
    """sympy's function classes → instruction names (built on first use: sympy loads late)."""
    if not _FUNCTION_TABLE:
        import sympy as sp

        for cls in (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.asin, sp.acos, sp.atan):
            _FUNCTION_TABLE[cls] = cls.__name__
        for cls in (sp.sinh, sp.cosh, sp.tanh, sp.asinh, sp.acosh, sp.atanh, sp.exp, sp.log):
            _FUNCTION_TABLE[cls] = cls.__name__
        _FUNCTION_TABLE[sp.Abs] = "abs"
        _FUNCTION_TABLE[sp.sign] = "sign"
    return _FUNCTION_TABLE


def sympy_constant(sp, node) -> Constant:
    """A sympy number as a program constant."""
    if isinstance(node, sp.Rational):
        return Fraction(int(node.p), int(node.q))
    return Real(node._mpf_)


def _instruction(sp, functions: dict, node, emit, symbols: set) -> tuple:
    if isinstance(node, sp.Symbol):
        symbols.add(node)
        return ("in", node)
    if isinstance(node, sp.Number):
        if not node.is_finite:
            raise UnsupportedExpression(f"the answer contains {node}, which is not a finite number")
        return constant(sympy_constant(sp, node))
    if node is sp.pi:  # singletons: `is`, not sympy's slow ==
        return constant(PI)
    if node is sp.E:
        return constant(E)
    if node is sp.I:  # only where a question declares the imaginary unit
        return constant(I)
    if isinstance(node, sp.Add):
        return ("add", tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Mul):
        return ("mul", tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Pow):
        base, exponent = node.args
        if isinstance(exponent, sp.Integer):
            return ("powi", emit(base), int(exponent))
        if isinstance(exponent, sp.Rational | sp.Float):
            return ("powc", emit(base), sympy_constant(sp, exponent))
        if base is sp.E:  # E**x is exp(x)
            return ("fn", "exp", emit(exponent))
        # b**e with a non-constant exponent: exp(e log b), defined for b > 0.
        return ("powe", emit(base), emit(exponent))
    if isinstance(node, sp.atan2):
        return ("atan2", emit(node.args[0]), emit(node.args[1]))
    if isinstance(node, sp.Max | sp.Min):  # the largest (smallest) of its arguments
        return ("max" if isinstance(node, sp.Max) else "min", tuple(emit(a) for a in node.args))
    if isinstance(node, sp.Function):
        name = functions.get(type(node))
        if name is None:
            raise UnsupportedExpression(f"the function {type(node).__name__} is not supported")
        if len(node.args) != 1:
            raise UnsupportedExpression(f"{type(node).__name__} with {len(node.args)} arguments")
        return ("fn", name, emit(node.args[0]))
    raise UnsupportedExpression(f"cannot evaluate {node} ({type(node).__name__})")


def top_terms(expr) -> tuple:
    """The top-level terms of a sympy expression, with a numeric factor distributed over a sum
    (½ (a + b) → ½ a, ½ b), so that the tolerance sees the size of each term, not of their
    sum."""
    import sympy as sp

    terms: list = []
    for term in sp.Add.make_args(expr):
        coeff, rest = term.as_coeff_Mul()
        if isinstance(rest, sp.Add) and coeff != 1:
            terms.extend(coeff * t for t in rest.args)
        else:
            terms.append(term)
    return tuple(terms)
