"""The progress bar draws on a terminal or when asked, and stays silent in pipes and logs."""

from __future__ import annotations

import io

from lagrade.cli.progress import ProgressBar


def test_silent_when_not_a_terminal() -> None:
    stream = io.StringIO()
    bar = ProgressBar(stream)
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
