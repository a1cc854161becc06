"""`lagrade export prairielearn`: the question folders follow PrairieLearn's v3 format, and
server.py honours PrairieLearn's contract when it is loaded and called the way PrairieLearn
does (a module per question; generate, parse and grade mutate one `data` dictionary). The
contract as PrairieLearn documents it, with question.html rendered: `test_prairielearn_contract`;
against PrairieLearn's real worker: `test_prairielearn_worker`.
"""

from __future__ import annotations

import importlib.util
import json
import time
import uuid
from pathlib import Path

import pytest

import lagrade.judge.driver as driver
from lagrade.cli.main import main

ASSIGNMENT = """\
title = "PL export test"
points = 1

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "eom"]
points = { lagrangian = 2 }
"""


@pytest.fixture(scope="module")
def questions(tmp_path_factory) -> list[Path]:
    root = tmp_path_factory.mktemp("pl")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    assert (
        main(
            [
                "export",
                "prairielearn",
                str(root / "assignment.toml"),
                "--seed",
                "3",
                "--out",
                str(root / "course"),
            ]
        )
        == 0
    )
    return sorted((root / "course" / "questions").iterdir())


def load_server(folder: Path):
    spec = importlib.util.spec_from_file_location(f"server_{folder.name}", folder / "server.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def new_data(seed: int) -> dict:
    return {"params": {}, "correct_answers": {}, "variant_seed": seed, "options": {}}


def test_one_v3_question_per_problem_with_a_stable_uuid(questions, tmp_path):
    (folder,) = questions
    info = json.loads((folder / "info.json").read_text())
    assert info["type"] == "v3" and info["topic"] and "simple_pendulum" in info["tags"]
    uuid.UUID(info["uuid"])
    html = (folder / "question.html").read_text()
    for key in ("dof", "lagrangian", "eom"):
        assert f'answers-name="{key}"' in html
    (tmp_path / "a.toml").write_text(ASSIGNMENT)
    main(
        [
            "export",
            "prairielearn",
            str(tmp_path / "a.toml"),
            "--seed",
            "3",
            "--out",
            str(tmp_path / "again"),
        ]
    )
    again = next((tmp_path / "again" / "questions").iterdir()).joinpath("info.json")
    again = json.loads(again.read_text())
    assert again["uuid"] == info["uuid"]  # a re-export updates the same question


def test_generate_draws_a_variant_and_renders_its_statement(questions):
    server = load_server(questions[0])
    data = new_data(12345)
    server.generate(data)
    assert data["params"]["seed"] in server.SEEDS
    assert (
        "<math" in data["params"]["statement_html"] and "<svg" in data["params"]["statement_html"]
    )
    other = new_data(12346)
    server.generate(other)
    assert set(data["params"]["prompts"]) == {"dof", "lagrangian", "eom"}


def test_unreadable_answers_are_format_errors_and_right_answers_score_full(questions):
    server = load_server(questions[0])
    data = new_data(7)
    server.generate(data)
    from lagrade.bank.registry import get_scene
    from lagrade.judge.key import key_answer

    variant = get_scene("simple_pendulum").variant(data["params"]["seed"])
    right = {
        "dof": "1",
        "lagrangian": key_answer(variant, "lagrangian"),
        "eom": "; ".join(key_answer(variant, "eom")),
    }
    data["submitted_answers"] = {**right, "lagrangian": "1/2 m (l theta_dot^2"}
    data["format_errors"] = {}
    server.parse(data)
    assert "lagrangian" in data["format_errors"] and "dof" not in data["format_errors"]

    data = {**data, "submitted_answers": right, "format_errors": {}, "partial_scores": {}}
    server.parse(data)
    assert data["format_errors"] == {}
    server.grade(data)
    assert data["score"] == pytest.approx(1.0)
    assert all(p["score"] == 1.0 for p in data["partial_scores"].values())

    wrong = {**right, "lagrangian": right["lagrangian"] + " + m*g*l"}
    data = {**data, "submitted_answers": wrong, "partial_scores": {}}
    server.grade(data)
    assert data["partial_scores"]["lagrangian"]["score"] == 1.0  # a constant changes nothing
    wrong = {**right, "dof": "2"}
    data = {**data, "submitted_answers": wrong, "partial_scores": {}}
    server.grade(data)
    assert data["partial_scores"]["dof"]["score"] == 0.0
    assert data["score"] == pytest.approx(3 / 4)  # dof 1 point of 1 + 2 + 1
    assert data["feedback"]["lagrade"]["dof"]["notes"]


SLOW_ASSIGNMENT = """\
title = "PL backstop test"
points = 1

[[problems]]
scene = "wedge"
parts = ["dof", "lagrangian", { quantity = "block_acceleration" }]
"""


def test_grade_stops_a_part_held_in_c_code_and_grades_the_others(tmp_path, monkeypatch):
    """PrairieLearn calls grade() in its own process: the check runs in a worker killed at the
    part's limit + grace, the held part (the planted checker spinning in C, `tests/planted.py`)
    is `timeout` and every other part is graded."""
    from lagrade.grading import prairielearn_runtime
    from lagrade.judge.clocks import GRACE
    from tests.planted import HANG, spinning

    monkeypatch.setattr(driver, "run_checker", spinning(driver.run_checker))
    (tmp_path / "a.toml").write_text(SLOW_ASSIGNMENT)
    out = tmp_path / "questions"
    assert (
        main(["export", "prairielearn", str(tmp_path / "a.toml"), "--seed", "3", "--out", str(out)])
        == 0
    )
    server = load_server(next((out / "questions").iterdir()))
    data = new_data(5)
    server.generate(data)
    data["submitted_answers"] = {"dof": "2", "lagrangian": "m*g*h", "block_acceleration": HANG}
    data["partial_scores"] = {}
    start = time.monotonic()
    server.grade(data)
    elapsed = time.monotonic() - start
    scores = data["partial_scores"]
    assert scores["block_acceleration"]["score"] == 0.0
    notes = data["feedback"]["lagrade"]["block_acceleration"]["notes"]
    assert any("ran out of time" in note["text"] for note in notes)
    assert scores["dof"]["score"] == 1.0
    assert scores["lagrangian"]["score"] == 0.0 and data["feedback"]["lagrade"]["lagrangian"]
    # the part's limit and grace, and a fresh worker's start for the rest
    assert elapsed < prairielearn_runtime.PART_TIME_LIMIT + GRACE + 2.0, elapsed


LIST_ASSIGNMENT = """\
title = "PL lists"
points = 1

[[problems]]
scene = "kepler"
parts = ["coordinates", "lagrangian", "eom", "momenta", "cyclic", "conserved"]
"""


@pytest.mark.parametrize("separator", ["; ", ", ", " and "])
def test_a_pl_answer_is_read_as_check_reads_the_same_text(tmp_path, separator):
    """The one door: PrairieLearn passes the typed text on as it is, so a list separated by
    `;`, commas or "and" gets exactly `check`'s verdict and feedback (it used to split at `;`
    only, and judged the rest as one unreadable equation)."""
    from lagrade.bank.registry import get_scene
    from lagrade.grading.rubric import Rubric
    from lagrade.judge.check import check
    from lagrade.judge.key import key_answer

    (tmp_path / "a.toml").write_text(LIST_ASSIGNMENT)
    out = tmp_path / "questions"
    assert (
        main(["export", "prairielearn", str(tmp_path / "a.toml"), "--seed", "5", "--out", str(out)])
        == 0
    )
    server = load_server(next((out / "questions").iterdir()))
    data = new_data(11)
    server.generate(data)
    seed = data["params"]["seed"]
    variant = get_scene("kepler").variant(seed)
    r, theta = variant.coordinates
    typed = {
        part: separator.join(
            key_answer(variant, part) if part != "cyclic" else [theta, r]  # r is not cyclic
        )
        for part in ("eom", "momenta", "cyclic", "conserved")
    }
    typed["coordinates"] = separator.join([theta, r])
    typed["lagrangian"] = key_answer(variant, "lagrangian")
    data["submitted_answers"] = typed
    data["partial_scores"] = {}
    server.grade(data)
    for part, text in typed.items():
        given = {"lagrangian": typed["lagrangian"]} if part != "coordinates" else None
        if part == "conserved":
            given = {**given, "all": True}  # the handout asks for the conserved quantities
        verdict = check({"scene": "kepler", "seed": seed}, part, text, time_limit=None, given=given)
        share = Rubric().fraction(
            verdict.status, verdict.score, verdict.mistakes, verdict.follows_from_own_answer
        )
        scored = data["partial_scores"][part]
        assert scored["score"] == pytest.approx(share), (part, text)
        notes = [note["text"] for note in data["feedback"]["lagrade"][part]["notes"]]
        assert notes == list(verdict.feedback), (part, text)
    assert data["partial_scores"]["eom"]["score"] == 1.0
    assert data["partial_scores"]["cyclic"]["score"] == 0.0  # every coordinate: a blind guess


def test_parse_reads_and_never_judges(tmp_path, monkeypatch):
    """PrairieLearn judges a submission once: `parse` only reads (a wrong answer costs it no
    judging at all — the checker planted to fail is never called), and refuses an unreadable
    line as a format error; `grade` then judges."""
    calls = []

    def never(*args, **kwargs):
        calls.append(args[1])
        raise AssertionError("parse judged an answer")

    (tmp_path / "a.toml").write_text(SLOW_ASSIGNMENT)
    out = tmp_path / "questions"
    assert (
        main(["export", "prairielearn", str(tmp_path / "a.toml"), "--seed", "3", "--out", str(out)])
        == 0
    )
    server = load_server(next((out / "questions").iterdir()))
    data = new_data(5)
    server.generate(data)
    wrong_l = "m*g*h + x_M_dot^3"
    data["submitted_answers"] = {"dof": "2", "lagrangian": wrong_l, "block_acceleration": "g*("}
    real = driver.run_checker
    monkeypatch.setattr(driver, "run_checker", never)  # the forked worker inherits it
    server.parse(data)
    assert calls == []
    assert set(data["format_errors"]) == {"block_acceleration"}
    shown = data["feedback"]["lagrade"]
    assert shown["lagrangian"]["read"] == "m*g*h + x_M_dot^3"
    assert shown["lagrangian"]["outcome"] == "" and shown["lagrangian"]["notes"] == []
    monkeypatch.setattr(driver, "run_checker", real)
    data["format_errors"] = {}
    data["submitted_answers"]["block_acceleration"] = "g"
    server.grade(data)
    assert data["partial_scores"]["lagrangian"]["score"] == 0.0


def test_the_vendored_lagrade_ships_its_bytecode(questions):
    """PrairieLearn runs each call in a fresh process that writes nothing: the copy of lagrade
    it runs carries its bytecode (checked against the sources' hashes), so no call compiles."""
    import importlib.util as util

    course = questions[0].parent.parent
    (vendored,) = (course / "serverFilesCourse").glob("lagrade-*")
    sources = sorted((vendored / "lagrade").rglob("*.py"))
    assert len(sources) > 100
    missing = [s for s in sources if not Path(util.cache_from_source(str(s))).is_file()]
    assert missing == []
    data = Path(util.cache_from_source(str(vendored / "lagrade" / "__init__.py"))).read_bytes()
    assert int.from_bytes(data[4:8], "little") & 0b11 == 0b11  # hash-based, source checked


def test_generate_reads_the_variants_rendered_at_export(questions):
    """Each variant of the pool is rendered once, at export, into variants.json (data): a
    generate call reads it instead of deriving the variant and drawing its figure, and gives
    exactly what rendering it in the call gives."""
    from lagrade.grading import prairielearn_runtime

    (folder,) = questions
    rendered = json.loads((folder / "variants.json").read_text())
    server = load_server(folder)
    assert sorted(rendered["variants"]) == sorted(str(s) for s in server.SEEDS)
    for seed in (0, 1, 7):
        from_file, live = new_data(seed), new_data(seed)
        server.generate(from_file)
        prairielearn_runtime.generate(
            live, server.ASSIGNMENT, server.PROBLEM, server.SEEDS, server.SCENES
        )
        assert from_file == live
        assert "<svg" in from_file["params"]["statement_html"]
