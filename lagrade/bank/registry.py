"""The bank: scenes by id."""

from __future__ import annotations

from lagrade.bank.scenes import SCENES
from lagrade.errors import UnknownSceneError
from lagrade.mechanics.scene import Scene

_BY_ID = {s.id: s for s in SCENES}
assert len(_BY_ID) == len(SCENES), "duplicate scene ids in the bank"


def scene_ids() -> list[str]:
    """Every scene id, in the bank's order."""
    return list(_BY_ID)


def get_scene(scene_id: str) -> Scene:
    """The scene `scene_id`; an UnknownSceneError lists the ids the bank has."""
    try:
        return _BY_ID[scene_id]
    except KeyError:
        raise UnknownSceneError(scene_id, scene_ids()) from None
