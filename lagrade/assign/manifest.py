"""The manifest (`manifest.json`) that fixes every student's variant for grading: the assignment's
hash, the seed, each problem's parts, the scene files used (their text and hash, so that grading
needs nothing but the manifest), and per student the files written and the names, options and
values drawn. Keys are sorted and nothing records a time, so a rerun gives the same bytes."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from lagrade.assign.assignment import Assignment
from lagrade.assign.roster import Student
from lagrade.assign.variants import VariantChoice

MANIFEST_FORMAT = "lagrade-manifest/1"


def project_version() -> str:
    """The installed lagrade version (the source tree's pyproject is not read at run time)."""
    from importlib import metadata

    try:
        return metadata.version("lagrade")
    except metadata.PackageNotFoundError:
        return "0+unknown"


def student_manifest(
    assignment: Assignment,
    formats: Sequence[str],
    student: Student,
    draws: dict[int, dict[str, VariantChoice]],
    views: list[dict[str, Any]],
) -> dict[str, Any]:
    """One student's entry: the files written for them and the variant of each problem."""
    files = {"answer_sheet": f"answer_sheets/{student.id}.toml"}
    for fmt in formats:
        files[f"handout_{fmt}"] = f"handouts/{student.id}.{fmt}"
        files[f"key_{fmt}"] = f"keys/{student.id}.{fmt}"
    problems = []
    for problem, view in zip(assignment.problems, views, strict=True):
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
                "figure": view["figure"]["svg"].removeprefix("../") if view["figure"] else None,
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


def manifest_json(
    assignment: Assignment,
    assignment_path: Path,
    seed: int,
    formats: Sequence[str],
    students: list[dict[str, Any]],
) -> str:
    """The whole manifest as JSON text, from the students' entries (`student_manifest`)."""
    data = assignment_path.read_bytes()
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
                    **({"all": part.all} if part.part == "conserved" else {}),
                }
                for part in p.parts
            ],
        }
        for i, p in enumerate(assignment.problems)
    ]
    manifest = {
        "format": MANIFEST_FORMAT,
        "lagrade_version": project_version(),
        "assignment": {
            "title": assignment.title,
            "course": assignment.course,
            "due": assignment.due,
            "file": "assignment.toml",
            "sha256": hashlib.sha256(data).hexdigest(),
            "total_points": assignment.total_points,
        },
        "seed": seed,
        "formats": list(formats),
        "problems": problems,
        "scenes": assignment.scene_files(),
        "students": students,
    }
    return json.dumps(manifest, indent=2, sort_keys=True, ensure_ascii=False) + "\n"
