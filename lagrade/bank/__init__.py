"""Layer 1½ (above notation, which reads its expressions): scenes as TOML files — the bank's 24,
shipped in `scenes/`, and instructors' own — read by one reader (`scenefile`); get_scene."""

from lagrade.bank.registry import get_scene, scene_ids

__all__ = ["get_scene", "scene_ids"]
