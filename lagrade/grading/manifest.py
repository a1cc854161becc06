"""Reading `manifest.json` back for grading, defensively: it is a file on disk that anyone may
have edited, and its student ids become file names under the output folder, so its structure
is checked once here (every problem listed in one error) before anything is graded or written.

The manifest carries the text of every scene file the assignment used (`scenes`, each with its
SHA-256): a text that does not match its hash is refused, and every student's variant is
rebuilt from the carried scene, so grading needs no file but the manifest. A problem entry of
a scene that is not the installed bank's own gets the scene's text (`scene_text`) in memory,
so that whatever judges it (a worker, the answer page, PrairieLearn) has what it needs.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.bank import get_scene, is_bank_scene, scene_from_text, sha256
from lagrade.errors import AssignmentError, LagradeError
from lagrade.mechanics import Scene, SceneVariant

FORMAT = "lagrade-manifest/1"
#: A manifest for a class of a thousand is a few megabytes.
MAX_MANIFEST_BYTES = 256 * 1024 * 1024


def load_manifest(path: Path) -> dict[str, Any]:
    """Read manifest.json, check its structure and ids, and check that the bank still
    reproduces every variant in it. Raises AssignmentError listing what is wrong."""
    path = Path(path)
    try:
        if path.stat().st_size > MAX_MANIFEST_BYTES:
            raise AssignmentError(f"{path} is larger than any manifest lagrade writes")
        data = path.read_bytes()
    except FileNotFoundError:
        raise AssignmentError(f"no manifest at {path}; run `lagrade generate` first") from None
    except OSError as error:
        raise AssignmentError(f"cannot read the manifest {path}: {error.strerror}") from None
    try:
        manifest = untrusted.load_json(untrusted.decode(data, str(path)), str(path))
    except LagradeError as error:
        raise AssignmentError(f"cannot read the manifest: {error}") from None
    if not isinstance(manifest, dict) or manifest.get("format") != FORMAT:
        raise AssignmentError(f"{path} is not a lagrade manifest (format {FORMAT})")
    problems = _structure_problems(manifest)
    if problems:
        shown = "\n".join(f"  - {p}" for p in problems[:20])
        more = f"\n  … and {len(problems) - 20} more" if len(problems) > 20 else ""
        raise AssignmentError(f"{path} is not a usable manifest:\n{shown}{more}")
    scenes = carried_scenes(manifest)
    for student in manifest["students"]:
        for entry in student["problems"]:
            scene = scenes.get(entry["scene"])
            if scenes and scene is None:
                raise AssignmentError(
                    f"student {student['id']}: the manifest carries no scene {entry['scene']!r}"
                )
            if scene is not None and not is_bank_scene(scene):
                entry["scene_text"] = scene.source
    _check_variants(manifest)
    return manifest


def carried_scenes(manifest: Mapping[str, Any]) -> dict[str, Scene]:
    """The scenes the manifest carries, by id, each read from its text after the text is checked
    against its hash (empty for a manifest written before scene files: the bank's then)."""
    carried = manifest.get("scenes")
    if carried is None:
        return {}
    if not isinstance(carried, dict):
        raise AssignmentError('the manifest\'s "scenes" must be an object')
    found = {}
    for scene_id, info in carried.items():
        where = f"the manifest's scene {scene_id!r}"
        if not isinstance(info, dict) or not all(
            isinstance(info.get(k), str) for k in ("ref", "sha256", "text")
        ):
            raise AssignmentError(f"{where} needs its ref, sha256 and text")
        if sha256(info["text"]) != info["sha256"]:
            raise AssignmentError(
                f"{where} does not match its SHA-256: the scene file's text in the manifest "
                "was changed after the assignment was generated"
            )
        try:
            found[scene_id] = scene_from_text(info["text"], scene_id, where, validate=False)
        except LagradeError as error:
            raise AssignmentError(str(error)) from None
    return found


def carried_scene_texts(manifest: Mapping[str, Any]) -> dict[str, str]:
    """The carried scene files' texts by the `scene` each problem of the assignment names
    (`scenes/parabola.toml`, `wedge`): what reading the manifest's copy of the assignment needs
    instead of the files, which may have moved or changed since."""
    carried_scenes(manifest)  # the hashes hold
    return {info["ref"]: info["text"] for info in (manifest.get("scenes") or {}).values()}


def _structure_problems(manifest: Mapping[str, Any]) -> list[str]:
    """Every way the manifest differs from what `lagrade generate` writes, as sentences."""
    found: list[str] = []
    info = manifest.get("assignment")
    if not isinstance(info, dict):
        found.append('"assignment" must be an object')
    elif "file" in info and not untrusted.is_safe_name(info["file"]):
        found.append(untrusted.unsafe_name_reason(info["file"], '"assignment.file"'))
    problems = manifest.get("problems")
    if not isinstance(problems, list) or not problems:
        found.append('"problems" must be a non-empty list')
        problems = []
    for n, problem in enumerate(problems, 1):
        parts = problem.get("parts") if isinstance(problem, dict) else None
        if not isinstance(parts, list) or not all(
            isinstance(p, dict)
            and isinstance(p.get("key"), str)
            and isinstance(p.get("part"), str)
            and _is_number(p.get("points"))
            for p in parts
        ):
            found.append(f"problem {n}: each part needs a key, a part name and points")
    students = manifest.get("students")
    if not isinstance(students, list):
        return [*found, '"students" must be a list']
    seen: dict[str, int] = {}
    for n, student in enumerate(students, 1):
        if not isinstance(student, dict):
            found.append(f"student {n} is not an object")
            continue
        sid = student.get("id")
        reason = untrusted.unsafe_name_reason(sid, f"student {n}: the id")
        if reason:
            found.append(reason)
            continue
        if sid.casefold() in seen:
            found.append(f"student {n}: the id {sid!r} repeats student {seen[sid.casefold()]}")
        seen.setdefault(sid.casefold(), n)
        if not isinstance(student.get("name"), str):
            found.append(f"student {sid}: the name must be text")
        entries = student.get("problems")
        if not isinstance(entries, list) or len(entries) != len(problems):
            found.append(f"student {sid}: needs one entry per problem")
            continue
        for entry in entries:
            if not _is_variant_entry(entry):
                found.append(f"student {sid}: a problem entry lacks scene, seed, names or values")
                break
    return found


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _is_variant_entry(entry: Any) -> bool:
    return (
        isinstance(entry, dict)
        and isinstance(entry.get("scene"), str)
        and isinstance(entry.get("seed"), int)
        and isinstance(entry.get("index"), int)
        and isinstance(entry.get("names"), dict)
        and isinstance(entry.get("options"), dict)
        and isinstance(entry.get("values"), dict)
        and all(_is_number(v) for v in entry["values"].values())
    )


@functools.lru_cache(maxsize=4096)
def student_variant(scene_id: str, seed: int, text: str | None = None) -> SceneVariant:
    """A student's variant, built once per process (the manifest check, the question key and
    the numeric follow-ups all ask for it, once per part of every submission otherwise): of
    the bank's scene, or of the scene file whose `text` the manifest carries."""
    scene = get_scene(scene_id) if text is None else scene_from_text(text, scene_id, validate=False)
    return scene.variant(seed)


def entry_variant(entry: Mapping[str, Any]) -> SceneVariant:
    """The variant of a student's problem entry (its scene's text when it carries one)."""
    return student_variant(entry["scene"], entry["seed"], entry.get("scene_text"))


def entry_spec(entry: Mapping[str, Any]) -> dict[str, Any]:
    """The judge's "problem" field of a student's problem entry."""
    spec = {"scene": entry["scene"], "seed": entry["seed"]}
    if entry.get("scene_text") is not None:
        spec["scene_text"] = entry["scene_text"]
    return spec


def _check_variants(manifest: Mapping[str, Any]) -> None:
    """Every variant must still come out of the bank as recorded, or grading would not match
    the handouts the students worked from."""
    mismatches = []
    for student in manifest["students"]:
        for entry in student["problems"]:
            try:
                variant = entry_variant(entry)
            except LagradeError as error:
                raise AssignmentError(f"student {student['id']}: {error}") from None
            if (
                variant.names != entry["names"]
                or variant.options != entry["options"]
                or {k: float(v) for k, v in variant.values.items()}
                != {k: float(v) for k, v in entry["values"].items()}
            ):
                mismatches.append(f"{student['id']} problem {entry['index']} ({entry['scene']})")
    if mismatches:
        raise AssignmentError(
            "the scenes no longer reproduce these variants, so grading would not match the "
            f"handouts: {', '.join(mismatches[:10])}" + (" …" if len(mismatches) > 10 else "")
        )
