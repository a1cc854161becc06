"""The reference by numbers agrees with sympy's derivation: the Euler–Lagrange rows [A | c], the
generalized momenta and the energy function at a question's sample points, from hyper-dual and
dual passes over the compiled L (`lagrade.judge.reference`, `rows.lagrangian_rows`), against the
expressions `lagrade.mechanics` derives symbolically (E_j = D_t ∂L/∂q̇_j − ∂L/∂q_j, p_j, h =
Σ q̇_j p_j − L), compiled and evaluated at the same points — for every bank scene and seed."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.bank.registry import scene_ids
from lagrade.judge.compiled import Compiled
from lagrade.judge.problem import build_problem
from lagrade.judge.reference import momenta_and_energy
from lagrade.judge.rows import equation_rows, lagrangian_rows

AGREE = 1e-12


def _close(a, b, size):
    """a and b agree to AGREE of the size of the terms they are made of (or of their values)."""
    scale = np.maximum(np.maximum(np.abs(a), np.abs(b)), size)
    return np.all(np.abs(a - b) <= AGREE * np.maximum(scale, 1e-300))


@settings(max_examples=40, deadline=None)
@given(scene=st.sampled_from(scene_ids()), seed=st.none() | st.integers(0, 10_000))
def test_rows_momenta_and_energy_by_numbers_agree_with_sympy(scene, seed):
    spec = {"scene": scene} if seed is None else {"scene": scene, "seed": seed}
    problem = build_problem(spec)
    jets, system = problem.jets, problem.system
    env = problem.points("eom").env
    with np.errstate(all="ignore"):
        mine = lagrangian_rows(problem.L, jets, env)
        theirs = equation_rows(problem.euler_lagrange, jets, env)
        size = np.maximum(mine.size, theirs.size)[:, :, None]
        assert _close(mine.coef.astype(float), theirs.coef.astype(float), size)
        p, h = momenta_and_energy(problem.L, jets, env)
        for k, pk in enumerate(system.generalized_momenta):
            value, psize = Compiled.of(pk).values(env)
            assert _close(p[:, k], value, psize)
        value, hsize = Compiled.of(system.energy_function).values(env)
        assert _close(h, value, hsize)
