"""Euler–Lagrange expressions are derived once per canonical form of L and renamed back for every
renaming of the coordinates; the renamed result must be the very expression a derivation under
the own names gives, term for term (the mistake catalogue names mistakes by those terms)."""

from __future__ import annotations

import itertools

import pytest
import sympy as sp

from lagrade.bank.registry import SCENES
from lagrade.mechanics.lagrange import _DERIVED, _RENAMED, Derivation, LagrangianSystem
from lagrade.mechanics.scene import SceneVariant


def _presentations():
    for scene in SCENES:
        renamings = [scene.renames.get(c, (c,)) for c in scene.coordinates]
        for choice in itertools.product(*scene.options.values()):
            options = dict(zip(scene.options, choice, strict=True))
            for names in itertools.product(*renamings):
                yield pytest.param(
                    scene,
                    dict(zip(scene.coordinates, names, strict=True)),
                    options,
                    id=f"{scene.id}-{'-'.join(names)}-{'-'.join(choice)}",
                )


@pytest.mark.parametrize("scene, names, options", list(_presentations()))
def test_a_shared_derivation_equals_the_own_one(scene, names, options):
    variant = SceneVariant(scene, names=names, options=options)
    system = LagrangianSystem(variant.lagrangian, variant.jets)
    own = Derivation(variant.lagrangian, variant.jets)
    assert system.euler_lagrange == own.equations
    assert system.generalized_momenta == own.momenta
    assert system.generalized_forces == own.forces
    # renamed back without a second expand, the results are expanded all the same
    for e in (*system.euler_lagrange, *system.generalized_momenta, *system.generalized_forces):
        assert sp.expand(e) == e


def test_renamed_systems_share_one_derivation():
    scene = next(s for s in SCENES if s.id == "pendulum_on_cart")
    renamings = [scene.renames.get(c, (c,)) for c in scene.coordinates]
    _DERIVED.clear()
    _RENAMED.clear()
    for names in itertools.product(*renamings):
        v = SceneVariant(scene, names=dict(zip(scene.coordinates, names, strict=True)))
        _ = LagrangianSystem(v.lagrangian, v.jets).euler_lagrange
    assert len(_DERIVED) == 1


def test_a_system_of_the_same_l_finds_what_another_derived_without_renaming_again():
    """Every variant of a scene builds its own system of one L: the second finds the first's
    results by (L, coordinates), the very expressions, and derives or renames nothing."""
    scene = next(s for s in SCENES if s.id == "pendulum_on_cart")
    first, second = SceneVariant(scene), SceneVariant(scene)  # two variants, two Ls
    assert first.lagrangian == second.lagrangian and first.jets == second.jets
    _RENAMED.clear()
    derived = LagrangianSystem(first.lagrangian, first.jets).euler_lagrange
    _DERIVED.clear()  # a second derivation, or a renaming of L, would put one here
    again = LagrangianSystem(second.lagrangian, second.jets)
    assert again.euler_lagrange is derived
    assert len(_DERIVED) == 0
