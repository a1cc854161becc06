"""The decision every equivalence test ends in: a residual measured against the size of the terms
it is made of, equal below 1e-10, different above 1e-6, and in between recomputed at 50 digits."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import numpy as np

from lagrade.judge.evaluate import FLOAT, MP, MP_DIGITS
from lagrade.judge.tolerances import DIFFERENT_ABOVE, EQUAL_BELOW, MP_EQUAL_BELOW


@dataclass(frozen=True)
class Decision:
    """A decision: equal or not, which method decided, the worst ratio of residual to term size,
    and when different the index of a point where the answers differ (and why)."""

    equal: bool
    method: str
    worst: float
    where: int | None = None
    reason: str = ""


Residual = Callable[[object], tuple[np.ndarray, np.ndarray]]


def decide(residual: Residual, backends: tuple = (FLOAT, MP)) -> Decision:
    """Decide whether `residual` vanishes identically. `residual(backend)` returns arrays
    (r, s) of the residual and the size of the terms it is made of, per point (a second axis
    is allowed: several components per point). nan in r means the answer is undefined there.
    `backends`: the float and high-precision backends (complex ones for values compared in
    complex arithmetic, `Points.backends`).

    A point where float64 has no value (an overflow: SI quantities to a high power, whose
    ratio is inf/inf) is judged in high precision, whose exponents are unbounded, unless the
    answers already differ clearly elsewhere; only a point without a value there is undefined."""
    float_backend, mp_backend = backends
    with np.errstate(all="ignore"):
        r, s = residual(float_backend)
        r, s = np.asarray(r), np.asarray(s, dtype=float)
        r = r if np.iscomplexobj(r) else r.astype(float)  # never drop an imaginary part
        ratio = _ratio(r, s)
    per_point = ratio.reshape(ratio.shape[0], -1).max(axis=1) if ratio.ndim > 1 else ratio
    finite = np.isfinite(per_point)
    worst = float(per_point[finite].max()) if finite.any() else 0.0
    if finite.all():
        if worst < EQUAL_BELOW:
            return Decision(True, "numeric", worst)
        if worst > DIFFERENT_ABOVE:
            return Decision(False, "numeric", worst, int(per_point.argmax()))
    elif worst > DIFFERENT_ABOVE:
        # different where both sides have values: the counter-example is quoted there, not at
        # a point where one side is undefined
        differ = np.flatnonzero(finite & (per_point > DIFFERENT_ABOVE))
        return Decision(False, "numeric", math.inf, int(differ[per_point[differ].argmax()]))
    with mpmath.workdps(MP_DIGITS), np.errstate(all="ignore"):
        try:
            r_mp, s_mp = residual(mp_backend)
        except (ZeroDivisionError, OverflowError, ValueError):
            # mpmath raises where float64 gives inf or nan (1/0, 0 ** -1): undefined there.
            where = int(np.flatnonzero(~finite)[0]) if not finite.all() else int(per_point.argmax())
            return Decision(False, "numeric+mpmath50", math.inf, where, "undefined")
        ratio_mp = np.array(
            [_mp_ratio(a, b) for a, b in zip(np.ravel(r_mp), np.ravel(s_mp), strict=True)]
        ).reshape(np.shape(r_mp))
    per_point = (
        ratio_mp.reshape(ratio_mp.shape[0], -1).max(axis=1) if ratio_mp.ndim > 1 else ratio_mp
    )
    if not np.all(np.isfinite(per_point)):
        where = int(np.flatnonzero(~np.isfinite(per_point))[0])
        return Decision(False, "numeric+mpmath50", math.inf, where, "undefined")
    worst_mp = float(per_point.max())
    if worst_mp < MP_EQUAL_BELOW:
        return Decision(True, "numeric+mpmath50", worst_mp)
    return Decision(False, "numeric+mpmath50", worst_mp, int(per_point.argmax()))


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
