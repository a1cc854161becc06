"""Figures: every scene draws itself, deterministically, with its coordinates labelled."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from lagrade.assign.figures import draw
from lagrade.bank import get_scene, scene_ids


@pytest.mark.parametrize("scene_id", scene_ids())
def test_scene_draws_itself_deterministically(scene_id: str) -> None:
    variant = get_scene(scene_id).variant(2)
    first, second = draw(variant), draw(get_scene(scene_id).variant(2))
    assert first.svg == second.svg and first.pdf == second.pdf
    root = ET.fromstring(first.svg)
    assert root.tag.endswith("svg")
    assert first.pdf.startswith(b"%PDF") and b"CreationDate" not in first.pdf


def test_wedge_and_hoop_label_their_coordinates() -> None:
    wedge = draw(get_scene("wedge").variant(2)).svg.decode()
    hoop = get_scene("hoop").variant(2)
    drawn = draw(hoop).svg.decode()
    assert "α" in wedge and "h" in wedge
    assert {"θ": "theta", "ϕ": "phi"}[next(c for c in "θϕ" if c in drawn)] == hoop.names["theta"]
    assert "ω" in drawn and "R" in drawn
