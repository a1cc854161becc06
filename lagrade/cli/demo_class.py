"""The synthetic class of `lagrade demo`: an assignment from the bank for 30 students, their
submissions (correct answers in varied notation, common mistakes, blank parts, a malformed file,
a missing one), generated, submitted and graded by `run_demo`.

The synthetic answers are built from each student's own variant, so they exercise the parser
(plain, implicit multiplication, `**`, `thetadot`, LaTeX) and the judge (scaled Lagrangians,
added constants, solved equations, any true conserved quantity, named mistakes) for real.
"""

from __future__ import annotations

import json
import random
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import sympy as sp

from lagrade.assign import generate, latex_symbol_names, toml_string
from lagrade.grading import BatchSummary, atomic, entry_variant, grade, question
from lagrade.judge import key_answer, verify_variant
from lagrade.mechanics import SceneVariant, phase_space
from lagrade.notation import plain

ASSIGNMENT = """\
# The demo assignment: `lagrade demo` writes it, generates handouts from it and grades against it.
title = "Demo problem set: the Lagrangian method"
course = "Classical Mechanics (demo)"
due = 2026-12-04T23:59:00
instructions = "Work each problem with the five-step method."
points = 1

[[problems]]
scene = "wedge"
parts = ["dof", "lagrangian", "eom", "momenta", "cyclic", "conserved",
         { quantity = "block_acceleration", points = 2 }]
points = { lagrangian = 3, eom = 3 }
variants = 8

[[problems]]
scene = "hoop"
parts = ["dof", "T", "V", "lagrangian", "eom", "conserved",
         { quantity = "equilibrium_angle", points = 2 }]
points = { lagrangian = 3, eom = 3 }
variants = 8

[[problems]]
scene = "kepler"
parts = ["lagrangian", "eom", "momenta", "cyclic", "conserved", "hamiltonian",
         "hamilton_equations"]
points = { lagrangian = 2, eom = 3, conserved = 2, hamiltonian = 2, hamilton_equations = 2 }
variants = 8

[[problems]]
scene = "coupled_oscillators"
parts = ["lagrangian", "equilibrium", "normal_modes", "mode_shapes"]
points = { normal_modes = 2, mode_shapes = 2 }
variants = 8

[rubric]
partial_credit = true
follow_through = 0.5
convention = 0.5
numeric_tolerance = 0.01
"""

FIRST = [
    "Ada",
    "Emmy",
    "Joseph",
    "Sofia",
    "Pierre",
    "Lise",
    "Paul",
    "Maria",
    "Niels",
    "Chien",
    "Henri",
    "Mileva",
    "Ludwig",
    "Marie",
    "Satyendra",
    "Cecilia",
    "Enrico",
    "Katherine",
    "Subrahmanyan",
    "Vera",
    "Werner",
    "Hedy",
    "Richard",
    "Jocelyn",
    "Erwin",
    "Rosalind",
    "Hideki",
    "Donna",
    "Abdus",
    "Andrea",
]
LAST = [
    "Lovelace",
    "Noether",
    "Lagrange",
    "Kovalevskaya",
    "Laplace",
    "Meitner",
    "Dirac",
    "Goeppert Mayer",
    "Bohr",
    "Wu",
    "Poincaré",
    "Marić",
    "Boltzmann",
    "Curie",
    "Bose",
    "Payne",
    "Fermi",
    "Johnson",
    "Chandrasekhar",
    "Rubin",
    "Heisenberg",
    "Lamarr",
    "Feynman",
    "Bell Burnell",
    "Schrödinger",
    "Franklin",
    "Yukawa",
    "Strickland",
    "Salam",
    "Ghez",
]
CLASS_SIZE = 30
MALFORMED = 7  # this student's file is broken TOML
MISSING = 23  # this student submits nothing


def _roster() -> str:
    rows = ["id,name,email,section"]
    for i in range(CLASS_SIZE):
        sid = f"s{i + 1:03d}"
        name = f"{FIRST[i]} {LAST[i]}"
        rows.append(f'{sid},"{name}",{sid}@example.edu,{"AB"[i % 2]}')
    return "\n".join(rows) + "\n"


# --- notations ----------------------------------------------------------------------------------


def _implicit(text: str) -> str:
    """'2*m*g*l' → '2 m g l': products by juxtaposition (the parser reads them back)."""
    return re.sub(r"(?<=[\w)])\*(?=[\w(])", " ", text)


def _undotted(text: str) -> str:
    """theta_dot → thetadot, x_M_ddot → x_Mddot."""
    return re.sub(r"_(d?dot)\b", r"\1", text)


def _latex(variant: SceneVariant, expr: sp.Expr) -> str:
    return sp.latex(expr, symbol_names=latex_symbol_names(variant))


NOTATIONS: dict[str, Callable[[SceneVariant, sp.Expr], str]] = {
    "plain": lambda v, e: plain(e),
    "python": lambda v, e: sp.sstr(e),
    "implicit": lambda v, e: _implicit(plain(e)),
    "undotted": lambda v, e: _undotted(plain(e)),
    "latex": _latex,
}


# --- one student's answers ----------------------------------------------------------------------


def _answers(
    variant: SceneVariant, parts: list[dict], entry: dict, rng: random.Random, profile: str
) -> tuple[dict[str, Any], list[str]]:
    """The answers of one student to one problem, and what was planted (for the summary)."""
    notation = NOTATIONS[rng.choice(sorted(NOTATIONS))]
    system = variant.system
    problem = question({"scene": variant.scene.id, "seed": variant.seed})
    planted: list[str] = []
    answers: dict[str, Any] = {}
    for part in parts:
        name, key = part["part"], part["key"]
        if profile == "weak" and rng.random() < 0.3:
            answers[key] = ""
            planted.append(f"{key}: blank")
            continue
        mistake = profile != "strong" and rng.random() < (0.25 if profile == "typical" else 0.5)
        if name == "lagrangian":
            L = variant.lagrangian
            if mistake and problem.catalogue.lagrangian_mutants:
                mutant = rng.choice(problem.catalogue.lagrangian_mutants[:4])
                L = mutant.expr
                planted.append(f"{key}: {mutant.kind}")
            else:
                L = rng.choice([L, 2 * L, L + 7, sp.expand(L * sp.Rational(1, 1))])
            answers[key] = notation(variant, L)
        elif name == "eom":
            rows = list(system.euler_lagrange)
            if mistake:
                rows[0] = rows[0] - 2 * sp.Add.make_args(rows[0])[-1]
                planted.append(f"{key}: sign of one term")
            elif len(rows) == 1 and rng.random() < 0.5:
                j = variant.jets[0]
                solved = sp.solve(rows[0], j.ddot)
                answers[key] = f"{notation(variant, j.ddot)} = {notation(variant, solved[0])}"
                continue
            else:
                rows = [-r if rng.random() < 0.5 else r for r in rows]
            answers[key] = "\n".join(f"{notation(variant, r)} = 0" for r in rows)
        elif name == "momenta":
            latex = notation is NOTATIONS["latex"]
            lines = [
                f"p_{{{sp.latex(j.q)}}} = {notation(variant, p)}"
                if latex
                else f"p_{j.name} = {notation(variant, p)}"
                for j, p in zip(variant.jets, system.generalized_momenta, strict=True)
            ]
            if mistake:
                lines[0] = (
                    lines[0].split("=")[0]
                    + "= "
                    + notation(variant, 2 * system.generalized_momenta[0])
                )
                planted.append(f"{key}: factor 2")
            answers[key] = "\n".join(lines)
        elif name == "conserved":
            quantities = list(system.conserved_quantities.values())
            if mistake and "h" in system.conserved_quantities:
                T, V = variant.kinetic_energy, variant.potential_energy
                quantities = [T - V]
                planted.append(f"{key}: T - V")
            answers[key] = "\n".join(
                notation(variant, 3 * q if rng.random() < 0.3 else q) for q in quantities
            )
        elif name == "cyclic":
            cyclic = list(system.cyclic_coordinates)
            if mistake:
                cyclic = list(variant.coordinates)
                planted.append(f"{key}: every coordinate")
            answers[key] = ", ".join(cyclic) or "none"
        elif name == "hamiltonian":
            H = phase_space(system).hamiltonian
            if mistake:  # H in the velocities: the energy function h, not yet in the momenta
                H = system.energy_function
                planted.append(f"{key}: H in the velocities")
            answers[key] = notation(variant, H)
        elif name == "expression":
            value = entry["quantities"][part["quantity"]]["value"]
            answers[key] = value if not mistake else str(-float(value))
            if mistake:
                planted.append(f"{key}: sign")
        else:
            key_text = key_answer(variant, name, part.get("quantity"))
            answers[key] = "\n".join(key_text) if isinstance(key_text, list) else key_text
            if mistake and name == "V":
                answers[key] = notation(variant, -variant.potential_energy)
                planted.append(f"{key}: sign of V")
            elif mistake and name == "normal_modes":  # ω² for the first frequency
                first, *rest = key_text.split(", ")
                answers[key] = ", ".join([f"({first})^2", *rest])
                planted.append(f"{key}: omega squared")
            elif mistake and name == "mode_shapes" and len(key_text) == 2:
                (w1, a1), (w2, a2) = (line.split(": ", 1) for line in key_text)
                answers[key] = f"{w1}: {a2}\n{w2}: {a1}"
                planted.append(f"{key}: the two vectors swapped")
    return answers, planted


def _toml_value(text: str) -> str:
    """A TOML literal string (LaTeX needs no escapes there) where the text allows, else basic."""
    if "'''" in text or text.endswith("'"):
        return json.dumps(text)
    return "'''\n" + text + "'''" if "\n" in text else "'''" + text + "'''"


def write_submissions(
    out: Path,
    manifest: dict[str, Any],
    *,
    malformed: int | None = MALFORMED,
    missing: int | None = MISSING,
) -> dict[str, list[str]]:
    """One answer sheet per student as TOML, but student number `missing` (0-based) sends none
    and `malformed`'s file is broken; returns what was planted in each."""
    planted: dict[str, list[str]] = {}
    profiles = ["strong", "typical", "typical", "weak"]
    for i, student in enumerate(manifest["students"]):
        sid = student["id"]
        if i == missing:
            planted[sid] = ["no submission"]
            continue
        rng = random.Random(f"demo:{sid}")
        profile = profiles[i % len(profiles)]
        lines = [f"student_id = {toml_string(sid)}", f"name = {toml_string(student['name'])}"]
        notes = [f"profile: {profile}"]
        for problem, entry in zip(manifest["problems"], student["problems"], strict=True):
            variant = entry_variant(entry)
            answers, planted_here = _answers(variant, problem["parts"], entry, rng, profile)
            notes += [f"problem {problem['index']} {p}" for p in planted_here]
            lines.append(f"\n[problem{problem['index']}]")
            lines += [f"{k} = {_toml_value(v)}" for k, v in answers.items()]
        text = "\n".join(lines) + "\n"
        if i == malformed:
            text = text.replace("[problem2]", "[problem2", 1)
            notes = ["malformed TOML"]
        atomic.write_text(out / f"{sid}.toml", text)
        planted[sid] = notes
    return planted


def run_demo(folder: Path, *, jobs: int = 2, progress=None) -> tuple[BatchSummary, dict[str, Path]]:
    """Generate, submit, grade; returns the grading summary and where the outputs are."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    assignment, roster = folder / "assignment.toml", folder / "roster.csv"
    atomic.write_text(assignment, ASSIGNMENT)
    atomic.write_text(roster, _roster())
    handouts = folder / "assignment"
    generate(
        assignment,
        roster,
        2026,
        handouts,
        formats=("md", "html"),
        force=True,
        progress=progress,
        verify=verify_variant,
    )
    manifest = json.loads((handouts / "manifest.json").read_text(encoding="utf-8"))
    submissions = folder / "submissions"
    planted = write_submissions(submissions, manifest)
    atomic.write_json(folder / "planted.json", planted)
    summary = grade(
        handouts / "manifest.json", submissions, folder / "grades", jobs=jobs, progress=progress
    )
    return summary, {
        "handouts": handouts / "handouts",
        "answer keys": handouts / "keys",
        "submissions": submissions,
        "gradebook": summary.out_dir / "gradebook.csv",
        "feedback": summary.out_dir / "feedback",
        "summary": summary.out_dir / "summary.md",
        "score chart": summary.out_dir / "scores.png",
    }
