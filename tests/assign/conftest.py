"""Fixtures for assignment generation: assignment files over the whole bank, small rosters."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.assign.assignment import PARTS
from lagrade.assign.phase_solution import PHASE_PARTS, can_ask_scene
from lagrade.bank import get_scene, scene_ids


def all_parts(scene_id: str) -> list:
    """Every part the scene can ask, with every quantity it declares."""
    scene = get_scene(scene_id)
    parts: list = [p for p in PARTS if p != "conserved" or scene.default.conserved_quantities]
    parts = [p for p in parts if p not in PHASE_PARTS or can_ask_scene(scene, p) is None]
    parts += [{"part": "expression", "quantity": q.name, "points": 2} for q in scene.quantities]
    return parts


def toml_value(value) -> str:
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + " }"
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    return str(value)


def write_assignment(path: Path, problems: list[dict], **top) -> Path:
    lines = [
        f"title = {toml_value(top.get('title', 'Test set'))}",
        f"course = {toml_value(top.get('course', 'PHYS 101'))}",
        "due = 2025-01-31",
    ]
    for problem in problems:
        lines.append("\n[[problems]]")
        lines += [f"{k} = {toml_value(v)}" for k, v in problem.items()]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def write_roster(path: Path, rows: list[tuple[str, str]], header: str = "id,name,email") -> Path:
    import csv
    import io

    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header.split(","))
    for sid, name in rows:
        writer.writerow([sid, name, f"{sid}@example.edu"])
    path.write_text(buffer.getvalue(), encoding="utf-8")
    return path


@pytest.fixture
def whole_bank(tmp_path: Path) -> Path:
    """An assignment asking every part of every scene in the bank."""
    return write_assignment(
        tmp_path / "bank.toml", [{"scene": s, "parts": all_parts(s)} for s in scene_ids()]
    )


@pytest.fixture
def small_assignment(tmp_path: Path) -> Path:
    return write_assignment(
        tmp_path / "small.toml",
        [
            {
                "scene": "wedge",
                "parts": [
                    "lagrangian",
                    "eom",
                    {"part": "expression", "quantity": "block_acceleration"},
                ],
            },
            {"scene": "hoop", "parts": ["lagrangian", "conserved"]},
        ],
    )


@pytest.fixture
def roster(tmp_path: Path) -> Path:
    return write_roster(
        tmp_path / "roster.csv", [(f"s{i:03d}", f"Student {i}") for i in range(1, 7)]
    )


def snapshot(folder: Path) -> dict[str, bytes]:
    """Every file under `folder` by relative path, with its bytes."""
    return {
        str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()
    }
