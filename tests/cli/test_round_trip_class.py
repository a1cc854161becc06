"""The round trip of issue 38 as a new instructor and four students take it: a scene file of
our own written from docs/scenes.md (a puck on a table tied through a hole to a hanging block:
not in the bank), an assignment with it and a bank scene, a roster with Greek, Chinese,
Japanese and Vietnamese names (the Vietnamese in decomposed form, combining marks), handouts,
sheets typed by hand the way students type (ASCII with `Mg`, Unicode Greek with dots and an
`ℓ =` label, LaTeX with \\frac and \\sqrt, primes inside '…' quotes and a worked count
`6 - 4 = 2`), grading, the answer page (a preview and a save), and the Gradescope and Canvas
exports. What the round trip found is pinned here: a prime in a one-line answer voided the
sheet, a worked count scored 0, a momentum short of r^2 was not named, and a wrong closed
form quoted sampled parameter values instead of the student's own."""

from __future__ import annotations

import csv
import json
import unicodedata
import zipfile
from pathlib import Path

import pytest

from lagrade.cli.main import main
from lagrade.grading.gradescope import run_autograder
from tests.serve.conftest import post, start_server, stop_server

SCENE = """\
title = "Puck on a table tied to a hanging mass"
statement = \"\"\"\\
A puck of mass m slides without friction on a horizontal table. A string of length b runs \\
from the puck through a small hole in the table to a block of mass M that hangs straight \\
down, in gravity g. Use the puck's polar coordinates {r} and {theta} about the hole.\"\"\"
coordinates = ["r", "theta"]
renames = { r = ["r", "rho"], theta = ["theta", "phi"] }
potential = "gravity"
domains = { r = "positive" }
constraints = ["z_puck", "x_block", "y_block", "sqrt(x_puck^2 + y_puck^2) - z_block - b"]

[parameters]
m = { domain = "positive", unit = "kg", values = [0.2, 0.3], description = "mass of the puck" }
M = { domain = "positive", unit = "kg", values = [0.5, 1.0], description = "mass of the block" }
g = { domain = "positive", unit = "m/s^2", values = [9.81], description = "gravity" }
b = { domain = "positive", unit = "m", values = [2.0], description = "length of the string" }
a = { domain = "positive", unit = "m", values = [0.4, 0.5], description = "radius of a circle" }

[bodies.puck]
mass = "m"
position = ["r cos(theta)", "r sin(theta)", "0"]

[bodies.block]
mass = "M"
position = ["0", "0", "r - b"]

[quantities.circular_angular_velocity]
description = "angular velocity of the puck on a circle of radius a"
value = "sqrt(M g/(m a))"
unit = "rad/s"
check = { at = { r = "a", r_dot = "0", theta_dot = "circular_angular_velocity" }, \
accelerations = { r = "0", theta = "0" } }
"""
ASSIGNMENT = """\
title = "Problem set 5"
points = 1

[[problems]]
scene = "scenes/table_hole.toml"
parts = ["dof", "transformation", "lagrangian", "eom", "momenta", "cyclic", "conserved",
         { quantity = "circular_angular_velocity", points = 2 }]

[[problems]]
scene = "simple_pendulum"
parts = ["T", "V", "lagrangian", "eom"]
"""
VIETNAMESE = unicodedata.normalize("NFD", "Nguyễn Thị Hương")
ROSTER = (
    "id,name,email\ns001,Αλέξανδρος Παπαδόπουλος,alex@example.edu\n"
    f"s002,王小明,ming@example.edu\ns003,{VIETNAMESE},huong@example.edu\n"
    "s004,山田 花子,hanako@example.edu\n"
)
GREEK = {"rho": "ρ", "phi": "φ", "theta": "θ", "psi": "ψ"}
DOT, DDOT = "\u0307", "\u0308"


def _answers(style: str, r: str, th: str, q: str) -> tuple[dict, dict]:
    """The two problems' answers as one student types them (`r`, `th`: the puck's coordinates,
    `q` the pendulum's, as the variant names them)."""
    if style == "ascii":
        one = {
            "lagrangian": f"1/2 (m+M) {r}_dot^2 + 1/2 m {r}^2 {th}_dot^2 - Mg ({r} - b)",
            "momenta": f"p_{r} = (m+M)*{r}_dot\np_{th} = m {r}^2 {th}_dot",
            "conserved": f"m {r}^2 {th}_dot\n"
            f"1/2 (m+M) {r}_dot^2 + 1/2 m {r}^2 {th}_dot^2 + M g {r}",
        }
        two = {"lagrangian": f"1/2 m l^2 {q}_dot^2 + m g l cos({q})"}
    elif style == "unicode":
        R, T, Q = GREEK.get(r, r), GREEK.get(th, th), GREEK.get(q, q)
        one = {
            "lagrangian": f"½ (m + M) {R}{DOT}² + ½ m {R}² {T}{DOT}² − M g ({R} − b)",
            "momenta": f"p_{R} = (m + M) {R}{DOT}\np_{T} = m {R}² {T}{DOT}",
            "conserved": f"ℓ = m {R}² {T}{DOT}\n"
            f"E = ½ (m + M) {R}{DOT}² + ½ m {R}² {T}{DOT}² + M g {R}",
        }
        two = {"lagrangian": f"½ m l² {Q}{DOT}² + m g l cos {Q}"}
    elif style == "latex":
        R, T, Q = (f"\\{n}" if n in GREEK else n for n in (r, th, q))
        one = {
            "lagrangian": f"\\frac{{1}}{{2}}(m+M)\\dot{{{R}}}^2 + \\frac{{1}}{{2}} m {R}^2 "
            f"\\dot{{{T}}}^2 - M g ({R} - b)",
            "momenta": f"p_{{{r}}} = (m+M)\\dot{{{R}}}\np_{{{th}}} = m {R}^2 \\dot{{{T}}}",
            "conserved": f"m {R}^2\\dot{{{T}}}",  # one of two: half the part
        }
        two = {"lagrangian": f"\\frac12 m l^2\\dot{{{Q}}}^2 + m g l \\cos {Q}"}
    else:  # primes in '…' quotes, a worked count, r^2 left out of p_θ, sqrt(g/a)
        one = {
            "dof": "6 - 4 = 2",
            "lagrangian": f"1/2 m ({r}'^2 + {r}^2 {th}'^2) + 1/2 M {r}'^2 - M g {r}",
            "momenta": f"p_{r} = (m+M) {r}'\np_{th} = m {th}'",
            "conserved": f"m {r}^2 {th}'\n1/2 (m+M) {r}'^2 + 1/2 m {r}^2 {th}'^2 + M g {r}",
            "circular_angular_velocity": "sqrt(g/a)",
        }
        two = {"lagrangian": f"1/2 m l^2 {q}'^2 - m g l cos({q})"}  # V added: wrong
    common = {
        "dof": "2",
        "transformation": f"x_puck = {r} cos({th})\ny_puck = {r} sin({th})\nz_puck = 0\n"
        f"x_block = 0\ny_block = 0\nz_block = {r} - b",
        "eom": f"(m+M) {r}_ddot - m {r} {th}_dot^2 + M g = 0\nd/dt(m {r}^2 {th}_dot) = 0",
        "cyclic": th,
        "circular_angular_velocity": "sqrt(M g/(m a))",
    }
    pendulum = {"T": f"1/2 m l^2 {q}_dot^2", "V": f"-m g l cos({q})",
                "eom": f"{q}_ddot + g/l sin({q}) = 0"}  # fmt: skip
    return {**common, **one}, {**pendulum, **two}


def _sheet(student: dict, style: str) -> str:
    """The student's sheet as typed: one-line answers between '…', the others in '''…'''."""
    one, two = _answers(style, *student["problems"][0]["coordinates"],
                        *student["problems"][1]["coordinates"])  # fmt: skip

    def line(key: str, value: str) -> str:
        return f"{key} = '''\n{value}\n'''" if "\n" in value else f"{key} = '{value}'"

    lines = [f'student_id = "{student["id"]}"', "[problem1]"]
    lines += [line(k, v) for k, v in one.items()] + ["[problem2]"]
    lines += [line(k, v) for k, v in two.items()]
    return "\n".join(lines) + "\n"


STYLES = {"s001": "unicode", "s002": "ascii", "s003": "latex", "s004": "primes"}


@pytest.fixture(scope="module")
def graded(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("round_trip")
    (root / "scenes").mkdir()
    (root / "scenes" / "table_hole.toml").write_text(SCENE, encoding="utf-8")
    (root / "assignment.toml").write_text(ASSIGNMENT, encoding="utf-8")
    (root / "roster.csv").write_text(ROSTER, encoding="utf-8")
    argv = ["generate", str(root / "assignment.toml"), "--roster", str(root / "roster.csv")]
    assert main([*argv, "--seed", "7", "--out", str(root / "ps"), "--formats", "md,html"]) == 0
    manifest = json.loads((root / "ps" / "manifest.json").read_text(encoding="utf-8"))
    (root / "subs").mkdir()
    for student in manifest["students"]:
        text = _sheet(student, STYLES[student["id"]])
        (root / "subs" / f"{student['id']}.toml").write_text(text, encoding="utf-8")
    argv = ["grade", str(root / "ps" / "manifest.json"), str(root / "subs")]
    argv += ["--out", str(root / "out"), "--export", "canvas", "--canvas-assignment-id", "77"]
    main(argv)
    return root


def _student(root: Path, student_id: str) -> dict:
    return json.loads((root / "out" / "students" / f"{student_id}.json").read_text("utf-8"))


def _parts(result: dict) -> dict:
    return {(p["index"], part["key"]): part for p in result["problems"] for part in p["parts"]}


def test_every_notation_is_graded_as_meant(graded):
    rows = {r["id"]: r for r in csv.DictReader((graded / "out" / "gradebook.csv").open())}
    assert {i: (r["status"], float(r["score"])) for i, r in rows.items()} == {
        "s001": ("graded", 13.0),
        "s002": ("graded", 13.0),
        "s003": ("graded", 12.5),  # one of two conserved quantities
        "s004": ("graded", 9.5),
    }
    assert rows["s003"]["name"] == VIETNAMESE  # the roster's own bytes, combining marks kept


def test_the_student_typing_primes_keeps_the_sheet_and_learns_what_to_fix(graded):
    result = _student(graded, "s004")
    manifest = json.loads((graded / "ps" / "manifest.json").read_text(encoding="utf-8"))
    (student,) = [s for s in manifest["students"] if s["id"] == "s004"]
    r, th = student["problems"][0]["coordinates"]
    values = student["problems"][0]["values"]
    parts = _parts(result)
    assert parts[(1, "dof")]["verdict"] == "correct"  # 6 - 4 = 2
    assert parts[(1, "lagrangian")]["verdict"] == "correct"  # primes read as d/dt
    momenta = " ".join(parts[(1, "momenta")]["feedback"])
    assert f"p_{th} is ∂L/∂{th}_dot without its factor {r}^2" in momenta, momenta
    quoted = " ".join(parts[(1, "circular_angular_velocity")]["feedback"])
    assert f"M = {values['M']:g} kg, a = {values['a']:g} m" in quoted, quoted  # their handout
    feedback = (graded / "out" / "feedback" / "s004.md").read_text(encoding="utf-8")
    assert feedback.count("the answer holds a quote (a prime") == 2  # both one-line L


def test_the_canvas_file_and_the_gradescope_autograder_agree(graded, tmp_path):
    canvas = (graded / "out" / "gradebook-canvas.csv").read_text(encoding="utf-8")
    assert "王小明" in canvas and "hanako@example.edu,,9.5" in canvas
    zip_path = tmp_path / "autograder.zip"
    argv = ["export", "gradescope", str(graded / "ps" / "manifest.json"), "--out", str(zip_path)]
    assert main(argv) == 0
    root = tmp_path / "autograder"
    with zipfile.ZipFile(zip_path) as zf:
        zf.extractall(root / "source")
    (root / "submission").mkdir()
    (root / "submission" / "sheet.toml").write_bytes((graded / "subs" / "s004.toml").read_bytes())
    user = {"email": "HANAKO@example.edu", "name": "Hanako", "sid": ""}
    (root / "submission_metadata.json").write_text(json.dumps({"users": [user]}))
    assert run_autograder(root) == 0
    results = json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))
    assert results["score"] == 9.5, results.get("output")
    # a classmate's sheet uploaded from this account is not graded as the classmate
    (root / "submission" / "sheet.toml").write_bytes((graded / "subs" / "s002.toml").read_bytes())
    assert run_autograder(root) == 0
    results = json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))
    assert results["score"] == 0 and "another student" in results["output"]


def test_the_answer_page_previews_and_saves_a_primed_answer(graded):
    served = start_server(graded, graded / "ps" / "manifest.json")
    try:
        url = served.url("s004")
        text = "p_r = (m+M) r'\np_theta = m r^2 theta'"
        status, body = post(url + "/preview", {"problem": 1, "key": "momenta", "text": text})
        assert status == 200 and body["status"] == "read", body
        assert any("a prime as d/dt" in w for w in body["warnings"]), body
        answers = {"1": {"dof": "3N - k = 6 - 4 = 2", "lagrangian": "1/2 m r'^2"}}
        status, body = post(url + "/save", {"answers": answers})
        assert status == 200 and body["status"] == "saved", body
    finally:
        assert stop_server(served) == 0
    saved = (served.sheets / "s004.toml").read_text(encoding="utf-8")
    assert "6 - 4 = 2" in saved and "r'^2" in saved
