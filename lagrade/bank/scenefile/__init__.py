"""Scene files: the TOML an instructor writes (and the bank is made of), read into a `Scene`.

`docs/scenes.md` is the format. Reading a file runs no code of the file's: TOML is parsed by the
untrusted-input rules (`lagrade.untrusted`: bounded size, nesting and numbers), every expression by
the notation layer's own grammar (the one students' answers go through), and everything wrong is
collected and raised as one `SceneFileError` listing each problem with its key (and, for an
expression, the parser's caret). A file that reads is then checked against itself in each
presentation (`SceneVariant.validate`: constraints the positions satisfy, DOF, coordinates that
move something).

Modules: `declaration` (the table's shape: names, keys, types, bounds), `reading` (expressions and
the names each field may use), `figure` (the `[figure]` tables), `claims` (what a quantity claims
about the motion, and its check), `assemble` (the Scene), `template` (`lagrade scene new`).
"""

from __future__ import annotations

import hashlib
import re
import threading
from pathlib import Path

import lagrade.untrusted as untrusted
from lagrade.bank.scenefile.assemble import assemble
from lagrade.bank.scenefile.declaration import read_declaration
from lagrade.bank.scenefile.fields import Problems
from lagrade.errors import SceneError, SceneFileError, UnreadableInput
from lagrade.mechanics import Scene, SceneVariant
from lagrade.recent import Recent

#: Far more than any scene needs (the bank's largest is about 4 KB), far less than a hostile file.
MAX_SCENE_BYTES = 256 * 1024
#: A scene's id is its file's name without `.toml`: it names figures and manifest entries.
SCENE_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9_-]{0,63}\Z")

_lock = threading.Lock()
#: Scenes read in this process, by (text's hash, id, validated): the same text gives the same
#: Scene object (caches keyed by a scene rely on it), the least recently read dropped past a
#: bound, so that requests carrying many different texts cannot grow the process without end.
_KEPT = 256
_read: Recent = Recent(_KEPT)


def sha256(text: str) -> str:
    """The hash a manifest records for a scene file's text."""
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def scene_id_of(path: str | Path) -> str:
    """The id of the scene in the file at `path`: its name without `.toml`."""
    stem = Path(path).name.removesuffix(".toml")
    if not SCENE_ID.match(stem):
        raise SceneFileError(
            str(path),
            [
                f"the file's name {Path(path).name!r} does not make a scene id (letters, digits, "
                "_ and -, starting with a letter or digit, at most 64, then .toml)"
            ],
        )
    return stem


def read_scene_file(path: str | Path, validate: bool = True) -> Scene:
    """The scene in the file at `path` (its id is the file's name without `.toml`)."""
    path = Path(path)
    scene_id = scene_id_of(path)
    try:
        if path.stat().st_size > MAX_SCENE_BYTES:
            raise SceneFileError(
                str(path), [f"larger than {MAX_SCENE_BYTES // 1024} KiB; no scene needs that"]
            )
        data = path.read_bytes()
    except FileNotFoundError:
        raise SceneFileError(str(path), ["no such file"]) from None
    except IsADirectoryError:
        raise SceneFileError(str(path), ["is a folder, not a scene file"]) from None
    except OSError as error:
        raise SceneFileError(str(path), [f"cannot be read: {error.strerror}"]) from None
    try:
        text = untrusted.decode(data, str(path))
    except UnreadableInput as error:
        raise SceneFileError(str(path), [str(error)]) from None
    return scene_from_text(text, scene_id, str(path), validate)


def scene_from_text(text: str, scene_id: str, origin: str = "", validate: bool = True) -> Scene:
    """The scene a scene file's `text` declares, with id `scene_id`; the same text and id give
    the same Scene object (read once per process). `validate` also checks the scene against
    itself in each presentation (the bank's files are held to that by its tests instead)."""
    origin = origin or f"scene {scene_id!r}"
    key = (sha256(text) if isinstance(text, str) else "", scene_id, validate)
    with _lock:
        found = _read.recalled(key)
    if found is not None:
        return found
    scene = _read_text(text, scene_id, origin, validate)
    with _lock:  # a thread that read the same text meanwhile: the Scene kept first
        return _read.made(key, lambda: scene)


def _read_text(text: str, scene_id: str, origin: str, validate: bool) -> Scene:
    if not isinstance(text, str):
        raise SceneFileError(origin, [f"the scene's text is {type(text).__name__}, not text"])
    if not SCENE_ID.match(scene_id):
        raise SceneFileError(origin, [f"{scene_id!r} is not a scene id"])
    if len(text.encode("utf-8", "surrogatepass")) > MAX_SCENE_BYTES:
        raise SceneFileError(
            origin, [f"larger than {MAX_SCENE_BYTES // 1024} KiB; no scene needs that"]
        )
    try:
        data = untrusted.load_toml(text, origin)
    except UnreadableInput as error:
        raise SceneFileError(origin, [str(error)]) from None
    problems = Problems()
    try:
        declaration = read_declaration(data, problems)
        scene = assemble(scene_id, declaration, text, problems)
        if scene is not None and validate and not problems.blocking:
            _check_presentations(scene, problems)
    except RecursionError:
        problems.add("", "an expression is nested too deeply to work with")
        scene = None
    if problems or scene is None:
        raise SceneFileError(origin, problems.items or ["cannot be read"])
    return scene


def presentations(scene: Scene) -> list[dict[str, str]]:
    """The default presentation, then each option's every other choice (the others at their
    first): each choice is met once, without the product of all options."""
    found: list[dict[str, str]] = [{}]
    for option, choices in scene.options.items():
        found += [{option: choice} for choice in choices[1:]]
    return found


def _check_presentations(scene: Scene, problems: Problems) -> None:
    """Each presentation valid (`SceneVariant.validate`), its quantities closed forms in the
    parameters; the value pools able to keep the relations (b < R)."""
    if scene.relations:
        try:
            scene.variant(0)
        except SceneError as error:
            for p in error.problems:
                problems.add("", p)
    for options in presentations(scene):
        where = "".join(f" (with {o} = {c})" for o, c in options.items())
        try:
            variant = SceneVariant(scene, options=options)
            variant.validate()
            parameters = set(variant.parameter_symbols.values())
            for name, value in variant.quantities.items():
                extra = sorted(str(s) for s in value.free_symbols - parameters)
                if extra:
                    problems.add(
                        f"quantities.{name}.value{where}",
                        f"uses {', '.join(extra)}; a quantity is a closed form in the parameters",
                    )
        except SceneError as error:
            for p in error.problems:
                problems.add("", f"{p}{where}")
        except (ArithmeticError, TypeError, ValueError) as error:
            problems.add("", f"cannot derive the scene{where}: {error}")


__all__ = [
    "MAX_SCENE_BYTES",
    "presentations",
    "read_scene_file",
    "scene_from_text",
    "scene_id_of",
    "sha256",
]
