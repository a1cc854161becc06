"""`lagrade scene check FILE` and `lagrade scene new NAME`: what an instructor runs on a scene file
of their own before it goes into an assignment.

The check reads the file as an assignment would (every problem at once, with keys and carets),
checks it against itself in each presentation, derives the five-step solution, checks every
quantity's claim against the derived motion in every combination of options (as the bank's
tests check the bank's), and draws each presentation's figure, writing the default one where
the author can open it.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from pathlib import Path

from lagrade.assign.figures import FigureError, draw
from lagrade.assign.solution import solution_text
from lagrade.bank import check_claim, read_scene_file, template
from lagrade.errors import AssignmentError, LagradeError
from lagrade.mechanics import Scene, SceneVariant

#: Beyond this many combinations of options, quantities are checked in each choice, not each
#: combination (the product of every option's choices).
MAX_COMBINATIONS = 64


@dataclass
class SceneCheck:
    """What `scene check` found: the text to print and the failures (empty: all holds)."""

    scene: Scene
    lines: list[str] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)
    figure: Path | None = None

    @property
    def text(self) -> str:
        return "\n".join(self.lines)


def combinations(scene: Scene) -> list[dict[str, str]]:
    """Every combination of the scene's options (or, past MAX_COMBINATIONS, each choice once)."""
    product = list(itertools.product(*scene.options.values()))
    if len(product) <= MAX_COMBINATIONS:
        return [dict(zip(scene.options, c, strict=True)) for c in product]
    return [{}] + [{o: c} for o, cs in scene.options.items() for c in cs[1:]]


def _described(options: dict[str, str]) -> str:
    return ", ".join(f"{o} = {c}" for o, c in options.items()) or "the default"


def check_scene_file(path: str | Path, figure: str | Path | None = None) -> SceneCheck:
    """Check the scene file at `path`; the default presentation's figure goes to `figure`
    (default: `<id>.svg` in the current folder). Raises SceneFileError when the file is not
    a usable scene."""
    scene = read_scene_file(path)
    report = SceneCheck(scene)
    presentations = combinations(scene)
    report.lines += [
        f"{path}: a valid scene file, {scene.id!r}, in {len(presentations)} presentation"
        + ("s" if len(presentations) != 1 else ""),
        "",
        solution_text(scene.default),
        "",
    ]
    _check_quantities(scene, presentations, report)
    _draw_figures(scene, presentations, Path(figure or f"{scene.id}.svg"), report)
    return report


def _check_quantities(scene: Scene, presentations: list[dict], report: SceneCheck) -> None:
    if not scene.quantities:
        return
    report.lines.append("quantities, checked against the derived motion:")
    for q in scene.quantities:
        if q.claim is None:
            report.lines.append(f"  {q.name}: not checked (it declares no check)")
            continue
        failed = []
        for options in presentations:
            variant = SceneVariant(scene, options=options)
            try:
                found = check_claim(variant, q.claim(variant.namespace))
            except (LagradeError, ArithmeticError, TypeError, ValueError) as error:
                found = [f"cannot be checked: {error}"]
            failed += [f"{f} (with {_described(options)})" for f in found]
        if failed:
            report.lines.append(f"  {q.name}: DOES NOT HOLD: {failed[0]}")
            report.failures += [f"quantity {q.name}: {f}" for f in failed]
        else:
            report.lines.append(f"  {q.name} = {scene.default.quantities[q.name]}: holds")
    report.lines.append("")


def _draw_figures(scene: Scene, presentations: list[dict], out: Path, report: SceneCheck) -> None:
    if scene.given_by_lagrangian:
        report.lines.append("figure: none (the scene is given by its Lagrangian: no bodies)")
        return
    for options in presentations:
        try:
            figure = draw(SceneVariant(scene, options=options))
        except (FigureError, LagradeError, ArithmeticError, TypeError, ValueError) as error:
            report.failures.append(f"figure (with {_described(options)}): {error}")
            report.lines.append(f"figure (with {_described(options)}): cannot be drawn: {error}")
            continue
        if not options or options == presentations[0]:
            try:
                out.write_bytes(figure.svg)
            except OSError as error:
                raise AssignmentError(f"cannot write the figure {out}: {error.strerror}") from None
            report.figure = out
            report.lines.append(f"figure: {out} (open it to see whether it shows the system)")


def new_scene_file(name: str, out: str | Path | None = None) -> Path:
    """Write the commented template of a scene file as `<name>.toml` (in folder `out`, default
    the current one); never over an existing file."""
    from lagrade.bank import SCENE_ID

    if not SCENE_ID.match(name):
        raise AssignmentError(
            f"{name!r} cannot name a scene: letters, digits, _ and -, starting with a letter "
            "or digit, at most 64 characters (it becomes the file's name and the scene's id)"
        )
    path = Path(out or ".") / f"{name}.toml"
    try:
        with open(path, "x", encoding="utf-8") as f:
            f.write(template(name))
    except FileExistsError:
        raise AssignmentError(f"{path} exists; choose another name or remove it") from None
    except OSError as error:
        raise AssignmentError(f"cannot write {path}: {error.strerror}") from None
    return path
