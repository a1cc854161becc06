"""Every scene in the bank is a valid declaration in every presentation it offers: the default,
seeded variants, each option choice and each coordinate name."""

from __future__ import annotations

import itertools
import string

import pytest

from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics.scene import SceneVariant

LECTURE = (
    "free_particle",
    "wedge",
    "hoop",
    "projectile",
    "kepler",
    "wheel",
    "charged_particle",
    "incline_pendulum",
)
REQUIRED = LECTURE + (
    "simple_pendulum",
    "double_pendulum",
    "spherical_pendulum",
    "spring_pendulum",
    "atwood",
    "pendulum_on_cart",
    "rotating_rod_bead",
    "cone_particle",
    "rolling_cylinder",
    "coupled_oscillators",
    "rotating_frame",
    "driven_pendulum",
    "harmonic_oscillator",
)


def test_the_bank_starts_with_the_lecture_systems_in_lecture_order():
    assert tuple(scene_ids()[: len(LECTURE)]) == LECTURE
    assert all("lecture" in get_scene(i).tags for i in LECTURE)
    assert not any("lecture" in get_scene(i).tags for i in scene_ids()[len(LECTURE) :])


def test_the_bank_holds_every_required_system():
    assert set(REQUIRED) <= set(scene_ids())
    assert len(scene_ids()) >= 22


@pytest.mark.parametrize("scene_id", scene_ids())
def test_default_variant_is_valid(scene_id):
    variant = get_scene(scene_id).default
    variant.validate()
    assert variant.dof == len(variant.coordinates)


@pytest.mark.parametrize("scene_id", scene_ids())
def test_every_option_choice_is_valid(scene_id):
    scene = get_scene(scene_id)
    for combo in itertools.product(*scene.options.values()):
        SceneVariant(scene, options=dict(zip(scene.options, combo, strict=True))).validate()


@pytest.mark.parametrize("scene_id", scene_ids())
def test_seeded_variants_are_valid_and_reproducible(scene_id):
    scene = get_scene(scene_id)
    for seed in range(4):
        variant = scene.variant(seed)
        variant.validate()
        again = scene.variant(seed)
        assert (variant.names, variant.options, variant.values) == (
            again.names,
            again.options,
            again.values,
        )


@pytest.mark.parametrize("scene_id", scene_ids())
def test_every_combination_of_names_is_usable(scene_id):
    """Alternative names never clash with a parameter or with each other, and the statement
    shows each of them."""
    scene = get_scene(scene_id)
    choices = [scene.renames.get(c, (c,)) for c in scene.coordinates]
    for names in itertools.product(*choices):
        variant = SceneVariant(scene, names=dict(zip(scene.coordinates, names, strict=True)))
        text = variant.statement()
        for name in names:
            assert name in text


@pytest.mark.parametrize("scene_id", scene_ids())
def test_statement_names_every_coordinate_and_option(scene_id):
    scene = get_scene(scene_id)
    fields = {f for _, f, _, _ in string.Formatter().parse(scene.statement) if f}
    parameters = {p.name for p in scene.parameters}
    # a parameter may be a field too, where its name is also an English word ("a distance {a}")
    assert set(scene.coordinates) | set(scene.options) <= fields
    assert fields - set(scene.coordinates) - set(scene.options) <= parameters


@pytest.mark.parametrize("scene_id", scene_ids())
def test_parameters_have_units_descriptions_and_values_inside_their_domain(scene_id):
    for p in get_scene(scene_id).parameters:
        assert p.unit and p.description, p.name
        assert p.values, f"{p.name} has no values for numeric variants"
        assert all(p.domain.contains(x) for x in p.values), p.name


@pytest.mark.parametrize("scene_id", scene_ids())
def test_quantities_have_units_and_use_only_parameters(scene_id):
    variant = get_scene(scene_id).default
    parameters = set(variant.parameter_symbols.values())
    for q in variant.scene.quantities:
        assert q.unit and q.description, q.name
        assert variant.quantities[q.name].free_symbols <= parameters, q.name
