"""One driver around the door (issue 34): for a class in which every student has a variant of
their own, `lagrade check --seed <the student's seed>` and `lagrade grade` give the same verdict
and byte-identical feedback for the same answer, for every student and part — and the numbers a
wrong answer's feedback quotes are the student's own. Before, `grade` built each question from
the first student asked it, and later students read that student's parameter values and points
("the reference q̈₁ = −0.654" for a student whose own value is 1.962).

The wrong answers are made from each student's own key, the ways students make them: the
handout's numbers put in for the symbols (a symbolic answer must hold for every value), an
equation of motion with its right side negated, a momentum doubled."""

from __future__ import annotations

import json
import re

import pytest

from lagrade.assign import generate
from lagrade.cli.main import main
from lagrade.grading.batch import grade
from lagrade.grading.manifest import entry_variant
from lagrade.judge.key import key_answer

ASSIGNMENT = """\
title = "One driver"
points = 1

[[problems]]
scene = "wedge"
parts = ["lagrangian", "V", "eom", "momenta", "conserved", { quantity = "block_acceleration" }]

[[problems]]
scene = "kepler"
parts = ["lagrangian", "eom", "momenta", "conserved", { quantity = "circular_angular_velocity" }]
"""
STUDENTS = ("s1", "s2", "s3", "s4")


def _plugged(text: str, values: dict[str, float]) -> str:
    """`text` with each parameter name replaced by the handout's value (whole words only)."""
    for name, value in sorted(values.items(), key=lambda kv: -len(kv[0])):
        text = re.sub(rf"(?<![\w.]){re.escape(name)}(?![\w])", f"({value:g})", text)
    return text


def _wrong(part: str, key, values: dict[str, float]):
    """A wrong answer made from the student's own key."""
    lines = key if isinstance(key, list) else [key]
    if part == "eom":  # the last equation solved for its acceleration, the right side negated
        left, _, _zero = lines[-1].partition("=")
        terms = [t.strip() for t in re.split(r"(?=[+-])", left.replace(" ", "")) if t.strip()]
        with_acceleration = [t for t in terms if "_ddot" in t]
        rest = [t for t in terms if "_ddot" not in t]
        return [*lines[:-1], f"{''.join(with_acceleration)} = {''.join(rest)}"]
    if part == "momenta":  # the first momentum doubled
        label, _, value = lines[0].partition("=")
        return [f"{label.strip()} = 2*({value.strip()})", *lines[1:]]
    if part == "expression":
        return f"2*({lines[0]})"
    plugged = [_plugged(line, values) for line in lines]
    return plugged if isinstance(key, list) else plugged[0]


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    root = tmp_path_factory.mktemp("one-driver")
    (root / "a.toml").write_text(ASSIGNMENT)
    (root / "roster.csv").write_text("id,name\n" + "".join(f"{s},{s}\n" for s in STUDENTS))
    generate(root / "a.toml", root / "roster.csv", 7, root / "out", formats=("md",))
    manifest = json.loads((root / "out" / "manifest.json").read_text())
    (root / "subs").mkdir()
    asked: dict[str, list] = {}
    for student in manifest["students"]:
        sheet = [f'student_id = "{student["id"]}"']
        for problem, entry in zip(manifest["problems"], student["problems"], strict=True):
            variant = entry_variant(entry)
            values = {k: float(v) for k, v in variant.values.items()}
            sheet.append(f"[problem{problem['index']}]")
            answers = {}
            for part in problem["parts"]:
                key = key_answer(variant, part["part"], part.get("quantity"))
                if part["part"] == "lagrangian":
                    answer = key  # right: it is also what follow-through reads
                else:
                    answer = _wrong(part["part"], key, values)
                answers[part["key"]] = answer
                sheet.append(f"{part['key']} = {json.dumps(answer)}")
            asked.setdefault(student["id"], []).append((problem, entry, answers))
        (root / "subs" / f"{student['id']}.toml").write_text("\n".join(sheet) + "\n")
    grade(root / "out" / "manifest.json", root / "subs", root / "grades", jobs=2)
    results = {
        s: json.loads((root / "grades" / "students" / f"{s}.json").read_text()) for s in STUDENTS
    }
    return manifest, asked, results


def _check(entry: dict, part: dict, answer, lagrangian: str, capsys) -> dict:
    """The answer through `lagrade check --seed` with what the sheet brings (the student's L for
    follow-through, all conserved quantities asked for), as its JSON."""
    args = ["check", "--scene", entry["scene"], "--seed", str(entry["seed"]), "--json"]
    args += ["--part", part["part"]]
    if part.get("quantity"):
        args += ["--quantity", part["quantity"]]
    for line in answer if isinstance(answer, list) else [answer]:
        args += ["--answer", line]
    if part["part"] in ("eom", "momenta", "conserved"):
        args += ["--given-lagrangian", lagrangian]
    if part["part"] == "conserved":
        args.append("--all")
    capsys.readouterr()
    main(args)
    return json.loads(capsys.readouterr().out)


def test_the_variants_differ(graded):
    manifest, _asked, _results = graded
    seeds = {tuple(e["seed"] for e in s["problems"]) for s in manifest["students"]}
    assert len(seeds) == len(STUDENTS)


def test_check_with_the_students_seed_and_grade_give_the_same_feedback(graded, capsys):
    _manifest, asked, results = graded
    compared = quoted = 0
    for student, problems in asked.items():
        for problem, entry, answers in problems:
            graded_parts = {
                p["key"]: p
                for p in next(
                    r for r in results[student]["problems"] if r["index"] == problem["index"]
                )["parts"]
            }
            for part in problem["parts"]:
                if part["part"] == "lagrangian":
                    continue
                mine = _check(entry, part, answers[part["key"]], answers["lagrangian"], capsys)
                theirs = graded_parts[part["key"]]
                assert theirs["verdict"] == mine["verdict"] == "incorrect", (student, part)
                assert theirs["feedback"] == mine["feedback"], (student, part["key"])
                assert theirs["witness"] == mine["witness"], (student, part["key"])
                compared += 1
                quoted += any(re.search(r"\d\.\d", f) for f in mine["feedback"])
    assert compared == len(STUDENTS) * 9
    assert quoted >= len(STUDENTS)  # the comparison covers feedback that quotes numbers


def test_the_plugged_in_hint_names_the_students_own_values(graded):
    """Every student put their own handout values into V: the hint names each parameter whose
    value was put in, for every student (not only those whose values match the first
    student's)."""
    _manifest, asked, results = graded
    for student in STUDENTS:
        (wedge, *_rest) = results[student]["problems"]
        v_part = next(p for p in wedge["parts"] if p["key"] == "V")
        hint = next(f for f in v_part["feedback"] if "handout's value" in f)
        assert "g" in hint and "m" in hint, (student, hint)
