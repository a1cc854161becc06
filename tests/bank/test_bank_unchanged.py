"""The bank as scene files derives what the Python scenes it replaced derived: for every scene and
every presentation (each combination of option choices and coordinate names), the declaration,
the seeded draws, the statement, bodies, constraints, DOF, transformation, T, V, L, Euler-Lagrange
expressions, momenta, cyclic coordinates, conserved quantities, quantities, used parameters and
the figure (SVG and PDF bytes) are those recorded from main at b755f21, the last commit before
the conversion (`bank_derived.py`; the record is never regenerated from the new code)."""

from __future__ import annotations

import json
import pathlib

import pytest

from lagrade.bank import get_scene, scene_ids
from tests.bank.bank_derived import scene_record

RECORD = json.loads((pathlib.Path(__file__).parent / "data" / "bank_derived.json").read_text())
BY_ID = {s["id"]: s for s in RECORD["scenes"]}


def test_the_bank_has_the_same_scenes_in_the_same_order():
    assert scene_ids() == RECORD["order"]


@pytest.mark.parametrize("scene_id", RECORD["order"])
def test_every_presentation_derives_what_it_did(scene_id):
    old = BY_ID[scene_id]
    new = scene_record(get_scene(scene_id))
    for key in old:
        if key != "presentations":
            assert new[key] == old[key], key
    assert len(new["presentations"]) == len(old["presentations"])
    for was, now in zip(old["presentations"], new["presentations"], strict=True):
        for key in was:
            assert now[key] == was[key], (was["names"], was["options"], key)
