"""Issue 24: text for terminals, logs and Markdown reports is sanitised. A stray file named with
terminal escape sequences went raw into summary.md and the printed summary (`cat summary.md`
cleared the screen and printed a fake line); the same held for a student's answer in the
Markdown feedback and for titles and messages `lagrade` prints. Control characters (C0 but tab
and line break, DEL, C1) and bidirectional overrides are now written as escapes (`\\x1b`)."""

from __future__ import annotations

import io
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.assign.templating import md_block, md_code, md_escape
from lagrade.cli.main import main
from lagrade.cli.progress import ProgressBar
from lagrade.cli.terminal import VisibleText
from lagrade.untrusted import visible
from tests.batch.hostile import no_traceback, run_lagrade
from tests.batch.test_hostile_inputs import grade

#: What a terminal acts on instead of showing (tab and line break aside).
ACTED_ON = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
FAKE = "\x1b[2J\x1b[H\rlagrade: all 6 students graded\x1b]0;pwned\x07\u202egpj.exe"


def assert_inert(text: str, where: str = "") -> None:
    found = ACTED_ON.search(text)
    assert found is None, f"{where}: raw {found.group()!r} in {text[:300]!r}"


def test_a_stray_file_named_with_escape_sequences_is_shown_not_run(classroom):
    (classroom / "subs" / f"{FAKE}.toml").write_text("x")
    proc = grade(classroom)
    no_traceback(proc)
    stdout = proc.stdout.decode("utf-8")
    summary = (classroom / "grades" / "summary.md").read_text(encoding="utf-8")
    for name, text in (("stdout", stdout), ("stderr", proc.stderr.decode()), ("md", summary)):
        assert_inert(text, name)
    assert "\\x1b[2J" in summary and "\\x1b[2J" in stdout  # named, as escapes


def test_an_escape_sequence_in_an_answer_is_inert_in_the_markdown_feedback(classroom):
    (classroom / "subs" / "s1.toml").write_text(
        '[problem1]\ndof = "1"\nlagrangian = "\\u001b[2J m l\\u0007^2"\neom = "x\\u009b31m = 0"\n'
    )
    no_traceback(grade(classroom))
    feedback = (classroom / "grades" / "feedback" / "s1.md").read_text(encoding="utf-8")
    assert_inert(feedback, "feedback.md")
    assert "\\x1b[2J" in feedback


def test_printed_titles_and_error_messages_are_inert(tmp_path):
    (tmp_path / "a.toml").write_text(
        'title = "Set\\u001b[2J"\n[[problems]]\nscene = "simple_pendulum"\n'
        'title = "P\\u001b]0;x\\u0007\\r fake"\nparts = ["dof"]\n'
    )
    proc = run_lagrade(
        "export", "prairielearn", "a.toml", "--seed", "1", "--out", "q", cwd=tmp_path
    )
    assert proc.returncode == 0, proc.stderr
    assert_inert(proc.stdout.decode(), "export stdout")
    (tmp_path / "r.csv").write_text("id,name\n\x1b[2Jx,A\n")
    proc = run_lagrade("generate", "a.toml", "--roster", "r.csv", "--seed", "1", "--out", "o",
                       cwd=tmp_path)  # fmt: skip
    assert proc.returncode == 2
    assert "\\x1b[2J" in proc.stderr.decode()
    assert_inert(proc.stderr.decode(), "generate stderr")


@pytest.mark.parametrize(
    "argv",
    [
        ["parse", "theta\x1b[2J + 1", "--coordinates", "theta"],
        ["check", "--scene", "simple_pendulum", "--part", "dof", "--answer", "1\x1b[2J"],
        ["check", "--scene", "no\x1b[2Jpe", "--part", "dof", "--answer", "1"],
    ],
    ids=["parse", "check answer", "check scene"],
)
def test_what_a_command_prints_about_an_answer_is_inert(argv, capsys):
    main(argv)
    out, err = capsys.readouterr()
    assert_inert(out, "stdout")
    assert_inert(err, "stderr")


def test_the_progress_bar_keeps_its_own_carriage_return_and_escapes_its_label():
    terminal = io.StringIO()
    bar = ProgressBar(stream=VisibleText(terminal), enabled=True, min_interval=0)
    bar(1, 2, "s1\x1b[2J\r")
    drawn = terminal.getvalue()
    assert drawn.startswith("\r[") and drawn.count("\r") == 1
    assert "\\x1b[2J\\r" in drawn


@settings(max_examples=300)
@given(text=st.text())
def test_markdown_text_and_terminal_text_hold_no_control_character(text):
    for shown in (md_escape(text), md_code(text), visible(text)):
        assert_inert(shown)
    assert_inert(md_block(text).replace("\t", " "))
