"""The bank is a folder of scene files read by the one reader: every file listed once in
`order.txt`, every file valid in every presentation when read as an instructor's file would be,
and every quantity's declared claim true of the derived motion (the check `lagrade scene check`
runs), in every combination of options."""

from __future__ import annotations

import itertools

import pytest

from lagrade.bank import get_scene, scene_ids
from lagrade.bank.registry import BANK
from lagrade.bank.scenefile import read_scene_file
from lagrade.bank.scenefile.claims import check_claim
from lagrade.mechanics.scene import SceneVariant


def test_every_file_is_listed_once_in_the_order():
    files = sorted(p.name.removesuffix(".toml") for p in BANK.glob("*.toml"))
    assert sorted(scene_ids()) == files
    assert len(set(scene_ids())) == len(scene_ids())


def test_no_scene_is_declared_in_python():
    assert not list(BANK.glob("*.py"))


@pytest.mark.parametrize("scene_id", scene_ids())
def test_each_file_reads_as_an_instructors_file(scene_id):
    """Read with full validation (the bank's own reading skips it for speed)."""
    scene = read_scene_file(BANK / f"{scene_id}.toml", validate=True)
    assert scene.coordinates == get_scene(scene_id).coordinates


@pytest.mark.parametrize("scene_id", [i for i in scene_ids() if get_scene(i).quantities])
def test_every_quantity_holds_for_the_derived_motion(scene_id):
    scene = get_scene(scene_id)
    for chosen in itertools.product(*scene.options.values()):
        variant = SceneVariant(scene, options=dict(zip(scene.options, chosen, strict=True)))
        for q in scene.quantities:
            assert q.claim is not None, f"{q.name} declares no check"
            assert check_claim(variant, q.claim(variant.namespace)) == [], (q.name, chosen)


def test_a_wrong_quantity_is_caught():
    """The hoop's equilibrium angle halved: the check says the bead accelerates there."""
    scene = get_scene("hoop")
    variant = scene.default
    (q,) = scene.quantities
    claim = q.claim(variant.namespace)
    theta = variant.jets[0]
    wrong = type(claim)(
        {theta.q: claim.at[theta.q] / 2, theta.dot: claim.at[theta.dot]}, claim.accelerations
    )
    failures = check_claim(variant, wrong)
    assert failures and "theta_ddot is" in failures[0]
