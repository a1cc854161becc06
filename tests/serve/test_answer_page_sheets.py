"""Issue 24: a saved sheet the reader refuses (here one nesting 3,000 deep by a dotted key, which
made the page answer 500) shows the page's "could not be read" message and an empty form; a DEL
typed into an answer is saved into a sheet that reads back (it was saved raw, and `grade`
refused the whole sheet)."""

from __future__ import annotations

from lagrade.grading.submission import read_sheet

from .conftest import get, post

DEEP_SHEET = "[problem1]\n" + ".".join(["a"] * 3000) + " = 1\n"


def test_a_sheet_nesting_by_a_dotted_key_shows_could_not_be_read_not_500(served):
    sheet = served.sheets / "s003.toml"
    served.sheets.mkdir(exist_ok=True)
    sheet.write_text(DEEP_SHEET)
    try:
        status, html = get(served.url("s003"))
        assert status == 200, html[:500]
        assert "could not be read" in html and "nests more than 64 deep" in html
    finally:
        sheet.unlink(missing_ok=True)


def test_a_del_in_an_answer_is_saved_into_a_sheet_that_reads_back(served):
    answer = "1/2 m l^2 theta_dot^2\x7f + m g l cos(theta)"
    status, reply = post(
        served.url("s003") + "/save", {"answers": {"1": {"lagrangian": answer, "dof": "1"}}}
    )
    try:
        assert status == 200 and reply["status"] == "saved", reply
        sheet = read_sheet(served.sheets / "s003.toml", "s003", 1)
        assert sheet.readable, sheet.reason
        assert sheet.answers[1]["lagrangian"] == answer
        status, html = get(served.url("s003"))
        assert status == 200 and "could not be read" not in html
    finally:
        (served.sheets / "s003.toml").unlink(missing_ok=True)
