"""Errors name the problem, list everything at once, and leave the disk as it was."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.assign.assignment import load_assignment
from lagrade.assign.roster import load_roster, parse_roster
from lagrade.bank import scene_ids
from lagrade.errors import AssignmentError

from .conftest import snapshot, write_assignment


def _error(path: Path) -> str:
    with pytest.raises(AssignmentError) as info:
        load_assignment(path)
    return str(info.value)


def test_unknown_scene_lists_the_bank(tmp_path: Path) -> None:
    message = _error(write_assignment(tmp_path / "a.toml", [{"scene": "wedgee", "parts": ["dof"]}]))
    assert "problems[1].scene: unknown scene 'wedgee'" in message
    assert all(s in message for s in scene_ids())


def test_every_problem_is_reported_at_once(tmp_path: Path) -> None:
    message = _error(
        write_assignment(
            tmp_path / "a.toml",
            [
                {
                    "scene": "wedge",
                    "parts": [
                        "lagrangain",
                        "eom",
                        "eom",
                        {"part": "expression", "quantity": "speed"},
                    ],
                    "points": {"momenta": 2},
                    "variants": 0,
                    "names": {"q": ["z"]},
                },
                {"scene": "hoop", "parts": ["lagrangian"], "options": {"colour": ["red"]}},
            ],
        )
    )
    for fragment in [
        "problems[1].parts[1]: unknown part 'lagrangain'",
        "problems[1].parts[3]: part 'eom' is asked twice",
        "problems[1].parts[4].quantity: scene 'wedge' declares no quantity 'speed' "
        "(it declares: block_acceleration)",
        "problems[1].points.momenta: no part 'momenta' is asked",
        "problems[1].variants: 0 is not a whole number",
        "problems[1].names.q: 'z' not offered (offered: q, s)",
        "problems[2].options.colour: the scene has no option 'colour'",
    ]:
        assert fragment in message, fragment


def test_missing_title_and_problems(tmp_path: Path) -> None:
    path = tmp_path / "a.toml"
    path.write_text('course = "x"\nsurprise = 1\n')
    message = _error(path)
    assert "title: missing" in message and "problems: the assignment asks no problem" in message
    assert "surprise: unknown field" in message


def test_invalid_toml_names_the_line(tmp_path: Path) -> None:
    path = tmp_path / "a.toml"
    path.write_text('title = "x\n')
    assert "is not valid TOML" in _error(path) and "line 1" in _error(path)


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("id,name\ns1,Ann\ns2\n", "line 3: 1 fields, but the header has 2"),
        ("id,name\ns1,Ann\nS1,Ben\n", "line 3: duplicate id 'S1' (already on line 2"),
        ("id,name\n,Ann\n", "line 2: the id is empty"),
        ("id,name\n../etc,Ann\n", "line 2: id '../etc' cannot name a file"),
        ("id,name\ns1,\n", "line 2: student 's1' has an empty name"),
        ("ident,name\ns1,Ann\n", "line 1: the header ident, name lacks the column(s) id"),
        ("", "is empty"),
    ],
)
def test_malformed_rosters(text: str, fragment: str) -> None:
    with pytest.raises(AssignmentError) as info:
        parse_roster(text)
    assert fragment in str(info.value)


def test_roster_as_lms_export_it(tmp_path: Path) -> None:
    path = tmp_path / "r.csv"
    path.write_bytes('\ufeffName,ID,Email,Section\r\n"Doe, Jane",j1,j@x.edu,A\r\n\r\n'.encode())
    (student,) = load_roster(path)
    assert (student.id, student.name, dict(student.extra)) == (
        "j1",
        "Doe, Jane",
        {"Email": "j@x.edu", "Section": "A"},
    )


def test_roster_that_is_not_utf8(tmp_path: Path) -> None:
    path = tmp_path / "r.csv"
    path.write_bytes("id,name\ns1,Jos\xe9\n".encode("latin-1"))
    with pytest.raises(AssignmentError, match="is not UTF-8"):
        load_roster(path)


def test_existing_output_needs_force_and_is_left_alone(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / "mine.txt").write_text("keep me")
    before = snapshot(tmp_path)
    with pytest.raises(AssignmentError, match="exists; choose another or pass --force"):
        generate(small_assignment, roster, 1, out, ["md"])
    assert snapshot(tmp_path) == before
    generate(small_assignment, roster, 1, out, ["md"], force=True)
    assert not (out / "mine.txt").exists() and (out / "manifest.json").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["out", "roster.csv", "small.toml"])


def test_errors_from_every_input_come_together(tmp_path: Path) -> None:
    bad = write_assignment(tmp_path / "a.toml", [{"scene": "nope", "parts": ["dof"]}])
    roster = tmp_path / "r.csv"
    roster.write_text("id,name\ns1,Ann\ns1,Ann\n")
    before = snapshot(tmp_path)
    with pytest.raises(AssignmentError) as info:
        generate(bad, roster, 1, tmp_path / "out", "md,docx")
    message = str(info.value)
    assert "unknown scene 'nope'" in message and "duplicate id 's1'" in message
    assert "unknown format(s) docx" in message
    assert snapshot(tmp_path) == before and not (tmp_path / "out").exists()


def test_verify_reports_stop_generation(
    small_assignment: Path, roster: Path, tmp_path: Path
) -> None:
    calls = []

    def verify(variant, parts):
        calls.append((variant.scene.id, variant.seed, tuple(p.key for p in parts)))
        return ["key for eom judged incorrect"] if variant.scene.id == "hoop" else []

    before = snapshot(tmp_path)
    with pytest.raises(AssignmentError, match=r"problem 2 \(hoop, seed \d+\): key for eom"):
        generate(small_assignment, roster, 1, tmp_path / "out", ["md"], verify=verify)
    assert snapshot(tmp_path) == before
    assert ("wedge", calls[0][1], ("lagrangian", "eom", "block_acceleration")) in calls
    assert len(calls) == len(set(calls))  # once per distinct variant
