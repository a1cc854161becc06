"""The assignment file an instructor writes (TOML): which scenes, which parts of the five-step
method, how many points, and how varied the students' variants may be.

Reading it checks everything against the bank and reports every problem in one
`AssignmentError`, each naming its field and value, so that one run shows the whole list.

    title = "Problem set 3"
    course = "PHYS 201"
    due = 2025-03-14T23:59:00
    points = 1                      # default points per part (optional)

    [[problems]]
    scene = "wedge"                 # a bank id, or a scene file: "scenes/parabola.toml"
    parts = ["dof", "lagrangian", "eom", { part = "expression", quantity = "block_acceleration" }]
    points = { lagrangian = 3, eom = 4 }   # or one number for every part
    variants = 12                          # size of the variant pool (default: one per student)
    names = { x_M = ["x_M"] }              # allowed coordinate names (default: all offered)
    options = {}                           # allowed presentation options (default: all)
"""

from __future__ import annotations

import datetime as dt
from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.assign.phase_solution import PHASE_PARTS, can_ask_scene
from lagrade.assign.solution import solution_data
from lagrade.bank import (
    find_scene,
    get_scene,
    is_scene_path,
    scene_from_text,
    scene_id_of,
    scene_ids,
    sha256,
)
from lagrade.errors import AssignmentError, LagradeError, UnreadableInput
from lagrade.mechanics import LAGRANGIAN_PARTS, Scene

#: The parts of the five-step method, in the order a handout asks them.
PARTS: tuple[str, ...] = (
    "dof",
    "coordinates",
    "transformation",
    "T",
    "V",
    "lagrangian",
    "eom",
    "momenta",
    "cyclic",
    "conserved",
    *PHASE_PARTS,
)
#: The numeric follow-up part; it names one of the scene's declared `Quantity`s.
EXPRESSION = "expression"

_TOP_KEYS = {
    "title",
    "course",
    "due",
    "instructions",
    "points",
    "problems",
    "rubric",
    "answer_page",
    "lms",
}
_PROBLEM_KEYS = {"scene", "title", "parts", "points", "variants", "names", "options"}
_PART_KEYS = {"part", "quantity", "points", "all"}
MAX_VARIANTS = 10_000


@dataclass(frozen=True)
class Part:
    """One question of a problem; `key` is its field in the answer sheet (the part's name, or the
    quantity's name for a numeric follow-up)."""

    part: str
    points: float
    quantity: str | None = None
    #: For `conserved`: the part asks for all the conserved quantities (a set that misses one
    #: is incomplete), or, with `all = false`, for any one of them. A field of the part, so that
    #: the grader never reads the rule from the prompt's wording.
    all: bool = True

    @property
    def key(self) -> str:
        return self.quantity if self.quantity else self.part


@dataclass(frozen=True)
class AssignedProblem:
    """A scene with the parts to ask and the limits of its variant pool. `scene_ref` is the
    assignment's `scene` as written (a bank id or a scene file's path); `loaded` the scene it
    names, read when the assignment was."""

    index: int
    scene_id: str
    parts: tuple[Part, ...]
    title: str = ""
    variants: int | None = None
    names: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    options: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    scene_ref: str = ""
    loaded: Scene | None = field(default=None, compare=False, repr=False)

    @property
    def scene(self) -> Scene:
        return self.loaded if self.loaded is not None else get_scene(self.scene_id)

    @property
    def total_points(self) -> float:
        return sum(p.points for p in self.parts)


@dataclass(frozen=True)
class Assignment:
    """A whole assignment as read from its file."""

    title: str
    course: str
    due: str
    problems: tuple[AssignedProblem, ...]
    instructions: str = ""

    @property
    def total_points(self) -> float:
        return sum(p.total_points for p in self.problems)

    def scene_files(self) -> dict[str, dict[str, str]]:
        """Every scene the assignment uses, by id: the `scene` as written, the text of its
        file (a bank scene's too) and that text's SHA-256: what a manifest carries, so that
        grading needs no file but the manifest."""
        found: dict[str, dict[str, str]] = {}
        for p in self.problems:
            text = p.scene.source
            found.setdefault(
                p.scene_id, {"ref": p.scene_ref or p.scene_id, "sha256": sha256(text), "text": text}
            )
        return found


#: Resolves an assignment's `scene` (as written) to a Scene.
SceneResolver = Callable[[str], Scene]
#: Runs a scene's derivation under a time and memory limit, naming the scene when it runs out
#: (`lagrade.judge.deriving`, which the command line passes: this layer cannot import it).
Within = Callable[[str], AbstractContextManager]


def scene_resolver(
    base: Path | None = None,
    scenes_dir: Path | None = None,
    texts: Mapping[str, str] | None = None,
    within: Within | None = None,
) -> SceneResolver:
    """How `scene = "..."` is found: in `texts` (a manifest's carried scene files, by the
    `scene` as written), else as a file relative to `base` (the assignment's folder), else as
    `<id>.toml` in `scenes_dir`, else in the bank. With `within`, the scene is read and its
    default variant's five-step solution derived under that limit (the variants derived later
    share its derivation), so that a scene that cannot be derived in time is refused before
    anything is written."""

    def find(ref: str) -> Scene:
        if texts is not None and ref in texts:
            scene_id = scene_id_of(ref) if is_scene_path(ref) else ref
            return scene_from_text(texts[ref], scene_id, origin=ref, validate=False)
        return find_scene(ref, base, scenes_dir)

    def resolve(ref: str) -> Scene:
        if within is None:
            return find(ref)
        with within(f"scene {ref!r}"):
            scene = find(ref)
            try:
                solution_data(scene.default)
            except (ArithmeticError, TypeError, ValueError):
                pass  # not a limit: the step that needs the failing part reports it
        return scene

    return resolve


def load_assignment(
    path: str | Path,
    scenes_dir: str | Path | None = None,
    scene_texts: Mapping[str, str] | None = None,
    within: Within | None = None,
) -> Assignment:
    """Read and check an assignment file; one AssignmentError lists every problem in it. Its
    scene files are found relative to its folder, or in `scenes_dir`, or in `scene_texts` (a
    manifest's copies, by the `scene` as written); `within` bounds each scene's derivation
    (`scene_resolver`)."""
    path = Path(path)
    folder = Path(scenes_dir) if scenes_dir else None
    resolve = scene_resolver(path.parent, folder, scene_texts, within)
    return parse_assignment(assignment_table(path), source=str(path), resolve=resolve)


def assignment_table(path: str | Path) -> dict[str, Any]:
    """The TOML of an assignment file, read by the untrusted-input rules, unchecked: what
    the tables other layers own (`[rubric]`, `[answer_page]`, `[lms]`) are read from."""
    path = Path(path)
    what = f"assignment file {str(path)!r}"
    try:
        return untrusted.load_toml(untrusted.decode(path.read_bytes(), what), what)
    except FileNotFoundError:
        raise AssignmentError(f"{what} does not exist") from None
    except OSError as exc:
        raise AssignmentError(f"cannot read {what}: {exc.strerror}") from None
    except UnreadableInput as exc:
        raise AssignmentError(str(exc)) from None


def parse_assignment(
    data: Mapping[str, Any], source: str = "assignment", resolve: SceneResolver | None = None
) -> Assignment:
    """Check the parsed TOML of an assignment against its scenes (see the module docstring);
    `resolve` finds each problem's scene (default: bank ids and files from the current folder)."""
    resolve = resolve or scene_resolver()
    problems: list[str] = []
    for key in sorted(set(data) - _TOP_KEYS):
        problems.append(f"{key}: unknown field (known: {', '.join(sorted(_TOP_KEYS))})")
    title = _text(data, "title", problems, required=True)
    course = _text(data, "course", problems)
    instructions = _text(data, "instructions", problems)
    due = data.get("due", "")
    if isinstance(due, dt.datetime | dt.date | dt.time):
        due = due.isoformat()
    elif not isinstance(due, str):
        problems.append(f"due: {due!r} is not a date (write 2025-03-14 or 2025-03-14T23:59:00)")
        due = ""
    default_points = data.get("points", 1)
    if not _is_points(default_points):
        problems.append(f"points: {default_points!r} is not a positive number")
        default_points = 1
    raw_problems = data.get("problems")
    parsed: list[AssignedProblem] = []
    if not isinstance(raw_problems, list) or not raw_problems:
        problems.append("problems: the assignment asks no problem (add [[problems]] tables)")
    else:
        for i, raw in enumerate(raw_problems, start=1):
            problem = _parse_problem(i, raw, default_points, problems, resolve)
            if problem is not None:
                parsed.append(problem)
        _one_scene_per_id(parsed, problems)
    if problems:
        lines = "\n".join(f"  - {p}" for p in problems)
        error = AssignmentError(f"{source} is not a valid assignment:\n{lines}")
        error.problems = problems  # type: ignore[attr-defined]
        raise error
    return Assignment(title, course, str(due), tuple(parsed), instructions)


def _text(data: Mapping[str, Any], key: str, problems: list[str], required: bool = False) -> str:
    value = data.get(key, None)
    if value is None:
        if required:
            problems.append(f"{key}: missing (the handouts print it)")
        return ""
    if not isinstance(value, str):
        problems.append(f"{key}: {value!r} is not a string")
        return ""
    return value


def _is_points(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and value > 0


def _one_scene_per_id(parsed: list[AssignedProblem], problems: list[str]) -> None:
    """Two different scenes under one id would share figures, manifest entries and variants."""
    seen: dict[str, AssignedProblem] = {}
    for p in parsed:
        first = seen.setdefault(p.scene_id, p)
        if first.scene is not p.scene:
            problems.append(
                f"problems[{p.index}].scene: {p.scene_ref!r} and problem {first.index}'s "
                f"{first.scene_ref!r} are two scenes with the id {p.scene_id!r}; rename one file"
            )


def _indented(message: str) -> str:
    return message.replace("\n", "\n    ")


def _parse_problem(
    index: int, raw: Any, default_points: float, problems: list[str], resolve: SceneResolver
) -> AssignedProblem | None:
    where = f"problems[{index}]"
    if not isinstance(raw, dict):
        problems.append(f"{where}: {raw!r} is not a table")
        return None
    for key in sorted(set(raw) - _PROBLEM_KEYS):
        problems.append(f"{where}.{key}: unknown field (known: {', '.join(sorted(_PROBLEM_KEYS))})")
    scene_ref = raw.get("scene")
    scene: Scene | None = None
    if not isinstance(scene_ref, str):
        problems.append(
            f"{where}.scene: missing or not a string; a scene file (scenes/pendulum.toml) or "
            f"one of the bank's: {', '.join(scene_ids())}"
        )
    else:
        try:
            scene = resolve(scene_ref)
        except LagradeError as exc:
            problems.append(f"{where}.scene: {_indented(str(exc))}")
    before = len(problems)
    points = raw.get("points", default_points)
    parts = _parse_parts(where, raw.get("parts"), scene, problems)
    parts = _apply_points(where, parts, points, default_points, problems)
    variants = raw.get("variants")
    if variants is not None and (
        not isinstance(variants, int)
        or isinstance(variants, bool)
        or not 1 <= variants <= MAX_VARIANTS
    ):
        problems.append(
            f"{where}.variants: {variants!r} is not a whole number from 1 to {MAX_VARIANTS}"
        )
        variants = None
    names = _parse_choices(where, "names", raw.get("names", {}), _offered_names(scene), problems)
    options = _parse_choices(
        where, "options", raw.get("options", {}), _offered_options(scene), problems
    )
    title = raw.get("title", "")
    if not isinstance(title, str):
        problems.append(f"{where}.title: {title!r} is not a string")
        title = ""
    if scene is None or len(problems) > before:
        return None
    return AssignedProblem(
        index, scene.id, tuple(parts), title or scene.title, variants, names, options,
        scene_ref, scene,
    )  # fmt: skip


def _parse_parts(where: str, raw: Any, scene: Scene | None, problems: list[str]) -> list[Part]:
    """Parts as strings or tables; returned with placeholder points (set by _apply_points)."""
    if not isinstance(raw, list) or not raw:
        problems.append(
            f"{where}.parts: missing or empty; choose from {', '.join(PARTS)}, {EXPRESSION}"
        )
        return []
    parts: list[Part] = []
    seen: set[str] = set()
    for j, item in enumerate(raw, start=1):
        at = f"{where}.parts[{j}]"
        points: Any = None
        asks_all = True
        if isinstance(item, str):
            name, quantity = item, None
        elif isinstance(item, dict):
            for key in sorted(set(item) - _PART_KEYS):
                problems.append(f"{at}.{key}: unknown field (known: part, quantity, points, all)")
            quantity = item.get("quantity")
            asks_all = item.get("all", True)
            if not isinstance(asks_all, bool):
                problems.append(f"{at}.all: must be true or false, not {asks_all!r}")
                asks_all = True
            elif "all" in item and item.get("part") != "conserved":
                problems.append(f"{at}.all: only the 'conserved' part asks for all or for one")
            name = item.get("part", EXPRESSION if quantity is not None else None)
            points = item.get("points")
            if points is not None and not _is_points(points):
                problems.append(f"{at}.points: {points!r} is not a positive number")
                points = None
        else:
            problems.append(f"{at}: {item!r} is neither a part name nor a table")
            continue
        if name not in PARTS and name != EXPRESSION:
            problems.append(
                f"{at}: unknown part {name!r}; the parts are {', '.join(PARTS)}, {EXPRESSION}"
            )
            continue
        if name == EXPRESSION:
            if not _check_quantity(at, quantity, scene, problems):
                continue
        elif quantity is not None:
            problems.append(f"{at}.quantity: only the {EXPRESSION!r} part names a quantity")
            continue
        elif scene is not None and not _scene_can_ask(at, name, scene, problems):
            continue
        part = Part(name, points or 0, quantity, asks_all)
        if part.key in seen:
            problems.append(f"{at}: part {part.key!r} is asked twice")
            continue
        seen.add(part.key)
        parts.append(part)
    return parts


def _check_quantity(at: str, quantity: Any, scene: Scene | None, problems: list[str]) -> bool:
    if not isinstance(quantity, str):
        problems.append(
            f"{at}.quantity: an {EXPRESSION!r} part names one of the scene's quantities"
        )
        return False
    if scene is None:
        return False
    declared = [q.name for q in scene.quantities]
    if quantity not in declared:
        offered = ", ".join(declared) if declared else "none"
        problems.append(
            f"{at}.quantity: scene {scene.id!r} declares no quantity {quantity!r} "
            f"(it declares: {offered})"
        )
        return False
    if quantity in PARTS:
        problems.append(f"{at}.quantity: {quantity!r} clashes with the part of that name")
        return False
    return True


def _scene_can_ask(at: str, name: str, scene: Scene, problems: list[str]) -> bool:
    """A scene whose conserved quantities cannot be derived cannot be asked for them (one
    that has none can: the answer is "none"); a scene given by its Lagrangian has no bodies to
    ask DOF, coordinates, transformation, T or V about."""
    if scene.given_by_lagrangian and name not in LAGRANGIAN_PARTS:
        problems.append(
            f"{at}: scene {scene.id!r} is given by its Lagrangian and declares no bodies, so "
            f"{name!r} cannot be asked; ask {', '.join(LAGRANGIAN_PARTS[:-1])} or a quantity"
        )
        return False
    if name in PHASE_PARTS:
        try:
            why = can_ask_scene(scene, name)
        except Exception as exc:  # a scene's own derivation failing is worth naming here
            why = f"its derivation fails: {exc}"
        if why is not None:
            problems.append(f"{at}: scene {scene.id!r} cannot be asked {name!r}: {why}")
            return False
    if name == "conserved":
        try:
            scene.default.conserved_quantities  # noqa: B018 (derived here to name a failure)
        except Exception as exc:  # a scene's own derivation failing is worth naming here
            problems.append(
                f"{at}: scene {scene.id!r} cannot derive its conserved quantities: {exc}"
            )
            return False
    return True


def _apply_points(
    where: str, parts: list[Part], points: Any, default: float, problems: list[str]
) -> list[Part]:
    """Each part's points: its own `points`, else the problem's table or number, else default."""
    table: Mapping[str, Any] = {}
    if isinstance(points, dict):
        table = points
        keys = {p.key for p in parts}
        for key, value in sorted(table.items()):
            if key not in keys:
                problems.append(f"{where}.points.{key}: no part {key!r} is asked in this problem")
            elif not _is_points(value):
                problems.append(f"{where}.points.{key}: {value!r} is not a positive number")
        base = default
    elif _is_points(points):
        base = points
    else:
        problems.append(f"{where}.points: {points!r} is neither a positive number nor a table")
        base = default
    result = []
    for p in parts:
        value = p.points or table.get(p.key, base)
        result.append(Part(p.part, value if _is_points(value) else base, p.quantity, p.all))
    return result


def _offered_names(scene: Scene | None) -> dict[str, tuple[str, ...]]:
    if scene is None:
        return {}
    return {c: tuple(scene.renames.get(c, (c,))) for c in scene.coordinates}


def _offered_options(scene: Scene | None) -> dict[str, tuple[str, ...]]:
    return {} if scene is None else {k: tuple(v) for k, v in scene.options.items()}


def _parse_choices(
    where: str, label: str, raw: Any, offered: Mapping[str, tuple[str, ...]], problems: list[str]
) -> dict[str, tuple[str, ...]]:
    """Restrictions of the scene's renames or options to a non-empty subset of what it offers."""
    if not isinstance(raw, dict):
        problems.append(f'{where}.{label}: {raw!r} is not a table such as {{ theta = ["theta"] }}')
        return {}
    if not offered and not raw:
        return {}
    chosen: dict[str, tuple[str, ...]] = {}
    for key, value in sorted(raw.items()):
        at = f"{where}.{label}.{key}"
        if key not in offered:
            known = ", ".join(offered) if offered else "none"
            problems.append(f"{at}: the scene has no {label[:-1]} {key!r} (it has: {known})")
            continue
        values = [value] if isinstance(value, str) else value
        if (
            not isinstance(values, list)
            or not values
            or not all(isinstance(v, str) for v in values)
        ):
            problems.append(f"{at}: {value!r} is not a non-empty list of strings")
            continue
        bad = [v for v in values if v not in offered[key]]
        if bad:
            problems.append(
                f"{at}: {', '.join(map(repr, bad))} not offered (offered: "
                f"{', '.join(offered[key])})"
            )
            continue
        chosen[key] = tuple(dict.fromkeys(values))
    return chosen
