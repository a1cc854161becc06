"""The result of parsing one answer: `Parsed`, with the expression or equation sympy holds, the
names found, warnings, and the reading shown back to the student."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

import lagrade.notation.printer as printer


@dataclass(frozen=True)
class Parsed:
    """A parsed answer: an expression (rhs None) or an equation lhs = rhs, the names found, and
    warnings about readings the student may want to check."""

    source: str
    lhs: sp.Expr
    rhs: sp.Expr | None
    symbols: frozenset[str]
    warnings: tuple[str, ...] = ()
    echo: str = ""  # the plain reading, written from the parse tree (see lagrade.notation.echo)

    @property
    def expr(self) -> sp.Expr:
        """The expression, or lhs − rhs for an equation (which then means expr = 0)."""
        return self.lhs if self.rhs is None else self.lhs - self.rhs

    @property
    def is_equation(self) -> bool:
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
        """LaTeX with dots over derivatives (\\dot{\\theta}, \\ddot{x}_{M}) and \\cdot products."""
        if self.rhs is None:
            return printer.answer_latex(self.lhs)
        return f"{printer.answer_latex(self.lhs)} = {printer.answer_latex(self.rhs)}"
