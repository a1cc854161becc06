"""Check the labels of the external cases (external.jsonl) independently of lagrade's judge:
both sides read by the project's parser (reading is not judging), then evaluated by sympy's own
`evalf` at 50 digits, in complex arithmetic on principal branches, at random points of the
declared domains (reals drawn from ±3 and ±40, the judge draws from ±3). A point counts where the
reference is finite; an answer undefined there, or different by more than 1e-40 relative,
differs. True needs agreement at every counted point (at least 10 of them); false needs one
difference.

Run: python benchmarks/corpus/verify_external.py
"""

from __future__ import annotations

import random
import sys
from pathlib import Path

import sympy as sp

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus.corpus import EXTERNAL, ParsedPair, load  # noqa: E402

DIGITS = 50
POINTS = 120


def _draw(domain, rng: random.Random) -> sp.Float:
    """A point of the domain: near the origin half the time (±3, where most features of
    textbook expressions are: (n + 1)^(1/(n + 1)) turns its branch on −2 < n < −1), within ±40
    otherwise."""
    reach = 3.0 if rng.random() < 0.5 else 40.0
    lo, hi = float(domain.lower), float(domain.upper)
    lo = max(lo, -reach) if lo != float("-inf") else -reach
    hi = min(hi, reach) if hi != float("inf") else reach
    if lo >= hi:  # a domain far from the origin (SI scales): its own bounds
        lo, hi = float(domain.lower), float(domain.upper)
    return sp.Float(rng.uniform(lo, hi), DIGITS)


def _finite(z: sp.Expr) -> bool:
    return z.is_number and z.is_finite is not False and not z.has(sp.nan, sp.zoo, sp.oo, -sp.oo)


def label_holds(pp: ParsedPair, points: int = POINTS, seed: int = 7) -> bool:
    """Whether the pair's stored label agrees with sympy's complex evaluation."""
    rng = random.Random(seed)
    compared = differs = 0
    for _ in range(points):
        values = {s: _draw(d, rng) for s, d in pp.domains.items()}
        ref = sp.N(pp.reference.xreplace(values), DIGITS)
        if not _finite(ref):
            continue
        compared += 1
        ans = sp.N(pp.answer.xreplace(values), DIGITS)
        if not _finite(ans) or abs(ans - ref) > sp.Float(10) ** -40 * (1 + abs(ref)):
            differs += 1
    if pp.pair.label:
        return compared >= 10 and differs == 0
    return differs > 0


def main() -> int:
    pairs = load(EXTERNAL)
    bad = [p.id for p in pairs if not label_holds(p)]
    print(f"external labels verified: {len(pairs) - len(bad)}/{len(pairs)}")
    for pid in bad:
        print(f"  does not verify: {pid}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
