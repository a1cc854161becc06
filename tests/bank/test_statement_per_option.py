"""A student's statement describes their own variant only: for every scene and every combination
of its presentation options, the statement never words a choice the variant did not make (a
handout once listed all three potentials of the free particle, and every gauge of the charged
particle), and the parameters a handout lists are exactly those the variant needs."""

from __future__ import annotations

import itertools
import re
import string

import pytest

from lagrade.assign.symbols import part_symbols
from lagrade.bank.registry import SCENES
from lagrade.mechanics.scene import SceneVariant


def _combinations():
    for scene in SCENES:
        choices = [
            dict(zip(scene.options, c, strict=True))
            for c in itertools.product(*scene.options.values())
        ]
        for options in choices or [{}]:
            yield pytest.param(scene, options, id=f"{scene.id}-{'-'.join(options.values())}")


def _worded(scene, option: str, choice: str) -> str:
    return scene.wording.get(option, {}).get(choice, choice)


#: How a statement spells out a choice for every student ("gravity means V = m g z", "landau_y:
#: A = …", "(a massive pulley is …"): the enumerations the first statements had.
_ENUMERATION = r"(?<!\w){choice}(?:\s*:|\s+means\b|\s+\w+\s+is\b)|\(an?\s+{choice}\b"


@pytest.mark.parametrize("scene, options", list(_combinations()))
def test_the_statement_words_no_other_choice(scene, options):
    variant = SceneVariant(scene, options=options)
    statement = variant.statement()
    for option, chosen in options.items():
        mine = _worded(scene, option, chosen)
        for other in scene.options[option]:
            words = _worded(scene, option, other)
            if other != chosen and words not in mine and " " in words:
                assert words not in statement, (scene.id, option, chosen, statement)
        fixed = scene.statement.format(**{**variant.statement_fill, option: "…"})
        for choice in scene.options[option]:
            pattern = _ENUMERATION.format(choice=re.escape(choice))
            assert not re.search(pattern, fixed), (
                f"{scene.id}: the statement spells out the {option} choice {choice!r} for "
                f"every student: {fixed}"
            )


@pytest.mark.parametrize("scene, options", list(_combinations()))
def test_listed_parameters_are_the_ones_the_variant_needs(scene, options):
    variant = SceneVariant(scene, options=options)
    used = set(variant.used_parameters)
    needed = set()
    exprs = [variant.lagrangian, *variant.quantities.values()]
    exprs += [x for x in variant.transformation.values()]
    for expr in exprs:
        needed |= {str(s) for s in expr.free_symbols}
    named = set(re.findall(r"[A-Za-z_]\w*", variant.statement()))
    for name in variant.parameter_symbols:
        assert (name in used) == (name in needed or name in named), (scene.id, options, name)
    may_use = set()
    for part in ("lagrangian", "eom", "expression", "transformation"):
        for group in part_symbols(variant, part):
            may_use |= set(group["names"])
    assert may_use & set(variant.parameter_symbols) == used


def test_options_that_drop_a_parameter_drop_it_from_the_handout():
    free = next(s for s in SCENES if s.id == "free_particle")
    gravity = SceneVariant(free, options={"potential": "gravity"})
    assert "k" not in gravity.used_parameters and "k_z" not in gravity.used_parameters
    assert {"m", "g"} <= set(gravity.used_parameters)
    atwood = next(s for s in SCENES if s.id == "atwood")
    assert "M" not in SceneVariant(atwood, options={"pulley": "massless"}).used_parameters
    assert "M" in SceneVariant(atwood, options={"pulley": "massive"}).used_parameters


@pytest.mark.parametrize("scene", SCENES, ids=lambda s: s.id)
def test_a_renamed_coordinate_is_named_through_its_field(scene):
    """A coordinate that variants rename appears in the statement only as its `{field}`: a
    literal name stays behind when a student's variant calls it something else (the Kepler
    statement once said V = -G M m / r to a student whose radius was ρ)."""
    literal = "".join(text for text, *_ in string.Formatter().parse(scene.statement))
    for coordinate in scene.coordinates:
        if len(scene.renames.get(coordinate, (coordinate,))) > 1:
            assert not re.search(rf"(?<![\w'’]){re.escape(coordinate)}(?![\w'’])", literal), (
                scene.id,
                coordinate,
            )
