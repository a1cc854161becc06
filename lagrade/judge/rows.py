"""Equations linear in the accelerations, E = A q̈ + c, as rows [A | c] at each sample point: is a
student's equation in the span of the reference's rows, the rank of a set of rows, and the
accelerations of the reference's motion."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from lagrade.judge.compiled import Compiled, tiled, to_length, total
from lagrade.judge.derivatives import euler_lagrange_values
from lagrade.judge.evaluate import FLOAT
from lagrade.judge.sampling import memo_inputs
from lagrade.judge.tolerances import RANK
from lagrade.mechanics import Jet


@dataclass
class Rows:
    """Equations E = A q̈ + c at each point: `coef` (points, equations, n + 1) holds [A | c],
    `size` (points, equations) the size of their terms, `nonlinear` (points, equations) the
    part that is not linear in q̈ (zero for a proper equation of motion)."""

    coef: np.ndarray
    size: np.ndarray
    nonlinear: np.ndarray


def acceleration_blocks(
    jets: Sequence[Jet], env: Mapping, backend=FLOAT, memo: bool = True
) -> dict:
    """env repeated n + 2 times with q̈ = 0, e_1, …, e_n, and the drawn q̈ (kept per points
    unless `memo=False`, for points seen once)."""
    if backend is FLOAT and memo:
        return memo_inputs("blocks", env, jets, lambda: _acceleration_blocks(jets, env, FLOAT))
    return _acceleration_blocks(jets, env, backend)


def _acceleration_blocks(jets: Sequence[Jet], env: Mapping, backend) -> dict:
    n_pts = len(next(iter(env.values())))
    n = len(jets)
    copies = n + 2
    stacked = {s: tiled(v, copies) for s, v in env.items()}
    for k, j in enumerate(jets):
        q_dd = np.zeros(copies * n_pts)
        q_dd[(k + 1) * n_pts : (k + 2) * n_pts] = 1.0
        arr = backend.array(q_dd) if backend is not FLOAT else q_dd
        arr[(n + 1) * n_pts :] = env[j.ddot]
        stacked[j.ddot] = arr
    return stacked


def rows_from_values(
    values: np.ndarray, sizes: np.ndarray, jets: Sequence[Jet], env: Mapping
) -> Rows:
    """Rows from equation values at the acceleration blocks: values (blocks·points, equations)."""
    n = len(jets)
    n_pts = len(next(iter(env.values())))
    blocks = values.reshape(n + 2, n_pts, -1)
    size_blocks = sizes.reshape(n + 2, n_pts, -1)
    c = blocks[0]
    A = [blocks[k + 1] - c for k in range(n)]
    coef = np.stack(A + [c], axis=-1)  # (points, equations, n + 1)
    predicted = c + total(A[k] * env[j.ddot][:, None] for k, j in enumerate(jets))
    nonlinear = blocks[n + 1] - predicted
    size = size_blocks.max(axis=0) if blocks.dtype != object else _mp_max(size_blocks)
    return Rows(coef, size, nonlinear)


def _mp_max(arr: np.ndarray) -> np.ndarray:
    out = arr[0].copy()
    for k in range(1, arr.shape[0]):
        out = np.where(arr[k] > out, arr[k], out)
    return out


def equation_rows(
    equations: Sequence[Compiled], jets: Sequence[Jet], env: Mapping, backend=FLOAT
) -> Rows:
    """Rows [A | c] of equations given as expressions (lhs − rhs)."""
    stacked = acceleration_blocks(jets, env, backend)
    n_all = len(next(iter(stacked.values())))
    vals, sizes = [], []
    for eq in equations:
        v, s = eq.values(stacked, backend)
        vals.append(to_length(v, n_all, backend))
        sizes.append(to_length(s, n_all, backend))
    return rows_from_values(np.stack(vals, axis=-1), np.stack(sizes, axis=-1), jets, env)


def lagrangian_rows(L: Compiled, jets: Sequence[Jet], env: Mapping, backend=FLOAT) -> Rows:
    """Rows [A | c] of the Euler–Lagrange equations of L (from hyper-dual values)."""
    stacked = acceleration_blocks(jets, env, backend)
    E, S = euler_lagrange_values(L, jets, stacked, backend)
    return rows_from_values(E, S, jets, env)


def in_span(student: Rows, reference: Rows, k: int, backend=FLOAT) -> tuple[np.ndarray, np.ndarray]:
    """Residual of student row k outside the span of the reference rows, and its size, per
    point. The size counts the student's terms and the rounding the reference rows carry."""
    if backend is FLOAT:
        return _in_span_float(
            student.coef[:, k, :].astype(float),
            student.size[:, k].astype(float),
            reference.coef.astype(float),
            reference.size.astype(float),
        )
    n_pts = student.coef.shape[0]
    dtype = object
    r = np.zeros(n_pts, dtype=dtype)
    s = np.zeros(n_pts, dtype=dtype)
    for p in range(n_pts):
        R = reference.coef[p]  # (m, n + 1)
        x = student.coef[p, k]
        res = _project_out(R, x, backend)
        ref_norms = [_norm(row) for row in R]
        rel_ref = max(
            (sz / nr if nr != 0 else 0) for sz, nr in zip(reference.size[p], ref_norms, strict=True)
        )
        r[p] = _norm(res)
        s[p] = student.size[p, k] + _norm(x) * rel_ref
    return r, s


def span_basis(reference: Rows) -> tuple[np.ndarray, np.ndarray]:
    """An orthonormal basis Q (points, n + 1, m) of the reference rows at each point, and the
    relative size of their terms (points,): what `outside_span` needs of them, made once."""
    return _basis(reference.coef.astype(float), reference.size.astype(float))


def outside_span(x: np.ndarray, size: np.ndarray, basis: tuple[np.ndarray, np.ndarray]):
    """The part of rows x (points, n + 1) outside the span of the reference rows (given by
    their `span_basis`), and its size, per point, in float64 (`in_span` for arrays)."""
    Q, rel_ref = basis
    with np.errstate(all="ignore"):
        res = x - np.einsum("pij,pj->pi", Q, np.einsum("pji,pj->pi", Q, x))
        return np.linalg.norm(res, axis=1), size + np.linalg.norm(x, axis=1) * rel_ref


def _basis(R: np.ndarray, R_size: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    with np.errstate(all="ignore"):
        Q, _ = np.linalg.qr(np.transpose(R, (0, 2, 1)))  # (points, n+1, m): basis of the rows
        ref_norm = np.linalg.norm(R, axis=2)
        rel_ref = np.max(
            np.where(ref_norm > 0, R_size / np.where(ref_norm > 0, ref_norm, 1), 0), axis=1
        )
    return Q, rel_ref


def _in_span_float(x: np.ndarray, size: np.ndarray, R: np.ndarray, R_size: np.ndarray):
    """in_span for all points at once: x (points, n+1), R (points, m, n+1)."""
    return outside_span(x, size, _basis(R, R_size))


def _norm(v):
    return total(abs(x) ** 2 for x in v) ** 0.5 if len(v) else 0


def _project_out(R: np.ndarray, x: np.ndarray, backend):
    """x minus its least-squares projection on the row space of R."""
    if backend is FLOAT:
        coeffs, *_ = np.linalg.lstsq(R.T.astype(float), x.astype(float), rcond=None)
        return x - R.T @ coeffs
    Rm = mpmath.matrix(R.tolist())
    xm = mpmath.matrix(list(x))
    G = Rm * Rm.T
    try:
        y = mpmath.lu_solve(G, Rm * xm)
    except ZeroDivisionError:
        return np.array(list(x), dtype=object)
    res = xm - Rm.T * y
    return np.array([res[i] for i in range(res.rows)], dtype=object)


def row_rank(coef: np.ndarray, rows: Sequence[int]) -> int:
    """The rank of the chosen rows at a typical point (the most common rank over the points).
    Each point's rows are scaled to unit length and its zero rows left out; the points whose
    rows are zero alike share one stacked SVD (numpy's per-matrix LAPACK call, so each point's
    singular values are those of an SVD of its own)."""
    if not rows:
        return 0
    M = np.array(coef[:, list(rows)], dtype=float)  # (points, rows, columns)
    norms = np.linalg.norm(M, axis=2)
    nonzero = norms > 0
    ranks = np.zeros(M.shape[0], dtype=int)
    for pattern in np.unique(nonzero, axis=0):
        if not pattern.any():
            continue  # no row: rank 0
        at = np.flatnonzero((nonzero == pattern).all(axis=1))
        kept = M[at][:, pattern] / norms[at][:, pattern][:, :, None]
        sv = np.linalg.svd(kept, compute_uv=False)
        ranks[at] = (sv > RANK * sv[:, :1]).sum(axis=1)
    return int(np.bincount(ranks).argmax())


def solve_accelerations(reference: Rows, backend=FLOAT) -> np.ndarray:
    """q̈ with A q̈ = −c at every point (the motion of the reference): shape (points, n)."""
    n_pts, m, cols = reference.coef.shape
    n = cols - 1
    if backend is FLOAT:
        A = reference.coef[:, :, :n].astype(float)
        b = -reference.coef[:, :, n].astype(float)
        if m == n:
            return np.linalg.solve(A, b[..., None])[..., 0]
        return np.stack([np.linalg.lstsq(A[p], b[p], rcond=None)[0] for p in range(n_pts)])
    out = np.empty((n_pts, n), dtype=object)
    for p in range(n_pts):
        A = mpmath.matrix(reference.coef[p, :, :n].tolist())
        b = mpmath.matrix([-x for x in reference.coef[p, :, n]])
        x = mpmath.lu_solve(A, b)
        for k in range(n):
            out[p, k] = x[k]
    return out
