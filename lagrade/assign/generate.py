"""Assignment generation: one handout, answer key and blank answer sheet per student, figures,
and a manifest that fixes every student's variant, rendered from jinja2 templates.

Everything is written to a temporary folder beside the destination and moved into place only
when complete, so an error leaves the disk as it was. The same assignment, roster and seed give
byte-identical files: keys are sorted, nothing records a time, and figures are deterministic.
Each distinct variant is derived and drawn once, however many students share it.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import jinja2
import sympy as sp
from markupsafe import Markup, escape

import lagrade.assign.figures as figures
from lagrade.assign.assignment import EXPRESSION, Assignment, Part, Problem, load_assignment
from lagrade.assign.roster import Student, load_roster
from lagrade.assign.variants import VariantChoice, student_variants
from lagrade.errors import AssignmentError, LagradeError
from lagrade.mechanics.scene import RigidBody, SceneVariant
from lagrade.notation import printer as rm

FORMATS: tuple[str, ...] = ("md", "html", "tex", "pdf")
MANIFEST_FORMAT = "lagrade-manifest/1"
TEX_PACKAGES = ("texlive-latex-base",)
PDFLATEX_HINT = (
    "pdflatex is not installed, so no PDF was made (the .tex files are written). Install it "
    "with: apt-get install --no-install-recommends " + " ".join(TEX_PACKAGES)
)

#: Progress callback: (steps done, steps in all, what is being done).
Progress = Callable[[int, int, str], None]
#: The grader's check of a variant: returns a description of each problem found (none: fine).
Verifier = Callable[[SceneVariant, Sequence[Part]], Iterable[str] | None]

PROMPTS: dict[str, str] = {
    "dof": "List the constraints and give the number of degrees of freedom.",
    "coordinates": "Name the generalized coordinates (use the ones named in the statement).",
    "transformation": "Write the transformation equations: each body's Cartesian coordinates "
    "in terms of the generalized coordinates (and t).",
    "T": "Write the kinetic energy T.",
    "V": "Write the potential energy V.",
    "lagrangian": "Write the Lagrangian L = T - V.",
    "eom": "Derive the Euler-Lagrange equations of motion, one per coordinate.",
    "momenta": "Give the generalized momentum of each coordinate.",
    "cyclic": "Which coordinates are cyclic? (Write none if there are none.)",
    "conserved": "Give the conserved quantities as functions of the coordinates and velocities.",
}
#: Parts whose answer sheet field holds several lines (one equation or item per line).
MULTILINE = frozenset({"transformation", "eom", "momenta", "conserved"})
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_ENGLISH = frozenset({"a", "A", "I"})
_TEX_SPECIALS = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
}
_MD_SPECIALS = re.compile(r"([\\`*_{}\[\]#!|<>&~$])")
_MD_LINE_START = re.compile(r"^(\s*)([-+=]|\d+(?=[.)]))")


@dataclass
class GenerateResult:
    """What `generate` wrote: the output folder, the students, and warnings to show the user."""

    out_dir: Path
    students: int
    files: int
    warnings: list[str] = field(default_factory=list)


# --- filters -----------------------------------------------------------------------------------


def tex_escape(value: Any) -> str:
    """Text made safe for LaTeX: every special character written as a command or escaped."""
    return "".join(_TEX_SPECIALS.get(ch, ch) for ch in str(value))


def md_escape(value: Any) -> str:
    """Text made inert in Markdown: punctuation backslash-escaped, so `<script>` is shown, not
    run, by any CommonMark renderer."""
    text = _MD_SPECIALS.sub(r"\\\1", str(value).replace("\n", " "))
    # a leading "- ", "+ " or "1." would start a list: escape its marker
    return _MD_LINE_START.sub(
        lambda m: (
            m.group(1) + (m.group(2) + "\\" if m.group(2)[0].isdigit() else "\\" + m.group(2))
        ),
        text,
    )


def toml_string(value: Any) -> str:
    """A TOML basic string (quoted) holding `value`."""
    out = []
    for ch in str(value):
        if ch in ('"', "\\"):
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def format_points(value: float) -> str:
    return f"{value:g}"


def one_line(value: Any) -> str:
    """Text for a TOML comment: line breaks would end the comment, so they become spaces."""
    return " ".join(str(value).split())


def environment(templates_dir: str | Path | None = None) -> jinja2.Environment:
    """The strict jinja2 environment: an instructor's folder first, then the shipped templates."""
    import lagrade.assign.templates as shipped

    loaders: list[jinja2.BaseLoader] = []
    if templates_dir is not None:
        if not Path(templates_dir).is_dir():
            raise AssignmentError(f"templates folder {str(templates_dir)!r} does not exist")
        loaders.append(jinja2.FileSystemLoader(str(templates_dir)))
    loaders.append(jinja2.FileSystemLoader(str(Path(shipped.__file__).parent)))
    env = jinja2.Environment(
        loader=jinja2.ChoiceLoader(loaders),
        undefined=jinja2.StrictUndefined,
        autoescape=jinja2.select_autoescape(
            enabled_extensions=("html.j2", "html"), default_for_string=False, default=False
        ),
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
    )
    env.filters.update(
        tex=tex_escape, md=md_escape, toml=toml_string, points=format_points, oneline=one_line
    )
    return env


# --- solutions ---------------------------------------------------------------------------------


def _statement(variant: SceneVariant) -> dict[str, Any]:
    """The statement with every coordinate and parameter name set as math, in each format."""
    text = variant.statement()
    names = set(variant.coordinates) | set(variant.parameter_symbols)
    md, html, tex = [], [], []
    last = 0
    for match in _WORD.finditer(text):
        word = match.group()
        if word not in names or word in _ENGLISH:
            continue
        before = text[last : match.start()]
        md.append(md_escape(before))
        html.append(str(escape(before)))
        tex.append(tex_escape(before))
        math = rm.render(sp.Symbol(word))
        md.append(f"${math.latex}$")
        html.append(str(math.mathml))
        tex.append(f"${math.latex}$")
        last = match.end()
    rest = text[last:]
    md.append(md_escape(rest))
    html.append(str(escape(rest)))
    tex.append(tex_escape(rest))
    return {"text": text, "md": "".join(md), "html": Markup("".join(html)), "tex": "".join(tex)}


def _body_kind(body: Any) -> str:
    return "rigid body" if isinstance(body, RigidBody) else "point mass"


@lru_cache(maxsize=512)
def _symbolic(scene_id: str, names: tuple, options: tuple) -> dict[str, Any]:
    """The derived solution of a presentation (names, options) of a scene: it does not depend on
    the parameter values, so every seed with the same names and options shares it."""
    from lagrade.bank.registry import get_scene

    scene = get_scene(scene_id)
    v = SceneVariant(scene, names=dict(names), options=dict(options))
    coords = v.coordinates

    def math(expr: sp.Basic) -> rm.Math:
        return rm.render(expr, coords)

    def eq(lhs: sp.Basic, rhs: sp.Basic) -> rm.Math:
        return rm.equation(lhs, rhs, coords)

    system = v.system
    parameters = set(v.parameter_symbols)
    energy = next(n for n in ("h", "H", "E_J") if n not in parameters and n not in coords)

    def label(name: str) -> sp.Symbol:
        """`p_x_M` → p_{xM}; the energy function `h` renamed when a parameter is called h."""
        if name == "h":
            return sp.Symbol(energy)
        head, _, sub = name.partition("_")
        return sp.Symbol(f"{head}_{sub.replace('_', '')}" if sub else head)

    constraints = [
        {"description": label if label != "declared" else "constraint", "math": eq(f, 0)}
        for label, f in v.constraints
    ]
    return {
        "statement": _statement(v),
        "coordinates": [math(sp.Symbol(c)) for c in coords],
        "coordinate_names": list(coords),
        "bodies": [
            {"name": b.name, "kind": _body_kind(b), "freedoms": b.freedoms} for b in v.bodies
        ],
        "freedoms": sum(b.freedoms for b in v.bodies),
        "constraints": constraints,
        "k": len(constraints),
        "dof": v.dof,
        "transformation": [eq(sp.Symbol(k), e) for k, e in v.transformation.items()],
        "T": math(v.kinetic_energy),
        "V": math(v.potential_energy),
        "L": math(v.lagrangian),
        "momenta": [
            eq(label(f"p_{c}"), p) for c, p in zip(coords, system.generalized_momenta, strict=True)
        ],
        "eom": [eq(e, 0) for e in system.euler_lagrange],
        "cyclic": [math(sp.Symbol(c)) for c in system.cyclic_coordinates],
        "cyclic_names": list(system.cyclic_coordinates),
        "conserved": [
            {"name": name, "math": eq(label(name), q)}
            for name, q in system.conserved_quantities.items()
        ],
        "figure": figures.draw(v),
    }


def _number(value: sp.Expr) -> str:
    number = complex(sp.N(value, 15))
    if abs(number.imag) > 1e-12 * max(1.0, abs(number.real)):
        return "not real for these values"
    return f"{number.real:.4g}"


def _problem_view(problem: Problem, choice: VariantChoice, figure_name: str) -> dict[str, Any]:
    """Everything a template shows about one student's variant of one problem."""
    scene = problem.scene
    key = (tuple(sorted(choice.names.items())), tuple(sorted(choice.options.items())))
    symbolic = _symbolic(scene.id, *key)
    variant = choice.variant(scene)
    coords = variant.coordinates
    parameters = []
    for p in scene.parameters:
        value = choice.values.get(p.name)
        parameters.append(
            {
                "name": p.name,
                "symbol": rm.render(variant.parameter_symbols[p.name]),
                "value": None if value is None else f"{value:g}",
                "unit": p.unit,
                "description": p.description,
                "domain": p.domain.text,
            }
        )
    declared = {q.name: q for q in scene.quantities}
    quantities = {}
    for part in problem.parts:
        if part.part != EXPRESSION:
            continue
        q = declared[part.quantity]
        expr = variant.quantities[q.name]
        quantities[q.name] = {
            "name": q.name,
            "description": q.description,
            "unit": q.unit,
            "formula": rm.equation(sp.Symbol(q.name), expr, coords),
            "value": _number(
                expr.xreplace(
                    {
                        variant.parameter_symbols[n]: sp.Float(v, 15)
                        for n, v in choice.values.items()
                    }
                )
            ),
        }
    parts = []
    for part in problem.parts:
        if part.part == EXPRESSION:
            q = declared[part.quantity]
            unit = f" (in {q.unit})" if q.unit else ""
            prompt = (
                f"Find {q.description}: a closed form in the parameters, and its value for "
                f"your parameter values{unit}."
            )
        else:
            prompt = PROMPTS[part.part]
        parts.append(
            {
                "key": part.key,
                "part": part.part,
                "quantity": part.quantity,
                "points": part.points,
                "prompt": prompt,
                "multiline": part.part in MULTILINE,
            }
        )
    return {
        "index": problem.index,
        "title": problem.title,
        "scene": scene.id,
        "seed": choice.seed,
        "statement": symbolic["statement"],
        "coordinates": symbolic["coordinates"],
        "coordinate_names": symbolic["coordinate_names"],
        "parameters": parameters,
        "parts": parts,
        "asked": [p.part for p in problem.parts],
        "total_points": problem.total_points,
        "figure": {
            "svg": f"../figures/{figure_name}.svg",
            "pdf": f"../figures/{figure_name}.pdf",
            "inline_svg": _inline_svg(symbolic["figure"].svg),
        },
        "solution": {
            **{k: v for k, v in symbolic.items() if k not in ("figure", "statement")},
            "quantities": quantities,
        },
    }


def _inline_svg(svg: bytes) -> Markup:
    text = svg.decode("utf-8")
    return Markup(text[text.index("<svg") :])


def _figure_name(problem: Problem, choice: VariantChoice) -> str:
    tag = json.dumps([sorted(choice.names.items()), sorted(choice.options.items())])
    digest = hashlib.sha256(tag.encode()).hexdigest()[:10]
    return f"p{problem.index}-{problem.scene_id}-{digest}"


# --- generation --------------------------------------------------------------------------------


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


def project_version() -> str:
    """The installed lagrade version (the source tree's pyproject is not read at run time)."""
    from importlib import metadata

    try:
        return metadata.version("lagrade")
    except metadata.PackageNotFoundError:
        return "0+unknown"


def generate(
    assignment_path: str | Path,
    roster_path: str | Path,
    seed: int,
    out_dir: str | Path,
    formats: str | Iterable[str] = ("md", "html", "tex"),
    templates_dir: str | Path | None = None,
    force: bool = False,
    progress: Progress | None = None,
    verify: Verifier | None = None,
) -> GenerateResult:
    """Write handouts, keys, answer sheets, figures and `manifest.json` for every student.

    Raises AssignmentError (listing every problem found) before anything is written when the
    assignment, roster, formats, templates or output folder cannot be used, or when `verify`
    reports a variant whose key the grader would not accept.
    """
    out = Path(out_dir)
    errors: list[str] = []
    assignment = roster = chosen = None
    for attempt in (
        lambda: load_assignment(assignment_path),
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
    return _Generator(
        assignment, roster, seed, out, chosen, env, progress, verify, Path(assignment_path)
    ).run(force)


class _Generator:
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
        self.files = 0
        self.views: dict[tuple[int, int], dict[str, Any]] = {}  # students sharing a variant

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
        return GenerateResult(self.out, len(self.roster), self.files, self.warnings)

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
        figures_written: set[str] = set()
        students_manifest = []
        base = {
            "title": self.assignment.title,
            "course": self.assignment.course,
            "due": self.assignment.due,
            "instructions": self.assignment.instructions,
            "total_points": self.assignment.total_points,
        }
        for student in self.roster:
            views = []
            for problem in self.assignment.problems:
                choice = draws[problem.index][student.id]
                name = _figure_name(problem, choice)
                cache_key = (problem.index, choice.seed)
                if cache_key not in self.views:
                    self.views[cache_key] = _problem_view(problem, choice, name)
                view = self.views[cache_key]
                if name not in figures_written:
                    figure = _symbolic(problem.scene_id, *_presentation(choice))["figure"]
                    self._write(tmp / "figures" / f"{name}.svg", figure.svg)
                    self._write(tmp / "figures" / f"{name}.pdf", figure.pdf)
                    figures_written.add(name)
                views.append(view)
            context = {
                "assignment": base,
                "student": {"id": student.id, "name": student.name, "extra": dict(student.extra)},
                "problems": views,
                "seed": self.seed,
            }
            try:
                for key, template in sorted(templates.items()):
                    kind, _, fmt = key.partition(".")
                    if kind == "answer_sheet":
                        self._write(
                            tmp / "answer_sheets" / f"{student.id}.toml", template.render(context)
                        )
                    else:
                        folder = "handouts" if kind == "handout" else "keys"
                        self._write(tmp / folder / f"{student.id}.{fmt}", template.render(context))
            except jinja2.TemplateError as exc:
                raise AssignmentError(f"template {key}: {exc}") from exc
            students_manifest.append(self._student_manifest(student, draws, views))
            done += 1
            self.progress(done, total, f"{student.id}")
        if "pdf" in self.formats:
            self._compile_pdfs(tmp, done, total)
        shutil.copyfile(self.assignment_path, tmp / "assignment.toml")
        self.files += 1
        self._write(tmp / "manifest.json", self._manifest(students_manifest))

    def _student_manifest(
        self,
        student: Student,
        draws: dict[int, dict[str, VariantChoice]],
        views: list[dict[str, Any]],
    ) -> dict[str, Any]:
        files = {"answer_sheet": f"answer_sheets/{student.id}.toml"}
        for fmt in self.formats:
            files[f"handout_{fmt}"] = f"handouts/{student.id}.{fmt}"
            files[f"key_{fmt}"] = f"keys/{student.id}.{fmt}"
        problems = []
        for problem, view in zip(self.assignment.problems, views, strict=True):
            choice = draws[problem.index][student.id]
            problems.append(
                {
                    "index": problem.index,
                    "scene": problem.scene_id,
                    "seed": choice.seed,
                    "names": dict(choice.names),
                    "options": dict(choice.options),
                    "values": dict(choice.values),
                    "coordinates": view["coordinate_names"],
                    "figure": view["figure"]["svg"].removeprefix("../"),
                    "quantities": {
                        k: {
                            "value": q["value"],
                            "unit": q["unit"],
                            "expression": q["formula"].plain,
                        }
                        for k, q in view["solution"]["quantities"].items()
                    },
                }
            )
        return {
            "id": student.id,
            "name": student.name,
            "extra": dict(student.extra),
            "files": files,
            "problems": problems,
        }

    def _manifest(self, students: list[dict[str, Any]]) -> str:
        data = self.assignment_path.read_bytes()
        problems = [
            {
                "index": p.index,
                "scene": p.scene_id,
                "title": p.title,
                "total_points": p.total_points,
                "variants": p.variants,
                "distinct_variants": len({s["problems"][i]["seed"] for s in students}),
                "parts": [
                    {
                        "key": part.key,
                        "part": part.part,
                        "quantity": part.quantity,
                        "points": part.points,
                    }
                    for part in p.parts
                ],
            }
            for i, p in enumerate(self.assignment.problems)
        ]
        manifest = {
            "format": MANIFEST_FORMAT,
            "lagrade_version": project_version(),
            "assignment": {
                "title": self.assignment.title,
                "course": self.assignment.course,
                "due": self.assignment.due,
                "file": "assignment.toml",
                "sha256": hashlib.sha256(data).hexdigest(),
                "total_points": self.assignment.total_points,
            },
            "seed": self.seed,
            "formats": list(self.formats),
            "problems": problems,
            "students": students,
        }
        return json.dumps(manifest, indent=2, sort_keys=True, ensure_ascii=False) + "\n"

    def _compile_pdfs(self, tmp: Path, done: int, total: int) -> None:
        pdflatex = shutil.which("pdflatex")
        if pdflatex is None:
            self.warnings.append(PDFLATEX_HINT)
            return
        env = dict(os.environ, SOURCE_DATE_EPOCH="0", FORCE_SOURCE_DATE="1")
        for folder in ("handouts", "keys"):
            for tex in sorted((tmp / folder).glob("*.tex")):
                problem = compile_pdf(pdflatex, tex, env)
                if problem:
                    self.warnings.append(f"{folder}/{tex.name}: {problem}")
                else:
                    self.files += 1
                done += 1
                self.progress(done, total, f"pdf {tex.stem}")

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


def _presentation(choice: VariantChoice) -> tuple[tuple, tuple]:
    return tuple(sorted(choice.names.items())), tuple(sorted(choice.options.items()))


def compile_pdf(pdflatex: str, tex: Path, env: dict[str, str], timeout: float = 120) -> str | None:
    """Compile `tex` next to itself (so `../figures/…` resolves); None, or why it failed."""
    with tempfile.TemporaryDirectory(prefix="lagrade-tex-") as build:
        try:
            run = subprocess.run(
                [
                    pdflatex,
                    "-interaction=nonstopmode",
                    "-halt-on-error",
                    "-no-shell-escape",
                    f"-output-directory={build}",
                    tex.name,
                ],
                cwd=tex.parent,
                env=env,
                capture_output=True,
                timeout=timeout,
                check=False,
            )
        except subprocess.TimeoutExpired:
            return f"pdflatex took more than {timeout:g} s"
        pdf = Path(build) / (tex.stem + ".pdf")
        if run.returncode != 0 or not pdf.exists():
            log = run.stdout.decode("utf-8", "replace").splitlines()
            first = next((line for line in log if line.startswith("!")), "see the LaTeX log")
            return f"pdflatex failed: {first}"
        shutil.move(str(pdf), tex.with_suffix(".pdf"))
    return None


__all__ = ["FORMATS", "GenerateResult", "compile_pdf", "environment", "generate", "parse_formats"]
