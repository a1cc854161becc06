"""The reference of a mechanics question by numbers: where its Euler–Lagrange expressions have
values, and its rows [A | c], from hyper-dual passes over the compiled L — not from compiling the
expressions sympy derives, which cost tens of milliseconds per question where these cost a
fraction of one (sympy stays for what is shown as text: keys, hints that quote a term)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from lagrade.judge.compiled import Compiled, finite_mask, to_length
from lagrade.judge.derivatives import el_seeds, euler_lagrange_values, gradient
from lagrade.judge.evaluate import MP, finite_in_mp
from lagrade.judge.rows import acceleration_blocks, rows_from_values
from lagrade.judge.tolerances import SINGULAR_MASS
from lagrade.mechanics import Jet


def lagrangian_mask(L: Compiled, jets: Sequence[Jet]) -> Callable[[dict], np.ndarray]:
    """A validity test for sampling a Lagrangian question: L and E(L) have values at the point.
    L is tested as `finite_mask` tests any reference (complex values are no values; a value
    past float range is one when high precision says so); E(L) by one hyper-dual pass, and at
    the points where float64 has none but L has a value, in high precision."""
    of_L = finite_mask([L])

    def valid(env: dict) -> np.ndarray:
        with np.errstate(all="ignore"):
            ok, finite = _finite_parts(L, jets, env)
        if not ok.all():
            ok = of_L(env)  # where float64 has no value: complex and high precision decide
        return _has_values(L, jets, env, ok, finite)

    return valid


def _finite_parts(L: Compiled, jets: Sequence[Jet], env: dict) -> tuple[np.ndarray, np.ndarray]:
    """Per point: every term of L finite, and every part E(L) is made of (D_t ∂L/∂q̇_j and
    ∂L/∂q_j of each term) finite, from one hyper-dual pass (the sizes need no summing here)."""
    n_pts, n = len(next(iter(env.values()))), len(jets)
    copies = 2 * n
    seeds = el_seeds(jets, env, L.symbols)
    terms = L.hyperdual({s: seeds[s] for s in L.symbols if s in seeds})
    value_ok = np.ones(n_pts, dtype=bool)
    parts_ok = np.ones(n_pts, dtype=bool)
    for a, _b, c, d in terms:
        value_ok &= np.isfinite(to_length(a, copies * n_pts)[:n_pts])
        c = to_length(c, copies * n_pts).reshape(copies, n_pts)[n:]
        d = to_length(d, copies * n_pts).reshape(copies, n_pts)[:n]
        parts_ok &= np.isfinite(c).all(axis=0) & np.isfinite(d).all(axis=0)
    return value_ok, parts_ok


def determined_mask(L: Compiled, jets: Sequence[Jet]) -> Callable[[dict], np.ndarray]:
    """`lagrangian_mask`, and the mass matrix A = ∂²L/∂q̇∂q̇ regular: the points where the
    equations of motion determine the accelerations (the eom and conserved parts). One
    hyper-dual pass at q̈ = 0, e_1, …, e_n and the drawn q̈ gives both."""
    of_L = finite_mask([L])
    n = len(jets)

    def valid(env: dict) -> np.ndarray:
        n_pts = len(next(iter(env.values())))
        with np.errstate(all="ignore"):
            blocks = acceleration_blocks(jets, env, memo=False)
            E, S = euler_lagrange_values(L, jets, blocks, memo=False)
            drawn = slice((n + 1) * n_pts, (n + 2) * n_pts)  # the block of the drawn q̈
            finite = np.all(np.isfinite(E[drawn]) & np.isfinite(S[drawn]), axis=1)
            ok = _has_values(L, jets, env, of_L(env), finite)
            M = rows_from_values(E, S, jets, env).coef[:, :, :n].astype(float)
            det = np.linalg.det(M)
            scale = np.prod(np.linalg.norm(M, axis=2), axis=1)
        return ok & np.isfinite(det) & (np.abs(det) > SINGULAR_MASS * scale)

    return valid


def _has_values(L, jets, env, ok: np.ndarray, finite: np.ndarray) -> np.ndarray:
    """ok, and E(L) finite where float64 says so (`finite`), else in high precision."""
    beyond = ok & ~finite
    if beyond.any():
        with np.errstate(all="ignore"):
            finite |= beyond & finite_in_mp(
                lambda p: euler_lagrange_values(L, jets, p, MP), env, beyond
            )
    return ok & finite


def momenta_and_energy(
    L: Compiled, jets: Sequence[Jet], env: dict
) -> tuple[np.ndarray, np.ndarray]:
    """p_j = ∂L/∂q̇_j (points, coordinates) and the energy function h = Σ q̇_j p_j − L
    (points,) at the points of env, from one dual pass over L (`derivatives.gradient`)."""
    n_pts = len(next(iter(env.values())))
    with np.errstate(all="ignore"):
        grads = gradient(L, [j.dot for j in jets], env)
        p = sum(grads) if grads else np.zeros((n_pts, len(jets)))
        p = np.broadcast_to(p, (n_pts, len(jets)))
        value, _ = L.values(env)
        h = sum(env[j.dot] * p[:, k] for k, j in enumerate(jets)) - value
    return np.asarray(p, float), np.broadcast_to(np.asarray(h, float), (n_pts,))
