"""The student's own coordinates through every door: a sheet graded by `lagrade grade`, the same
answers through `check` (with the sheet's transformation as `given`) and through PrairieLearn's
`server.py` give the same verdicts, points and feedback; the rubric's `own_coordinates` charges
the transformation part only; `check --given-transformation` and `given.transformation` in a
`check --batch` request are that same `given`."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

from lagrade.cli.main import main
from lagrade.grading.answer_page.sheets import sheet_text
from lagrade.grading.batch import _rubric, grade
from lagrade.grading.manifest import entry_spec
from lagrade.grading.rubric import Rubric
from lagrade.grading.student import grade_student, question
from lagrade.judge.check import check, run_batch

from .own_coordinates_cases import CASES, answers

#: Cases by scene, with the names and presentation their labels are written in pinned.
VERTICAL = '\noptions = { angle_from = ["vertical"] }'
PICKED = {
    "incline_pendulum": 'names = { s = ["s"], phi = ["phi"] }' + VERTICAL,
    "wedge": 'names = { x_M = ["x_M"], q = ["q"] }',
    "spring_pendulum": 'names = { r = ["r"], theta = ["theta"] }' + VERTICAL,
    "two_body_spring": 'names = { r = ["r"], theta = ["theta"] }',
    "sliding_ladder": 'names = { theta = ["theta"] }\noptions = { angle_from = ["wall"] }',
}
BY_SCENE = {c.scene: c for c in CASES}
PARTS = ["transformation", "lagrangian", "eom", "momenta", "cyclic", "conserved"]
MULTI = {"transformation", "eom", "momenta", "conserved"}


def _assignment(rubric: str = "") -> str:
    problems = "\n".join(
        f'[[problems]]\nscene = "{scene}"\nparts = {json.dumps(PARTS)}\n{pinned}\n'
        for scene, pinned in PICKED.items()
    )
    return f'title = "Own coordinates"\npoints = 1\n{rubric}\n{problems}'


def _sheet(which: str) -> dict:
    """own: right in the student's coordinates; mixed: the student's transformation with the
    statement's answers; slips: the student's transformation and answers with an error."""
    sheet = {}
    for k, scene in enumerate(PICKED, 1):
        case = BY_SCENE[scene]
        mine = answers(case)
        source = answers(case, "statement") if which == "mixed" else mine
        table = {}
        for part in PARTS:
            value = getattr(source, part)
            if which == "slips" and part in mine.wrong:
                value = mine.wrong[part]
            if part == "transformation":
                value = mine.transformation
            table[part] = ", ".join(value) if part == "cyclic" else value
            if part == "cyclic" and not value:
                table[part] = "none"
        sheet[f"problem{k}"] = table
    return sheet


ROSTER = {"s1": "own", "s2": "mixed", "s3": "slips"}


@pytest.fixture(scope="module")
def graded(tmp_path_factory) -> tuple[Path, dict, dict]:
    root = tmp_path_factory.mktemp("own-coordinates")
    (root / "assignment.toml").write_text(_assignment())
    (root / "roster.csv").write_text("id,name\n" + "".join(f"{s},Student {s}\n" for s in ROSTER))
    assert main(
        ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv"),
         "--seed", "5", "--out", str(root / "out"), "--formats", "md"]
    ) == 0  # fmt: skip
    (root / "sheets").mkdir()
    for student, which in ROSTER.items():
        (root / "sheets" / f"{student}.json").write_text(json.dumps(_sheet(which)))
    summary = grade(root / "out" / "manifest.json", root / "sheets", jobs=1)
    assert summary.all_graded
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    results = {r["student"]["id"]: r for r in summary.results}
    full = {
        s: json.loads((summary.out_dir / "students" / f"{s}.json").read_text()) for s in results
    }
    return root, manifest, full


def _checked(entry: dict, part: str, table: dict):
    """The same answer through `check`, with the sheet's transformation and L as `given`."""
    given = {"transformation": table["transformation"]}
    if part in ("eom", "momenta", "cyclic", "conserved"):
        given["lagrangian"] = table["lagrangian"]
    if part == "conserved":  # the generated part asks for all of them (its `all` field)
        given["all"] = True
    answer = table[part]
    if part == "cyclic":
        answer = [n.strip() for n in answer.split(",") if n.strip() and n.strip() != "none"]
    if part == "transformation":
        given = None
    return check(question(entry_spec(entry)), part, answer, given=given)


@pytest.mark.parametrize("student", sorted(ROSTER))
def test_grade_and_check_give_the_same_verdicts(graded, student):
    _root, manifest, results = graded
    entries = next(s for s in manifest["students"] if s["id"] == student)["problems"]
    sheet = _sheet(ROSTER[student])
    for problem, entry in zip(results[student]["problems"], entries, strict=True):
        table = sheet[f"problem{problem['index']}"]
        for part in problem["parts"]:
            by_check = _checked(entry, part["part"], table)
            assert part["verdict"] == by_check.status, (student, entry["scene"], part["key"])
            assert part["feedback"] == list(by_check.feedback)
            assert part["mistakes"] == list(by_check.mistakes)
            assert part["follows_from_own_answer"] == by_check.follows_from_own_answer
            share = Rubric().fraction(
                by_check.status, by_check.score, by_check.mistakes, by_check.follows_from_own_answer
            )
            assert part["points"] == pytest.approx(share)


def test_a_sheet_in_the_students_coordinates_gets_full_marks(graded):
    _root, _manifest, results = graded
    own = results["s1"]
    assert own["score"] == own["max_score"]
    for problem in own["problems"]:
        transformation, *later = problem["parts"]
        assert "Your coordinates are not the statement's" in transformation["feedback"][-1]
        for part in later:
            assert part["feedback"][0].startswith("Judged in your coordinates"), part


def test_the_statements_answers_under_the_students_transformation_are_told_why(graded):
    _root, _manifest, results = graded
    told = [
        part
        for problem in results["s2"]["problems"]
        for part in problem["parts"]
        if part["verdict"] == "incorrect"
    ]
    assert told and all(
        any("right in the statement's coordinates, not in yours" in f for f in p["feedback"])
        for p in told
    )
    slips = results["s3"]
    assert all(
        part["verdict"] == "incorrect"
        for problem in slips["problems"]
        for part in problem["parts"]
        if part["part"] in ("lagrangian", "eom", "momenta", "conserved")
    )


def _load_server(folder: Path):
    spec = importlib.util.spec_from_file_location(f"server_{folder.name}", folder / "server.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_prairielearn_gives_what_grade_gives(graded, tmp_path):
    root, manifest, results = graded
    assert main(
        ["export", "prairielearn", str(root / "out" / "manifest.json"), "--out",
         str(tmp_path / "questions")]
    ) == 0  # fmt: skip
    folders = sorted(
        (tmp_path / "questions" / "questions").iterdir(),
        key=lambda f: int(f.name.split("-p")[-1].split("-")[0]),
    )
    for student, which in ROSTER.items():
        entries = next(s for s in manifest["students"] if s["id"] == student)["problems"]
        sheet = _sheet(which)
        for folder, entry, graded_problem in zip(
            folders, entries, results[student]["problems"], strict=True
        ):
            server = _load_server(folder)
            table = sheet[f"problem{graded_problem['index']}"]
            submitted = {k: "; ".join(v) if isinstance(v, list) else v for k, v in table.items()}
            data = {"params": {"seed": entry["seed"]}, "submitted_answers": submitted,
                    "partial_scores": {}, "correct_answers": {}}  # fmt: skip
            server.grade(data)
            for part in graded_problem["parts"]:
                pl = data["partial_scores"][part["key"]]
                assert pl["score"] * pl["weight"] == pytest.approx(part["points"])
                shown = data["feedback"]["lagrade"][part["key"]]
                assert [note["text"] for note in shown["notes"]] == part["feedback"]
                assert f"{part['points']:g} of {part['max_points']:g} point" in shown["outcome"]


def test_the_rubric_may_charge_another_convention_on_the_transformation_only(tmp_path):
    (tmp_path / "assignment.toml").write_text(_assignment("[rubric]\nown_coordinates = 0.25\n"))
    (tmp_path / "roster.csv").write_text("id,name\ns1,Own\ns4,Statement\n")
    main(["generate", str(tmp_path / "assignment.toml"), "--roster", str(tmp_path / "roster.csv"),
          "--seed", "5", "--out", str(tmp_path / "out"), "--formats", "md"])  # fmt: skip
    (tmp_path / "sheets").mkdir()
    (tmp_path / "sheets" / "s1.json").write_text(json.dumps(_sheet("own")))
    statement = {}
    for k, scene in enumerate(PICKED, 1):
        theirs = answers(BY_SCENE[scene], "statement")
        statement[f"problem{k}"] = {
            p: (", ".join(getattr(theirs, p)) or "none") if p == "cyclic" else getattr(theirs, p)
            for p in PARTS
        }
    (tmp_path / "sheets" / "s4.json").write_text(json.dumps(statement))
    summary = grade(tmp_path / "out" / "manifest.json", tmp_path / "sheets", jobs=1)
    by_id = {r["student"]["id"]: r for r in summary.results}
    assert by_id["s4"]["score"] == by_id["s4"]["max_score"]
    assert by_id["s1"]["score"] == pytest.approx(by_id["s1"]["max_score"] - 0.25 * len(PICKED))
    for problem in by_id["s1"]["problems"]:
        for part in problem["parts"]:
            expected = 0.75 if part["key"] == "transformation" else 1.0
            assert part["points"] == pytest.approx(expected), part


def test_check_given_transformation_on_the_command_line(capsys):
    case = BY_SCENE["wedge"]
    mine = answers(case)
    flags = [f for line in mine.transformation for f in ("--given-transformation", line)]
    answer = [f for line in mine.eom for f in ("--answer", line)]
    assert main(["check", "--scene", "wedge", "--part", "eom", *answer, *flags]) == 0
    out = capsys.readouterr().out
    assert "eom: correct" in out and "Judged in your coordinates" in out
    assert main(["check", "--scene", "wedge", "--part", "eom", *answer]) == 1


def test_a_batch_request_carries_the_transformation_in_given():
    case = BY_SCENE["incline_pendulum"]
    mine = answers(case)
    request = {
        "id": 1,
        "problem": {"scene": case.scene},
        "part": "momenta",
        "answer": mine.momenta,
        "given": {"transformation": "\n".join(mine.transformation)},
    }
    bad = {**request, "id": 2, "given": {"transformation": {"x_bob": "l sin(phi)"}}}
    lines = [json.dumps(request), json.dumps(bad)]
    first, second = run_batch(lines)
    assert first["verdict"] == "correct"
    assert first["feedback"][0].startswith("Judged in your coordinates")
    assert second["verdict"] == "invalid" and "transformation" in second["feedback"][0]


def test_the_answer_page_grades_a_saved_sheet_as_grade_does(graded, tmp_path):
    """The page writes the fields into a sheet with its own writer and grades a save with
    `grade_student` (`[answer_page] feedback = true`): the same verdicts as `grade`."""
    root, manifest, results = graded
    student = next(s for s in manifest["students"] if s["id"] == "s1")
    fields = {
        int(name.removeprefix("problem")): {
            key: "\n".join(value) if isinstance(value, list) else value
            for key, value in table.items()
        }
        for name, table in _sheet("own").items()
    }
    path = tmp_path / "s1.toml"
    path.write_text(sheet_text(manifest, student, fields))
    task = {"student": student, "path": str(path), "part_time_limit": 5.0}
    saved = grade_student(manifest, _rubric(root / "out" / "manifest.json", manifest), task)
    for mine, theirs in zip(saved["problems"], results["s1"]["problems"], strict=True):
        assert [(p["verdict"], p["points"], p["feedback"]) for p in mine["parts"]] == [
            (p["verdict"], p["points"], p["feedback"]) for p in theirs["parts"]
        ]
