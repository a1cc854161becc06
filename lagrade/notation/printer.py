"""The one place that prints expressions: LaTeX (with dots over velocities), presentation MathML
and the plain text a student types, for handouts and for showing a student what was read.

Velocities are plain symbols such as `theta_dot` (see `lagrade.mechanics.lagrange.jet`); sympy's
printers would show them as θ with a subscript "dot", so the printers here put the dots back.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import sympy as sp
from markupsafe import Markup
from sympy.printing.mathml import MathMLPresentationPrinter
from sympy.printing.str import StrPrinter

from lagrade.mechanics import lagrange as mech

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


def _subscripted_latex(name: str, accent: str | None = None) -> str:
    """`x_{M}` for 'x_M', with `\\dot{…}` or `\\ddot{…}` over the head letter when `accent` says
    so: the dot sits over the letter, not over its subscript."""
    head, _, sub = name.partition("_")
    text = name_latex(head)
    if accent:
        text = rf"\{accent}{{{text}}}"
    return text + (f"_{{{name_latex(sub)}}}" if sub else "")


def dotted_latex(base: str, suffix: str) -> str:
    """`\\dot{\\theta}` for ('theta', '_dot'), `\\ddot{x}_{M}` for ('x_M', '_ddot')."""
    return _subscripted_latex(base, _DOTS[suffix][0])


def jet_name_latex(name: str) -> str:
    """theta_dot → \\dot{\\theta}; x_M_ddot → \\ddot{x}_{M}; x_M → x_{M}: any name ending in
    _dot or _ddot is dotted, whether or not its base is a coordinate."""
    for suffix in (mech.DDOT, mech.DOT):
        if name.endswith(suffix) and len(name) > len(suffix):
            return dotted_latex(name[: -len(suffix)], suffix)
    return _subscripted_latex(name)


def symbol_names(coordinates: Iterable[str]) -> dict[sp.Symbol, str]:
    """The `symbol_names` mapping for `sympy.latex` that dots every jet of `coordinates`."""
    names: dict[sp.Symbol, str] = {}
    for c in coordinates:
        j = mech.jet(c)
        names[j.dot] = dotted_latex(c, mech.DOT)
        names[j.ddot] = dotted_latex(c, mech.DDOT)
        names[sp.Symbol(MOMENTUM + c)] = f"p_{{{_subscripted_latex(c)}}}"
    return names


#: The prefix of a generalized momentum's name, p_<coordinate>: printed p with the coordinate
#: as its subscript (p_θ₁, p_{x_M}), not the coordinate's name spelled out (p_theta1).
MOMENTUM = "p_"


class _JetMathMLPrinter(MathMLPresentationPrinter):
    """Presentation MathML with q̇ and q̈ drawn as accents over the coordinate's letter."""

    def __init__(self, coordinates: Iterable[str], settings: dict | None = None):
        super().__init__(settings or {})
        self.coordinates = tuple(coordinates)

    def _print_Symbol(self, sym, style="plain"):
        coordinate = sym.name.removeprefix(MOMENTUM)
        if coordinate != sym.name and coordinate in self.coordinates:
            msub = self.dom.createElement("msub")
            msub.appendChild(super()._print_Symbol(sp.Symbol("p"), style))
            msub.appendChild(super()._print_Symbol(sp.Symbol(coordinate), style))
            return msub
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
        # the subscript as a symbol: a momentum's rate ṗ_θ has θ there, not the word theta
        msub.appendChild(super()._print_Symbol(sp.Symbol(sub), style))
        return msub


def symbol_mathml(name: str, coordinates: Iterable[str] = ()) -> str:
    """Presentation MathML of one symbol (no `<math>` around it), dotted where it is the
    velocity or acceleration of one of `coordinates`: a name as `mathml` writes it."""
    return _JetMathMLPrinter(coordinates).doprint(sp.Symbol(name))


def latex(expr: sp.Basic, coordinates: Iterable[str] = ()) -> str:
    """LaTeX of `expr` with dotted velocities and accelerations."""
    return sp.latex(expr, symbol_names=symbol_names(coordinates))


def mathml(expr: sp.Basic, coordinates: Iterable[str] = (), display: str = "inline") -> Markup:
    """A complete `<math>` element (presentation MathML) for `expr`, safe to put in HTML, with
    its text alternative: the formula in the notation students type (`aria-label`), which a
    browser's accessibility tree otherwise drops from a label holding it (a field named
    "which exists when > :" for "which exists when ω²R > g")."""
    inner = _JetMathMLPrinter(coordinates).doprint(expr)
    return Markup(
        f'<math xmlns="{_MATHML_NS}" display="{display}" aria-label="{_alternative(expr)}">'
        f"{inner}</math>"
    )


def _alternative(expr: sp.Basic) -> str:
    return str(Markup.escape(plain(expr)))


class _PlainPrinter(StrPrinter):
    """sympy's str printer, but Euler's number alone is `exp(1)`: `E` is a plain symbol to the
    grammar, so what this printer writes reads back as what it printed."""

    def _print_Exp1(self, expr: sp.Basic) -> str:
        return "exp(1)"


def plain(expr: sp.Basic, order: str | None = None) -> str:
    """The notation students type: `m*theta_dot^2/2`, `sin(theta)`, terms in sympy's usual order
    (`1 - x`); `order="lex"` sorts them strictly (`-x + 1`), as handouts do. An equation reads
    `lhs = rhs`, as the grader parses it (sympy would print `Eq(lhs, rhs)`)."""
    if isinstance(expr, sp.Equality):
        return f"{plain(expr.lhs, order)} = {plain(expr.rhs, order)}"
    return _PlainPrinter({"order": order}).doprint(expr).replace("**", "^")


def answer_latex(expr: sp.Basic) -> str:
    """A parsed answer in LaTeX, as a student's check: every velocity and acceleration dotted,
    and products shown with \\cdot so that an implicit multiplication is visible."""
    names = {s: jet_name_latex(s.name) for s in expr.free_symbols if isinstance(s, sp.Symbol)}
    return sp.latex(expr, symbol_names=names, mul_symbol="dot")


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
        latex(expr, coords),
        mathml(expr, coords),
        mathml(expr, coords, "block"),
        plain(expr, order="lex"),
    )


def equation(lhs: sp.Basic, rhs: sp.Basic, coordinates: Iterable[str] = ()) -> Math:
    """`lhs = rhs` in every notation (unevaluated, so `E = 0` stays an equation)."""
    return render(sp.Eq(lhs, rhs, evaluate=False), coordinates)


def named_equation(name: str, expr: sp.Basic, coordinates: Iterable[str] = ()) -> Math:
    """`name = expr` with the name written out as a word (a quantity's `block_acceleration`),
    not read as a symbol with a subscript (block_{acceleration})."""
    coords = tuple(coordinates)
    word = name.replace("_", r"\_")
    rhs = latex(expr, coords)

    def mathml_of(display: str) -> Markup:
        inner = _JetMathMLPrinter(coords).doprint(expr)
        text = str(Markup.escape(name))
        label = f"{text} = {_alternative(expr)}"
        return Markup(
            f'<math xmlns="{_MATHML_NS}" display="{display}" aria-label="{label}"><mrow>'
            f"<mtext>{text}</mtext><mo>=</mo>{inner}</mrow></math>"
        )

    return Math(
        rf"\text{{{word}}} = {rhs}",
        mathml_of("inline"),
        mathml_of("block"),
        f"{name} = {plain(expr, order='lex')}",
    )
