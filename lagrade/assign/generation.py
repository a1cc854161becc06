"""Assignment generation: one handout, answer key and blank answer sheet per student, figures,
and a manifest that fixes every student's variant, rendered from jinja2 templates.

`generate` checks everything it is given first (assignment, roster, formats, templates, output
folder) and reports every problem at once; the run itself is `pipeline.Generator`. The same
assignment, roster and seed give byte-identical files: keys are sorted, nothing records a time,
and figures are deterministic.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from lagrade.assign.assignment import Assignment, Within, load_assignment
from lagrade.assign.pipeline import GenerateResult, Generator, Progress, Verifier
from lagrade.assign.roster import Student, load_roster
from lagrade.assign.templating import environment
from lagrade.errors import AssignmentError, LagradeError

FORMATS: tuple[str, ...] = ("md", "html", "tex", "pdf")
#: What `generate` writes unless told: Markdown and HTML to read, print or paste into an LMS
#: page, and the LaTeX source of the PDFs, which costs nothing and needs no TeX here (`pdf`
#: compiles it, where TeX Live is installed).
DEFAULT_FORMATS: tuple[str, ...] = ("md", "html", "tex")


def parse_formats(formats: str | Iterable[str]) -> tuple[str, ...]:
    """`md,html,tex,pdf` (any order, any subset) as a tuple in canonical order; pdf implies tex."""
    items = [
        f.strip().lower() for f in (formats.split(",") if isinstance(formats, str) else formats)
    ]
    items = [f for f in items if f]
    unknown = [f for f in items if f not in FORMATS]
    if unknown or not items:
        raise AssignmentError(
            f"unknown format(s) {', '.join(unknown) or '(none given)'}; "
            f"choose from {', '.join(FORMATS)}"
        )
    chosen = set(items) | ({"tex"} if "pdf" in items else set())
    return tuple(f for f in FORMATS if f in chosen)


def generate(
    assignment_path: str | Path,
    roster_path: str | Path,
    seed: int,
    out_dir: str | Path,
    formats: str | Iterable[str] = DEFAULT_FORMATS,
    templates_dir: str | Path | None = None,
    force: bool = False,
    progress: Progress | None = None,
    verify: Verifier | None = None,
    scenes_dir: str | Path | None = None,
    within: Within | None = None,
) -> GenerateResult:
    """Write handouts, keys, answer sheets, figures and `manifest.json` for every student.

    Raises AssignmentError (listing every problem found) before anything is written when the
    assignment (or a scene file it names), roster, formats, templates or output folder cannot be
    used, or when `verify` reports a variant whose key the grader would not accept. Scene files
    are found relative to the assignment file, or by id in `scenes_dir`, else in the bank.
    `within` bounds each scene's derivation (time and memory; the command line passes
    `lagrade.judge.deriving`): a scene that runs out is one of the problems listed.
    """
    out = Path(out_dir)
    errors: list[str] = []
    assignment = roster = chosen = None
    for attempt in (
        lambda: load_assignment(assignment_path, scenes_dir, within=within),
        lambda: load_roster(roster_path),
        lambda: parse_formats(formats),
    ):
        try:
            result = attempt()
        except LagradeError as exc:
            errors.append(str(exc))
            continue
        if isinstance(result, Assignment):
            assignment = result
        elif isinstance(result, tuple) and result and isinstance(result[0], Student):
            roster = result
        else:
            chosen = result
    if not isinstance(seed, int) or isinstance(seed, bool) or seed < 0:
        errors.append(f"seed {seed!r} is not a whole number >= 0")
    if out.exists() and not force:
        errors.append(
            f"output folder {str(out)!r} exists; choose another or pass --force to replace it"
        )
    if out.exists() and not out.is_dir():
        errors.append(f"output path {str(out)!r} is a file, not a folder")
    try:
        env = environment(templates_dir)
    except LagradeError as exc:
        errors.append(str(exc))
    if errors:
        raise AssignmentError("\n".join(errors))
    assert assignment is not None and roster is not None and chosen is not None
    return Generator(
        assignment, roster, seed, out, chosen, env, progress, verify, Path(assignment_path)
    ).run(force)


__all__ = [
    "DEFAULT_FORMATS",
    "FORMATS",
    "GenerateResult",
    "Progress",
    "Verifier",
    "generate",
    "parse_formats",
]
