"""Every way of deciding "is the answer equal to the reference expression?" that the speed-against-
accuracy study compares, each behind one interface, so that the benchmark, the stability tests and
an instructor choosing a setting all see the same methods.

A method is an object with a `name` and `decide(answer, reference, domains) -> bool | None`
(None: this method cannot decide the pair — outside its scope, or no usable sample point).
`domains` maps each free symbol to the `Domain` its values are drawn from; a symbol without an
entry is taken as real. Expressions may come from student text, so nothing here calls `lambdify`,
`sympify` or `eval`: numbers come from the whitelist compiler of `lagrade.judge.evaluate`.

The families (`all_methods()` lists them, named as in docs/methods.csv):

- `structural`, `structural_expand`: a == b after sympy's automatic canonicalisation (and expand).
- `simplify`: sympy.simplify(a − b) == 0.   `equals`: sympy's Expr.equals (may answer None).
- `float{n}pt_rtol{ε}`: float64 at n points drawn in the declared domains,
  |a − b| ≤ ε max(|a|, |b|).
- `mp{d}_{n}pt`: the same in mpmath at d digits, ε = 10^-(d − 8).
- `exact_rational`: exact evaluation at random rational points of rational functions of the symbols
  and of sin, cos, tan of their integer combinations (Weierstrass substitution, see below).
- `numeric_hybrid`: the project's previous default, `numeric_equivalent` (below)
  (wrapped, not reimplemented); `exact_then_adaptive` replaced it as the default.
- `webwork`, `numbas`: those systems' documented default rules, reimplemented for comparison.
- `exact_then_scaled`: exact where it applies, otherwise a term-scaled float64 test with
  mpmath confirmation near the tolerance (the study's proposal; see its docstring).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import mpmath
import numpy as np
import sympy as sp

import lagrade.judge.evaluate as ev
from benchmarks.exact_rational import ExactRational
from lagrade.errors import ReferenceUndefined
from lagrade.judge.adaptive import (
    Domains,
    ExactThenAdaptive,
    compile_pair,
    draw,
    evaluate_float,
    sample_ranges,
    sampled_pair,
    sorted_symbols,
)
from lagrade.judge.compiled import Compiled, finite_mask
from lagrade.judge.equivalence import expressions_equal
from lagrade.judge.sampling import Space
from lagrade.mechanics.domains import Domain


@runtime_checkable
class Method(Protocol):
    """One way of deciding expression equivalence; `decide` returns True (equivalent), False (not)
    or None (cannot decide)."""

    name: str

    def decide(self, answer: sp.Expr, reference: sp.Expr, domains: Domains) -> bool | None: ...


# --- structural and symbolic -----------------------------------------------------------------


@dataclass(frozen=True)
class Structural:
    """a == b as sympy trees after automatic canonicalisation (`expand` also expands both):
    never wrong when it says True, blind to every rewrite it does not perform."""

    expand: bool = False
    name: str = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", "structural_expand" if self.expand else "structural")

    def decide(self, answer, reference, domains) -> bool | None:
        if answer == reference:
            return True
        if self.expand:
            return sp.expand(answer) == sp.expand(reference)
        return False


@dataclass(frozen=True)
class Simplify:
    """sympy.simplify(a − b) == 0: what many graders do; exact when it succeeds, slow, and it
    knows nothing of the declared domains beyond the symbols' assumptions."""

    name: str = "simplify"

    def decide(self, answer, reference, domains) -> bool | None:
        return sp.simplify(answer - reference) == 0


@dataclass(frozen=True)
class Equals:
    """sympy's Expr.equals (a numeric test at random complex points, then simplification);
    None when it cannot tell, which a grader must count as not decided."""

    name: str = "equals"

    def decide(self, answer, reference, domains) -> bool | None:
        verdict = answer.equals(reference)
        return None if verdict is None else bool(verdict)


# --- numeric at sample points -----------------------------------------------------------------


def _fmt_tol(rtol: float) -> str:
    return f"{rtol:.0e}".replace("e-0", "e-")


@dataclass(frozen=True)
class FloatSampling:
    """float64 at `points` points drawn in the declared domains; equal when every point has
    |a − b| ≤ rtol · max(|a|, |b|). Points where the reference is undefined are redrawn; an answer
    undefined where the reference is defined is wrong."""

    points: int
    rtol: float
    seed: int = 20240
    name: str = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", f"float{self.points}pt_rtol{_fmt_tol(self.rtol)}")

    def decide(self, answer, reference, domains) -> bool | None:
        sampled = sampled_pair(
            answer, reference, lambda s, w=1.0: sample_ranges(s, domains, w), self.points, self.seed
        )
        if sampled is None:
            return None
        a, b, _ = sampled[2]
        if not np.all(np.isfinite(a)):
            return False
        return bool(np.all(np.abs(a - b) <= self.rtol * np.maximum(np.abs(a), np.abs(b))))


@dataclass(frozen=True)
class MultiPrecision:
    """The same test in mpmath at `digits` digits (points drawn as for float64, then evaluated
    exactly as given), with the tolerance 10^-(digits − 8) that such precision allows."""

    digits: int
    points: int = 10
    seed: int = 20240
    name: str = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", f"mp{self.digits}_{self.points}pt")

    def decide(self, answer, reference, domains) -> bool | None:
        program = compile_pair(answer, reference)
        if program is None:
            return None
        symbols = sorted_symbols(answer, reference)
        rng = np.random.default_rng(self.seed)
        ranges = sample_ranges(symbols, domains)
        rtol = mpmath.mpf(10) ** (8 - self.digits)
        with mpmath.workdps(self.digits):
            have = 0
            for _ in range(6):
                env = {
                    s: ev.MP.array(v) for s, v in draw(symbols, ranges, self.points, rng).items()
                }
                a, b = (
                    np.broadcast_to(np.asarray(x, dtype=object), (self.points,))
                    for x in ev.run(program, env, ev.MP)
                )
                for x, y in zip(a, b, strict=True):
                    if not mpmath.isfinite(y):
                        continue
                    if not mpmath.isfinite(x) or abs(x - y) > rtol * max(abs(x), abs(y)):
                        return False
                    have += 1
                if have >= self.points:
                    return True
            return True if have else None


# --- the project's default ---------------------------------------------------------------------


@dataclass(frozen=True)
class Equivalence:
    """The answer to "are these two expressions equal on the domains?": the decision, the method
    that made it, and a point where they differ (symbol name → value) when they do."""

    equivalent: bool
    method: str
    witness: dict[str, float] | None = None


def numeric_equivalent(
    answer: sp.Expr,
    reference: sp.Expr,
    domains: Mapping[sp.Symbol, Domain] | None = None,
    *,
    seed: int = 0,
) -> Equivalence:
    """The numeric hybrid (float64 relative to the top-level terms, 50-digit confirmation near
    the tolerance): the default until the speed-against-accuracy study (docs/methods.csv)
    showed it accepts near misses of 1e-12 and misses cancellation inside products; kept as a
    method of that study and for the witness point of a wrong answer."""
    domains = dict(domains or {})
    for s in (answer.free_symbols | reference.free_symbols) - set(domains):
        domains[s] = Domain(str(s), sp.Integer(-5) / 2, sp.Integer(5) / 2)
    ref = Compiled.of(reference)
    points = Space((), domains).draw(seed, valid=finite_mask([ref]))
    out = expressions_equal(Compiled.of(answer), ref, points)
    witness = (
        None
        if out.where is None
        else points.point(out.where, answer.free_symbols | reference.free_symbols)
    )
    return Equivalence(out.equal, out.method, witness)


@dataclass(frozen=True)
class HybridDefault:
    """The project's previous default, `numeric_equivalent` (above) (numeric first,
    float64 relative to the size of the top-level terms, 50-digit confirmation between 1e-10 and
    1e-6), wrapped, not reimplemented: its Equivalence maps to True/False, and None when the
    reference is undefined everywhere or holds something the evaluator does not know."""

    seed: int = 0
    name: str = "numeric_hybrid"

    def decide(self, answer, reference, domains) -> bool | None:
        try:
            return bool(numeric_equivalent(answer, reference, domains, seed=self.seed).equivalent)
        except (ReferenceUndefined, ev.UnsupportedExpression):
            return None


# --- other systems' documented rules -----------------------------------------------------------


@dataclass(frozen=True)
class WeBWorK:
    """WeBWorK's MathObjects Formula check with its defaults: every variable drawn uniformly from
    [−2, 2] (the context's `limits`, whatever the physics says), 5 points (`num_points`), relative
    tolerance 0.1 % (`tolerance` 1e-3, `tolType` relative), and an absolute 1e-12 where the
    correct value is below `zeroLevel` 1e-14; points where the correct answer is undefined are
    replaced, an answer undefined where it is defined is wrong.

    Source of the rule: the WeBWorK forum answer on default tolerances
    (https://webwork.maa.org/moodle/mod/forum/discuss.php?d=3483: "the default domain for
    variables in the context is [-2,2], by default five randomly selected points … the value of the
    student's answer has to be within 0.1 percent"), and on zeroLevel/zeroLevelTol 1e-14/1e-12
    (https://webwork.maa.org/moodle/mod/forum/discuss.php?d=2922); the `limits => [-2,2]`,
    `num_points => 5` flags of the MathObjects default context (openwebwork pg, lib/Value.pm).
    """

    seed: int = 20240
    name: str = "webwork"

    def decide(self, answer, reference, domains) -> bool | None:
        sampled = sampled_pair(
            answer, reference, lambda s, w=1.0: [(-2.0, 2.0)] * len(s), 5, self.seed
        )
        if sampled is None:
            return None
        a, b, _ = sampled[2]
        if not np.all(np.isfinite(a)):
            return False
        tol = np.where(np.abs(b) < 1e-14, 1e-12, 1e-3 * np.abs(b))
        return bool(np.all(np.abs(a - b) <= tol))


@dataclass(frozen=True)
class Numbas:
    """Numbas's JME `compare` with its default settings: 5 points (`vsetRangePoints`), each
    variable uniform in [0, 1] (`vsetRangeStart`/`End`), `checkingType` absdiff with
    `checkingAccuracy` 1e-4, `failureRate` 1 (one failing point rejects); an evaluation that fails
    rejects; there is no redraw where the correct answer is undefined.

    Source of the rule: `Numbas.jme.compare`'s `default_settings` in numbas/Numbas,
    runtime/scripts/jme.js (vsetRangeStart 0, vsetRangeEnd 1, vsetRangePoints 5, checkingType
    'absdiff', checkingAccuracy 0.0001, failureRate 1), and the Numbas documentation of the
    mathematical-expression part ("picking a sample of random values for the free variables …
    if the two expressions agree on enough inputs").
    """

    seed: int = 20240
    name: str = "numbas"

    def decide(self, answer, reference, domains) -> bool | None:
        program = compile_pair(answer, reference)
        if program is None:
            return None
        symbols = sorted_symbols(answer, reference)
        rng = np.random.default_rng(self.seed)
        env = draw(symbols, [(0.0, 1.0)] * len(symbols), 5, rng)
        a, b = evaluate_float(program, env, 5)
        with np.errstate(invalid="ignore"):
            return bool(np.all(np.abs(a - b) < 1e-4))


# --- registry ----------------------------------------------------------------------------------

FLOAT_POINTS = (1, 2, 3, 5, 10, 20, 50)
FLOAT_TOLERANCES = (1e-3, 1e-6, 1e-9)

#: The name of the method the project grades with (lagrade.judge.adaptive.ExactThenAdaptive);
#: the chart marks it.
DEFAULT_NAME = "exact_then_adaptive"


def all_methods(include_default: bool = True) -> list[Method]:
    """Every method of the study, in the order of the chart's legend."""
    methods: list[Method] = [Structural(False), Structural(True), Simplify(), Equals()]
    methods += [FloatSampling(n, tol) for tol in FLOAT_TOLERANCES for n in FLOAT_POINTS]
    methods += [MultiPrecision(30), MultiPrecision(50), ExactRational()]
    if include_default:
        methods.append(HybridDefault())
    methods += [WeBWorK(), Numbas(), ExactThenAdaptive()]
    return methods


def method_named(name: str) -> Method:
    """The method called `name` (a KeyError lists the names)."""
    for m in all_methods():
        if m.name == name:
            return m
    raise KeyError(f"no method {name!r}; known: {', '.join(m.name for m in all_methods())}")
