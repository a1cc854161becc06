"""Math as handouts show it: LaTeX (with dots over velocities), presentation MathML and the plain
text a student types, from one sympy expression.

Velocities are plain symbols such as `theta_dot` (see `mechanics.jet`); sympy's printers would
show them as θ with a subscript "dot", so both printers here are told which symbols are jets.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import sympy as sp
from markupsafe import Markup
from sympy.printing.mathml import MathMLPresentationPrinter

from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.lagrange import DDOT, DOT

_MATHML_NS = "http://www.w3.org/1998/Math/MathML"
_DOTS = {mech.DOT: ("dot", "\u02d9"), mech.DDOT: ("ddot", "\u00a8")}


def _split_jet(name: str, coordinates: Iterable[str]) -> tuple[str, str] | None:
    """('x_M', '_ddot') for 'x_M_ddot' when x_M is a coordinate, else None."""
    for suffix in (mech.DDOT, mech.DOT):
        base = name[: -len(suffix)]
        if name.endswith(suffix) and base in coordinates:
            return base, suffix
    return None


def name_latex(name: str) -> str:
    """LaTeX of a plain symbol name as sympy writes it (`alpha` → `\\alpha`, `x_M` → `x_{M}`)."""
    return sp.latex(sp.Symbol(name))


def dotted_latex(base: str, suffix: str) -> str:
    """`\\dot{\\theta}` for ('theta', '_dot'), `\\ddot{x}_{M}` for ('x_M', '_ddot'): the dot sits
    over the letter, not over its subscript."""
    head, _, sub = base.partition("_")
    accent = _DOTS[suffix][0]
    text = rf"\{accent}{{{name_latex(head)}}}"
    return text + (f"_{{{sub}}}" if sub else "")


def symbol_names(coordinates: Iterable[str]) -> dict[sp.Symbol, str]:
    """The `symbol_names` mapping for `sympy.latex` that dots every jet of `coordinates`."""
    names: dict[sp.Symbol, str] = {}
    for c in coordinates:
        j = mech.jet(c)
        names[j.dot] = dotted_latex(c, mech.DOT)
        names[j.ddot] = dotted_latex(c, mech.DDOT)
    return names


class _JetMathMLPrinter(MathMLPresentationPrinter):
    """Presentation MathML with q̇ and q̈ drawn as accents over the coordinate's letter."""

    def __init__(self, coordinates: Iterable[str], settings: dict | None = None):
        super().__init__(settings or {})
        self.coordinates = tuple(coordinates)

    def _print_Symbol(self, sym, style="plain"):
        split = _split_jet(sym.name, self.coordinates)
        if split is None:
            return super()._print_Symbol(sym, style)
        base, suffix = split
        head, _, sub = base.partition("_")
        mover = self.dom.createElement("mover")
        mover.setAttribute("accent", "true")
        mover.appendChild(super()._print_Symbol(sp.Symbol(head), style))
        mo = self.dom.createElement("mo")
        mo.appendChild(self.dom.createTextNode(_DOTS[suffix][1]))
        mover.appendChild(mo)
        if not sub:
            return mover
        msub = self.dom.createElement("msub")
        msub.appendChild(mover)
        mi = self.dom.createElement("mi")
        mi.appendChild(self.dom.createTextNode(sub))
        msub.appendChild(mi)
        return msub


def latex(expr: sp.Basic, coordinates: Iterable[str] = ()) -> str:
    """LaTeX of `expr` with dotted velocities and accelerations."""
    return sp.latex(expr, symbol_names=symbol_names(coordinates))


def mathml(expr: sp.Basic, coordinates: Iterable[str] = (), display: str = "inline") -> Markup:
    """A complete `<math>` element (presentation MathML) for `expr`, safe to put in HTML."""
    inner = _JetMathMLPrinter(coordinates).doprint(expr)
    return Markup(f'<math xmlns="{_MATHML_NS}" display="{display}">{inner}</math>')


def plain(expr: sp.Basic) -> str:
    """The notation students type: `m*theta_dot^2/2`, `sin(theta)`."""
    return sp.sstr(expr, order="lex").replace("**", "^")


@dataclass(frozen=True)
class Math:
    """One formula in every notation a template may want."""

    latex: str
    mathml: Markup
    block: Markup
    plain: str

    def __str__(self) -> str:
        return self.plain


def render(expr: sp.Basic, coordinates: Iterable[str] = ()) -> Math:
    """All notations of `expr` at once (inline and display MathML)."""
    coords = tuple(coordinates)
    return Math(
        latex(expr, coords), mathml(expr, coords), mathml(expr, coords, "block"), plain(expr)
    )


def equation(lhs: sp.Basic, rhs: sp.Basic, coordinates: Iterable[str] = ()) -> Math:
    """`lhs = rhs` in every notation (unevaluated, so `E = 0` stays an equation)."""
    return render(sp.Eq(lhs, rhs, evaluate=False), coordinates)


# --- answers as the preview shows them -----------------------------------------------------------


def as_typed(expr: sp.Expr) -> str:
    """An expression as a student would type it, in sympy's default term order (what feedback,
    key answers and the parser's plain reading print; `plain` orders terms for handouts), with
    ^ for powers and explicit *: 'R^2*m*theta_ddot - R*g*m*sin(theta)'."""
    return sp.sstr(expr).replace("**", "^")


def _latex_name(name: str) -> str:
    """theta_dot → \\dot{\\theta}; x_M_ddot → \\ddot{x}_{M}; x_M → x_{M}."""
    accent = None
    for suffix, command in ((DDOT, "ddot"), (DOT, "dot")):
        if name.endswith(suffix) and len(name) > len(suffix):
            name, accent = name[: -len(suffix)], command
            break
    head, _, subscript = name.partition("_")
    body = sp.latex(sp.Symbol(head))
    if accent:
        body = f"\\{accent}{{{body}}}"
    if subscript:
        body += "_{" + sp.latex(sp.Symbol(subscript)) + "}"
    return body


def render_latex(expr: sp.Expr) -> str:
    """LaTeX with \\dot/\\ddot over velocities and accelerations and \\cdot for products."""
    names = {s: _latex_name(s.name) for s in expr.free_symbols if isinstance(s, sp.Symbol)}
    return sp.latex(expr, symbol_names=names, mul_symbol="dot")
