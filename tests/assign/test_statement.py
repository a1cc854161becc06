"""Statements as handouts print them: coordinates set as math where the scene placed them and
nowhere else (never inside "pendulum's"), each variant told only its own convention."""

from __future__ import annotations

import itertools
import re

import pytest

from lagrade.assign.views import _statement
from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics.scene import SceneVariant


def every_naming(scene_id: str) -> list[SceneVariant]:
    scene = get_scene(scene_id)
    renames = sorted(scene.renames.items())
    keys = sorted(scene.options)
    variants = []
    for names in itertools.product(*(choices for _, choices in renames)):
        for combo in itertools.product(*(scene.options[k] for k in keys)):
            variants.append(
                SceneVariant(
                    scene,
                    names=dict(zip([c for c, _ in renames], names, strict=True)),
                    options=dict(zip(keys, combo, strict=True)),
                )
            )
    return variants


@pytest.mark.parametrize("scene_id", scene_ids())
def test_no_math_inside_a_word(scene_id: str) -> None:
    for variant in every_naming(scene_id):
        st = _statement(variant)
        assert not re.search(r"['\u2019]\$|\w\$\w", st["md"]), st["md"]
        assert not re.search(r"['\u2019]\$", st["tex"]), st["tex"]
        assert not re.search(r"(&#39;|&#x27;|')<math", str(st["html"])), st["html"]


def test_a_coordinate_renamed_s_leaves_the_possessive_alone() -> None:
    variant = SceneVariant(get_scene("incline_pendulum"), names={"s": "s", "phi": "psi"})
    st = _statement(variant)
    for fmt in ("md", "tex"):
        assert "pendulum's angle $\\psi$" in st[fmt]
        assert "incline's slope" in st[fmt]
        assert "the distance $s$ the block" in st[fmt]
    assert "pendulum&#39;s angle <math" in str(st["html"])


def test_each_incline_pendulum_variant_states_only_its_own_convention() -> None:
    scene = get_scene("incline_pendulum")
    vertical = SceneVariant(scene, options={"angle_from": "vertical"}).statement()
    horizontal = SceneVariant(scene, options={"angle_from": "horizontal"}).statement()
    assert "downward vertical" in vertical and "horizontal" not in vertical
    assert "horizontal that points" in horizontal and "vertical," not in horizontal


def test_a_parameter_that_is_also_an_english_word_is_set_as_math_where_marked() -> None:
    st = _statement(get_scene("coupled_oscillators").default)
    assert "the blocks are a distance $a$ apart" in st["md"]
    assert "Two blocks" in st["md"] and "$a$ spring" not in st["md"]
