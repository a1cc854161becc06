"""One run of generation, step by step: check every variant with the grader, render each
student's handouts, keys and answer sheet into a temporary folder beside the destination, write
figures and manifest, compile PDFs, and only then move the folder into place, so an error leaves
the disk as it was. Each distinct variant is derived and drawn once, however many students share
it."""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import jinja2

import lagrade.untrusted as untrusted
from lagrade.assign.assignment import Assignment, Part
from lagrade.assign.manifest import manifest_json, student_manifest
from lagrade.assign.pdf import PDFLATEX_HINT, compile_pdf, engines
from lagrade.assign.roster import Student
from lagrade.assign.variants import VariantChoice, student_variants
from lagrade.assign.views import figure_name, presentation, problem_view, symbolic_solution
from lagrade.errors import AssignmentError, UnreadableInput
from lagrade.mechanics import SceneVariant

#: Progress callback: (steps done, steps in all, what is being done).
Progress = Callable[[int, int, str], None]
#: The grader's check of a variant: returns a description of each problem found (none: fine).
Verifier = Callable[[SceneVariant, Sequence[Part]], Iterable[str] | None]


@dataclass
class GenerateResult:
    """What `generate` wrote: the output folder, the students, and warnings to show the user."""

    out_dir: Path
    students: int
    files: int
    warnings: list[str] = field(default_factory=list)
    #: Files asked for but not made (a PDF LaTeX could not typeset), by student id and kind
    #: (`handout_pdf`, `key_pdf`), with the reason; the manifest lists them as `unwritten`.
    unwritten: dict[str, dict[str, str]] = field(default_factory=dict)


class Generator:
    """One run of `generate` (state shared by its steps)."""

    def __init__(
        self,
        assignment: Assignment,
        roster: Sequence[Student],
        seed: int,
        out: Path,
        formats: Sequence[str],
        env: jinja2.Environment,
        progress: Progress | None,
        verify: Verifier | None,
        assignment_path: Path,
    ):
        self.assignment, self.roster, self.seed, self.out = assignment, roster, seed, out
        self.formats, self.env, self.verify = formats, env, verify
        self.progress = progress or (lambda done, total, label: None)
        self.assignment_path = assignment_path
        self.warnings: list[str] = []
        self.unwritten: dict[str, dict[str, str]] = {}
        self.files = 0
        self.views: dict[tuple[int, int], dict[str, Any]] = {}  # students sharing a variant
        self.figures_written: set[str] = set()

    def run(self, force: bool) -> GenerateResult:
        ids = [s.id for s in self.roster]
        draws = {p.index: student_variants(p, self.seed, ids) for p in self.assignment.problems}
        self._verify(draws)
        templates = self._templates()
        self.out.parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(
            tempfile.mkdtemp(prefix=f".{self.out.name}.", suffix=".tmp", dir=self.out.parent)
        )
        try:
            self._write_all(tmp, draws, templates)
            self._move_into_place(tmp, force)
        except BaseException:
            shutil.rmtree(tmp, ignore_errors=True)
            raise
        return GenerateResult(self.out, len(self.roster), self.files, self.warnings, self.unwritten)

    def _verify(self, draws: dict[int, dict[str, VariantChoice]]) -> None:
        if self.verify is None:
            return
        problems: list[str] = []
        for problem in self.assignment.problems:
            seen: set[int] = set()
            for choice in draws[problem.index].values():
                if choice.seed in seen:
                    continue
                seen.add(choice.seed)
                reported = self.verify(choice.variant(problem.scene), problem.parts) or ()
                problems += [
                    f"problem {problem.index} ({problem.scene_id}, seed {choice.seed}): {message}"
                    for message in reported
                ]
        if problems:
            lines = "\n".join(f"  - {p}" for p in problems)
            raise AssignmentError(f"the grader does not accept some answer keys:\n{lines}")

    def _templates(self) -> dict[str, jinja2.Template]:
        names = {"answer_sheet": "answer_sheet.toml.j2"}
        for fmt in self.formats:
            if fmt != "pdf":
                names[f"handout.{fmt}"] = f"handout.{fmt}.j2"
                names[f"key.{fmt}"] = f"key.{fmt}.j2"
        try:
            return {k: self.env.get_template(v) for k, v in names.items()}
        except jinja2.TemplateError as exc:
            raise AssignmentError(f"template {getattr(exc, 'name', '') or ''}: {exc}") from exc

    def _write(self, path: Path, data: str | bytes) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(data, str):
            data = data.encode("utf-8")
        path.write_bytes(data)
        self.files += 1

    def _write_all(
        self,
        tmp: Path,
        draws: dict[int, dict[str, VariantChoice]],
        templates: dict[str, jinja2.Template],
    ) -> None:
        total = len(self.roster) + (2 * len(self.roster) if "pdf" in self.formats else 0)
        done = 0
        students_manifest = []
        base = {
            "title": self.assignment.title,
            "course": self.assignment.course,
            "due": self.assignment.due,
            "instructions": self.assignment.instructions,
            "total_points": self.assignment.total_points,
        }
        for student in self.roster:
            views = self._student_views(tmp, student, draws)
            context = {
                "assignment": base,
                "student": {"id": student.id, "name": student.name, "extra": dict(student.extra)},
                "problems": views,
                "seed": self.seed,
            }
            self._render(tmp, student, templates, context)
            students_manifest.append(
                student_manifest(self.assignment, self.formats, student, draws, views)
            )
            done += 1
            self.progress(done, total, f"{student.id}")
        if "pdf" in self.formats:
            self.unwritten = self._compile_pdfs(tmp, done, total)
            for entry in students_manifest:  # the manifest lists only files that exist
                for kind in self.unwritten.get(entry["id"], {}):
                    entry["files"].pop(kind, None)
                if entry["id"] in self.unwritten:
                    entry["unwritten"] = dict(sorted(self.unwritten[entry["id"]].items()))
        shutil.copyfile(self.assignment_path, tmp / "assignment.toml")
        self.files += 1
        manifest = manifest_json(
            self.assignment, self.assignment_path, self.seed, self.formats, students_manifest
        )
        try:  # read back as `grade` reads it
            untrusted.load_json(manifest, "the manifest")
        except UnreadableInput as error:
            raise AssignmentError(f"{error}; `lagrade grade` could not read it") from None
        self._write(tmp / "manifest.json", manifest)

    def _student_views(
        self, tmp: Path, student: Student, draws: dict[int, dict[str, VariantChoice]]
    ) -> list[dict[str, Any]]:
        """The student's view of each problem; a figure is written the first time it is met."""
        views = []
        for problem in self.assignment.problems:
            choice = draws[problem.index][student.id]
            name = figure_name(problem, choice)
            cache_key = (problem.index, choice.seed)
            if cache_key not in self.views:
                self.views[cache_key] = problem_view(problem, choice, name)
            view = self.views[cache_key]
            if name not in self.figures_written:
                figure = symbolic_solution(problem.scene, *presentation(choice))["figure"]
                if figure is not None:  # a scene given by its Lagrangian has none
                    self._write(tmp / "figures" / f"{name}.svg", figure.svg)
                    self._write(tmp / "figures" / f"{name}.pdf", figure.pdf)
                self.figures_written.add(name)
            views.append(view)
        return views

    def _render(
        self,
        tmp: Path,
        student: Student,
        templates: dict[str, jinja2.Template],
        context: dict[str, Any],
    ) -> None:
        """The student's answer sheet, handouts and keys, one file per template."""
        try:
            for key, template in sorted(templates.items()):
                kind, _, fmt = key.partition(".")
                if kind == "answer_sheet":
                    text = template.render(context)
                    read_back_sheet(text, student, self.assignment)
                    self._write(tmp / "answer_sheets" / f"{student.id}.toml", text)
                else:
                    folder = "handouts" if kind == "handout" else "keys"
                    self._write(tmp / folder / f"{student.id}.{fmt}", template.render(context))
        except jinja2.TemplateError as exc:
            raise AssignmentError(f"template {key}: {exc}") from exc

    def _compile_pdfs(self, tmp: Path, done: int, total: int) -> dict[str, dict[str, str]]:
        """Every handout and key as PDF (`pdf.compile_pdf`); returns those not made, by student
        and file kind (`handout_pdf`), with the reason, each also a warning."""
        found = engines()
        unwritten: dict[str, dict[str, str]] = {}
        if not found:
            self.warnings.append(PDFLATEX_HINT)
            for student in self.roster:
                unwritten[student.id] = dict.fromkeys(("handout_pdf", "key_pdf"), PDFLATEX_HINT)
            return unwritten
        env = dict(os.environ, SOURCE_DATE_EPOCH="0", FORCE_SOURCE_DATE="1")
        for folder in ("handouts", "keys"):
            for tex in sorted((tmp / folder).glob("*.tex")):
                problem = compile_pdf(found, tex, env)
                if problem:
                    kind = "handout_pdf" if folder == "handouts" else "key_pdf"
                    unwritten.setdefault(tex.stem, {})[kind] = (
                        f"LaTeX could not typeset it ({problem})"
                    )
                    self.warnings.append(f"{folder}/{tex.stem}.pdf was not made: {problem}")
                else:
                    self.files += 1
                done += 1
                self.progress(done, total, f"pdf {tex.stem}")
        return unwritten

    def _move_into_place(self, tmp: Path, force: bool) -> None:
        old = None
        if self.out.exists():
            if not force:  # appeared while we were writing
                raise AssignmentError(f"output folder {str(self.out)!r} exists; pass --force")
            old = self.out.with_name(f".{self.out.name}.old-{os.getpid()}")
            self.out.rename(old)
        tmp.rename(self.out)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)


def read_back_sheet(text: str, student: Student, assignment: Assignment) -> None:
    """Read a blank answer sheet back as `grade` reads it (the untrusted-input TOML rules): it
    must parse, and what it says of the student (id, name) and of each part (blank) must be
    what was meant; otherwise AssignmentError, before anything is written (a title or name
    that broke the TOML would otherwise make every sheet of the class `invalid`). An
    instructor's own template may leave a field out."""
    what = f"the answer sheet of {student.id}"
    try:
        table = untrusted.load_toml(text, what)
    except UnreadableInput as error:
        raise AssignmentError(f"{error}; check the text that went into it") from None
    changed = [
        k for k, v in (("student_id", student.id), ("name", student.name)) if table.get(k, v) != v
    ]
    for problem in assignment.problems:
        answers = table.get(f"problem{problem.index}", {})
        if not isinstance(answers, dict):
            changed.append(f"problem{problem.index}")
            continue
        changed += [
            f"problem{problem.index}.{part.key}"
            for part in problem.parts
            if answers.get(part.key, "") != ""
        ]
    if changed:
        raise AssignmentError(f"{what} does not read back as written ({', '.join(changed)})")
