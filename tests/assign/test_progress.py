"""The progress bar draws on a terminal or when asked; in pipes and logs it writes plain lines
now and then (a run piped to a log must not be silent), never a carriage return."""

from __future__ import annotations

import io

from lagrade.cli.progress import ProgressBar


def test_plain_lines_when_not_a_terminal() -> None:
    stream = io.StringIO()
    bar = ProgressBar(stream)
    for done in range(1, 31):
        bar(done, 30, f"s{done:03d}")
    bar.close()
    text = stream.getvalue()
    assert "\r" not in text
    lines = text.splitlines()
    # the first, every tenth of the run, the last: a log shows life without a line per student
    assert lines[0] == "progress: 1/30 s001" and lines[-1] == "progress: 30/30 s030"
    assert 3 <= len(lines) <= 12


def test_plain_line_after_a_pause() -> None:
    stream = io.StringIO()
    bar = ProgressBar(stream, log_interval=0.0)
    bar(2, 1000, "s002")
    assert stream.getvalue() == "progress: 2/1000 s002\n"


def test_quiet_is_silent() -> None:
    stream = io.StringIO()
    bar = ProgressBar(stream, quiet=True)
    bar(1, 2, "s001")
    bar.close()
    assert stream.getvalue() == ""


def test_draws_when_asked() -> None:
    stream = io.StringIO()
    bar = ProgressBar(stream, enabled=True, width=10)
    bar(2, 4, "s002")
    bar(4, 4, "done")
    bar.close()
    assert "[#####-----] 2/4 s002" in stream.getvalue()
    assert stream.getvalue().endswith("\n") and "4/4 done" in stream.getvalue()
