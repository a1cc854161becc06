"""Layer 1: the bank of scenes, one small declarative module per scene family."""

from lagrade.bank.registry import get_scene, scene_ids

__all__ = ["get_scene", "scene_ids"]
