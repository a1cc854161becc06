"""Numerical integration of a scene's equations of motion A(q, q̇, t) q̈ = b(q, q̇, t), with the
project's default integrator and tolerances.

Why LSODA at rtol = atol = 1e-12 (measured by `python benchmarks/bench_integrators.py`,
docs/integrators.csv and .png): over long runs of four bank scenes — simple pendulum to t = 500,
double pendulum released at (2, 2.5) rad (chaotic) to t = 200, an eccentric Kepler orbit to
t = 200, the bead on the rotating hoop to t = 500 — it is the fastest setting whose conserved
quantities (h, and p_θ for Kepler) drift less than 1e-8 relative to their terms in every scene:
2.8 s for all four, worst drift 1.4e-9 (double pendulum); DOP853 at 1e-12 drifts less (worst
1.3e-10) but took 7.3 s; RK45 at 1e-12 15.5 s (worst 4.5e-10); Radau at 1e-9 46 s (worst
3.1e-9; 1e-12 is slower still). At 1e-6 every method drifts 8e-6 … 6e-4 in its worst scene,
at 1e-9 1.6e-7 … 9e-7 (Radau 3e-9), so 1e-12 it is. A symplectic Störmer–Verlet step (for the
separable pendulum and hoop) keeps its energy error bounded but at h² — 2e-7 at h = 0.001,
7–14 s a run — so it does not earn a place here. (Wall times on a shared 2-core machine; drifts
are reproducible.)

The right-hand side is built from `variant.system.mass_matrix` and `.forcing` with lambdify —
these are bank expressions derived by the project, never student text.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.integrate import OdeSolution, solve_ivp

from lagrade.errors import LagradeError
from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.scene import SceneVariant

#: The default method and tolerances (see the module docstring for the measurements).
METHOD = "LSODA"
RTOL = 1e-12
ATOL = 1e-12


class IntegrationError(LagradeError):
    """The integrator could not follow the motion (a singular mass matrix, a step underflow)."""


def parameter_values(
    variant: SceneVariant, values: Mapping[str, float] | None = None
) -> dict[sp.Symbol, float]:
    """Every parameter's number: the variant's drawn values, overridden by `values`; a parameter
    with neither gets the middle of its domain's sampling range."""
    out = {}
    given = dict(variant.values) | dict(values or {})
    for name, symbol in variant.parameter_symbols.items():
        if name in given:
            out[symbol] = float(given[name])
        else:
            lo, hi = variant.domains[name].sample_range()
            out[symbol] = 0.5 * (lo + hi)
    return out


def right_hand_side(variant: SceneVariant, values: Mapping[str, float] | None = None) -> Callable:
    """f(t, y) with y = (q, q̇): returns (q̇, q̈), q̈ solving A q̈ = b at every call."""
    params = parameter_values(variant, values)
    jets = variant.jets
    args = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    # lambdify on the bank's own derived matrices, never on student text (see the docstring)
    A = sp.lambdify(args, variant.system.mass_matrix.xreplace(params), "numpy")
    b = sp.lambdify(args, variant.system.forcing.xreplace(params), "numpy")
    n = len(jets)

    def rhs(time: float, y: np.ndarray) -> np.ndarray:
        Am = np.array(A(time, *y), dtype=float).reshape(n, n)
        bm = np.array(b(time, *y), dtype=float).reshape(n)
        return np.concatenate([y[n:], np.linalg.solve(Am, bm)])

    return rhs


def integrate(
    variant: SceneVariant,
    y0: Sequence[float],
    t_end: float,
    *,
    values: Mapping[str, float] | None = None,
    t_eval: Sequence[float] | None = None,
    method: str = METHOD,
    rtol: float = RTOL,
    atol: float = ATOL,
    dense_output: bool = False,
):
    """Integrate the scene's motion from y0 = (q₁ … q_n, q̇₁ … q̇_n) at t = 0 to t_end.

    Returns scipy's OdeResult (`t`, `y`, `sol` when dense_output). Example, a simple pendulum
    released at 1 rad: `integrate(get_scene("simple_pendulum").default, [1.0, 0.0], 10.0)`.
    """
    n = len(variant.jets)
    if len(y0) != 2 * n:
        raise IntegrationError(
            f"y0 needs {2 * n} numbers (q, then q_dot, for {list(variant.coordinates)}), "
            f"got {len(y0)}"
        )
    rhs = right_hand_side(variant, values)
    try:
        sol = solve_ivp(
            rhs,
            (0.0, float(t_end)),
            np.asarray(y0, dtype=float),
            method=method,
            rtol=rtol,
            atol=atol,
            t_eval=t_eval,
            dense_output=dense_output,
        )
    except np.linalg.LinAlgError as error:
        raise IntegrationError(
            f"{variant.scene.id}: the mass matrix became singular ({error})"
        ) from None
    if not sol.success:
        raise IntegrationError(f"{variant.scene.id}: {method} failed: {sol.message}")
    return sol


__all__ = [
    "ATOL",
    "METHOD",
    "RTOL",
    "IntegrationError",
    "OdeSolution",
    "integrate",
    "parameter_values",
    "right_hand_side",
]
