"""The equations of motion a kinetic mistake of L leads to are derived monomial by monomial (E is
linear) and shared between mistakes; the result must be the very expression deriving E of the
whole change gives, term for term, since the catalogue names mistakes by those terms."""

from __future__ import annotations

import itertools

import pytest
import sympy as sp

from lagrade.bank.registry import SCENES
from lagrade.judge.mutations import _linear_euler_lagrange
from lagrade.mechanics.lagrange import LagrangianSystem
from lagrade.mechanics.scene import SceneVariant


def _variants():
    for scene in SCENES:
        for choice in itertools.product(*scene.options.values()):
            options = dict(zip(scene.options, choice, strict=True))
            yield pytest.param(scene, options, id=f"{scene.id}-{'-'.join(choice)}")


@pytest.mark.parametrize("scene, options", list(_variants()))
def test_per_monomial_derivation_equals_the_whole(scene, options):
    variant = SceneVariant(scene, options=options)
    T, jets = variant.kinetic_energy, variant.jets
    terms = sp.Add.make_args(sp.expand(T))
    shared: dict = {}
    for change in [T, *terms, *(-t for t in terms), *(t / 2 for t in terms)]:
        change = sp.expand(change)
        assert _linear_euler_lagrange(change, jets, shared) == (
            LagrangianSystem(change, jets).euler_lagrange
        ), change
