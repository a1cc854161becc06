"""Where integrators drift, pinned, and the default (benchmarks/integrate.py) holding the
conserved quantities of bank scenes to 1e-8 over runs long enough to show the drift
(figures and chart: docs/integrators.csv, benchmarks/bench_integrators.py)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from benchmarks.integrate import ATOL, METHOD, RTOL, integrate, parameter_values
from lagrade.bank.registry import get_scene
from lagrade.mechanics import lagrange as mech


def relative_drift(variant, expr: sp.Expr, sol) -> float:
    """max |Q(t) − Q(0)| over the run / Σ |terms of Q| at t = 0."""
    params = parameter_values(variant)
    jets = variant.jets
    args = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    expr = expr.xreplace(params)
    values = np.asarray(
        sp.lambdify(args, expr, "numpy")(sol.t, *sol.y), dtype=float
    ) * np.ones_like(sol.t)
    scale = sum(
        abs(float(sp.lambdify(args, term, "numpy")(sol.t[0], *sol.y[:, 0])))
        for term in sp.Add.make_args(sp.expand(expr))
    )
    return float(np.max(np.abs(values - values[0])) / scale)


RUNS = {
    "double_pendulum": ((2.0, 2.5, 0.0, 0.0), 30.0, "h"),
    "kepler": ((1.0, 0.0, 0.0, 1.2), 30.0, "p_theta"),
    "simple_pendulum": ((1.0, 0.0), 60.0, "h"),
}


def _run(scene: str, **options):
    y0, t_end, quantity = RUNS[scene]
    variant = get_scene(scene).default
    sol = integrate(variant, y0, t_end, t_eval=np.linspace(0.0, t_end, 301), **options)
    return relative_drift(variant, variant.conserved_quantities[quantity], sol)


@pytest.mark.parametrize("scene", sorted(RUNS))
def test_default_integrator_holds_conserved_quantity(scene):
    assert _run(scene) < 1e-8


def test_double_pendulum_energy_drifts_with_rk45_at_scipys_default_tolerances():
    # solve_ivp's own defaults are rtol 1e-3, atol 1e-6.
    assert _run("double_pendulum", method="RK45", rtol=1e-3, atol=1e-6) > 1e-6


def test_double_pendulum_energy_drifts_at_loose_tolerances():
    for method in ("RK45", "DOP853", "LSODA"):
        assert _run("double_pendulum", method=method, rtol=1e-6, atol=1e-6) > 1e-8, method


def test_kepler_angular_momentum_drifts_with_lsoda_at_1e_6():
    assert _run("kepler", method="LSODA", rtol=1e-6, atol=1e-6) > 1e-6


def test_default_is_what_the_docstring_names():
    import benchmarks.integrate as integrate_module

    assert f"{METHOD}" in integrate_module.__doc__
    assert f"{RTOL:g}" in integrate_module.__doc__ and ATOL == RTOL
