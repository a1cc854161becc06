"""Issue 14, case by case: one bad byte, line, sheet or name costs only its own result, never
the class's, and no output format can be broken out of. Each test drives the `lagrade` command
in a child process, as an instructor would, and asserts what any fix must do (one result per
line, `invalid` with a reason, nothing outside `--out`), not the wording of a message."""

from __future__ import annotations

import json
import os
import re
import resource
import signal
import subprocess
import time

import pytest

from tests.batch.conftest import HOSTILE_NAMES
from tests.batch.hostile import (
    AD_HOC,
    ENV,
    PENDULUM,
    command,
    gradebook,
    no_traceback,
    request,
    run_batch,
    run_lagrade,
    tree,
    undecodable,
)

DIGITS = b"9" * 5000
PROBLEM = json.dumps(PENDULUM).encode()

# --- check --batch: a bad line is that line's `invalid`, the others are judged ------------------

BAD_LINES = {
    "lone surrogate": b'{"id": 2, "problem": %s, "part": "dof", "answer": "\\ud800"}' % PROBLEM,
    "5000-digit id": b'{"id": %s, "problem": %s, "part": "dof", "answer": "1"}' % (DIGITS, PROBLEM),
    "5000-digit time_limit": b'{"id": 2, "time_limit": %s, "problem": %s, "part": "dof", '
    b'"answer": "1"}' % (DIGITS, PROBLEM),
    "100,000 nested brackets": b"[" * 100_000 + b"]" * 100_000,
    "100,000 nested brackets in an answer": b'{"id": 2, "problem": %s, "part": "dof", '
    b'"answer": %s}' % (PROBLEM, b"[" * 100_000 + b"]" * 100_000),
    "byte that is not UTF-8": b'{"id": 2, "problem": %s, "part": "dof", "answer": "\xff"}'
    % PROBLEM,
    "null": b"null",
    "part as a list": b'{"id": 2, "problem": %s, "part": ["eom"], "answer": "1"}' % PROBLEM,
}


@pytest.mark.parametrize("line", BAD_LINES.values(), ids=BAD_LINES.keys())
def test_a_bad_request_line_is_invalid_and_the_others_are_judged(tmp_path, line):
    proc, results = run_batch(tmp_path, [request(1, "1"), line, request(3, "1")])
    no_traceback(proc)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert len(results) == 3
    assert [results[0]["id"], results[2]["id"]] == [1, 3]
    assert results[0]["verdict"] == results[2]["verdict"] == "correct"
    assert results[1]["verdict"] == "invalid"
    assert results[1]["feedback"] and all(results[1]["feedback"])


@pytest.mark.parametrize("separator", ["\u2028", "\u2029", "\u0085"], ids=repr)
def test_a_unicode_line_separator_inside_a_json_string_is_not_a_line_end(tmp_path, separator):
    """JSON lets U+2028, U+2029 and U+0085 stand raw in a string; str.splitlines() breaks there."""
    answer = f"1{separator}"
    proc, results = run_batch(tmp_path, [request(1, "1"), request(2, answer), request(3, "1")])
    no_traceback(proc)
    assert [r["id"] for r in results] == [1, 2, 3]
    assert results[1]["verdict"] != "error"


@pytest.mark.parametrize("part", ["lagrangian", "eom", "conserved"])
def test_zero_to_the_power_of_a_coordinate_is_judged_not_an_internal_error(tmp_path, part):
    """0^theta is 0 for theta > 0 and 1/0 for theta < 0: the evaluation meets a division by zero,
    which must be the student's wrong answer, not our bug."""
    answer = "0^theta" if part == "lagrangian" else ["0^theta"]
    proc, results = run_batch(tmp_path, [request(1, answer, part, AD_HOC)])
    assert [r["verdict"] for r in results] in (["incorrect"], ["invalid"]), results
    no_traceback(proc)


def test_a_5000_digit_dof_answer_is_judged_not_an_internal_error(tmp_path):
    """`dof` reads the answer with int(), which refuses more than 4,300 digits (ValueError)."""
    proc, results = run_batch(tmp_path, [request(1, "9" * 5000), request(2, "1")])
    no_traceback(proc)
    assert [r["verdict"] for r in results] in (["incorrect", "correct"], ["invalid", "correct"])


INSTRUCTOR_INPUT = {
    "5000-digit domain bound": {**AD_HOC, "parameters": {"m": "(0, " + "9" * 5000 + ")"}},
    "2000 coordinates": {**AD_HOC, "coordinates": ["theta"] + [f"q{i}" for i in range(1999)]},
    "lone surrogate in a coordinate": {**AD_HOC, "coordinates": ["theta\ud800"]},
}


@pytest.mark.parametrize("problem", INSTRUCTOR_INPUT.values(), ids=INSTRUCTOR_INPUT.keys())
def test_instructor_side_input_is_bounded_like_a_students(tmp_path, problem):
    """An ad-hoc question is input too: past the limits it is `invalid` with a reason, not our
    bug and not a minute spent deriving it."""
    line = json.dumps({"id": 1, "problem": problem, "part": "lagrangian", "answer": "m"})
    proc, results = run_batch(tmp_path, [line.encode(), request(2, "1")])
    no_traceback(proc)
    assert [r["verdict"] for r in results] == ["invalid", "correct"], results[0]["feedback"]


def test_a_huge_answer_gives_a_bounded_result_line(tmp_path):
    """`interpreted` and `feedback` echo the answer; a 1 MB answer must not make a 1 MB line."""
    answer = "m*" * 500_000 + "g"
    proc, _results = run_batch(tmp_path, [request(1, answer, "lagrangian", AD_HOC)])
    no_traceback(proc)
    assert (tmp_path / "results.jsonl").stat().st_size < 100_000


def test_check_batch_exit_status_is_zero_with_invalid_lines_and_two_without_a_file(tmp_path):
    proc, results = run_batch(tmp_path, [b"{", b"[]", request(3, "1")])
    assert proc.returncode == 0 and [r["verdict"] for r in results] == [
        "invalid",
        "invalid",
        "correct",
    ]
    missing = run_lagrade("check", "--batch", tmp_path / "nothing.jsonl", cwd=tmp_path)
    assert missing.returncode == 2 and missing.stderr.strip()
    no_traceback(missing)


@pytest.mark.parametrize(
    "number", [b"1e400", b"-1e400", b"9" * 101 + b".5"], ids=["1e400", "-1e400", "101-digit float"]
)
def test_an_id_that_is_a_huge_float_gives_a_strict_json_result(tmp_path, number):
    """Python reads 1e400 as inf and writes it back as `Infinity`, which is not JSON; a
    101-digit float comes back as 1e+101, which is not the id the client sent."""
    line = b'{"id": %s, "problem": %s, "part": "dof", "answer": "1"}' % (number, PROBLEM)
    proc, results = run_batch(tmp_path, [request(1, "1"), line, request(3, "1")])
    no_traceback(proc)
    assert [results[0]["id"], results[2]["id"]] == [1, 3]
    assert results[1]["id"] is None or json.dumps(results[1]["id"]).encode() == number


# --- grade: a bad sheet is that student's `invalid`, the class is graded ------------------------


def grade(classroom, *extra, preexec_fn=None):
    """`lagrade grade` on the classroom fixture's manifest and submissions, into `grades/`."""
    return run_lagrade(
        "grade",
        classroom / "class" / "manifest.json",
        classroom / "subs",
        "--out",
        classroom / "grades",
        *extra,
        cwd=classroom,
        preexec_fn=preexec_fn,
    )


def statuses(classroom) -> dict[str, tuple[str, str]]:
    return {r["id"]: (r["status"], r["reason"]) for r in gradebook(classroom / "grades")}


def assert_only_s1_invalid(classroom, proc):
    no_traceback(proc)
    assert proc.returncode == 1, proc.stderr[-2000:]
    table = statuses(classroom)
    assert sorted(table) == sorted(HOSTILE_NAMES)
    status, reason = table["s1"]
    assert status == "invalid" and reason.strip()
    assert all(table[s][0] == "graded" for s in HOSTILE_NAMES if s != "s1"), table
    for sid in HOSTILE_NAMES:
        assert (classroom / "grades" / "feedback" / f"{sid}.md").exists(), sid
    assert undecodable(classroom / "grades") == []


SURROGATE_SHEETS = {
    "in an answer": b'{"problem1": {"dof": "1", "lagrangian": "\\ud800"}}',
    "in the student_id": b'{"student_id": "\\udfff", "problem1": {"dof": "1"}}',
}


@pytest.mark.parametrize("sheet", SURROGATE_SHEETS.values(), ids=SURROGATE_SHEETS.keys())
def test_a_lone_surrogate_in_a_json_sheet_is_invalid_and_the_class_is_graded(classroom, sheet):
    (classroom / "subs" / "s1.toml").unlink()
    (classroom / "subs" / "s1.json").write_bytes(sheet)
    assert_only_s1_invalid(classroom, grade(classroom))


BIG_NUMBER_SHEETS = {
    "s1.toml": b"[problem1]\ndof = " + DIGITS + b"\n",
    "s1.json": b'{"problem1": {"dof": ' + DIGITS + b"}}",
}


@pytest.mark.parametrize("name", BIG_NUMBER_SHEETS)
def test_a_5000_digit_integer_in_a_sheet_is_invalid_not_error(classroom, name):
    (classroom / "subs" / "s1.toml").unlink()
    (classroom / "subs" / name).write_bytes(BIG_NUMBER_SHEETS[name])
    assert_only_s1_invalid(classroom, grade(classroom))


def test_a_5000_digit_dof_string_in_a_sheet_is_graded_not_error(classroom):
    (classroom / "subs" / "s1.toml").write_text("[problem1]\ndof = '" + "9" * 5000 + "'\n")
    proc = grade(classroom)
    no_traceback(proc)
    assert statuses(classroom)["s1"][0] in ("graded", "invalid")


def test_gradebook_names_that_would_run_as_formulas_begin_with_a_quote(classroom):
    """OWASP's rule: a cell starting with = + - @, a tab or a carriage return gets a leading '.
    The first four come through the roster; a tab or CR only through the manifest (the roster
    reader strips them)."""
    manifest_path = classroom / "class" / "manifest.json"
    manifest = json.loads(manifest_path.read_text())
    planted = {**HOSTILE_NAMES, "s5": "\tcmd", "s6": "\r=cmd"}
    for student in manifest["students"]:
        student["name"] = planted[student["id"]]
    manifest_path.write_text(json.dumps(manifest))
    proc = grade(classroom)
    no_traceback(proc)
    names = {r["id"]: r["name"] for r in gradebook(classroom / "grades")}
    assert sorted(names) == sorted(planted), proc.stderr[-2000:]
    for sid, name in names.items():
        assert name.startswith("'"), (sid, name)
        assert planted[sid].strip() in name, (sid, name)  # neutralised, not dropped


def test_a_carriage_return_inside_a_name_does_not_split_its_gradebook_row(classroom):
    """Python's csv module quotes a cell holding its line terminator (here \\n) but not a lone
    \\r, which every CSV reader and spreadsheet takes for a line end."""
    manifest_path = classroom / "class" / "manifest.json"
    manifest = json.loads(manifest_path.read_text())
    manifest["students"][4]["name"] = "Ann\rBob"
    manifest_path.write_text(json.dumps(manifest))
    no_traceback(grade(classroom))
    rows = gradebook(classroom / "grades")
    assert [r["id"] for r in rows] == list(HOSTILE_NAMES)
    assert all(r["status"] in ("graded", "invalid") for r in rows), rows


def test_gradebook_keeps_plain_names_as_they_are(classroom):
    proc = grade(classroom)
    no_traceback(proc)
    names = {r["id"]: r["name"] for r in gradebook(classroom / "grades")}
    assert (names["s5"], names["s6"]) == (HOSTILE_NAMES["s5"], HOSTILE_NAMES["s6"])


def test_a_backtick_in_an_answer_cannot_leave_its_code_span(classroom):
    """CommonMark closes a code span at the first backtick run as long as its opening fence, so
    the fence must be longer than every run of backticks in the text."""
    (classroom / "subs" / "s1.toml").write_text(
        "[problem1]\ndof = '1'\nlagrangian = 'x` <img src=x onerror=alert(1)> ``y'\neom = '```'\n"
    )
    proc = grade(classroom)
    no_traceback(proc)
    page = (classroom / "grades" / "feedback" / "s1.md").read_text(encoding="utf-8")
    spans = {}
    for line in page.splitlines():
        found = re.fullmatch(r"- (\w+): (`+)(.*)\2", line)
        if found:
            spans[found[1]] = (found[2], found[3])
    assert {"lagrangian", "eom"} <= set(spans), page
    for key, (fence, text) in spans.items():
        runs = [len(r) for r in re.findall(r"`+", text)]
        assert max(runs, default=0) < len(fence), (key, fence, text)
    assert "<img" in spans["lagrangian"][1]  # the text is shown, inside its span
    html = (classroom / "grades" / "feedback" / "s1.html").read_text(encoding="utf-8")
    assert "<img" not in html


def test_summary_md_escapes_the_assignment_title(classroom):
    proc = grade(classroom)
    no_traceback(proc)
    summary = (classroom / "grades" / "summary.md").read_text(encoding="utf-8")
    assert "alert(1)" in summary  # the title is there ...
    assert "<script>" not in summary  # ... but inert
    assert "*bold*" not in summary


# --- paths: nothing is written outside --out, and no link is followed ---------------------------


@pytest.mark.parametrize("bad_id", ["../../x", "ABSOLUTE", "..", ".hidden"])
def test_a_student_id_that_names_a_path_is_refused_and_nothing_is_written_outside(
    classroom, bad_id
):
    if bad_id == "ABSOLUTE":
        bad_id = str(classroom / "abs")
    manifest_path = classroom / "class" / "manifest.json"
    manifest = json.loads(manifest_path.read_text())
    manifest["students"][1]["id"] = bad_id
    manifest_path.write_text(json.dumps(manifest))
    before = tree(classroom)
    proc = grade(classroom)
    no_traceback(proc)
    assert tree(classroom, skip=classroom / "grades") == before
    refused_run = proc.returncode == 2 and bad_id.encode() in proc.stderr
    refused_row = proc.returncode == 1 and statuses(classroom).get(bad_id, ("",))[0] == "invalid"
    assert refused_run or refused_row, (proc.returncode, proc.stderr[-2000:])


def test_a_roster_id_that_names_a_path_is_refused_by_generate(tmp_path):
    (tmp_path / "a.toml").write_text('title = "t"\n[[problems]]\nscene = "simple_pendulum"\n')
    (tmp_path / "r.csv").write_text("id,name\n../../x,Mallory\n")
    proc = run_lagrade(
        "generate", "a.toml", "--roster", "r.csv", "--seed", 1, "--out", "o", cwd=tmp_path
    )
    no_traceback(proc)
    assert proc.returncode == 2 and b"../../x" in proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.toml", "r.csv"]


def test_a_submission_that_is_a_symlink_is_refused_and_not_read(classroom):
    """The link points at a sheet that would score; refusing it must give 0 and a reason."""
    outside = classroom / "outside.toml"
    outside.write_text("[problem1]\ndof = '1'\n")
    (classroom / "subs" / "s1.toml").unlink()
    (classroom / "subs" / "s1.toml").symlink_to(outside)
    assert_only_s1_invalid(classroom, grade(classroom))
    assert gradebook(classroom / "grades")[0]["score"] == "0"


def test_a_folder_or_fifo_named_like_a_sheet_gets_a_row_and_no_hang(classroom):
    subs = classroom / "subs"
    (subs / "s1.toml").unlink()
    (subs / "s1.toml").mkdir()
    (subs / "s2.toml").unlink()
    os.mkfifo(subs / "s2.toml")
    proc = grade(classroom)  # run_lagrade's timeout catches a read that blocks on the fifo
    no_traceback(proc)
    table = statuses(classroom)
    assert table["s1"][0] in ("invalid", "missing") and table["s1"][1].strip()
    assert table["s2"][0] in ("invalid", "missing") and table["s2"][1].strip()


# --- exit statuses: a script can tell the outcomes apart ------------------------------------------


def test_grade_exits_0_when_all_are_graded_and_1_when_one_is_missing(classroom):
    assert grade(classroom).returncode == 0
    (classroom / "subs" / "s3.toml").unlink()
    proc = grade(classroom)
    assert proc.returncode == 1 and statuses(classroom)["s3"][0] == "missing"


def test_grade_exits_2_on_a_manifest_that_is_not_json(classroom):
    (classroom / "class" / "manifest.json").write_bytes(b"\xff{not json")
    proc = grade(classroom)
    no_traceback(proc)
    assert proc.returncode == 2 and proc.stderr.strip()


def _small_files_only():
    """In the child: files may not grow past 4 KB, as on a full disk (EFBIG, not a signal)."""
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))


def test_grade_on_a_full_disk_exits_with_its_own_status_and_no_traceback(classroom):
    """A full disk is an environment fault: neither success (0), nor students missing (1), nor
    bad input (2) — a script must be able to tell them apart."""
    proc = grade(classroom, preexec_fn=_small_files_only)
    no_traceback(proc)
    assert proc.returncode not in (0, 1, 2), proc.returncode
    assert proc.stderr.strip()


@pytest.mark.parametrize("delay", [0.1, 0.3, 0.6, 1.0])
def test_ctrl_c_early_in_a_run_ends_it_quietly(classroom, delay):
    """Ctrl-C while the command is still importing or warming up: status 130 (or killed by the
    signal before Python handles it), and no traceback."""
    run = subprocess.Popen(
        command("grade", "class/manifest.json", "subs", "--out", "grades"),
        cwd=classroom,
        env=ENV,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    time.sleep(delay)
    run.send_signal(signal.SIGINT)
    _out, err = run.communicate(timeout=60)
    assert b"Traceback" not in err, err.decode("utf-8", "replace")[-3000:]
    assert run.returncode in (130, -signal.SIGINT, 0), (  # 0: it had finished
        run.returncode,
        err.decode("utf-8", "replace")[-3000:],
    )
