"""Exact equivalence of expressions that are rational functions of their symbols and of sin, cos,
tan (and cot, sec, csc) of integer combinations of them: exact rational arithmetic at random
rational points, no rounding anywhere. A method of the speed-versus-accuracy chart
(`benchmarks/methods.py`), no longer the judge's (its exact stage is modular arithmetic,
`lagrade.judge.modular`): kept here, beside the chart that still draws it, since only the
chart and the stability tests that pin where it fails use it. None for anything outside that
class, and for a pair whose exact evaluation would cost too much (`MAX_TRIG_DEGREE`,
`MAX_EXACT_WORK`): exact numbers grow with every power and every multiple of a trig argument,
and a right answer must never run out of time here; the high-precision stage decides such pairs
as surely.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

import lagrade.judge.evaluate as ev
from lagrade.judge.adaptive import Domains, sorted_symbols
from lagrade.mechanics.domains import REAL, Domain

_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


#: The highest power the exact test raises a random rational to (53-bit points: the result has
#: up to 53 × n bits); higher powers go to the adaptive test, whose mpmath has no such cost.
MAX_EXACT_POWER = 2_000
#: The highest multiple n of a trig argument once every symbol is scaled to its unit: sin(n y)
#: expands into a polynomial of degree n in sin y and cos y, and its exact value at a rational
#: point into numbers of some 200 n bits (sin(10^6 t), sin(x/1000 + x/999) = sin(1999 y): none
#: of that is computed; the high-precision stage takes the pair).
MAX_TRIG_DEGREE = 48
#: The estimated work of evaluating the pair once at a rational point (`exact_work`), in units
#: of about 0.1 ns on this machine's 2 cores: 3·10^8 is some 30 ms per point. Above it the pair
#: goes to the high-precision stage, which has no such growth.
MAX_EXACT_WORK = 3e7


class _OutOfScope(Exception):
    """The expression is not a rational function of symbols and trig of their combinations."""


def _check_rational_trig(expr: sp.Expr, inside_trig: bool = False) -> bool:
    """Raise _OutOfScope unless expr is built from rationals, symbols, +, ×, integer powers, and
    sin/cos/tan/cot/sec/csc of (rational combinations of symbols + rational multiples of π).
    Returns whether it has a trig function (a rational function as it stands needs no
    reduction of trig arguments)."""
    if expr.is_Symbol or expr.is_Rational:
        return False
    if expr is sp.pi:
        if inside_trig:
            return False
        raise _OutOfScope("π outside a trig argument")
    if expr.is_Add or expr.is_Mul:
        found = [_check_rational_trig(a, inside_trig) for a in expr.args]  # every arg checked
        return any(found)
    if expr.is_Pow:
        if not expr.exp.is_Integer or inside_trig:
            raise _OutOfScope(f"power {expr}")
        if abs(int(expr.exp)) > MAX_EXACT_POWER:  # exact numbers of 10^5 bits and more: slow
            raise _OutOfScope(f"power {expr.exp} too high for exact arithmetic")
        return _check_rational_trig(expr.base, inside_trig)
    if isinstance(expr, _TRIG) and not inside_trig:
        arg = expr.args[0]
        if not all(
            _is_linear(term) or _monomial_symbol(term) is not None for term in sp.Add.make_args(arg)
        ):
            raise _OutOfScope(f"non-linear trig argument {arg}")
        _check_rational_trig(arg, inside_trig=True)
        return True
    raise _OutOfScope(f"{type(expr).__name__}")


def _is_linear(arg: sp.Expr) -> bool:
    """arg = Σ r_i x_i + r π with rational r_i, r: what expand_trig splits into single symbols."""
    for term in sp.Add.make_args(arg):
        coeff, rest = term.as_coeff_Mul()
        if not coeff.is_Rational or not (rest.is_Symbol or rest is sp.pi or rest == 1):
            return False
    return True


def _trig_units(exprs: Iterable[sp.Expr]) -> tuple[dict[sp.Symbol, int], int]:
    """For each symbol inside a trig argument, the lcm of the denominators of its coefficients
    there: with x = L·y every argument becomes an integer combination Σ n_i y_i of the y's; and
    the largest Σ |n_i| over the arguments, the degree of the polynomial in sin y_i, cos y_i
    that expand_trig makes of them (read in the same pass, before anything is expanded)."""
    units: dict[sp.Symbol, int] = {}
    arguments: list[dict[sp.Symbol, sp.Rational]] = []
    for e in exprs:
        for f in e.atoms(*_TRIG):
            arg = f.args[0]
            coefficients = {s: sp.Rational(arg.coeff(s)) for s in arg.free_symbols}
            arguments.append(coefficients)
            for s, c in coefficients.items():
                units[s] = math.lcm(units.get(s, 1), int(c.q))
    degree = max(
        (sum(abs(c) * units[s] for s, c in coefficients.items()) for coefficients in arguments),
        default=0,
    )
    return units, int(math.ceil(degree))


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

    def decide(self, answer, reference, domains, pair: ev.Program | None = None) -> bool | None:
        """`pair`: answer and reference compiled as one program, when the caller has it (used
        as it is when no trig function needs reducing)."""
        try:
            trig = any([_check_rational_trig(e) for e in (answer, reference)])  # both checked
            # rational functions as they stand need no reduction of trig arguments
            a, b = _weierstrass_ready(answer, reference) if trig else (answer, reference)
        except _OutOfScope:
            return None
        rng = np.random.default_rng(self.seed)
        return _exact_compare(a, b, domains, self.points, rng, trig, None if trig else pair)


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
    """Both expressions with trig arguments reduced to single symbols (x = L·y, expand_trig).
    _OutOfScope when an argument is a multiple beyond `MAX_TRIG_DEGREE` (checked before
    expand_trig, whose own work grows with it)."""
    answer, reference = _flatten_monomials(answer, reference)
    units, degree = _trig_units((answer, reference))
    if degree > MAX_TRIG_DEGREE:
        raise _OutOfScope(f"a trig argument {degree} times a symbol: too costly exactly")
    scale = {s: units[s] * sp.Dummy(s.name, real=True) for s in units if units[s] != 1}
    scaled = [e.xreplace(scale) if scale else e for e in (answer, reference)]
    out = []
    for e in scaled:
        if not e.atoms(*_TRIG):  # a rational function already (π passed only inside trig)
            out.append(e)
            continue
        e = sp.expand_trig(e)
        for f in e.atoms(*_TRIG):
            if not f.args[0].is_Symbol:
                raise _OutOfScope(f"trig argument {f.args[0]} did not reduce to a symbol")
        if not _pi_free(e):
            raise _OutOfScope("π remained after expand_trig")
        out.append(e)
    # Symbols scaled by L keep their domain through the original symbol (see _exact_compare).
    return out[0], out[1]


def exact_work(program: ev.Program, bits: Mapping[sp.Basic, tuple[int, int]]) -> float:
    """An estimate of the work of running `program` once on Fractions, from the bits of each
    input's numerator and denominator (`bits`), in 30-bit digits: a product or a sum of
    fractions normalises by gcd, quadratic in their digits; a power is repeated squaring,
    Karatsuba's n^1.585, without gcd. A denominator is followed as the product of the factors
    it is made of, so that a sum over a common denominator (a polynomial's terms) stays the
    size of its terms while a sum of 1/(x + k)^50 over k grows with every term, as the exact
    numbers do."""
    if _small(program, bits):
        return 0.0
    sizes: list[tuple[int, dict]] = []
    work = 0.0
    for k, instr in enumerate(program.code):
        op = instr[0]
        if op == "in":  # a float read exactly: its denominator is a power of two
            num, den = bits.get(instr[1], (64, 64))
            size = (num, {"two": den})
        elif op == "const":
            value = instr[1]
            num, q = (
                (abs(value.numerator), value.denominator)
                if isinstance(value, Fraction)
                else (2**64, 2**64)
            )
            size = (num.bit_length(), {("const", q): q.bit_length()} if q != 1 else {})
        elif op in ("add", "mul"):
            num, den = sizes[instr[1][0]]
            for j in instr[1][1:]:
                n, d = sizes[j]
                if op == "mul":
                    num, den = num + n, _merged(den, d, lambda a, b: a + b)
                else:  # over the lcm of the denominators
                    both = _merged(den, d, max)
                    total = sum(both.values())
                    num, den = max(num - sum(den.values()), n - sum(d.values())) + total + 1, both
                work += ((num + sum(den.values())) / 30) ** 2
            size = (num, den)
        elif op == "powi":
            num, den = sizes[instr[1]]
            e = abs(instr[2])
            if instr[2] >= 0:
                size = (num * e, {f: b * e for f, b in den.items()})
            else:  # the base's numerator becomes a denominator of its own
                size = (sum(den.values()) * e, {k: num * e})
            work += 3 * ((size[0] + sum(size[1].values())) / 30) ** 1.585
        else:  # never reached: such programs are out of scope
            size = (64, {k: 64})
        sizes.append(size)
    return work


def _small(program: ev.Program, bits: Mapping[sp.Basic, tuple[int, int]]) -> bool:
    """A quick bound that settles most pairs: every number's bits taken as their worst
    (denominators multiplied out in every sum), and still no instruction's work could bring the
    whole program near `MAX_EXACT_WORK`."""
    sizes: list[int] = []
    for instr in program.code:
        op = instr[0]
        if op == "in":
            size = sum(bits.get(instr[1], (64, 64)))
        elif op == "const":
            value = instr[1]
            size = (
                abs(value.numerator).bit_length() + value.denominator.bit_length()
                if isinstance(value, Fraction)
                else 128
            )
        elif op in ("add", "mul"):
            size = sum(sizes[k] for k in instr[1]) + len(instr[1])
        elif op == "powi":
            size = sizes[instr[1]] * abs(instr[2])
        else:
            size = 128
        if size > _SMALL_BITS:
            return False
        sizes.append(size)
    return len(sizes) * (_SMALL_BITS / 30) ** 2 <= MAX_EXACT_WORK


#: The bits below which the quick bound of `_small` settles a program of a few hundred
#: instructions as cheap.
_SMALL_BITS = 3_000


def _merged(a: dict, b: dict, combine) -> dict:
    out = dict(a)
    for key, value in b.items():
        out[key] = combine(out[key], value) if key in out else value
    return out


def _fraction_bits(lo: float, hi: float) -> tuple[int, int]:
    """Bits of the numerator and denominator of a float drawn in (lo, hi), read exactly: a
    53-bit mantissa over 2^(53 − e) for a binary exponent e below 53, an integer above."""
    e = math.frexp(max(abs(lo), abs(hi), 1e-300))[1]
    return (max(53, e), max(0, 53 - e))


def _exact_compare(
    a: sp.Expr,
    b: sp.Expr,
    domains: Domains,
    points: int,
    rng,
    trig: bool = True,
    pair: ev.Program | None = None,
) -> bool | None:
    """Compare at `points` random rational points, exactly. Each trig atom stands for a
    placeholder set from the half-angle tangent u, the pair is compiled once by the project's
    evaluator (`pair`, when given, is a and b compiled already) and run on Fractions: no sympy
    arithmetic per point."""
    if pair is not None and not trig:  # its symbols are the pair's, found when it was compiled
        symbols = sorted(pair.symbols, key=lambda s: s.name)
    else:
        symbols = sorted_symbols(a, b)
    atoms = [f for e in (a, b) for f in e.atoms(*_TRIG)] if trig else []
    trig_syms = sorted({f.args[0] for f in atoms}, key=str)
    stand_in = {f(y): sp.Dummy(f"{f.__name__}_{y}") for y in trig_syms for f in _TRIG}
    exprs = [a.xreplace(stand_in), b.xreplace(stand_in)] if stand_in else [a, b]
    try:
        program = pair if pair is not None else ev.compile_program(exprs)
    except ev.UnsupportedExpression:
        return None
    if any(op[0] not in _RATIONAL_OPS for op in program.code):
        return None
    ranges = [(s, _domain_of(s, domains).sample_range()) for s in symbols]
    half_tan = [(y, _half_tan_range(*_domain_of(y, domains).sample_range())) for y in trig_syms]
    bits = {s: _fraction_bits(lo, hi) for s, (lo, hi) in ranges}
    for y, (lo, hi) in half_tan:  # sin y = 2u/(1 + u²): twice the bits of u, and a few
        u_num, u_den = _fraction_bits(lo, hi)
        bits |= {stand_in[f(y)]: (2 * (u_num + u_den) + 2,) * 2 for f in _TRIG}
    if exact_work(program, bits) > MAX_EXACT_WORK:
        return None  # the high-precision stage decides this pair as surely, in bounded time
    alone: list[ev.Program] = []  # each side on its own, for a point where one is undefined
    done = 0
    for _ in range(points * 4):
        env: dict[sp.Basic, Fraction] = {}
        for s, (lo, hi) in ranges:
            env[s] = _fraction_in(lo, hi, rng)
        for y, (lo, hi) in half_tan:
            u = _fraction_in(lo, hi, rng)
            den = 1 + u * u
            sin, cos = 2 * u / den, (1 - u * u) / den
            env.update({stand_in[sp.sin(y)]: sin, stand_in[sp.cos(y)]: cos})
            if cos:
                env.update({stand_in[sp.tan(y)]: sin / cos, stand_in[sp.sec(y)]: 1 / cos})
            if sin:
                env.update({stand_in[sp.cot(y)]: cos / sin, stand_in[sp.csc(y)]: 1 / sin})
        both = _exact_values(program, env)
        if both is not None:
            va, vb = both
        else:  # one side has no value here: which one decides
            if not alone:
                alone = [ev.compile_program([e]) for e in exprs]
            vb = _exact_value(alone[1], env)
            if vb is None:
                continue  # the reference is undefined here: redraw
            va = _exact_value(alone[0], env)
        if va is None or va != vb:
            return False  # undefined where the reference is defined, or different
        done += 1
        if done >= points:
            return True
    return True if done else None


#: The instructions a rational function compiles to (after the trig atoms are stood in for).
_RATIONAL_OPS = frozenset({"in", "const", "add", "mul", "powi"})


class _FractionBackend:
    """Exact rational arithmetic for `evaluate.run`: constants are Fractions; anything else
    never reaches it (`_RATIONAL_OPS`)."""

    @staticmethod
    def const(value: ev.Constant) -> Fraction:
        if not isinstance(value, Fraction):
            raise _OutOfScope(f"constant {value}")
        return value


def _exact_values(program, env: Mapping) -> list[Fraction] | None:
    """The program's values at a point, exactly; None where one is undefined (a division by
    zero, or a trig function without a value there)."""
    try:
        return ev.run(program, env, _FractionBackend)
    except (ZeroDivisionError, ev.UnsupportedExpression, _OutOfScope):
        return None


def _exact_value(program, env: Mapping) -> Fraction | None:
    values = _exact_values(program, env)
    return None if values is None else values[0]


def _fraction_in(lo: float, hi: float, rng: np.random.Generator) -> Fraction:
    """A random rational inside (lo, hi): a float drawn there, read exactly, so that the points
    keep the scale of the domain (1e-27 stays 1e-27, not a rounded 0)."""
    return Fraction(float(rng.uniform(lo, hi)))


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
