"""The decision every equivalence test ends in: a residual measured against the size of the terms
it is made of, equal below 1e-10, different above 1e-6, and in between recomputed at 50 digits."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import numpy as np

from lagrade.judge.evaluate import FLOAT, MP, MP_DIGITS

#: Below this ratio of residual to term size the answers agree in float64.
EQUAL_BELOW = 1e-10
#: Above it they differ; in between, 50-digit arithmetic decides.
DIFFERENT_ABOVE = 1e-6
#: The 50-digit decision: equal below this ratio.
MP_EQUAL_BELOW = 1e-30


@dataclass(frozen=True)
class Outcome:
    """A decision: equal or not, which method decided, the worst ratio of residual to term size,
    and when different the index of a point where the answers differ (and why)."""

    equal: bool
    method: str
    worst: float
    where: int | None = None
    reason: str = ""


Residual = Callable[[object], tuple[np.ndarray, np.ndarray]]


def decide(residual: Residual) -> Outcome:
    """Decide whether `residual` vanishes identically. `residual(backend)` returns arrays
    (r, s) of the residual and the size of the terms it is made of, per point (a second axis
    is allowed: several components per point). nan in r means the answer is undefined there."""
    with np.errstate(all="ignore"):
        r, s = residual(FLOAT)
        r, s = np.asarray(r), np.asarray(s, dtype=float)
        r = r if np.iscomplexobj(r) else r.astype(float)  # never drop an imaginary part
        ratio = _ratio(r, s)
    per_point = ratio.reshape(ratio.shape[0], -1).max(axis=1) if ratio.ndim > 1 else ratio
    if not np.all(np.isfinite(per_point)):
        # a counter-example where both sides are defined, when there is one: a point where
        # one side is undefined is quoted only when the answers differ nowhere else
        differ = np.flatnonzero(np.isfinite(per_point) & (per_point > DIFFERENT_ABOVE))
        if differ.size:
            return Outcome(False, "numeric", math.inf, int(differ[per_point[differ].argmax()]))
        where = int(np.flatnonzero(~np.isfinite(per_point))[0])
        return Outcome(False, "numeric", math.inf, where, "undefined")
    worst = float(per_point.max()) if per_point.size else 0.0
    if worst < EQUAL_BELOW:
        return Outcome(True, "numeric", worst)
    if worst > DIFFERENT_ABOVE:
        return Outcome(False, "numeric", worst, int(per_point.argmax()))
    with mpmath.workdps(MP_DIGITS), np.errstate(all="ignore"):
        try:
            r_mp, s_mp = residual(MP)
        except (ZeroDivisionError, OverflowError, ValueError):
            # mpmath raises where float64 gives inf or nan (1/0, 0 ** -1): undefined there.
            where = int(per_point.argmax())
            return Outcome(False, "numeric+mpmath50", math.inf, where, "undefined")
        ratio_mp = np.array(
            [_mp_ratio(a, b) for a, b in zip(np.ravel(r_mp), np.ravel(s_mp), strict=True)]
        ).reshape(np.shape(r_mp))
    per_point = (
        ratio_mp.reshape(ratio_mp.shape[0], -1).max(axis=1) if ratio_mp.ndim > 1 else ratio_mp
    )
    worst_mp = float(per_point.max())
    if worst_mp < MP_EQUAL_BELOW:
        return Outcome(True, "numeric+mpmath50", worst_mp)
    return Outcome(False, "numeric+mpmath50", worst_mp, int(per_point.argmax()))


def _ratio(r: np.ndarray, s: np.ndarray) -> np.ndarray:
    """|r| / s, with 0/0 = 0 (an answer and reference that are both exactly zero agree) and
    r/0 = inf for r ≠ 0; nan where r is nan (undefined). Call under np.errstate."""
    ratio = np.abs(r) / s
    both_zero = (s == 0) & (r == 0)
    if both_zero.any():
        ratio = np.where(both_zero, 0.0, ratio)
    return ratio


def _mp_ratio(r, s) -> float:
    if not (mpmath.isfinite(r) and mpmath.isfinite(s)):
        return math.inf
    if s == 0:
        return 0.0 if r == 0 else math.inf
    return float(abs(r) / s)
