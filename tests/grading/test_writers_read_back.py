"""Issue 24: every writer of a format our readers read is checked against that reader. TOML
strings and comments escape what TOML forbids raw (U+0000–U+001F but tab, U+007F); the answer
page's sheets, `generate`'s blank sheets and its manifest are read back with the reader the next
step uses (`read_sheet`, `untrusted.load_toml`/`load_json`) before they are written.

Before: a DEL typed into an answer was saved raw into a literal string, and `grade` refused the
whole sheet; a control character in the assignment title went raw into a TOML comment of every
blank sheet while `generate` exited 0; a seed of 150 digits gave a manifest `grade` refuses."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import lagrade.untrusted as untrusted
from lagrade.assign import generate
from lagrade.assign.templating import one_line, toml_literal, toml_string
from lagrade.cli.main import main
from lagrade.errors import AssignmentError
from lagrade.grading.answer_page.sheets import save_sheet, saved_answers, sheet_text
from lagrade.grading.savelog import SaveLog, log_path, now_ns
from lagrade.grading.submission import read_sheet

#: Any text a browser or a file can hold: every code point but lone surrogates (which no UTF-8
#: text holds; the page's JSON reader refuses them), controls and DEL included.
ANY_TEXT = st.text(st.characters(exclude_categories=["Cs"]))
#: Characters TOML forbids raw, and their neighbours, drawn often.
CONTROLS = st.text(
    st.sampled_from(["\x00", "\x07", "\x08", "\t", "\n", "\r", "\x1b", "\x7f", "\x85", "\u2028"])
    | st.sampled_from(list("\\'\"abt u{}"))
)
MANIFEST = {
    "assignment": {"title": "Set 3"},
    "problems": [
        {"index": 1, "parts": [{"key": "lagrangian"}, {"key": "eom"}]},
    ],
}
STUDENT = {"id": "s001", "name": "Ada"}
KEYS = {1: ["lagrangian", "eom"]}


def load(text: str) -> dict:
    return untrusted.load_toml(text, "the test sheet")


# --- the TOML writers, one value at a time ---------------------------------------------------


@settings(max_examples=300)
@given(text=ANY_TEXT | CONTROLS)
def test_a_toml_basic_string_reads_back_unchanged(text):
    assert load(f"v = {toml_string(text)}\n")["v"] == text


@settings(max_examples=300)
@given(text=ANY_TEXT | CONTROLS)
def test_a_toml_literal_reads_back_unchanged(text):
    assert load(f"v = {toml_literal(text)}\n")["v"] == text


@settings(max_examples=300)
@given(text=ANY_TEXT | CONTROLS)
def test_a_multiline_toml_literal_reads_back_unchanged_but_for_its_last_line_break(text):
    written = toml_literal(text, multiline=True)
    value = load(f"v = {written}\n")["v"]
    closing = "\n" if written.startswith("'''") and text else ""  # before the closing \'\'\'
    assert value == text + closing


@settings(max_examples=300)
@given(text=ANY_TEXT | CONTROLS)
def test_text_made_one_line_is_a_valid_toml_comment(text):
    assert load(f"# {one_line(text)}\nv = 1\n") == {"v": 1}


def test_del_and_other_controls_never_go_raw_into_a_literal_string():
    for text in ("m\x7f", "a\x00b", "x\x1b[2J"):
        written = toml_literal(text)
        assert written.startswith('"') and load(f"v = {written}\n")["v"] == text


# --- the answer page's sheet, through `grade`'s reader ---------------------------------------


def save_and_read(folder: Path, answer: str, key: str = "lagrangian", title: str = "Set 3"):
    manifest = {**MANIFEST, "assignment": {"title": title}}
    text = sheet_text(manifest, STUDENT, {1: {key: answer}})
    log = SaveLog(log_path(folder))
    saved = save_sheet(log, folder, "s001", text, answers={1: {key: answer}}, saved_ns=now_ns())
    path = folder / saved.file
    assert log.saves("s001")[-1].sheet == path.read_bytes()  # logged, byte for byte
    return read_sheet(path, "s001", 1, KEYS), saved_answers(folder, manifest, "s001")


def test_a_del_typed_into_an_answer_is_saved_into_a_sheet_grade_reads(tmp_path):
    sheet, (answers, warnings) = save_and_read(tmp_path, "1/2 m v^2\x7f")
    assert sheet.readable, sheet.reason
    assert sheet.answers[1]["lagrangian"] == "1/2 m v^2\x7f"
    assert answers == {1: {"lagrangian": "1/2 m v^2\x7f"}} and warnings == []


def test_a_control_character_in_the_title_does_not_break_a_saved_sheet(tmp_path):
    sheet, _ = save_and_read(tmp_path, "x", title="Set\x07 3\x1b[2J\x7f")
    assert sheet.readable, sheet.reason


def test_a_line_break_and_letters_in_a_quoted_answer_are_not_taken_for_latex(tmp_path):
    """A multi-line answer that needs a basic string (it holds ''') keeps `\\n` + `u` as typed:
    the writer never writes a letter escape the reader would take for an eaten `\\nu`."""
    answer = "x''' = 1\nu = 2\n\theta"
    sheet, (answers, warnings) = save_and_read(tmp_path, answer, key="eom")
    assert answers[1]["eom"] == answer and warnings == []


@settings(
    max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(answer=ANY_TEXT | CONTROLS, key=st.sampled_from(["lagrangian", "eom"]))
def test_any_answer_saved_by_the_page_comes_back_unchanged_through_the_sheet_reader(
    tmp_path, answer, key
):
    """The page keeps an answer without its surrounding white space, and omits a blank one."""
    sheet, (answers, warnings) = save_and_read(tmp_path, answer, key)
    assert sheet.readable, sheet.reason
    assert warnings == []
    if answer.strip():
        assert answers == {1: {key: answer.strip()}}
        value = sheet.answers[1][key]
        assert value.strip("\n") == answer.strip()
    else:
        assert not any(answers.values())


# --- generate: blank sheets and the manifest, read back --------------------------------------

ASSIGNMENT = """\
title = {title}
course = {course}

[[problems]]
scene = "simple_pendulum"
title = {title}
parts = ["dof", "eom"]
variants = 1
"""


def write_class(root: Path, title: str, name: str, course: str = "PHYS 1") -> tuple[Path, Path]:
    assignment = root / "a.toml"
    assignment.write_text(
        ASSIGNMENT.format(title=toml_string(title), course=toml_string(course)), encoding="utf-8"
    )
    roster = root / "roster.csv"
    cell = '"' + name.replace('"', '""') + '"'
    roster.write_bytes(f"id,name\ns001,{cell}\n".encode())
    return assignment, roster


def blank_sheet_reads_back(out: Path, name: str) -> None:
    sheet = read_sheet(out / "answer_sheets" / "s001.toml", "s001", 1, {1: ["dof", "eom"]})
    assert sheet.readable, sheet.reason
    assert sheet.warnings == ()
    assert sheet.answers == {1: {"dof": "", "eom": ""}}
    table = load((out / "answer_sheets" / "s001.toml").read_text(encoding="utf-8"))
    assert table["name"] == name


@pytest.mark.parametrize("title", ["Set\x07 3", "Set 3\x1b[2J", "Set\x7f 3", "Set\x00", "a\rb"])
def test_a_control_character_in_the_title_gives_blank_sheets_that_read_back(tmp_path, title):
    assignment, roster = write_class(tmp_path, title, "Ada")
    generate(assignment, roster, 1, tmp_path / "out", formats=("md",))
    blank_sheet_reads_back(tmp_path / "out", "Ada")


@settings(
    max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    title=ANY_TEXT.filter(lambda t: t.strip()) | CONTROLS.filter(lambda t: t.strip()),
    name=st.text(st.characters(exclude_categories=["Cs"], exclude_characters="\n\r\x00"))
    .map(str.strip)
    .filter(bool),
    course=ANY_TEXT,
)
def test_any_title_name_and_course_write_blank_sheets_that_read_back(
    tmp_path_factory, title, name, course
):
    root = tmp_path_factory.mktemp("any")
    assignment, roster = write_class(root, title, name, course)
    try:
        generate(assignment, roster, 1, root / "out", formats=("md",))
    except AssignmentError as error:  # refused with a reason is fine; a broken sheet is not
        assert "roster" in str(error) or "name" in str(error), error
        return
    blank_sheet_reads_back(root / "out", name)


def test_a_seed_whose_manifest_grade_could_not_read_is_refused(tmp_path, capsys):
    assignment, roster = write_class(tmp_path, "Set", "Ada")
    seed = "1" + "0" * 150
    status = main(
        ["generate", str(assignment), "--roster", str(roster), "--seed", seed, "--out",
         str(tmp_path / "out"), "--formats", "md"]
    )  # fmt: skip
    assert status == 2
    assert "manifest" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_sheet_that_would_not_read_back_is_not_saved(monkeypatch):
    """The old writer's DEL bug planted again: the page refuses to save, saying why."""
    import lagrade.grading.answer_page.sheets as sheets
    from lagrade.errors import OutputError

    monkeypatch.setattr(sheets, "toml_literal", lambda text, multiline=False: f"'{text}'")
    with pytest.raises(OutputError, match="would not read back"):
        sheets.sheet_text(MANIFEST, STUDENT, {1: {"lagrangian": "m v^2\x7f"}})
