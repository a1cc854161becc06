"""Derivatives of a compiled expression along the jet space at the sample points, from one
hyper-dual evaluation: the Euler–Lagrange expressions E(L), gradients, and the on-shell time
derivative D_t Q of a candidate conserved quantity."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp

from lagrade.judge.compiled import Compiled, tiled, to_length
from lagrade.judge.evaluate import FLOAT, Program, run_hyperdual
from lagrade.judge.sampling import memo_inputs
from lagrade.mechanics import Jet, t


def _tile(x, copies: int, n: int, backend):
    return tiled(to_length(x, n, backend), copies)


def _unit_blocks(copies: int, n: int, hot: int, backend):
    """An array of `copies` blocks of n entries: ones in block `hot`, zeros elsewhere."""
    arr = np.zeros(copies * n)
    arr[hot * n : (hot + 1) * n] = 1.0
    return backend.array(arr) if backend is not FLOAT else arr


def euler_lagrange_values(
    L: Compiled, jets: Sequence[Jet], env: Mapping, backend=FLOAT, memo: bool = True
):
    """E_j = D_t(∂L/∂q̇_j) − ∂L/∂q_j at the points of env, and the size of its terms; both of
    shape (points, coordinates).

    `memo=False` for points seen once (a draw's candidates): their seeds are not kept.

    Hyper-dual evaluation: ε₁ is the direction of the motion (∂t = 1, ∂q = q̇, ∂q̇ = q̈), ε₂ is
    ∂/∂q̇_j in copy j and ∂/∂q_j in copy n + j; then D_t ∂L/∂q̇_j is the ε₁ε₂ part of copy j and
    ∂L/∂q_j the ε₂ part of copy n + j.
    """
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = 2 * n
    for j in jets:
        if j.ddot in L.symbols:
            raise ValueError("a Lagrangian must not contain accelerations")
    if backend is FLOAT and memo:
        seeds = memo_inputs("el", env, jets, lambda: _el_seeds(jets, env, env, backend))
    else:
        seeds = _el_seeds(jets, env, L.symbols, backend)
    terms = L.hyperdual({s: seeds[s] for s in L.symbols if s in seeds}, backend)
    dtype = float if backend is FLOAT else object
    E = np.zeros((n_pts, n), dtype=dtype)
    S = np.zeros((n_pts, n), dtype=dtype)
    for term in terms:
        d = to_length(term[3], copies * n_pts, backend)
        c = to_length(term[2], copies * n_pts, backend)
        for k in range(n):
            dk = d[k * n_pts : (k + 1) * n_pts]
            ck = c[(n + k) * n_pts : (n + k + 1) * n_pts]
            E[:, k] = E[:, k] + dk - ck
            S[:, k] = S[:, k] + abs(dk) + abs(ck)
    return E, S


def euler_lagrange_terms(program: Program, jets: Sequence[Jet], env: Mapping):
    """E_j of each output of `program` separately and its size, (outputs, points, coordinates)
    each, in float64 from one hyper-dual pass: the Euler–Lagrange values of many terms (a
    reference's terms and the pieces of its mistakes) for the price of one evaluation."""
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = 2 * n
    seeds = memo_inputs("el", env, jets, lambda: _el_seeds(jets, env, env, FLOAT))
    terms = run_hyperdual(program, {s: seeds[s] for s in program.symbols if s in seeds})
    E = np.zeros((len(terms), n_pts, n))
    S = np.zeros((len(terms), n_pts, n))
    for k, term in enumerate(terms):
        d = to_length(term[3], copies * n_pts).reshape(copies, n_pts)
        c = to_length(term[2], copies * n_pts).reshape(copies, n_pts)
        E[k] = (d[:n] - c[n:]).T
        S[k] = (np.abs(d[:n]) + np.abs(c[n:])).T
    return E, S


def el_seeds(jets: Sequence[Jet], env: Mapping, wanted) -> dict:
    """The hyper-dual inputs of `euler_lagrange_values` (float64) for the symbols in `wanted`,
    not memoised: for points seen once."""
    return _el_seeds(jets, env, wanted, FLOAT)


def _el_seeds(jets: Sequence[Jet], env: Mapping, wanted, backend) -> dict:
    """Hyper-dual inputs of the symbols in `wanted` for `euler_lagrange_values`."""
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = 2 * n
    seeds: dict = {}
    for s in wanted:
        if s in env:
            seeds[s] = (_tile(env[s], copies, n_pts, backend), 0, 0, 0)
    for k, j in enumerate(jets):
        if j.q in wanted:
            seeds[j.q] = (
                _tile(env[j.q], copies, n_pts, backend),
                _tile(env[j.dot], copies, n_pts, backend),
                _unit_blocks(copies, n_pts, n + k, backend),
                0,
            )
        if j.dot in wanted:
            seeds[j.dot] = (
                _tile(env[j.dot], copies, n_pts, backend),
                _tile(env[j.ddot], copies, n_pts, backend),
                _unit_blocks(copies, n_pts, k, backend),
                0,
            )
    if t in wanted:
        seeds[t] = (_tile(env[t], copies, n_pts, backend), 1, 0, 0)
    return seeds


def gradient(expr: Compiled, variables: Sequence[sp.Symbol], env: Mapping, backend=FLOAT):
    """∂expr/∂v for each v in `variables`, per term: a list over terms of arrays
    (points, variables), from one dual evaluation with one copy per variable."""
    n_pts = len(next(iter(env.values())))
    copies = max(1, len(variables))
    hd: dict = {}
    for s in expr.symbols:
        if s in env:
            hd[s] = (_tile(env[s], copies, n_pts, backend), 0, 0, 0)
    for k, v in enumerate(variables):
        if v in expr.symbols:
            hd[v] = (hd[v][0], _unit_blocks(copies, n_pts, k, backend), 0, 0)
    per_term = []
    for term in expr.hyperdual(hd, backend):
        d = to_length(term[1], copies * n_pts, backend)
        per_term.append(d.reshape(copies, n_pts).T)
    return per_term


def directions(jets: Sequence[Jet]) -> list[sp.Symbol]:
    """The variables of a function on the jet space without accelerations: t, q, q̇."""
    return [t] + [j.q for j in jets] + [j.dot for j in jets]


def time_derivative_on_shell(
    Q: Compiled, jets: Sequence[Jet], env: Mapping, accelerations: np.ndarray, backend=FLOAT
):
    """D_t Q = ∂Q/∂t + Σ q̇ ∂Q/∂q + Σ q̈ ∂Q/∂q̇ with q̈ the reference accelerations, and the
    size of its contributions; plus the gradient (for the "is it a constant" test)."""
    variables = directions(jets)
    grads = gradient(Q, variables, env, backend)
    n = len(jets)
    speed = [1] + [env[j.dot] for j in jets] + [accelerations[:, k] for k in range(n)]
    total, size = 0, 0
    grad_total = 0
    for g in grads:
        for k, v in enumerate(speed):
            contribution = g[:, k] * v
            total = total + contribution
            size = size + abs(contribution)
        grad_total = grad_total + g
    return total, size, grad_total
