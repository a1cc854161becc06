"""Numerical integration of a scene's equations of motion A(q, q̇, t) q̈ = b(q, q̇, t), with the
project's default integrator and tolerances.

Why these defaults (measured by benchmarks/bench_integrators.py, docs/integrators.csv): FIGURES

The right-hand side is built from `variant.system.mass_matrix` and `.forcing` with lambdify —
these are bank expressions derived by the project, never student text.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.integrate import OdeSolution, solve_ivp

from . import mechanics as mech
from .errors import LagradeError
from .scene import SceneVariant

#: The default method and tolerances (see the module docstring for the measurements).
METHOD = "DOP853"
RTOL = 1e-12
ATOL = 1e-12


class IntegrationError(LagradeError):
    """The integrator could not follow the motion (a singular mass matrix, a step size underflow)."""


def parameter_values(variant: SceneVariant, values: Mapping[str, float] | None = None) -> dict[sp.Symbol, float]:
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
        raise IntegrationError(f"y0 needs {2 * n} numbers (q then q_dot for {list(variant.coordinates)}), got {len(y0)}")
    rhs = right_hand_side(variant, values)
    try:
        sol = solve_ivp(rhs, (0.0, float(t_end)), np.asarray(y0, dtype=float), method=method, rtol=rtol,
                        atol=atol, t_eval=t_eval, dense_output=dense_output)
    except np.linalg.LinAlgError as error:
        raise IntegrationError(f"{variant.scene.id}: the mass matrix became singular ({error})") from None
    if not sol.success:
        raise IntegrationError(f"{variant.scene.id}: {method} failed: {sol.message}")
    return sol


__all__ = ["ATOL", "METHOD", "RTOL", "IntegrationError", "OdeSolution", "integrate", "parameter_values",
           "right_hand_side"]
