"""`lagrade export gradescope`: the autograder zip unpacked into a folder laid out like
Gradescope's container (`source/` from the zip, `run_autograder` copied beside it,
`submission/`, `submission_metadata.json`, `results/`: Gradescope's "Autograder
Specifications"), set up with its own setup.sh, and run with its own run_autograder: each
results.json matches Gradescope's documented format and gives the score `lagrade grade` gives.

Offline, setup.sh installs the wheel with `--no-deps` into the virtual environment it builds,
and the test then hands that environment this interpreter's site-packages for the dependencies
(a plain path in a .pth file: lagrade itself is still imported from the installed wheel, which
the test checks). The slow test runs setup.sh with the dependencies installed by pip, as on
Gradescope (here pip takes them from the machine's wheel cache).
"""

from __future__ import annotations

import csv
import json
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.cli.demo_class import write_submissions
from lagrade.cli.main import main
from lagrade.grading.batch import grade
from lagrade.grading.gradescope import SETTINGS, export_gradescope, identify
from tests.batch.gradescope_schema import problems

ASSIGNMENT = """\
title = "PS <b>3</b>"
points = 1

[[problems]]
scene = "simple_pendulum"
parts = ["dof", "lagrangian", "eom", "momenta"]
variants = 3

[[problems]]
scene = "atwood"
parts = ["lagrangian", { quantity = "acceleration", points = 2 }]
variants = 2

[[problems]]
scene = "coupled_oscillators"
parts = ["hamiltonian", "hamilton_equations", "equilibrium", "normal_modes", "mode_shapes"]
variants = 2
"""
#: The next lecture's parts, asked in the third problem.
PHASE_PARTS = ("hamiltonian", "hamilton_equations", "equilibrium", "normal_modes", "mode_shapes")
ROSTER = [
    ("s01", "Ada Lovelace", "ada@uni.edu"),
    ("s02", "Ben Okri", "Ben@Uni.edu"),
    ("s03", "Chen Wei", "chen@uni.edu"),
    ("s04", "Dana Scully", ""),
    ("s05", "Eve Moneypenny", "eve@uni.edu"),
]


def _python_for_venv() -> str:
    """The interpreter this test runs on, outside any virtual environment (setup.sh builds
    its own environment from it)."""
    return getattr(sys, "_base_executable", None) or sys.executable


@pytest.fixture(scope="module")
def course(tmp_path_factory) -> Path:
    """A generated class with emails on the roster, every student's sheet (demo profiles:
    strong, typical, weak), and the class graded by `lagrade grade`."""
    root = tmp_path_factory.mktemp("gradescope-class")
    (root / "assignment.toml").write_text(ASSIGNMENT)
    with (root / "roster.csv").open("w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["id", "name", "email"])
        writer.writerows(ROSTER)
    generate(root / "assignment.toml", root / "roster.csv", 5, root / "ps", formats=("md",))
    manifest = json.loads((root / "ps" / "manifest.json").read_text())
    write_submissions(root / "sheets", manifest, malformed=None, missing=None)
    grade(root / "ps" / "manifest.json", root / "sheets", root / "grades")
    return root


def unpack(zip_path: Path, root: Path) -> None:
    """What Gradescope does with the zip: its files in root/source, modes kept (as unzip
    keeps them), run_autograder copied to root/."""
    source = root / "source"
    source.mkdir(parents=True)
    with zipfile.ZipFile(zip_path) as zf:
        for info in zf.infolist():
            target = source / info.filename
            target.write_bytes(zf.read(info))
            target.chmod((info.external_attr >> 16) & 0o777)
    shutil.copy2(source / "run_autograder", root / "run_autograder")
    (root / "submission").mkdir()


def environment(root: Path, **more: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("LAGRADE_")}
    env.pop("VIRTUAL_ENV", None)
    env.update({"LAGRADE_AUTOGRADER_ROOT": str(root), "LAGRADE_PYTHON": _python_for_venv()})
    env.update(more)
    return env


@pytest.fixture(scope="module")
def autograder(course, tmp_path_factory) -> Path:
    """The zip exported, unpacked into a Gradescope-like root, set up by its setup.sh
    (`--no-deps`; the dependencies from this interpreter, see the module docstring)."""
    root = tmp_path_factory.mktemp("autograder")
    zip_path = export_gradescope(course / "ps" / "manifest.json", root / "autograder.zip")
    unpack(zip_path, root)
    setup = subprocess.run(
        ["bash", str(root / "source" / "setup.sh")],
        env=environment(root, LAGRADE_PIP_ARGS="--no-deps"),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert setup.returncode == 0, setup.stdout + setup.stderr
    venv = root / "lagrade-venv"
    site = next(venv.glob("lib/python*/site-packages"))
    (site / "zz-test-dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    return root


def metadata(email: str | None = None, sid: str | int | None = None) -> dict:
    """submission_metadata.json as Gradescope documents it ("Submission Metadata",
    gradescope-autograders.readthedocs.io/en/latest/submission_metadata/: id, created_at,
    assignment, submission_method, users[] with email, id, name), with the user's `sid` (the
    Student ID of Gradescope's roster, as cs161-staff/gradescope-api's GradescopeStudent and
    the metadata's users carry it) when given. An account without email still has the key."""
    user: dict = {"email": email or "", "id": 7, "name": "someone"}
    if sid is not None:
        user["sid"] = sid
    return {
        "id": 123456,
        "created_at": "2018-07-01T14:22:32.365935-07:00",
        "assignment": {"id": 25828, "course_id": 1234, "title": "PS 3", "total_points": "7.0"},
        "submission_method": "upload",
        "users": [user] if email or sid is not None else [],
        "previous_submissions": [],
    }


def submit(
    root: Path,
    files: dict[str, str | bytes],
    email: str | None = None,
    sid: str | int | None = None,
    trust_sheet: bool = False,
) -> dict:
    """One Gradescope run: the upload, the submitter, ./run_autograder; the results.json.
    `trust_sheet` writes the setting `export --trust-sheet` puts in the zip."""
    shutil.rmtree(root / "submission")
    shutil.rmtree(root / "results", ignore_errors=True)
    (root / "submission").mkdir()
    for name, data in files.items():
        path = root / "submission" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
    (root / "submission_metadata.json").write_text(json.dumps(metadata(email, sid)))
    (root / "source" / SETTINGS).write_text(json.dumps({"trust_sheet": trust_sheet}))
    run = subprocess.run(
        [str(root / "run_autograder")],
        cwd=root,
        env=environment(root),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    payload = json.loads((root / "results" / "results.json").read_text())
    assert problems(payload) == [], payload
    return payload


def test_the_zip_has_gradescope_s_two_scripts_at_its_root_and_what_grade_reads(course, tmp_path):
    """setup.sh and run_autograder at the root of the archive, executable; the wheel, the
    manifest and the assignment copy beside them; the same class gives the same bytes."""
    first = export_gradescope(course / "ps" / "manifest.json", tmp_path / "a.zip")
    second = export_gradescope(course / "ps" / "manifest.json", tmp_path / "b.zip")
    assert first.read_bytes() == second.read_bytes()
    with zipfile.ZipFile(first) as zf:
        modes = {i.filename: (i.external_attr >> 16) & 0o777 for i in zf.infolist()}
        assert zf.read("manifest.json") == (course / "ps" / "manifest.json").read_bytes()
        assert zf.read("assignment.toml") == (course / "ps" / "assignment.toml").read_bytes()
        assert zf.read("setup.sh").startswith(b"#!/usr/bin/env bash\n")
        assert zf.read("run_autograder").startswith(b"#!/usr/bin/env bash\n")
    assert modes["setup.sh"] == modes["run_autograder"] == 0o755
    assert {"README.txt", "lagrade-0.1.0-py3-none-any.whl"} <= set(modes)


def test_trust_sheet_is_an_instructor_setting_written_into_the_zip(course, tmp_path):
    """`lagrade export gradescope --trust-sheet` is the one way back to trusting the sheet's
    student_id; the zip says which choice was made, and its README says what it means."""
    for flags, trusted in (([], False), (["--trust-sheet"], True)):
        out = tmp_path / f"{trusted}.zip"
        args = ["export", "gradescope", str(course / "ps" / "manifest.json"), "--out", str(out)]
        assert main([*args, *flags]) == 0
        with zipfile.ZipFile(out) as zf:
            assert json.loads(zf.read(SETTINGS)) == {"trust_sheet": trusted}
            readme = zf.read("README.txt").decode()
        assert ("exported with --trust-sheet" in readme) is trusted
        assert "Student ID (SID)" in readme


def test_setup_installs_lagrade_from_the_wheel(autograder):
    venv = autograder / "lagrade-venv"
    where = subprocess.run(
        [str(venv / "bin" / "python"), "-c", "import lagrade; print(lagrade.__file__)"],
        cwd=autograder,  # Gradescope's working directory, /autograder
        env=environment(autograder),
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    assert Path(where).is_relative_to(venv)  # not this checkout
    assert (venv / "bin" / "lagrade").exists()


def test_each_sheet_earns_on_gradescope_what_lagrade_grade_gives(course, autograder):
    """Every student's sheet, uploaded under another name by the student's Gradescope
    account: the score and each part's test are those of `lagrade grade` for that sheet."""
    for sid, name, email in ROSTER:
        if not email:
            continue
        sheet = (course / "sheets" / f"{sid}.toml").read_text()
        payload = submit(autograder, {"my answers.toml": sheet}, email=email.upper())
        ours = json.loads((course / "grades" / "gradescope" / sid / "results.json").read_text())
        graded = json.loads((course / "grades" / "students" / f"{sid}.json").read_text())
        assert payload["score"] == pytest.approx(graded["score"]), sid
        assert payload["tests"] == ours["tests"], sid
        assert payload["output"].startswith(f"Graded as {name} ({sid}): the student whose email")
        assert payload["output_format"] == "text"


def test_the_key_with_the_next_lecture_s_parts_earns_full_marks_on_gradescope(course, autograder):
    """The answer key's own sheet (the TOML the key prints), uploaded by the student's account:
    every test at its full points, the next lecture's parts among them."""
    key = (course / "ps" / "keys" / "s03.md").read_text()
    sheet = 'student_id = "s03"\n' + "\n".join(re.findall(r"```toml\n(.*?)```", key, flags=re.S))
    payload = submit(autograder, {"key.toml": sheet}, email="chen@uni.edu")
    assert payload["tests"] and all(t["score"] == t["max_score"] for t in payload["tests"])
    names = " ".join(t["name"] for t in payload["tests"])
    assert all(part in names for part in PHASE_PARTS), names
    total = sum(t["max_score"] for t in payload["tests"])
    assert payload["score"] == pytest.approx(total)


def test_an_account_without_a_roster_email_is_found_by_gradescope_s_student_id(course, autograder):
    """Dana has no email on the roster: Gradescope's student ID (sid) finds her, whatever
    the sheet or its file is called."""
    sheet = (course / "sheets" / "s04.toml").read_text()
    graded = json.loads((course / "grades" / "students" / "s04.json").read_text())
    payload = submit(autograder, {"answers.toml": sheet}, email="dana@elsewhere.org", sid="S04")
    assert payload["score"] == pytest.approx(graded["score"])
    assert payload["output"].startswith(
        "Graded as Dana Scully (s04): the student whose id is your Gradescope account's student ID"
    )


def test_a_classmate_s_sheet_from_an_account_on_no_roster_row_is_not_graded(course, autograder):
    """The attack: an account the roster does not know uploads Dana's filled-in sheet. It was
    graded on Dana's variant and its points credited to the uploader; now it scores 0, says
    why, and names the account as Gradescope gave it."""
    sheet = (course / "sheets" / "s04.toml").read_text()
    payload = submit(autograder, {"s04.toml": sheet}, email="mallory@elsewhere.org", sid=99)
    assert payload["score"] == 0 and payload["tests"] == []
    assert payload["output"].startswith(
        "Not graded: your Gradescope account (email mallory@elsewhere.org, student ID 99) "
        "matches no student on the class roster"
    )
    assert "Dana" not in payload["output"] and "s04" not in payload["output"]


def test_with_trust_sheet_the_sheet_says_whose_it_is(course, autograder):
    """`export --trust-sheet`: an account on no roster row is taken at its sheet's
    student_id; a sheet without one is known by its file name."""
    sheet = (course / "sheets" / "s04.toml").read_text()
    graded = json.loads((course / "grades" / "students" / "s04.json").read_text())
    by_claim = submit(
        autograder, {"answers.toml": sheet}, email="dana@elsewhere.org", trust_sheet=True
    )
    assert by_claim["score"] == pytest.approx(graded["score"])
    assert "the student_id in your file answers.toml" in by_claim["output"]
    unsigned = "\n".join(line for line in sheet.splitlines() if not line.startswith("student_id"))
    by_name = submit(autograder, {"folder/S04.toml": unsigned}, trust_sheet=True)
    assert by_name["score"] == pytest.approx(graded["score"])
    assert "the name of your file S04.toml" in by_name["output"]


def test_an_upload_lagrade_cannot_place_is_told_what_to_do(course, autograder):
    nothing = submit(autograder, {"notes.txt": "hello"}, email="nobody@uni.edu")
    assert nothing["score"] == 0 and "no answer sheet" in nothing["output"]
    unknown = submit(autograder, {"answers.toml": "[problem1]\ndof = '1'\n"}, trust_sheet=True)
    assert unknown["score"] == 0 and "could not tell whose answer sheet" in unknown["output"]
    two = {
        "s01.toml": (course / "sheets" / "s01.toml").read_text(),
        "s02.toml": (course / "sheets" / "s02.toml").read_text(),
    }
    assert "several answer sheets" in submit(autograder, two, trust_sheet=True)["output"]
    mine = submit(autograder, two, email="ada@uni.edu")  # the account picks its own
    assert mine["output"].startswith("Graded as Ada Lovelace (s01)")


def test_a_sheet_naming_another_student_scores_0_with_a_sentence(course, autograder):
    """Ada's account uploads Ben's sheet: not graded on either variant, told why."""
    sheet = (course / "sheets" / "s02.toml").read_text()
    payload = submit(autograder, {"answers.toml": sheet}, email="ada@uni.edu")
    assert payload["score"] == 0 and payload["tests"] == []
    assert payload["output"] == (
        "Not graded: your file answers.toml is the answer sheet of another student "
        "(student_id = 's02'), and your Gradescope account is Ada Lovelace (s01) on the class "
        "roster. Upload your own answer sheet, s01.toml, with its student_id line as it came."
    )


def test_with_trust_sheet_a_sheet_naming_someone_else_is_graded_as_the_account_s_student(
    course, autograder
):
    sheet = (course / "sheets" / "s02.toml").read_text()
    payload = submit(autograder, {"s02.toml": sheet}, email="ada@uni.edu", trust_sheet=True)
    assert payload["output"].startswith("Graded as Ada Lovelace (s01)")
    assert "Warning:" in payload["output"] and "s02" in payload["output"]


def test_email_wins_over_student_id_and_a_numeric_sid_matches(tmp_path):
    """Identification alone, on Gradescope's documented metadata: a group submission whose
    second user has the roster email wins over the first user's sid; a sid Gradescope gives as
    a number matches a roster id typed as digits (or the roster's sid column)."""
    students = [
        {"id": "1001", "name": "A", "extra": {"email": ""}},
        {"id": "x2", "name": "B", "extra": {"email": "b@uni.edu", "SID": "2002"}},
    ]
    manifest = {"students": students}
    upload = tmp_path / "submission"
    upload.mkdir()
    (upload / "sheet.toml").write_text("[problem1]\n")
    group = metadata("nobody@x.org", 1001)
    group["users"].append({"email": "B@UNI.EDU", "id": 8, "name": "B"})
    assert identify(manifest, group, upload).student["id"] == "x2"
    assert identify(manifest, metadata(None, 1001), upload).student["id"] == "1001"
    assert identify(manifest, metadata(None, "2002"), upload).student["id"] == "x2"
    assert identify(manifest, metadata(None, True), upload).student is None


def test_an_unreadable_sheet_is_plain_text_feedback_not_html(autograder):
    """Gradescope renders a top-level output as HTML unless told otherwise; the reason for an
    unreadable sheet quotes the file."""
    payload = submit(autograder, {"a.toml": "<img src=x onerror=alert(1)> = ["}, "ada@uni.edu")
    assert payload["score"] == 0
    assert "invalid" in payload["output"]
    assert payload["output_format"] == payload["test_output_format"] == "text"


def test_a_failure_of_the_grader_still_writes_results(autograder, tmp_path):
    broken = tmp_path / "root"
    shutil.copytree(autograder, broken, symlinks=True)
    (broken / "source" / "manifest.json").write_text("{}")
    payload = submit(broken, {"s01.toml": "student_id = 's01'\n"}, email="ada@uni.edu")
    assert payload["score"] == 0 and "autograder failed" in payload["output"]


def test_the_schema_check_is_not_vacuous():
    assert problems({"tests": [{"name": "x"}]}) == [
        "a score is required at the top level or on every test"
    ]
    assert problems({"score": 1, "output_format": "rtf", "tests": [{"visibility": "x"}]}) == [
        "output_format must be one of ['ansi', 'html', 'md', 'simple_format', 'text']",
        "test 1: visibility must be one of "
        "['after_due_date', 'after_published', 'hidden', 'visible']",
    ]


@pytest.mark.slow
def test_setup_installs_the_dependencies_too(course, tmp_path):
    """setup.sh as Gradescope runs it, pip installing lagrade's dependencies (about a minute
    here); then a sheet is graded with nothing from this interpreter."""
    zip_path = export_gradescope(course / "ps" / "manifest.json", tmp_path / "autograder.zip")
    unpack(zip_path, tmp_path / "root")
    root = tmp_path / "root"
    setup = subprocess.run(
        ["bash", str(root / "source" / "setup.sh")],
        env=environment(root),
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert setup.returncode == 0, setup.stdout[-3000:] + setup.stderr[-3000:]
    sheet = (course / "sheets" / "s01.toml").read_text()
    graded = json.loads((course / "grades" / "students" / "s01.json").read_text())
    payload = submit(root, {"s01.toml": sheet}, email="ada@uni.edu")
    assert payload["score"] == pytest.approx(graded["score"])
