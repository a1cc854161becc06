"""Layer 1½ (above notation, which reads its expressions): scenes as TOML files — the bank's 24,
shipped in `scenes/`, and instructors' own — read by one reader (`scenefile`); get_scene."""

from __future__ import annotations

from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "check_claim": "lagrade.bank.scenefile.claims",
    "find_scene": "lagrade.bank.registry",
    "get_scene": "lagrade.bank.registry",
    "is_bank_scene": "lagrade.bank.registry",
    "is_scene_path": "lagrade.bank.registry",
    "list_scenes": "lagrade.bank.listing",
    "read_scene_file": "lagrade.bank.scenefile",
    "scene_from_text": "lagrade.bank.scenefile",
    "SCENE_ID": "lagrade.bank.scenefile",
    "scene_id_of": "lagrade.bank.scenefile",
    "scene_ids": "lagrade.bank.registry",
    "scene_reference": "lagrade.bank.registry",
    "sha256": "lagrade.bank.scenefile",
    "template": "lagrade.bank.scenefile.template",
}
#: The modules exported as a whole.
_MODULES = {}

__all__ = [
    "check_claim",
    "find_scene",
    "get_scene",
    "is_bank_scene",
    "is_scene_path",
    "list_scenes",
    "read_scene_file",
    "scene_from_text",
    "SCENE_ID",
    "scene_id_of",
    "scene_ids",
    "scene_reference",
    "sha256",
    "template",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
