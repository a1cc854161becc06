"""Gradescope: an autograder zip in which lagrade itself grades each student's answer sheet.

Gradescope's autograder contract ("Autograder Specifications" in its documentation): the zip
holds `setup.sh`, which Gradescope runs once when it builds the autograder's image (Ubuntu), and
`run_autograder`, which it runs for each submission with the working directory `/autograder`;
the zip's contents are in `/autograder/source`, the student's upload in
`/autograder/submission`, the submitter in `/autograder/submission_metadata.json`, and
`run_autograder` must write `/autograder/results/results.json` (score, tests, output).

`run_autograder` here grades with `lagrade grade` itself, on a manifest narrowed to the one
student, so a sheet earns on Gradescope exactly what it earns in `lagrade grade`. The student is
the Gradescope account's: the roster student whose email is the account's (`users[].email`),
failing that the one whose id is the account's student ID (`users[].sid`, the SID column of
Gradescope's roster). An uploaded sheet is text the student controls, so it never chooses the
variant by itself: an account that matches no roster student, or a sheet whose `student_id`
names another roster student, scores 0 with a sentence, unless the instructor exported with
`--trust-sheet` (written into the zip as SETTINGS), which goes back to the sheet's `student_id`
and file name. `LAGRADE_AUTOGRADER_ROOT` moves `/autograder` elsewhere (the tests run the
autograder in a folder laid out like Gradescope's).
"""

from __future__ import annotations

import json
import os
import tempfile
import time
import traceback
import zipfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
import lagrade.grading.report as report
import lagrade.untrusted as untrusted
from lagrade.errors import AssignmentError, LagradeError
from lagrade.grading.batch import grade
from lagrade.grading.canvas import SIS_USER_ID
from lagrade.grading.lms import roster_value
from lagrade.grading.manifest import load_manifest
from lagrade.grading.moodle import EMAIL
from lagrade.grading.submission import SUFFIXES, read_regular_file
from lagrade.grading.wheel import build_wheel

ROOT_VARIABLE = "LAGRADE_AUTOGRADER_ROOT"
DEFAULT_ROOT = "/autograder"
#: Where setup.sh puts lagrade and its dependencies, under the root.
VENV = "lagrade-venv"
#: Files looked at in an upload, at most (a student may upload a folder of anything).
MAX_CANDIDATES = 200
#: The instructor's choices made at export, inside the zip beside the manifest.
SETTINGS = "lagrade-gradescope.json"
#: Roster columns that may hold the student ID Gradescope's roster has (besides `id`).
SID_COLUMNS = ("sid", "student id", *SIS_USER_ID)
_EPOCH = (1980, 1, 1, 0, 0, 0)

SETUP_SH = """\
#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder: it installs lagrade (the wheel
# beside this script) with its dependencies into a virtual environment for run_autograder.
# Written by `lagrade export gradescope`. Settings, all optional:
#   LAGRADE_AUTOGRADER_ROOT  instead of /autograder
#   LAGRADE_PYTHON           the Python (3.11 or newer) to build the environment with
#   LAGRADE_PIP_ARGS         more arguments for pip (an index, --no-deps, ...)
set -euo pipefail
ROOT="${LAGRADE_AUTOGRADER_ROOT:-/autograder}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
VENV="$ROOT/lagrade-venv"

usable() { "$1" -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; }

PYTHON="${LAGRADE_PYTHON:-}"
if [ -z "$PYTHON" ]; then
  for candidate in python3.13 python3.12 python3.11 python3; do
    if command -v "$candidate" >/dev/null && usable "$candidate"; then
      PYTHON="$(command -v "$candidate")"
      break
    fi
  done
fi
if [ -z "$PYTHON" ]; then
  # Ubuntu 22.04, Gradescope's default image, has Python 3.10; lagrade needs 3.11.
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y python3.11 python3.11-venv
  PYTHON="$(command -v python3.11)"
fi
if ! "$PYTHON" -m venv "$VENV"; then
  # Debian and Ubuntu ship the virtual environments' pip as a package of its own.
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y "$(basename "$PYTHON")-venv"
  rm -rf "$VENV"
  "$PYTHON" -m venv "$VENV"
fi
# shellcheck disable=SC2086  # LAGRADE_PIP_ARGS is a list of arguments
"$VENV/bin/python" -m pip install --disable-pip-version-check ${LAGRADE_PIP_ARGS:-} \\
  "$HERE"/lagrade-*-py3-none-any.whl
"$VENV/bin/python" -c 'import lagrade, sys; print("lagrade", lagrade.__version__, "in", sys.prefix)'
"""

RUN_AUTOGRADER = """\
#!/usr/bin/env bash
# Gradescope runs this for each submission: lagrade grades the answer sheet in
# /autograder/submission into /autograder/results/results.json.
# Written by `lagrade export gradescope`; LAGRADE_AUTOGRADER_ROOT moves /autograder.
ROOT="${LAGRADE_AUTOGRADER_ROOT:-/autograder}"
export LAGRADE_AUTOGRADER_ROOT="$ROOT"
exec "$ROOT/lagrade-venv/bin/python" -c \\
  'from lagrade.grading.gradescope import run_autograder; raise SystemExit(run_autograder())'
"""


# --- the export ----------------------------------------------------------------------------------


def export_gradescope(manifest_path: Path, out: Path, *, trust_sheet: bool = False) -> Path:
    """Write the autograder zip for a generated assignment: setup.sh, run_autograder, the
    lagrade wheel, the manifest and the files `grade` reads beside it, and a README.
    `trust_sheet`: when the account matches no roster student, take the student the sheet
    names (for a roster without emails or Gradescope's student IDs; see the module docstring)."""
    manifest_path = Path(manifest_path)
    if manifest_path.suffix != ".json":
        raise AssignmentError(
            f"{manifest_path} is not a manifest: give the manifest.json that `lagrade generate` "
            "wrote (Gradescope grades each student's own variant)"
        )
    manifest = load_manifest(manifest_path)  # refuse a broken manifest here, not per student
    files: dict[str, tuple[bytes, int]] = {
        "setup.sh": (SETUP_SH.encode(), 0o755),
        "run_autograder": (RUN_AUTOGRADER.encode(), 0o755),
        "manifest.json": (manifest_path.read_bytes(), 0o644),
        "README.txt": (_readme(manifest, trust_sheet).encode(), 0o644),
        SETTINGS: (json.dumps({"trust_sheet": trust_sheet}).encode(), 0o644),
    }
    for name in _files_grade_reads(manifest):
        path = manifest_path.parent / name
        if path.exists():
            files[name] = (path.read_bytes(), 0o644)
    with tempfile.TemporaryDirectory() as scratch:
        wheel = build_wheel(Path(scratch))
        files[wheel.name] = (wheel.read_bytes(), 0o644)
    out = Path(out)
    with atomic.writing(out) as stream, zipfile.ZipFile(stream, "w", zipfile.ZIP_DEFLATED) as zf:
        for name in sorted(files):  # the same assignment gives the same bytes
            data, mode = files[name]
            entry = zipfile.ZipInfo(name, date_time=_EPOCH)
            entry.external_attr = (0o100000 | mode) << 16  # a regular file; unzip keeps the mode
            entry.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(entry, data)
    return out


def _files_grade_reads(manifest: Mapping[str, Any]) -> list[str]:
    """Files beside the manifest that grading reads: the assignment's copy (its rubric)."""
    return [str(manifest["assignment"].get("file", "assignment.toml"))]


def _readme(manifest: Mapping[str, Any], trust_sheet: bool) -> str:
    title = manifest["assignment"].get("title", "")
    if trust_sheet:
        who = """\
The student is found by the email of their Gradescope account in the roster's email column,
then by the account's Student ID (SID) in the roster's id (or sid) column; failing both, this
autograder was exported with --trust-sheet: it takes the student_id in the sheet, then the
file's name. A sheet whose student_id names someone else is graded as the account's student,
with a warning."""
    else:
        who = """\
The student is found by the email of their Gradescope account in the roster's email column,
then by the account's Student ID (SID) in the roster's id (or sid) column. An account that
matches neither, or a sheet whose student_id names another student, scores 0 with a sentence
saying why (export with --trust-sheet to take the sheet's student_id when the account matches
no one)."""
    return f"""\
Gradescope autograder for {title!r}, written by `lagrade export gradescope`.

On Gradescope: create a Programming Assignment worth {report.format_number(_total(manifest))}
points, then Configure Autograder > upload this zip (base image: Ubuntu; setup.sh installs
Python 3.11 when the image has an older one) > Update Autograder.

Students upload their answer sheet: the <id>.toml that `lagrade generate` wrote for them, filled
in (or the same fields as .json). Each is graded against their own variant, as `lagrade grade`
grades it.
{who}

results.json gives one test per part: the points, and lagrade's feedback as plain text.
"""


def _total(manifest: Mapping[str, Any]) -> float:
    return float(
        manifest["assignment"].get("total_points")
        or sum(float(p["points"]) for prob in manifest["problems"] for p in prob["parts"])
    )


# --- inside Gradescope's container ---------------------------------------------------------------


@dataclass(frozen=True)
class Identified:
    """Whose submission this is, which uploaded file is their sheet, and how we know."""

    student: Mapping[str, Any] | None
    sheet: Path | None
    how: str
    notes: tuple[str, ...] = ()


def run_autograder(root: Path | None = None) -> int:
    """Grade `ROOT/submission` into `ROOT/results/results.json` (ROOT: the argument, else
    $LAGRADE_AUTOGRADER_ROOT, else /autograder). Always writes a results file: a failure of
    ours gives a sentence to the student and the traceback to the instructor's log."""
    root = Path(root or os.environ.get(ROOT_VARIABLE) or DEFAULT_ROOT)
    started = time.monotonic()
    try:
        payload = grade_submission(root)
    except Exception:  # the boundary of the whole run: Gradescope must get a results file
        traceback.print_exc()  # stdout and stderr go to the instructor only
        payload = _message(
            "The autograder failed on this submission; your instructor can see why in the "
            "autograder's log. Your submission is kept."
        )
    payload["execution_time"] = round(time.monotonic() - started, 3)
    atomic.write_json(root / "results" / "results.json", payload)
    return 0


def grade_submission(root: Path) -> dict[str, Any]:
    """The results.json for the upload in `root/submission` (see the module docstring)."""
    manifest_path = root / "source" / "manifest.json"
    manifest = load_manifest(manifest_path)
    settings = _json_object(root / "source" / SETTINGS)
    found = identify(
        manifest,
        _json_object(root / "submission_metadata.json"),
        root / "submission",
        trust_sheet=settings.get("trust_sheet") is True,
    )
    if found.student is None:
        return _message(found.how)
    student = found.student
    with tempfile.TemporaryDirectory(prefix="lagrade-gradescope-") as scratch:
        work = Path(scratch)
        narrowed = {**manifest, "students": [student]}
        (work / "manifest.json").write_text(json.dumps(narrowed), encoding="utf-8")
        for name in _files_grade_reads(manifest):
            if (manifest_path.parent / name).exists():
                (work / name).write_bytes((manifest_path.parent / name).read_bytes())
        submissions = work / "submissions"
        submissions.mkdir()
        notes = list(found.notes)
        if found.sheet is not None:
            data, why = read_regular_file(found.sheet)
            if why:
                notes.append(f"{found.sheet.name} could not be read: {why}.")
            else:
                (submissions / f"{student['id']}{found.sheet.suffix.lower()}").write_bytes(data)
        grade(work / "manifest.json", submissions, work / "grades")
        result = json.loads(
            (work / "grades" / "students" / f"{student['id']}.json").read_text(encoding="utf-8")
        )
    payload = report.gradescope_results(result)
    lines = [
        f"Graded as {student['name']} ({student['id']}): {found.how}.",
        f"Score: {report.format_number(result['score'])} of "
        f"{report.format_number(result['max_score'])}.",
        *notes,
        *(f"Warning: {w}" for w in result.get("warnings", [])),
    ]
    if result["status"] != "graded":
        lines.append(f"{result['status']}: {result['reason']}")
    payload["output"] = "\n".join(lines)
    return payload


def identify(
    manifest: Mapping[str, Any],
    metadata: Mapping[str, Any],
    upload: Path,
    *,
    trust_sheet: bool = False,
) -> Identified:
    """The roster student and the sheet of an upload (see the module docstring); a student of
    None means nothing is graded and `how` is the sentence to show."""
    students = manifest["students"]
    sheets = _candidate_sheets(upload)
    by_id = {s["id"].casefold(): s for s in students}
    claims = {path: _claimed_id(path) for path in sheets}

    def named(path: Path, sid: str) -> bool:
        return path.stem.casefold() == sid.casefold() or claims[path] == sid.casefold()

    account = _account_student(students, metadata)
    if account is not None:
        student, how = account
        mine = [p for p in sheets if named(p, student["id"])] or (
            sheets if len(sheets) == 1 else []
        )
        if len(mine) != 1 and sheets:
            return Identified(student, None, how, (_which_file(sheets),))
        sheet = mine[0] if mine else None
        claimed = claims.get(sheet, "") if sheet is not None else ""
        if claimed in by_id and claimed != student["id"].casefold() and not trust_sheet:
            other = by_id[claimed]["id"]
            return Identified(
                None,
                None,
                f"Not graded: your file {sheet.name} is the answer sheet of another student "
                f"(student_id = {other!r}), and your Gradescope account is {student['name']} "
                f"({student['id']}) on the class roster. Upload your own answer sheet, "
                f"{student['id']}.toml, with its student_id line as it came.",
            )
        return Identified(student, sheet, how, _no_sheet(sheets))
    if not sheets:
        return Identified(None, None, _no_sheet(sheets)[0])
    if not trust_sheet:
        return Identified(None, None, _unknown_account(metadata))
    owners = {}
    for path in sheets:
        sid = claims[path] or path.stem.casefold()
        if sid in by_id:
            owners.setdefault(path, by_id[sid])
    if len({s["id"] for s in owners.values()}) == 1:
        path, student = next(iter(owners.items()))
        source = "the student_id in" if claims[path] in by_id else "the name of"
        return Identified(student, path, f"{source} your file {path.name}")
    if len(owners) > 1:
        return Identified(None, None, _which_file(sheets))
    return Identified(
        None,
        None,
        "lagrade could not tell whose answer sheet this is: your Gradescope account is not on "
        "the class roster, and the file names no student on it. Keep the student_id line the "
        "answer sheet came with (or name the file <your id>.toml) and submit again.",
    )


def _account_student(
    students: Sequence[Mapping[str, Any]], metadata: Mapping[str, Any]
) -> tuple[Mapping[str, Any], str] | None:
    """The roster student of the submitting Gradescope account, and how it was found: by the
    account's email in the roster's email column, then by its student ID (`sid`, as Gradescope's
    roster has it) in the roster's `id` or sid column. Each is tried over every user of a group
    submission before the next, so an email match always wins."""
    users = [u for u in metadata.get("users") or [] if isinstance(u, Mapping)]
    by_email: dict[str, Mapping[str, Any]] = {}
    by_sid: dict[str, Mapping[str, Any]] = {}
    for s in students:
        extra = s.get("extra") or {}
        email = roster_value(extra, EMAIL).casefold()
        if email:
            by_email.setdefault(email, s)
        for sid in (roster_value(extra, SID_COLUMNS), s["id"]):
            if sid:
                by_sid.setdefault(sid.casefold(), s)
    for user in users:
        student = by_email.get(_text(user.get("email")))
        if student is not None:
            return student, "the student whose email is your Gradescope account's"
    for user in users:
        student = by_sid.get(_text(user.get("sid")))
        if student is not None:
            return student, "the student whose id is your Gradescope account's student ID"
    return None


def _text(value: Any) -> str:
    """A metadata field as a casefolded string ("" when absent); a sid may come as a number."""
    if isinstance(value, bool) or value is None:
        return ""
    return str(value).strip().casefold() if isinstance(value, str | int) else ""


def _unknown_account(metadata: Mapping[str, Any]) -> str:
    users = [u for u in metadata.get("users") or [] if isinstance(u, Mapping)]
    shown = "; ".join(
        ", ".join(
            f"{label} {str(user[key]).strip()}"
            for key, label in (("email", "email"), ("sid", "student ID"))
            if _text(user.get(key))
        )
        or "no email or student ID"
        for user in users
    )
    account = f" ({shown})" if shown else ""
    return (
        f"Not graded: your Gradescope account{account} matches no student on the class roster, "
        "so lagrade cannot tell which variant of the assignment is yours. Ask your instructor "
        "to add your email (or Gradescope student ID) to the roster; your submission is kept."
    )


def _candidate_sheets(upload: Path) -> list[Path]:
    """The .toml and .json files of an upload (any depth; hidden files and macOS's
    __MACOSX folders skipped), regular files only, at most MAX_CANDIDATES."""
    found = []
    if not upload.is_dir():
        return found
    for dirpath, dirnames, filenames in os.walk(upload):  # never follows links to folders
        dirnames[:] = sorted(d for d in dirnames if not d.startswith(".") and d != "__MACOSX")
        for name in sorted(filenames):
            path = Path(dirpath) / name
            if name.startswith(".") or path.suffix.lower() not in SUFFIXES:
                continue
            if path.is_symlink() or not path.is_file():
                continue
            found.append(path)
            if len(found) >= MAX_CANDIDATES:
                return found
    return found


def _claimed_id(path: Path) -> str:
    """The `student_id` a sheet gives itself, casefolded, or ""; an unreadable sheet claims
    nothing (`grade` will say what is wrong with it)."""
    data, why = read_regular_file(path)
    if why:
        return ""
    try:
        text = untrusted.decode(data, path.name)
        sheet = (
            untrusted.load_json(text, path.name)
            if path.suffix.lower() == ".json"
            else untrusted.load_toml(text, path.name)
        )
    except LagradeError:
        return ""
    sid = sheet.get("student_id") if isinstance(sheet, Mapping) else None
    return sid.strip().casefold() if isinstance(sid, str) else ""


def _no_sheet(sheets: Sequence[Path]) -> tuple[str, ...]:
    if sheets:
        return ()
    return (
        "Your submission has no answer sheet (a .toml or .json file); upload the answer "
        "sheet you filled in.",
    )


def _which_file(sheets: Sequence[Path]) -> str:
    shown = ", ".join(p.name for p in sheets[:10])
    return (
        f"Your submission has several answer sheets ({shown}) and none is clearly yours; "
        "upload only your own answer sheet."
    )


def _json_object(path: Path) -> Mapping[str, Any]:
    """A JSON object from a file (submission_metadata.json, the settings), or {} when it is
    absent or unreadable."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _message(text: str) -> dict[str, Any]:
    """A results.json that tells the student something and grades nothing."""
    return {"score": 0.0, "output": text, "output_format": "text", "tests": []}
