"""Every way of deciding "is the answer equal to the reference expression?" that the speed-against-
accuracy study compares, each behind one interface, so that the benchmark, the stability tests and
an instructor choosing a setting all see the same methods.

A method is an object with a `name` and `decide(answer, reference, domains) -> bool | None`
(None: this method cannot decide the pair — outside its scope, or no usable sample point).
`domains` maps each free symbol to the `Domain` its values are drawn from; a symbol without an
entry is taken as real. Expressions may come from student text, so nothing here calls `lambdify`,
`sympify` or `eval`: numbers come from the whitelist compiler of `grader.evaluate`.

The families (`all_methods()` lists them, named as in docs/methods.csv):

- `structural`, `structural_expand`: a == b after sympy's automatic canonicalisation (and expand).
- `simplify`: sympy.simplify(a − b) == 0.   `equals`: sympy's Expr.equals (may answer None).
- `float{n}pt_rtol{ε}`: float64 at n points drawn in the declared domains,
  |a − b| ≤ ε max(|a|, |b|).
- `mp{d}_{n}pt`: the same in mpmath at d digits, ε = 10^-(d − 8).
- `exact_rational`: exact evaluation at random rational points of rational functions of the symbols
  and of sin, cos, tan of their integer combinations (Weierstrass substitution, see below).
- `numeric_hybrid`: the project's previous default, `grader.equivalence.numeric_equivalent`
  (wrapped, not reimplemented); `exact_then_adaptive` replaced it as the default.
- `webwork`, `numbas`: those systems' documented default rules, reimplemented for comparison.
- `exact_then_scaled`: exact where it applies, otherwise a term-scaled float64 test with
  mpmath confirmation near the tolerance (the study's proposal; see its docstring).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Protocol, runtime_checkable

import mpmath
import numpy as np
import sympy as sp

from problem_bank.domains import REAL, Domain

from . import evaluate as ev

Domains = Mapping[sp.Symbol, Domain]


@runtime_checkable
class Method(Protocol):
    """One way of deciding expression equivalence; `decide` returns True (equivalent), False (not)
    or None (cannot decide)."""

    name: str

    def decide(self, answer: sp.Expr, reference: sp.Expr, domains: Domains) -> bool | None: ...


# --- sampling ---------------------------------------------------------------------------------


def _free_symbols(*exprs: sp.Expr) -> list[sp.Symbol]:
    """Free symbols of all exprs in a stable order (by name), so that seeded draws repeat."""
    found: set[sp.Symbol] = set()
    for e in exprs:
        found |= e.free_symbols
    return sorted(found, key=lambda s: s.name)


def _ranges(symbols: Sequence[sp.Symbol], domains: Domains) -> list[tuple[float, float]]:
    return [domains.get(s, REAL).sample_range() for s in symbols]


def draw(
    symbols: Sequence[sp.Symbol],
    ranges: Sequence[tuple[float, float]],
    n: int,
    rng: np.random.Generator,
) -> dict[sp.Symbol, np.ndarray]:
    """n points, each coordinate uniform in its range (float64 arrays keyed by symbol)."""
    return {s: rng.uniform(lo, hi, n) for s, (lo, hi) in zip(symbols, ranges, strict=True)}


def _program(answer: sp.Expr, reference: sp.Expr) -> ev.Program | None:
    try:
        return ev.compile_program([answer, reference])
    except ev.UnsupportedExpression:
        return None


def _as_float_array(values, n: int) -> np.ndarray:
    out = np.asarray(values, dtype=float)
    return np.broadcast_to(out, (n,)) if out.ndim == 0 else out


def _evaluate_float(program: ev.Program, env: Mapping[sp.Symbol, np.ndarray], n: int):
    with np.errstate(all="ignore"):
        a, b = ev.run(program, env, ev.FLOAT)
    return _as_float_array(a, n), _as_float_array(b, n)


def _sampled(answer, reference, ranges_of, n: int, seed: int) -> tuple | None:
    """(program, symbols, (a, b, env)) for the pair at n points where the reference is
    defined, each symbol drawn in `ranges_of(symbols)`; None when the pair cannot be compiled
    or too few points are usable (the method has no verdict)."""
    program = _program(answer, reference)
    if program is None:
        return None
    symbols = _free_symbols(answer, reference)
    rng = np.random.default_rng(seed)
    got = _usable_points(program, symbols, ranges_of(symbols), n, rng)
    return None if got is None else (program, symbols, got)


def _usable_points(
    program: ev.Program,
    symbols,
    ranges,
    n: int,
    rng,
    rounds: int = 6,
) -> tuple[np.ndarray, np.ndarray, dict] | None:
    """Values of (answer, reference) at n points where the reference is defined (finite and
    real); points where it is not are redrawn, `rounds` times at most. None: too few points."""
    kept_a, kept_b, kept_env = [], [], {s: [] for s in symbols}
    have = 0
    for _ in range(rounds):
        want = n - have
        batch = max(want, 4)
        env = draw(symbols, ranges, batch, rng)
        a, b = _evaluate_float(program, env, batch)
        ok = np.isfinite(b)
        idx = np.nonzero(ok)[0][:want]
        kept_a.append(a[idx])
        kept_b.append(b[idx])
        for s in symbols:
            kept_env[s].append(env[s][idx])
        have += len(idx)
        if have >= n:
            break
    if have == 0:
        return None
    env_all = {s: np.concatenate(v) for s, v in kept_env.items()}
    return np.concatenate(kept_a), np.concatenate(kept_b), env_all


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
        sampled = _sampled(answer, reference, lambda s: _ranges(s, domains), self.points, self.seed)
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
        program = _program(answer, reference)
        if program is None:
            return None
        symbols = _free_symbols(answer, reference)
        rng = np.random.default_rng(self.seed)
        ranges = _ranges(symbols, domains)
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


# --- exact rational evaluation ----------------------------------------------------------------

_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


class _OutOfScope(Exception):
    """The expression is not a rational function of symbols and trig of their combinations."""


def _check_rational_trig(expr: sp.Expr, inside_trig: bool = False) -> None:
    """Raise _OutOfScope unless expr is built from rationals, symbols, +, ×, integer powers, and
    sin/cos/tan/cot/sec/csc of (rational combinations of symbols + rational multiples of π)."""
    if expr.is_Symbol or expr.is_Rational:
        return
    if expr is sp.pi:
        if inside_trig:
            return
        raise _OutOfScope("π outside a trig argument")
    if expr.is_Add or expr.is_Mul:
        for a in expr.args:
            _check_rational_trig(a, inside_trig)
        return
    if expr.is_Pow:
        if not expr.exp.is_Integer or inside_trig:
            raise _OutOfScope(f"power {expr}")
        _check_rational_trig(expr.base, inside_trig)
        return
    if isinstance(expr, _TRIG) and not inside_trig:
        arg = expr.args[0]
        if not all(
            _is_linear(term) or _monomial_symbol(term) is not None for term in sp.Add.make_args(arg)
        ):
            raise _OutOfScope(f"non-linear trig argument {arg}")
        _check_rational_trig(arg, inside_trig=True)
        return
    raise _OutOfScope(f"{type(expr).__name__}")


def _is_linear(arg: sp.Expr) -> bool:
    """arg = Σ r_i x_i + r π with rational r_i, r: what expand_trig splits into single symbols."""
    for term in sp.Add.make_args(arg):
        coeff, rest = term.as_coeff_Mul()
        if not coeff.is_Rational or not (rest.is_Symbol or rest is sp.pi or rest == 1):
            return False
    return True


def _trig_units(exprs: Iterable[sp.Expr]) -> dict[sp.Symbol, int]:
    """For each symbol inside a trig argument, the lcm of the denominators of its coefficients
    there: with x = L·y every argument becomes an integer combination of the y's."""
    units: dict[sp.Symbol, int] = {}
    for e in exprs:
        for f in e.atoms(*_TRIG):
            arg = f.args[0]
            for s in arg.free_symbols:
                q = sp.Rational(arg.coeff(s)).q
                units[s] = math.lcm(units.get(s, 1), int(q))
    return units


def _pi_free(expr: sp.Expr) -> bool:
    return not expr.has(sp.pi)


@dataclass(frozen=True)
class ExactRational:
    """Exact evaluation at random rational points, for rational functions of the symbols and of
    sin, cos, tan of their integer combinations; None for anything else (sqrt, exp, log, acos, a
    float constant).

    Why it is exact: after expand_trig every trig function is sin y or cos y of a single symbol y,
    and the Weierstrass substitution sin y = 2u/(1+u²), cos y = (1−u²)/(1+u²) turns them into
    rational functions of u = tan(y/2). A symbol that also stands outside trig gets its own
    independent rational value: y and e^{iy} are algebraically independent functions, so
    P(y, sin y, cos y) ≡ 0 exactly when it vanishes at independent generic (y, u). Sympy's rational
    arithmetic then decides each point without rounding; a nonzero rational function vanishes at
    `points` random rationals with negligible probability (Schwartz–Zippel).
    """

    points: int = 3
    seed: int = 20240
    name: str = "exact_rational"

    def decide(self, answer, reference, domains) -> bool | None:
        try:
            for e in (answer, reference):
                _check_rational_trig(e)
            a, b = _weierstrass_ready(answer, reference)
        except _OutOfScope:
            return None
        return _exact_compare(a, b, domains, self.points, np.random.default_rng(self.seed))


def _monomial_symbol(arg: sp.Expr) -> sp.Symbol | None:
    """For a trig argument c·s₁·s₂⋯ (ω t), the symbol to solve for: the last by name."""
    coeff, rest = arg.as_coeff_Mul()
    factors = sp.Mul.make_args(rest)
    if not coeff.is_Rational or len(factors) < 2 or not all(f.is_Symbol for f in factors):
        return None
    return max(factors, key=lambda f: f.name)


def _flatten_monomials(answer: sp.Expr, reference: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Replace each monomial trig argument c·ω·t by a fresh symbol w through t = w/(c ω), in both
    expressions at once: a change of variables (ω ≠ 0 on its domain) after which every trig
    argument is linear."""
    for _ in range(4):
        monomials = {
            term
            for e in (answer, reference)
            for f in e.atoms(*_TRIG)
            for term in sp.Add.make_args(f.args[0])
            if not _is_linear(term)
        }
        if not monomials:
            return answer, reference
        arg = min(monomials, key=str)
        solved = _monomial_symbol(arg)
        if solved is None:
            raise _OutOfScope(f"trig argument {arg}")
        w = sp.Dummy(f"w_{solved.name}", real=True)
        value = solved * w / arg.as_coeff_Mul()[1]
        if value.has(solved):
            raise _OutOfScope(f"trig argument {arg}")
        answer, reference = answer.xreplace({solved: value}), reference.xreplace({solved: value})
    raise _OutOfScope("too many monomial trig arguments")


def _weierstrass_ready(answer: sp.Expr, reference: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Both expressions with trig arguments reduced to single symbols (x = L·y, expand_trig)."""
    answer, reference = _flatten_monomials(answer, reference)
    units = _trig_units((answer, reference))
    scale = {s: units[s] * sp.Dummy(s.name, real=True) for s in units if units[s] != 1}
    out = []
    for e in (answer, reference):
        e = e.xreplace(scale) if scale else e
        e = sp.expand_trig(e)
        for f in e.atoms(*_TRIG):
            if not f.args[0].is_Symbol:
                raise _OutOfScope(f"trig argument {f.args[0]} did not reduce to a symbol")
        if not _pi_free(e):
            raise _OutOfScope("π remained after expand_trig")
        out.append(e)
    # Symbols scaled by L keep their domain through the original symbol (see _exact_compare).
    return out[0], out[1]


def _rational_in(lo: float, hi: float, rng: np.random.Generator) -> sp.Rational:
    """A random rational inside (lo, hi): a float drawn there, read exactly, so that the points
    keep the scale of the domain (1e-27 stays 1e-27, not a rounded 0)."""
    value = Fraction(float(rng.uniform(lo, hi)))  # the float itself, exactly (dyadic)
    return sp.Rational(value.numerator, value.denominator)


def _exact_compare(a: sp.Expr, b: sp.Expr, domains: Domains, points: int, rng) -> bool | None:
    symbols = _free_symbols(a, b)
    trig_syms = sorted({f.args[0] for e in (a, b) for f in e.atoms(*_TRIG)}, key=str)
    done = 0
    for _ in range(points * 4):
        subs: dict[sp.Basic, sp.Expr] = {}
        for s in symbols:
            dom = _domain_of(s, domains)
            lo, hi = dom.sample_range()
            subs[s] = _rational_in(lo, hi, rng)
        for y in trig_syms:
            lo, hi = _domain_of(y, domains).sample_range()
            u_lo, u_hi = _half_tan_range(lo, hi)
            u = _rational_in(u_lo, u_hi, rng)
            den = 1 + u**2
            s_val, c_val = 2 * u / den, (1 - u**2) / den
            subs.update(
                {
                    sp.sin(y): s_val,
                    sp.cos(y): c_val,
                }
            )
            if c_val != 0:
                subs[sp.tan(y)] = s_val / c_val
                subs[sp.sec(y)] = 1 / c_val
            if s_val != 0:
                subs[sp.cot(y)] = c_val / s_val
                subs[sp.csc(y)] = 1 / s_val
        # Functions first (their arguments are symbols that are substituted next).
        funcs = {k: v for k, v in subs.items() if not k.is_Symbol}
        plain = {k: v for k, v in subs.items() if k.is_Symbol}
        va = a.xreplace(funcs).xreplace(plain)
        vb = b.xreplace(funcs).xreplace(plain)
        if not (vb.is_Rational and vb.is_finite):
            continue  # the reference is undefined here: redraw
        if not (va.is_Rational and va.is_finite):
            if va.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
                return False
            return None
        if va != vb:
            return False
        done += 1
        if done >= points:
            return True
    return True if done else None


def _domain_of(symbol: sp.Symbol, domains: Domains) -> Domain:
    if symbol in domains:
        return domains[symbol]
    # A dummy standing for x / L keeps x's domain scaled; the domain only steers where points
    # fall, so the unscaled range is good enough for an identity that must hold everywhere.
    for s, d in domains.items():
        if isinstance(symbol, sp.Dummy) and s.name == symbol.name:
            return d
    return REAL


def _half_tan_range(lo: float, hi: float) -> tuple[float, float]:
    """Range of u = tan(y/2) for y in (lo, hi), when that lies within (−π, π); else (−3, 3)."""
    if -math.pi < lo < hi < math.pi:
        return math.tan(lo / 2), math.tan(hi / 2)
    return (-3.0, 3.0)


# --- the study's proposal: exact where possible, else rounding-aware numbers --------------------

# Derivatives of the whitelisted functions, for the running error bound: f(x + δ) − f(x) ≈ f'(x) δ.
_DERIVATIVE: dict[str, Callable] = {
    "sin": lambda B, x, f: B.cos(x),
    "cos": lambda B, x, f: B.sin(x),
    "tan": lambda B, x, f: 1 + f * f,
    "cot": lambda B, x, f: 1 + f * f,
    "sec": lambda B, x, f: f * B.tan(x),
    "csc": lambda B, x, f: f / B.tan(x),
    "asin": lambda B, x, f: 1 / B.sqrt(1 - x * x),
    "acos": lambda B, x, f: 1 / B.sqrt(1 - x * x),
    "atan": lambda B, x, f: 1 / (1 + x * x),
    "sinh": lambda B, x, f: B.cosh(x),
    "cosh": lambda B, x, f: B.sinh(x),
    "tanh": lambda B, x, f: 1 - f * f,
    "exp": lambda B, x, f: f,
    "log": lambda B, x, f: 1 / x,
    "abs": lambda B, x, f: 1,
    "sign": lambda B, x, f: 0,
}


def _bounded_run(program: ev.Program, env: Mapping, B) -> list[tuple]:
    """Values of the program's outputs with a first-order running error bound (Wilkinson's
    running error analysis): each node carries (v, e) with |computed − exact| ≲ e · u, u the unit
    roundoff of the arithmetic. The bound follows the cancellation inside the expression, not
    only at its top level, so a true identity evaluated through 1 − cos x or γ − 1 is not
    mistaken for a difference, while a real difference stands out once u is small enough."""
    vals: list[tuple] = []
    for instr in program.code:
        op = instr[0]
        if op == "in":
            vals.append((env[instr[1]], 0))
        elif op == "const":
            c = B.const(instr[1])
            vals.append((c, abs(c)))
        elif op == "add":
            parts = [vals[k] for k in instr[1]]
            v = parts[0][0]
            for p in parts[1:]:
                v = v + p[0]
            mag = sum((abs(p[0]) for p in parts[1:]), abs(parts[0][0]))
            err = sum((p[1] for p in parts[1:]), parts[0][1])
            vals.append((v, err + (len(parts) - 1) * mag))
        elif op == "mul":
            parts = [vals[k] for k in instr[1]]
            v, e = parts[0]
            for w, f in parts[1:]:
                e = abs(w) * e + abs(v) * f
                v = v * w
                e = e + abs(v)
            vals.append((v, e))
        elif op == "powi":
            (b, eb), n = vals[instr[1]], instr[2]
            v = b**n if n >= 0 else 1 / b ** (-n)
            vals.append((v, abs(n) * abs(v) * eb / abs(b) + (abs(n) + 1) * abs(v)))
        elif op == "powc":
            (b, eb), r = vals[instr[1]], B.const(instr[2])
            v = B.power(b, r)
            vals.append((v, abs(r) * abs(v) * eb / abs(b) + 4 * abs(v)))
        elif op == "powe":
            (b, eb), (x, ex) = vals[instr[1]], vals[instr[2]]
            v = B.exp(x * B.log(b))
            vals.append((v, abs(v) * (abs(B.log(b)) * ex + abs(x) * eb / abs(b)) + 8 * abs(v)))
        else:
            name, (x, ex) = instr[1], vals[instr[2]]
            f = ev._apply(B, name, x)
            d = _DERIVATIVE[name](B, x, f)
            vals.append((f, abs(d) * ex + 2 * abs(f)))
    return [vals[k] for k in program.outputs]


#: Safety factor on the first-order bound (higher-order terms, the rounding of the bound itself).
_SAFETY = 64.0


@dataclass(frozen=True)
class ExactThenAdaptive:
    """The study's proposal for the default, built because no measured method was both never
    wrong and fast: exact evaluation (`ExactRational`) where the expressions allow it, otherwise
    numbers whose rounding is bounded, with precision raised only where the bound cannot decide.

    1. float64 at `points` points in the declared domains, each value with a running error bound
       E (see `_bounded_run`): |a − b| > 64 E u means the answers differ — most wrong answers stop
       here, in microseconds. (The bound follows cancellation inside the expression, so a true
       identity that loses digits in float64 is not rejected.)
    2. Otherwise, if the pair is a rational function of symbols and of trig of their
       combinations, the exact test decides.
    3. Otherwise mpmath at 50, 100, 200 digits on `confirm` of the points: different as soon as
       |a − b| exceeds the bound, equal once the bound is below 10^-(digits/2) of the values and
       |a − b| within it (a difference that small at every point is no student's answer), and
       equal at 200 digits if still within the bound.
    """

    points: int = 12
    confirm: int = 3
    seed: int = 20240
    name: str = "exact_then_adaptive"

    def decide(self, answer, reference, domains) -> bool | None:
        sampled = _sampled(answer, reference, lambda s: _ranges(s, domains), self.points, self.seed)
        if sampled is None:
            return None
        program, symbols, (_, _, env) = sampled
        n = len(next(iter(env.values()))) if env else 1
        with np.errstate(all="ignore"):
            (a, ea), (b, eb) = _bounded_run(program, env, ev.FLOAT)
        a, b = _as_float_array(a, n), _as_float_array(b, n)
        bound = _SAFETY * np.finfo(float).eps * (_as_float_array(ea, n) + _as_float_array(eb, n))
        finite = np.isfinite(a) & np.isfinite(b) & np.isfinite(bound)
        if np.any(finite & (np.abs(a - b) > bound)):
            return False
        exact = ExactRational(seed=self.seed).decide(answer, reference, domains)
        if exact is not None:
            return exact
        order = np.argsort(finite, kind="stable")  # points the float test left open first
        chosen = order[: max(self.confirm, int(np.count_nonzero(~finite)))]
        return _adaptive_mp(answer, reference, symbols, env, chosen)


def _mp_bounded(program: ev.Program, values: Mapping) -> tuple:
    """(value, bound) of a one-output program in mpmath; a division by zero is undefined (nan)."""
    try:
        return _bounded_run(program, values, _MpScalar)[0]
    except ZeroDivisionError:
        return mpmath.mpf("nan"), mpmath.mpf("nan")


def _adaptive_mp(answer: sp.Expr, reference: sp.Expr, symbols, env, chosen) -> bool:
    """Decide at the chosen points in mpmath, raising the precision while the bound cannot."""
    prog_a, prog_b = ev.compile_program([answer]), ev.compile_program([reference])
    for i in chosen:
        point = {s: float(env[s][i]) for s in symbols}
        for digits in (50, 100, 200):
            with mpmath.workdps(digits):
                values = {s: mpmath.mpf(v) for s, v in point.items()}
                (a, ea), (b, eb) = _mp_bounded(prog_a, values), _mp_bounded(prog_b, values)
                if not (mpmath.isfinite(b) and mpmath.isfinite(eb)):
                    break  # the reference is undefined here after all: skip the point
                if not (mpmath.isfinite(a) and mpmath.isfinite(ea)):
                    return False
                u = mpmath.mpf(2) ** (-mpmath.mp.prec)
                bound = _SAFETY * u * (ea + eb)
                diff = abs(a - b)
                if diff > bound:
                    return False
                scale = max(abs(a), abs(b))
                if bound <= mpmath.mpf(10) ** (-digits // 2) * scale:
                    break  # equal at this point
    return True


class _MpScalar:
    """mpmath scalars as a backend of `_bounded_run`; complex results (outside the real domain)
    become nan, as in float64."""

    @staticmethod
    def _real(f):
        def g(*xs):
            try:
                y = f(*xs)
            except (ValueError, ZeroDivisionError, OverflowError):
                return mpmath.mpf("nan")
            return mpmath.mpf("nan") if isinstance(y, mpmath.mpc) else y

        return staticmethod(g)

    sin, cos, tan = _real(mpmath.sin), _real(mpmath.cos), _real(mpmath.tan)
    exp, log, sqrt = _real(mpmath.exp), _real(mpmath.log), _real(mpmath.sqrt)
    asin, acos, atan = _real(mpmath.asin), _real(mpmath.acos), _real(mpmath.atan)
    sinh, cosh, tanh = _real(mpmath.sinh), _real(mpmath.cosh), _real(mpmath.tanh)
    power, sign = _real(mpmath.power), _real(mpmath.sign)
    abs = staticmethod(abs)
    const = staticmethod(ev.MP.const)


# --- the project's default ---------------------------------------------------------------------


@dataclass(frozen=True)
class HybridDefault:
    """The project's previous default, `grader.equivalence.numeric_equivalent` (numeric first,
    float64 relative to the size of the top-level terms, 50-digit confirmation between 1e-10 and
    1e-6), wrapped, not reimplemented: its Equivalence maps to True/False, and None when the
    reference is undefined everywhere or holds something the evaluator does not know."""

    seed: int = 0
    name: str = "numeric_hybrid"

    def decide(self, answer, reference, domains) -> bool | None:
        from .equivalence import ReferenceUndefined, numeric_equivalent  # noqa: PLC0415

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
        sampled = _sampled(answer, reference, lambda s: [(-2.0, 2.0)] * len(s), 5, self.seed)
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
        program = _program(answer, reference)
        if program is None:
            return None
        symbols = _free_symbols(answer, reference)
        rng = np.random.default_rng(self.seed)
        env = draw(symbols, [(0.0, 1.0)] * len(symbols), 5, rng)
        a, b = _evaluate_float(program, env, 5)
        with np.errstate(invalid="ignore"):
            return bool(np.all(np.abs(a - b) < 1e-4))


# --- registry ----------------------------------------------------------------------------------

FLOAT_POINTS = (1, 2, 3, 5, 10, 20, 50)
FLOAT_TOLERANCES = (1e-3, 1e-6, 1e-9)

#: The name of the method the project grades with (grader.equivalence.expressions_equivalent);
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
