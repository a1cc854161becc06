"""The reference of a mechanics question by numbers: where its Euler–Lagrange expressions have
values, and its rows [A | c], from hyper-dual passes over the compiled L — not from compiling the
expressions sympy derives, which cost tens of milliseconds per question where these cost a
fraction of one (sympy stays for what is shown as text: keys, hints that quote a term)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from lagrade.judge.compiled import Compiled, finite_mask
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import MP, finite_in_mp
from lagrade.judge.rows import lagrangian_rows
from lagrade.mechanics.lagrange import Jet

#: A mass matrix whose determinant is below this fraction of the product of its rows' norms is
#: singular at the point: the accelerations are not determined there.
SINGULAR = 1e-6


def lagrangian_mask(L: Compiled, jets: Sequence[Jet]) -> Callable[[dict], np.ndarray]:
    """A validity test for sampling a Lagrangian question: L and E(L) have values at the point.
    L is tested as `finite_mask` tests any reference (complex values are no values; a value
    past float range is one when high precision says so); E(L) by one hyper-dual pass, and at
    the points where float64 has none but L has a value, in high precision."""
    of_L = finite_mask([L])

    def valid(env: dict) -> np.ndarray:
        ok = of_L(env)
        with np.errstate(all="ignore"):
            E, S = euler_lagrange_values(L, jets, env)
            finite = np.all(np.isfinite(E) & np.isfinite(S), axis=1)
            beyond = ok & ~finite
            if beyond.any():
                finite |= beyond & finite_in_mp(
                    lambda p: euler_lagrange_values(L, jets, p, MP), env, beyond
                )
        return ok & finite

    return valid


def determined_mask(L: Compiled, jets: Sequence[Jet]) -> Callable[[dict], np.ndarray]:
    """`lagrangian_mask`, and the mass matrix A = ∂²L/∂q̇∂q̇ regular: the points where the
    equations of motion determine the accelerations (the eom and conserved parts)."""
    mask = lagrangian_mask(L, jets)
    n = len(jets)

    def valid(env: dict) -> np.ndarray:
        ok = mask(env)
        with np.errstate(all="ignore"):
            M = lagrangian_rows(L, jets, env).coef[:, :, :n].astype(float)
            det = np.linalg.det(M)
            scale = np.prod(np.linalg.norm(M, axis=2), axis=1)
        return ok & np.isfinite(det) & (np.abs(det) > SINGULAR * scale)

    return valid
