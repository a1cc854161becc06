"""What `lagrade bank list` shows: the bank's scenes, or the scenes of the files, folders and ids
given, each as (id, title, coordinates); a file that is not a usable scene is named with its
problems and the others are still listed."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from lagrade.bank.registry import find_scene, get_scene, scene_files, scene_ids
from lagrade.errors import LagradeError


def list_scenes(paths: Sequence[str | Path] = ()) -> tuple[list[tuple], list[str]]:
    """(rows, problems): a row per scene found, a problem per file or id that is not one."""
    refs: list[str] = []
    problems: list[str] = []
    for item in paths:
        path = Path(item)
        if path.is_dir():
            found = scene_files(path)
            if not found:
                problems.append(f"{path}: no scene files (*.toml) in this folder")
            refs += [str(p) for p in found]
        else:
            refs.append(str(item))
    rows = []
    for ref in refs or scene_ids():
        try:
            scene = find_scene(ref) if paths else get_scene(ref)
        except LagradeError as error:
            problems.append(str(error))
            continue
        rows.append((scene.id, scene.title, tuple(scene.coordinates)))
    return rows, problems
