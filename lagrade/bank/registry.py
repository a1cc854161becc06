"""The bank: the scene files shipped in `lagrade/bank/scenes/`, by id, read on first use.

The bank is data, read by the same reader as an instructor's scene file (`lagrade.bank.scenefile`);
no scene is declared in Python. `order.txt` in the folder gives the order `lagrade bank list`
shows (the lecture's eight systems first, in the lecture's order).
"""

from __future__ import annotations

import functools
from pathlib import Path

from lagrade.bank.scenefile import read_scene_file
from lagrade.errors import UnknownSceneError
from lagrade.mechanics import Scene

#: The folder of the bank's scene files, inside the installed package.
BANK = Path(__file__).parent / "scenes"


@functools.cache
def scene_ids() -> list[str]:
    """Every scene id, in the bank's order."""
    lines = (BANK / "order.txt").read_text(encoding="utf-8").splitlines()
    return [line.strip() for line in lines if line.strip() and not line.startswith("#")]


@functools.cache
def _scene(scene_id: str) -> Scene:
    # The bank's files are held to every presentation's validity by tests/bank, not at each run.
    return read_scene_file(BANK / f"{scene_id}.toml", validate=False)


def get_scene(scene_id: str) -> Scene:
    """The scene `scene_id`; an UnknownSceneError lists the ids the bank has."""
    if not isinstance(scene_id, str) or scene_id not in scene_ids():
        raise UnknownSceneError(scene_id, scene_ids())
    return _scene(scene_id)


def bank_file(scene_id: str) -> Path:
    """The file of a bank scene."""
    get_scene(scene_id)
    return BANK / f"{scene_id}.toml"


def __getattr__(name: str):
    # SCENES, every scene in the bank's order, is read only when asked for.
    if name == "SCENES":
        return tuple(get_scene(i) for i in scene_ids())
    raise AttributeError(name)


def is_scene_path(ref: str) -> bool:
    """Whether an assignment's or a command's `scene` names a file (`scenes/parabola.toml`)
    rather than an id (`wedge`)."""
    return ref.endswith(".toml") or "/" in ref or "\\" in ref


def find_scene(ref: str, base: Path | None = None, scenes_dir: Path | None = None) -> Scene:
    """The scene `ref` names: a scene file (relative to `base`, the folder of the file that
    names it), else an id found as `<id>.toml` in `scenes_dir`, else in the bank. Instructors'
    files are read with full validation."""
    if is_scene_path(ref):
        path = Path(ref)
        return read_scene_file(path if path.is_absolute() or base is None else base / path)
    if scenes_dir is not None and (Path(scenes_dir) / f"{ref}.toml").is_file():
        return read_scene_file(Path(scenes_dir) / f"{ref}.toml")
    return get_scene(ref)


def scene_files(folder: Path) -> list[Path]:
    """The scene files in a folder (`*.toml`), by name."""
    return sorted(p for p in Path(folder).glob("*.toml") if p.is_file())


def is_bank_scene(scene: Scene) -> bool:
    """Whether `scene` is the installed bank's own (its id and its file's very text)."""
    if scene.id not in scene_ids():
        return False
    bank = get_scene(scene.id)
    return bank is scene or bank.source == scene.source


def scene_reference(scene: Scene) -> dict[str, str]:
    """How a judge request (`check --batch`'s "problem", a manifest entry) names a scene: the
    bank's by id alone; any other by id and the text of its file, so that the request carries
    what it needs wherever it is judged."""
    if is_bank_scene(scene):
        return {"scene": scene.id}
    return {"scene": scene.id, "scene_text": scene.source}
