"""Parameter and coordinate domains: where a parameter or coordinate may lie, which sympy
assumptions that implies, how to draw sample values from it, and what holds there.

Domains are written as `positive`, `nonnegative`, `real`, or an interval such as `(0, pi/2)` or
`[0, 1]`. They come from scene declarations and from instructors' ad-hoc problems, never from
students; bounds are read by a tiny grammar of our own (a number, optionally times pi, optionally
over a number), not by sympify.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property, lru_cache

import sympy as sp

from lagrade.errors import DomainError, SceneError

_BOUND = re.compile(
    r"""^\s*(?P<sign>[+-])?\s*
        (?P<num>\d{1,100}(?:\.\d{1,100})?(?:[eE][+-]?\d{1,3})?)?\s*
        (?:\*?\s*(?P<pi>pi|π))?\s*
        (?:/\s*(?P<den>\d{1,100}(?:\.\d{1,100})?(?:[eE][+-]?\d{1,3})?))?\s*$""",
    re.VERBOSE,
)
_INTERVAL = re.compile(r"^\s*(?P<lo_br>[\(\[])(?P<lo>[^,]+),(?P<hi>[^\)\]]+)(?P<hi_br>[\)\]])\s*$")


def _parse_bound(text: str) -> sp.Expr:
    """'pi/2' → π/2, '-1.5' → −3/2, '2pi' → 2π, '1e-28' → 10⁻²⁸ (exactly); inf is ±oo."""
    stripped = text.strip()
    if stripped in ("inf", "oo", "+inf", "+oo"):
        return sp.oo
    if stripped in ("-inf", "-oo"):
        return -sp.oo
    match = _BOUND.match(stripped)
    if not match or not (match["num"] or match["pi"]):
        shown = text if len(text) <= 40 else text[:40] + "…"
        raise DomainError(
            f"cannot read the interval bound {shown!r}; write a number of at most 100 digits "
            "(1.5, 2e-3), pi, 2*pi or pi/2"
        )
    value: sp.Expr = sp.Rational(str(Fraction(match["num"]))) if match["num"] else sp.S.One
    if match["pi"]:
        value *= sp.pi
    if match["den"]:
        value /= sp.Rational(str(Fraction(match["den"])))
    if not math.isfinite(float(value)):
        raise DomainError(f"the interval bound {text!r} is too large for a number")
    return -value if match["sign"] == "-" else value


@dataclass(frozen=True)
class Domain:
    """An interval of the real line, open or closed at each end; `text` is how it was written."""

    text: str
    lower: sp.Expr
    upper: sp.Expr
    lower_open: bool = True
    upper_open: bool = True

    @classmethod
    def parse(cls, text: str | Domain) -> Domain:
        """Read `positive`, `nonnegative`, `real` or an interval `(a, b)`, `[a, b]`, `(a, b]`."""
        if isinstance(text, Domain):
            return text
        if not isinstance(text, str):
            raise DomainError(
                f"a domain must be a string such as 'positive' or '(0, pi/2)', got {text!r}"
            )
        key = text.strip().lower()
        if key == "positive":
            return cls("positive", sp.S.Zero, sp.oo, True, True)
        if key == "nonnegative":
            return cls("nonnegative", sp.S.Zero, sp.oo, False, True)
        if key == "real":
            return cls("real", -sp.oo, sp.oo, True, True)
        match = _INTERVAL.match(text)
        if not match:
            raise DomainError(
                f"unknown domain {text!r}; use positive, nonnegative, real, or an interval "
                "such as (0, pi/2) or [0, 1]"
            )
        lower, upper = _parse_bound(match["lo"]), _parse_bound(match["hi"])
        if not bool(lower < upper):
            raise DomainError(
                f"empty interval {text!r}: the lower bound must be below the upper one"
            )
        return cls(text.strip(), lower, upper, match["lo_br"] == "(", match["hi_br"] == ")")

    @property
    def assumptions(self) -> dict[str, bool]:
        """The sympy assumptions a symbol in this domain may carry."""
        if self.lower == 0 and self.lower_open or bool(self.lower > 0):
            return {"positive": True}
        if self.lower == 0:
            return {"nonnegative": True}
        return {"real": True}

    def symbol(self, name: str) -> sp.Symbol:
        """The sympy symbol of a parameter `name` in this domain."""
        return sp.Symbol(name, **self.assumptions)

    @cached_property
    def bounds(self) -> tuple[float, float]:
        """(lower, upper) as floats, converted once: float() of a sympy number costs
        microseconds, and every draw of sample points asks for the ranges again."""
        return float(self.lower), float(self.upper)

    def contains(self, value: float) -> bool:
        lo, hi = self.bounds
        above = value > lo if self.lower_open else value >= lo
        below = value < hi if self.upper_open else value <= hi
        return above and below

    def sample_range(self, widen: float = 1.0) -> tuple[float, float]:
        """A finite range to draw test points from, strictly inside the domain.

        Unbounded sides get a physically sized span (0.5 … 3 for positive quantities, ±3 for
        reals), so that sampled values are neither tiny nor huge; closed ends are kept slightly
        inside so that a point never lands on a boundary where an expression may be singular.
        `widen` stretches the unbounded sides' span (10, 100): where an expression is defined
        only far out (sqrt(y − 2)·sqrt(y − 6) for real y: y ≥ 6), a search finds it.
        """
        lo, hi = self.bounds
        span = 3.0 * widen
        if math.isinf(lo) and math.isinf(hi):
            return (-span, span)
        if math.isinf(hi):
            return (
                (lo + 0.5, lo + span)
                if lo == 0
                else (lo + 0.1 * abs(lo) + 0.1, lo + span + abs(lo))
            )
        if math.isinf(lo):
            return (hi - span - abs(hi), hi - 0.1 * abs(hi) - 0.1)
        margin = 0.02 * (hi - lo)
        return (lo + margin, hi - margin)


POSITIVE = Domain.parse("positive")
NONNEGATIVE = Domain.parse("nonnegative")
REAL = Domain.parse("real")


def exact_number(value: object) -> sp.Expr:
    """A parameter's value as an exact number, a decimal read as the rational it shows (9.81 is
    981/100): what keys and handout checks compute with. sympy's `nsimplify` takes
    milliseconds per value, and a class's variants draw their values from a few, so each is
    converted once per process."""
    try:
        return _exact_number(value)
    except TypeError:  # unhashable: not one of a scene's values, converted as it is
        return sp.nsimplify(value, rational=True)


@lru_cache(maxsize=4_096, typed=True)
def _exact_number(value: object) -> sp.Expr:
    return sp.nsimplify(value, rational=True)


def within(
    expr: sp.Expr,
    domains: Mapping[sp.Symbol, Domain],
    then: Callable[[sp.Expr], sp.Expr] = lambda e: e,
) -> sp.Expr:
    """expr as the symbols' domains let sympy simplify it: √(r²) = r and |r| = r for r > 0
    (each symbol with a signed domain stands in for a symbol carrying that assumption while
    `then` works on it, and back)."""
    swap = {
        s: sp.Dummy(s.name, **d.assumptions)
        for s, d in domains.items()
        if "real" not in d.assumptions
    }
    if not swap:
        return then(expr)
    return then(expr.xreplace(swap)).xreplace({d: s for s, d in swap.items()})


def vanishes_within(
    expr: sp.Expr,
    box: Mapping[sp.Symbol, tuple[float, float]],
    relations: Sequence[sp.Expr] = (),
    points: int = 8,
) -> bool:
    """Whether expr is 0 at `points` seeded points of `box` (each symbol uniform in its range,
    the `relations` kept), to 30 digits relative to the size of its terms; a complex or
    infinite value is not 0."""
    rng = random.Random(0)
    terms = sp.Add.make_args(sp.expand(expr))
    for _ in range(points):
        for _draw in range(64):
            point = {s: sp.Float(rng.uniform(lo, hi), 30) for s, (lo, hi) in box.items()}
            if keeps(relations, point):
                break
        else:
            return False  # the relations keep no point of the box
        value = sp.N(expr.xreplace(point), 30)
        if not value.is_number or value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            return False
        size = sum((abs(sp.N(x.xreplace(point), 30)) for x in terms), sp.S.Zero)
        if abs(value) > sp.Float(10) ** -20 * (1 + size):
            return False
    return True


def branched(expr: sp.Expr) -> bool:
    """expr holds a branch choice (|r|, a root, atan2, a sign) that a coordinate's domain may
    settle."""
    roots = any(p.exp.is_Rational and not p.exp.is_Integer for p in expr.atoms(sp.Pow))
    return roots or expr.has(sp.Abs, sp.sign, sp.atan2, sp.arg, sp.Piecewise)


def keeps(relations: Sequence[sp.Expr], values: Mapping[sp.Symbol, float]) -> bool:
    """Each relation (an expression that must be positive) is positive at `values`, where it
    names only parameters that have one (a relation with a symbolic parameter is the judge's)."""
    for g in relations:
        if g.free_symbols <= set(values) and not float(g.xreplace(values)) > 0:
            return False
    return True


@dataclass(frozen=True)
class Parameter:
    """A named constant of a scene, with the domain it lives in and, for numeric variants, its SI
    unit and a pool of values to draw from (empty pool: the parameter stays symbolic)."""

    name: str
    domain: Domain
    unit: str = ""
    values: tuple[float, ...] = ()
    description: str = ""


def param(
    name: str,
    domain: str | Domain | None = "positive",
    unit: str = "",
    values: Sequence[float] = (),
    description: str = "",
) -> Parameter:
    """Declare a parameter; `domain` is `positive`, `nonnegative`, `real` or an interval."""
    if domain is None:
        raise SceneError(
            "?", [f"parameter {name!r}: no domain (declare positive, real or an interval)"]
        )
    return Parameter(name, Domain.parse(domain), unit, tuple(values), description)
