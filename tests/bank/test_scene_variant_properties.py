"""Property tests over seeded variants: any seed of any scene gives a valid declaration whose
drawn values lie in their domains and whose follow-up quantities are finite real numbers."""

from __future__ import annotations

import math

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.bank import get_scene, scene_ids


@settings(max_examples=40, deadline=None)
@given(scene_id=st.sampled_from(scene_ids()), seed=st.integers(0, 10**6))
def test_any_seeded_variant_is_valid(scene_id, seed):
    scene = get_scene(scene_id)
    variant = scene.variant(seed)
    variant.validate()
    assert variant.statement()
    for name, value in variant.values.items():
        assert variant.domains[name].contains(value), name
    # The solution does not depend on the presentation: the same number of EOM, DOF.
    assert len(variant.euler_lagrange) == variant.dof == len(scene.coordinates)


@settings(max_examples=40, deadline=None)
@given(scene_id=st.sampled_from(scene_ids()), seed=st.integers(0, 10**6))
def test_quantities_are_finite_reals_at_the_drawn_values(scene_id, seed):
    variant = get_scene(scene_id).variant(seed)
    for name, expr in variant.quantities.items():
        value = sp.N(expr.xreplace(variant.numeric_values))
        assert value.is_real and math.isfinite(float(value)), (name, value)
