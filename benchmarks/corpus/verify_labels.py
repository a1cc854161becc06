"""Check every label of the corpus independently of the methods being measured.

Run: python benchmarks/corpus/verify_labels.py [--fast] [--points N] [--no-proofs]

Numbers: each pair is evaluated at N (default 60) random points in its declared domains by a
small evaluator of its own (a recursive walk of the sympy tree in mpmath, real-valued
semantics: the log or square root of a negative number, asin outside [−1, 1], a division by zero
are undefined) — deliberately not lagrade.judge.evaluate, which some methods use. 60 digits
first; where
the two sides differ by more than 1e-40 relative, 150 digits decide whether that was cancellation
(the difference vanishes) or a real difference. Points where the reference is undefined are
skipped; an answer undefined where the reference is defined differs.

A true label needs agreement at every point (and at least 10 points where the reference is
defined); a false label needs a difference at one point at least.

Proofs: for true pairs, a − b is put through expand, ratsimp, trigsimp, expand_trig + ratsimp,
simplify and a half-angle substitution x = 2y (each with a time limit); the first that gives 0
is recorded, or "unproved" (identities that hold only on the declared domain have no such proof).
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import mpmath
import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus.corpus import ParsedPair, load  # noqa: E402

EQUAL_BELOW = mpmath.mpf(10) ** -40


class Undefined(Exception):
    """The expression has no real value at this point."""


_FUNCTIONS = {
    sp.sin: mpmath.sin,
    sp.cos: mpmath.cos,
    sp.tan: mpmath.tan,
    sp.cot: mpmath.cot,
    sp.sec: mpmath.sec,
    sp.csc: mpmath.csc,
    sp.asin: mpmath.asin,
    sp.acos: mpmath.acos,
    sp.atan: mpmath.atan,
    sp.sinh: mpmath.sinh,
    sp.cosh: mpmath.cosh,
    sp.tanh: mpmath.tanh,
    sp.exp: mpmath.exp,
    sp.log: mpmath.log,
    sp.Abs: abs,
    sp.sign: mpmath.sign,
}


def value(expr: sp.Basic, env: dict) -> mpmath.mpf:
    """expr at the point env (symbol → mpf), real-valued, at the current mpmath precision."""
    if expr.is_Symbol:
        return env[expr]
    if expr.is_Rational:
        return mpmath.mpf(int(expr.p)) / int(expr.q)
    if expr is sp.pi:
        return +mpmath.pi
    if expr is sp.E:
        return +mpmath.e
    if expr.is_Float:
        return mpmath.mpf(expr._mpf_)
    if expr.is_Add:
        return mpmath.fsum(value(a, env) for a in expr.args)
    if expr.is_Mul:
        return mpmath.fprod(value(a, env) for a in expr.args)
    if expr.is_Pow:
        base, exponent = value(expr.base, env), expr.exp
        if exponent.is_Integer:
            if base == 0 and exponent < 0:
                raise Undefined
            return base ** int(exponent)
        e = value(exponent, env)
        if base < 0 or (base == 0 and e <= 0):
            raise Undefined
        return mpmath.power(base, e)
    f = _FUNCTIONS.get(type(expr))
    if f is None or len(expr.args) != 1:
        raise TypeError(f"the verifier cannot evaluate {type(expr).__name__}")
    try:
        result = f(value(expr.args[0], env))
    except (ValueError, ZeroDivisionError):
        raise Undefined from None
    if isinstance(result, mpmath.mpc) or not mpmath.isfinite(result):
        raise Undefined
    return result


def _safe(expr, env):
    try:
        v = value(expr, env)
    except (Undefined, ZeroDivisionError):
        return None
    return v if mpmath.isfinite(v) else None


def _relative(a, b):
    scale = max(abs(a), abs(b))
    return mpmath.mpf(0) if scale == 0 else abs(a - b) / scale


@dataclass(frozen=True)
class Check:
    """What the verifier found for one pair."""

    id: str
    label: bool
    numeric: (
        bool | None
    )  # True: equal at every point; False: differs somewhere; None: too few points
    defined_points: int
    worst: float  # largest relative difference seen (at the decisive precision)
    proof: str  # "proved by …", "unproved", or "" for false pairs / when proofs are skipped

    @property
    def ok(self) -> bool:
        return self.numeric is not None and self.numeric == self.label


def numeric_verdict(
    pp: ParsedPair, points: int = 60, seed: int = 7
) -> tuple[bool | None, int, float]:
    """(equal?, number of points where the reference is defined, worst relative difference)."""
    symbols = sorted(pp.answer.free_symbols | pp.reference.free_symbols, key=lambda s: s.name)
    rng = np.random.default_rng(seed)
    defined, worst, differs = 0, 0.0, False
    for _ in range(points):
        point = {s: float(rng.uniform(*pp.domains[s].sample_range())) for s in symbols}
        verdict = None
        for digits in (60, 150):
            with mpmath.workdps(digits):
                env = {s: mpmath.mpf(v) for s, v in point.items()}
                b = _safe(pp.reference, env)
                if b is None:
                    break
                a = _safe(pp.answer, env)
                if a is None:
                    verdict, rel = False, mpmath.inf
                    break
                rel = _relative(a, b)
                if rel < EQUAL_BELOW:
                    verdict = True
                    break
                verdict = False
        if verdict is None:
            continue
        defined += 1
        worst = max(worst, float(rel))
        differs |= not verdict
    if differs:
        return False, defined, worst
    return (True if defined >= 10 else None), defined, worst


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


def _halve_angles(e: sp.Expr) -> sp.Expr:
    """Substitute x = 2y for every symbol x that appears as x/2 in a trig argument, then
    expand_trig and ratsimp: half-angle identities become polynomial identities in sin y, cos y."""
    halves = {
        s
        for f in e.atoms(sp.sin, sp.cos, sp.tan, sp.cot)
        for s in f.args[0].free_symbols
        if sp.Rational(f.args[0].coeff(s)).q == 2
    }
    if not halves:
        return e
    e = e.xreplace({s: 2 * sp.Dummy(s.name, real=True) for s in halves})
    return sp.ratsimp(sp.expand_trig(e).rewrite(sp.sin, sp.cos).rewrite(sp.tan, sp.sin))


PROOFS = (
    ("expand", sp.expand),
    ("ratsimp", sp.ratsimp),
    ("trigsimp", sp.trigsimp),
    ("expand_trig+ratsimp", lambda e: sp.ratsimp(sp.expand_trig(e))),
    ("simplify", sp.simplify),
    ("half-angle substitution", lambda e: sp.trigsimp(_halve_angles(e))),
)


def proof(pp: ParsedPair, seconds: int = 5) -> str:
    """The first exact simplification that turns answer − reference into 0, or 'unproved'."""
    difference = pp.answer - pp.reference
    if difference == 0:
        return "proved by sympy's automatic evaluation"
    old = signal.signal(signal.SIGALRM, _alarm)
    try:
        for name, simplify in PROOFS:
            signal.alarm(seconds)
            try:
                if simplify(difference) == 0:
                    return f"proved by {name}"
            except _Timeout:
                continue
            except Exception:  # noqa: BLE001 - a simplifier that fails has proved nothing
                continue
            finally:
                signal.alarm(0)
    finally:
        signal.signal(signal.SIGALRM, old)
    return "unproved"


def check(pp: ParsedPair, points: int = 60, proofs: bool = True) -> Check:
    numeric, defined, worst = numeric_verdict(pp, points)
    found = proof(pp) if proofs and pp.label else ""
    return Check(pp.id, pp.label, numeric, defined, worst, found)


def fast_subset(pairs: list[ParsedPair]) -> list[ParsedPair]:
    """Every hand-written pair and every eighth bank pair: what the test suite verifies."""
    bank = [p for p in pairs if p.pair.category.startswith("bank")]
    return [p for p in pairs if not p.pair.category.startswith("bank")] + bank[::8]


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument(
        "--points", type=int, default=60, help="random points per pair (default 60)"
    )
    parser.add_argument(
        "--fast", action="store_true", help="hand-written pairs and every 8th bank pair"
    )
    parser.add_argument("--no-proofs", action="store_true", help="numbers only")
    args = parser.parse_args()
    start = time.perf_counter()
    pairs = load()
    if args.fast:
        pairs = fast_subset(pairs)
    results = [check(p, args.points, not args.no_proofs) for p in pairs]
    bad = [r for r in results if not r.ok]
    for r in bad:
        print(
            f"LABEL WRONG OR UNDECIDED: {r.id}: label {r.label}, numbers say {r.numeric} "
            f"({r.defined_points} points, worst relative difference {r.worst:.3g})"
        )
    proofs = Counter(r.proof for r in results if r.label and r.proof)
    print(
        f"verified {len(results) - len(bad)}/{len(results)} labels at {args.points} points "
        f"in {time.perf_counter() - start:.1f} s"
    )
    if proofs:
        true_pairs = sum(proofs.values())
        print(f"true pairs: {true_pairs - proofs.get('unproved', 0)}/{true_pairs} proved exactly")
        for how, n in proofs.most_common():
            print(f"  {how:45} {n}")
        unproved = [r.id for r in results if r.proof == "unproved"]
        if unproved:
            print("  unproved: " + ", ".join(unproved))
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
