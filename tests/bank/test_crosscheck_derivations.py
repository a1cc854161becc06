"""Every scene's Euler–Lagrange equations against sympy.physics.mechanics.LagrangesMethod."""

import pytest
import sympy as sp

from lagrade.bank import get_scene, scene_ids

from .crosscheck import lagranges_method_equations


@pytest.mark.parametrize("scene_id", scene_ids())
def test_euler_lagrange_matches_lagranges_method(scene_id):
    variant = get_scene(scene_id).default
    ours = variant.euler_lagrange
    theirs = lagranges_method_equations(variant)
    assert len(ours) == len(theirs)
    for mine, reference in zip(ours, theirs, strict=True):
        assert sp.simplify(mine - reference) == 0, (scene_id, mine, reference)


@pytest.mark.parametrize("scene_id", scene_ids())
def test_every_scene_validates_in_every_presentation(scene_id):
    scene = get_scene(scene_id)
    scene.default.validate()
    for seed in range(4):
        scene.variant(seed).validate()
