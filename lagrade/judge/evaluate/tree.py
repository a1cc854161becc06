"""Student text compiled straight from the parser's tree (`lagrade.notation.nodes.Node`) into a
`Program`, without building a sympy expression: a program per answer costs a walk of its tree.

The tree is split into the terms sympy would hold at its top level — sums flattened, a number
times a sum distributed over it (½ (a + b) is ½ a + ½ b), numbers added up and like terms
collected — so that the size of an answer's terms, the scale a residual is measured against,
is the one the sympy form of the same answer has. Numbers are exact (Fractions) and folded where
they meet; everything else is computed as written.

Only trees the parser's screen left unbuilt come here (`lagrade.notation.screen`: no time
derivative, no function of a constant but a few, no cancelling sum, …); for any other the caller
compiles the sympy form, as sympy evaluated it."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import Any

from lagrade.judge.evaluate.program import PI, I, Program, constant
from lagrade.notation import fold

#: The parser's function names → (instruction, constant power): sqrt is x^(1/2) as in sympy.
_CALLS: dict[str, tuple[str, Fraction | None]] = {
    "sin": ("sin", None), "cos": ("cos", None), "tan": ("tan", None), "sec": ("sec", None),
    "csc": ("csc", None), "cot": ("cot", None), "sinh": ("sinh", None), "cosh": ("cosh", None),
    "tanh": ("tanh", None), "asin": ("asin", None), "acos": ("acos", None),
    "atan": ("atan", None), "arcsin": ("asin", None), "arccos": ("acos", None),
    "arctan": ("atan", None), "exp": ("exp", None), "ln": ("log", None), "log": ("log", None),
    "abs": ("abs", None), "Abs": ("abs", None), "sign": ("sign", None), "sgn": ("sign", None),
    "asinh": ("asinh", None), "acosh": ("acosh", None), "atanh": ("atanh", None),
    "arcsinh": ("asinh", None), "arccosh": ("acosh", None), "arctanh": ("atanh", None),
    "arsinh": ("asinh", None), "arcosh": ("acosh", None), "artanh": ("atanh", None),
    "sqrt": ("pow", Fraction(1, 2)), "cbrt": ("pow", Fraction(1, 3)),
    "atan2": ("atan2", None), "arctan2": ("atan2", None),
    "Max": ("max", None), "max": ("max", None), "Min": ("min", None), "min": ("min", None),
}  # fmt: skip


class NotCompiled(Exception):
    """The tree holds what only sympy evaluates as the student means it (see the module)."""


def compile_tree(
    sides: Sequence[tuple[Any, int]],
    rename: Mapping | None = None,
    whole: bool = False,
) -> Program | None:
    """A program of `sides` — (node, sign) pairs, added up: an equation lhs = rhs is
    ((lhs, 1), (rhs, −1)) — whose outputs are the sum's top-level terms (`whole`: one output,
    the sum). `rename` maps the parser's symbols to the question's where they differ. None when
    the tree needs sympy (`NotCompiled`)."""
    builder = _Builder(rename or {})
    try:
        terms: dict[Any, Fraction] = {}
        order: list[Any] = []
        for node, sign in sides:
            for coefficient, key in builder.terms(node, Fraction(sign)):
                if key not in terms:
                    order.append(key)
                    terms[key] = coefficient
                else:
                    terms[key] += coefficient
        outputs = [builder.term(terms[key], key) for key in order if terms[key] != 0]
        if not outputs:
            outputs = [builder.emit(constant(Fraction(0)))]
        if whole and len(outputs) > 1:
            outputs = [builder.emit(("add", tuple(outputs)))]
    except NotCompiled:
        return None
    return Program(tuple(builder.code), tuple(outputs), frozenset(builder.symbols))


class _Builder:
    """Instructions emitted once each (a repeated subexpression is computed once)."""

    def __init__(self, rename: Mapping):
        self.rename = rename
        self.code: list[tuple] = []
        self.index: dict[tuple, int] = {}
        self.symbols: set = set()

    def emit(self, instr: tuple) -> int:
        found = self.index.get(instr)
        if found is None:
            found = self.index[instr] = len(self.code)
            self.code.append(instr)
        return found

    # --- terms -------------------------------------------------------------------------------
    def terms(self, node, coefficient: Fraction):
        """(coefficient, key) per top-level term: key None for a number, else the instruction
        of the term's product of factors other than numbers."""
        kind = node.kind
        if kind == "add":
            for term in node.value:
                yield from self.terms(term, coefficient)
            return
        if kind == "neg":
            yield from self.terms(node.value, -coefficient)
            return
        number, rest = self.split(node)
        if number is not None and len(rest) == 1 and rest[0].kind in ("add", "neg"):
            yield from self.terms(rest[0], coefficient * number)  # c (a + b) = c a + c b
            return
        if number is None:
            number = Fraction(1)
        if not rest:
            yield coefficient * number, None
            return
        yield coefficient * number, self.product(rest)

    def term(self, coefficient: Fraction, key: int | None) -> int:
        if key is None:
            return self.emit(constant(coefficient))
        if coefficient == 1:
            return key
        return self.emit(("mul", (self.emit(constant(coefficient)), key)))

    def split(self, node) -> tuple[Fraction | None, list]:
        """A term as (its numeric coefficient, or None, and its other factors)."""
        if node.kind == "num":
            return _fraction(node.value), []
        if node.kind != "mul":
            return None, [node]
        number: Fraction | None = None
        rest = []
        for factor in node.value:
            value = self.folded(factor.value if factor.kind == "inv" else factor)
            if value is None:
                rest.append(factor)
                continue
            if factor.kind == "inv":
                value = 1 / value
            number = value if number is None else number * value
        return number, rest

    def product(self, factors: Sequence) -> int:
        """The product of factors (an `inv` factor divides), as one instruction."""
        parts = []
        for factor in factors:
            if factor.kind == "inv":
                parts.append(self.emit(("powi", self.value(factor.value), -1)))
            else:
                parts.append(self.value(factor))
        if len(parts) == 1:
            return parts[0]
        return self.emit(("mul", tuple(sorted(parts))))

    # --- values --------------------------------------------------------------------------------
    def value(self, node) -> int:
        """The instruction of a node's value."""
        folded = self.folded(node)
        if folded is not None:
            return self.emit(constant(folded))
        kind = node.kind
        if kind == "sym":
            symbol = node.value
            if getattr(symbol, "is_Symbol", False):
                symbol = self.rename.get(symbol, symbol)
                self.symbols.add(symbol)
                return self.emit(("in", symbol))
            return self.emit(constant(I))  # the declared imaginary unit
        if kind == "pi":
            return self.emit(constant(PI))
        if kind in ("add", "neg"):
            parts = [self.term(c, key) for c, key in self.terms(node, Fraction(1))]
            if not parts:
                return self.emit(constant(Fraction(0)))
            return parts[0] if len(parts) == 1 else self.emit(("add", tuple(sorted(parts))))
        if kind == "mul":
            number, rest = self.split(node)
            return self.term(Fraction(1) if number is None else number, self.product(rest))
        if kind == "pow":
            return self.power(node)
        if kind == "call":
            return self.call(node)
        raise NotCompiled  # ddt: the time derivative is sympy's (D_t on the jets)

    def power(self, node) -> int:
        exponent = self.folded(node.extra)
        base = self.value(node.value)
        if exponent is None:
            return self.emit(("powe", base, self.value(node.extra)))
        return self.raised(base, exponent)

    def raised(self, base: int, exponent: Fraction) -> int:
        if exponent.denominator == 1:
            n = int(exponent)
            return base if n == 1 else self.emit(("powi", base, n))
        return self.emit(("powc", base, exponent))

    def call(self, node) -> int:
        name = node.value
        argument, power = node.extra
        operation, root = _CALLS[name]
        arguments = (argument,) if hasattr(argument, "kind") else argument
        inner = [self.value(a) for a in arguments]
        if operation == "pow":
            result = self.raised(inner[0], root)
        elif operation == "atan2":
            result = self.emit(("atan2", inner[0], inner[1]))
        elif operation in ("max", "min"):
            result = self.emit((operation, tuple(inner)))
        else:
            result = self.emit(("fn", operation, inner[0]))
        return result if power is None else self.emit(("powi", result, power))

    @staticmethod
    def folded(node) -> Fraction | None:
        """The exact value of a node made of numbers alone (sums, products, quotients, integer
        powers), or None."""
        return fold(node)


def _fraction(value) -> Fraction:
    p, q = value
    return Fraction(p, q)
