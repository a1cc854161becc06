"""Same inputs, same bytes; nothing records where or when it ran."""

from __future__ import annotations

from pathlib import Path

from lagrade.assign import generate

from .conftest import snapshot


def test_generating_twice_gives_identical_bytes(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    first, second = tmp_path / "one", tmp_path / "elsewhere" / "two"
    generate(small_assignment, roster, 42, first, "md,html,tex")
    generate(small_assignment, roster, 42, second, "md,html,tex")
    a, b = snapshot(first), snapshot(second)
    assert sorted(a) == sorted(b)
    assert [name for name in a if a[name] != b[name]] == []


def test_another_seed_gives_other_variants(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    import json

    generate(small_assignment, roster, 1, tmp_path / "a", ["md"])
    generate(small_assignment, roster, 2, tmp_path / "b", ["md"])
    seeds = [
        [
            p["seed"]
            for s in json.loads((tmp_path / d / "manifest.json").read_text())["students"]
            for p in s["problems"]
        ]
        for d in ("a", "b")
    ]
    assert seeds[0] != seeds[1]
