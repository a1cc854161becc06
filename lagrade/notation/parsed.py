"""The result of parsing one answer: `Parsed`, with the tree the parser read, the names found,
warnings, the reading shown back to the student, and the expression or equation in sympy — built
from the tree on first use, or at once where the parser's screen wants sympy's own checks
(`lagrade.notation.screen`)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, NamedTuple

import sympy as sp
from markupsafe import Markup

import lagrade.notation.printer as printer
import lagrade.notation.typeset as typeset
from lagrade.notation.nodes import Node


class Tree(NamedTuple):
    """The sides of an answer as read, for a caller that compiles them itself: `rhs` None with
    `equation` True is a bare expression read as an equation (its right side is 0)."""

    lhs: Node
    rhs: Node | None
    equation: bool


_UNBUILT: Any = object()


class Parsed:
    """A parsed answer: an expression (rhs None) or an equation lhs = rhs, the names found, and
    warnings about readings the student may want to check. `tree` is the parser's tree when
    the sympy form is left to be built on demand (None when it was built at once)."""

    __slots__ = ("source", "symbols", "warnings", "echo", "tree", "sides", "text", "_lhs", "_rhs")
    __slots__ += ("_build",)

    def __init__(
        self,
        source: str,
        lhs: sp.Expr | Any,
        rhs: sp.Expr | None | Any,
        symbols: frozenset[str],
        warnings: tuple[str, ...] = (),
        echo: str = "",
        tree: Tree | None = None,
        build: Any = None,
        sides: Tree | None = None,
        text: str = "",
    ):
        self.source = source
        self.symbols = symbols
        self.warnings = warnings
        self.echo = echo  # the plain reading, from the parse tree (see lagrade.notation.echo)
        self.tree = tree
        self.sides = sides if sides is not None else tree  # the tree, for the typeset echo
        self.text = text  # the text the tree was read from (LaTeX translated)
        self._lhs, self._rhs, self._build = lhs, rhs, build

    @classmethod
    def unbuilt(
        cls, source: str, tree: Tree, symbols: frozenset[str], warnings, echo: str, build, text
    ) -> Parsed:
        """A Parsed whose sympy sides `build(node)` makes when first asked for."""
        return cls(
            source, _UNBUILT, _UNBUILT, symbols, tuple(warnings), echo, tree, build, text=text
        )

    @property
    def lhs(self) -> sp.Expr:
        if self._lhs is _UNBUILT:
            self._lhs = self._build(self.tree.lhs)  # type: ignore[union-attr]
        return self._lhs

    @property
    def rhs(self) -> sp.Expr | None:
        if self._rhs is _UNBUILT:
            tree = self.tree
            if tree.rhs is not None:  # type: ignore[union-attr]
                self._rhs = self._build(tree.rhs)  # type: ignore[union-attr]
            else:
                self._rhs = sp.S.Zero if tree.equation else None  # type: ignore[union-attr]
        return self._rhs

    @property
    def expr(self) -> sp.Expr:
        """The expression, or lhs − rhs for an equation (which then means expr = 0)."""
        return self.lhs if self.rhs is None else self.lhs - self.rhs

    @property
    def is_equation(self) -> bool:
        if self.tree is not None:
            return self.tree.rhs is not None or self.tree.equation
        return self.rhs is not None

    def plain(self) -> str:
        """Echo with explicit * and ^ in the student's order, e.g.
        'm*R^2*theta_ddot - m*g*R*sin(theta) = 0'."""
        if self.echo:
            return self.echo
        if self.rhs is None:
            return printer.plain(self.lhs)
        return f"{printer.plain(self.lhs)} = {printer.plain(self.rhs)}"

    def latex(self) -> str:
        """LaTeX in the student's order, with dots over derivatives (\\dot{\\theta},
        \\ddot{x}_{M}) and every product shown (\\cdot), from the tree (`typeset`)."""
        if self.sides is None:
            if self.rhs is None:
                return printer.answer_latex(self.lhs)
            return f"{printer.answer_latex(self.lhs)} = {printer.answer_latex(self.rhs)}"
        lhs, rhs, equation = self.sides
        shown = typeset.latex(lhs, self.text)
        if rhs is not None:
            return f"{shown} = {typeset.latex(rhs, self.text)}"
        return f"{shown} = 0" if equation else shown

    def mathml(self, coordinates: Iterable[str] = ()) -> Markup:
        """Presentation MathML of the reading, in the student's order (`typeset`); velocities
        and accelerations of `coordinates` dotted."""
        if self.sides is None:  # made from sympy forms, with no tree: sympy's order
            shown = self.lhs if self.rhs is None else sp.Eq(self.lhs, self.rhs, evaluate=False)
            return printer.mathml(shown, coordinates)
        lhs, rhs, equation = self.sides
        if rhs is None and equation:
            zero = Node("num", 0, 0, (0, 1), True)
            return typeset.mathml((lhs, zero), self.text, coordinates, self.plain())
        sides = (lhs,) if rhs is None else (lhs, rhs)
        return typeset.mathml(sides, self.text, coordinates, self.plain())

    def __repr__(self) -> str:
        return f"Parsed({self.source!r}, echo={self.echo!r})"
