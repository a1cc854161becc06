"""Numerical integration keeps what each scene calls conserved constant, and only that.

Every scene is integrated with DOP853 at tight tolerances over many characteristic times (the
parameters are of order one, so periods are of order one); a quantity is conserved when its
drift stays below 1e-8 of the size of its terms, and a non-cyclic momentum must drift visibly.
"""

import numpy as np
import pytest

from lagrade.bank import get_scene, scene_ids

from .crosscheck import evaluate_along, integrate, term_scale

T_END = 12.0
#: Start states that keep a run regular where a generic one would not (collisions, r → 0).
START = {
    "kepler": lambda n: [1.0, 0.3, 0.1, 0.9],
}


def start_state(scene_id: str, n: int) -> list[float]:
    if scene_id in START:
        return START[scene_id](n)
    rng = np.random.default_rng(7)
    return list(np.concatenate([rng.uniform(0.4, 0.9, n), rng.uniform(-0.4, 0.4, n)]))


@pytest.mark.parametrize("scene_id", scene_ids())
def test_declared_conserved_quantities_stay_constant(scene_id):
    variant = get_scene(scene_id).default
    n = len(variant.jets)
    ts, ys, params = integrate(variant, start_state(scene_id, n), T_END)
    conserved = variant.system.conserved_quantities
    assert conserved or variant.system.L.has(variant.namespace.t), (
        "a time-independent L conserves h"
    )
    for name, Q in conserved.items():
        values = evaluate_along(variant, Q, ts, ys, params)
        scale = term_scale(variant, Q, ts, ys, params)
        drift = np.max(np.abs(values - values[0])) / scale
        assert drift < 1e-8, f"{scene_id}: {name} drifts by {drift:.2e} of its terms"


@pytest.mark.parametrize("scene_id", scene_ids())
def test_momenta_of_non_cyclic_coordinates_change(scene_id):
    variant = get_scene(scene_id).default
    n = len(variant.jets)
    ts, ys, params = integrate(variant, start_state(scene_id, n), T_END)
    cyclic = set(variant.system.cyclic_coordinates)
    for name, p in zip(variant.coordinates, variant.system.generalized_momenta, strict=True):
        if name in cyclic:
            continue
        values = evaluate_along(variant, p, ts, ys, params)
        scale = term_scale(variant, p, ts, ys, params)
        assert np.max(np.abs(values - values[0])) / scale > 1e-3, f"p_{name} looks conserved"
