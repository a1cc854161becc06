"""The log of saves (`lagrade.grading.savelog`) and the instants it is read by: a save and its
sheet are one transaction (a sheet that cannot be written leaves no row; a row that cannot be
committed puts the replaced sheet back), concurrent saves all land, a sheet the page did not
write is logged before a save replaces it, `sheets_as_of` rebuilds a folder byte for byte; the
due date's states and sentences; `[answer_page]` late and timezone; `--as-of` times."""

from __future__ import annotations

import contextlib
import datetime as dt
import os
import sqlite3
import threading

import pytest

from lagrade.errors import OutputError, RequestError
from lagrade.grading.answer_page.due import CLOSED, LATE, OPEN, DueRule, due_rule
from lagrade.grading.answer_page.settings import PageSettings, settings_from_table
from lagrade.grading.answer_page.sheets import save_sheet, sheet_text
from lagrade.grading.instants import read_instant, shown, to_ns, zone
from lagrade.grading.savelog import (
    SaveLog,
    canonical_answers,
    log_path,
    now_ns,
    sheets_as_of,
)

MANIFEST = {
    "assignment": {"title": "Set 3"},
    "problems": [{"index": 1, "parts": [{"key": "dof"}, {"key": "lagrangian"}]}],
}
STUDENT = {"id": "s001", "name": "Ada"}
UTC = dt.UTC


def _save(log, folder, answers, ns=None, token=None, student=STUDENT):
    ns = ns or now_ns()
    text = sheet_text(MANIFEST, student, {1: answers}, dt.datetime.fromtimestamp(ns / 1e9, UTC))
    return save_sheet(
        log, folder, student["id"], text, answers={1: answers}, saved_ns=ns, token=token
    )


def test_a_save_is_a_row_and_its_sheet_byte_for_byte(tmp_path):
    log = SaveLog(log_path(tmp_path))
    saved = _save(log, tmp_path, {"dof": "1", "lagrangian": ""}, token="abcdefgh")
    (row,) = log.saves("s001")
    assert row.sheet == (tmp_path / "s001.toml").read_bytes() == saved.sheet
    assert row.answers == {"1": {"dof": "1"}}  # blank answers are not in the sheet either
    assert row.token == "abcdefgh" and row.origin == "page" and not row.late
    assert log.by_token("s001", "abcdefgh").id == row.id
    assert sqlite3.connect(log.path).execute("PRAGMA journal_mode").fetchone() == ("wal",)


def test_a_sheet_that_cannot_be_written_leaves_no_row(tmp_path, monkeypatch):
    import lagrade.grading.atomic as atomic

    log = SaveLog(log_path(tmp_path))
    _save(log, tmp_path, {"dof": "1"})
    before = (tmp_path / "s001.toml").read_bytes()

    def full_disk(path, data):
        raise OutputError(f"cannot write {path}: No space left on device")

    monkeypatch.setattr(atomic, "write_bytes", full_disk)
    with pytest.raises(OutputError, match="No space left"):
        _save(log, tmp_path, {"dof": "2"})
    assert len(log.saves("s001")) == 1
    assert (tmp_path / "s001.toml").read_bytes() == before


class _CommitFails(SaveLog):
    """A log whose COMMIT fails (a disk error at the last moment)."""

    @contextlib.contextmanager
    def _connect(self):
        with super()._connect() as conn:

            class Proxy:
                def execute(self, sql, *args):
                    if sql == "COMMIT":
                        raise sqlite3.OperationalError("disk I/O error")
                    return conn.execute(sql, *args)

            yield Proxy()


def test_a_row_that_cannot_be_committed_puts_the_old_sheet_back(tmp_path):
    log = SaveLog(log_path(tmp_path))
    _save(log, tmp_path, {"dof": "1"})
    before = (tmp_path / "s001.toml").read_bytes()
    failing = _CommitFails(log_path(tmp_path))
    with pytest.raises(OutputError, match="disk I/O error"):
        _save(failing, tmp_path, {"dof": "2"})
    assert (tmp_path / "s001.toml").read_bytes() == before  # the folder and the log agree
    assert [r.answers for r in log.saves("s001")] == [{"1": {"dof": "1"}}]
    with pytest.raises(OutputError, match="disk I/O error"):
        _save(failing, tmp_path, {"dof": "3"}, student={"id": "s002", "name": "Emmy"})
    assert not (tmp_path / "s002.toml").exists()  # a first save undone: no sheet at all


def test_concurrent_saves_all_land(tmp_path):
    """Eight students, 25 saves each, from eight threads with a connection each."""
    log = SaveLog(log_path(tmp_path))
    errors = []

    def student(k: int) -> None:
        who = {"id": f"s{k:03d}", "name": f"Student {k}"}
        try:
            for n in range(25):
                _save(log, tmp_path, {"dof": str(n)}, student=who)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=student, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    rows = log.saves()
    assert len(rows) == 200
    for k in range(8):
        mine = [r for r in rows if r.student == f"s{k:03d}"]
        assert [r.answers["1"]["dof"] for r in mine] == [str(n) for n in range(25)]
        assert mine[-1].sheet == (tmp_path / f"s{k:03d}.toml").read_bytes()


def test_a_sheet_the_page_did_not_write_is_logged_before_it_is_replaced(tmp_path):
    log = SaveLog(log_path(tmp_path))
    by_hand = tmp_path / "s001.json"
    by_hand.write_text('{"problem1": {"dof": "2"}}')
    os.utime(by_hand, ns=(1_700_000_000_000_000_000, 1_700_000_000_000_000_000))
    _save(log, tmp_path, {"dof": "1"})
    found, page = log.saves("s001")
    assert found.origin == "found" and found.file == "s001.json"
    assert found.sheet == b'{"problem1": {"dof": "2"}}'
    assert to_ns(found.saved_at) == 1_700_000_000_000_000_000  # its modification time
    assert page.origin == "page" and not by_hand.exists()  # one sheet for `grade`
    _save(log, tmp_path, {"dof": "3"})
    assert [r.origin for r in log.saves("s001")] == ["found", "page", "page"]  # logged once


def test_sheets_as_of_rebuilds_the_folder_at_an_instant(tmp_path):
    sheets, out = tmp_path / "sheets", tmp_path / "then"
    sheets.mkdir()
    log = SaveLog(log_path(sheets))
    base = now_ns()
    saves = [_save(log, sheets, {"dof": str(n)}, ns=base + n * 10**9) for n in range(3)]
    never_logged = sheets / "s002.toml"
    never_logged.write_text('student_id = "s002"\n[problem1]\ndof = "4"\n')
    os.utime(never_logged, ns=(base, base))
    moment = saves[1].saved_at + dt.timedelta(milliseconds=500)
    chosen = sheets_as_of(sheets, ["s001", "s002", "s003"], moment, out)
    assert chosen["s001"].id == saves[1].id
    assert (out / "s001.toml").read_bytes() == saves[1].sheet
    assert (out / "s002.toml").read_bytes() == never_logged.read_bytes()
    assert "s003" not in chosen and sorted(p.name for p in out.iterdir()) == [
        "s001.toml",
        "s002.toml",
    ]
    early = sheets_as_of(sheets, ["s001", "s002"], saves[0].saved_at - dt.timedelta(1), out / "x")
    assert early == {}


def test_a_folder_without_a_log_or_with_another_database_is_refused(tmp_path):
    with pytest.raises(RequestError, match="there is no log of saves"):
        sheets_as_of(tmp_path, ["s001"], dt.datetime.now(UTC), tmp_path / "out")
    other = sqlite3.connect(log_path(tmp_path))
    other.execute("CREATE TABLE people (name TEXT)")
    other.execute("PRAGMA user_version = 7")
    other.commit()
    other.close()
    with pytest.raises(RequestError, match="not a log of saves this lagrade can use"):
        SaveLog(log_path(tmp_path))


def test_canonical_answers_are_equal_for_equal_answers():
    assert canonical_answers({1: {"b": "x", "a": "y", "c": " "}}) == canonical_answers(
        {"1": {"a": "y", "b": "x"}}
    )


# --- instants, the due date and its settings -------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("2025-03-14T23:59:00+01:00", dt.datetime(2025, 3, 14, 22, 59, tzinfo=UTC)),
        ("2025-03-14T23:59:00Z", dt.datetime(2025, 3, 14, 23, 59, tzinfo=UTC)),
        ("2025-03-14T23:59:00", dt.datetime(2025, 3, 14, 22, 59, tzinfo=UTC)),  # Berlin, CET
        ("2025-07-14 23:59", dt.datetime(2025, 7, 14, 21, 59, tzinfo=UTC)),  # CEST
        ("2025-03-14", dt.datetime(2025, 3, 14, 22, 59, 59, 999_999, tzinfo=UTC)),  # day's end
        ("2025-03-14T23:59:00.250", dt.datetime(2025, 3, 14, 22, 59, 0, 250_000, tzinfo=UTC)),
    ],
)
def test_instants_read_as_an_instructor_writes_them(text, expected):
    assert read_instant(text, zone("Europe/Berlin")) == expected


@pytest.mark.parametrize("text", ["Friday", "2025-13-01", "2025-03-14T25:00", "14/03/2025"])
def test_what_is_not_an_instant_is_refused_saying_what_is(text):
    with pytest.raises(RequestError, match="date and time"):
        read_instant(text)


def test_the_due_dates_states_and_sentences():
    due = dt.datetime(2025, 3, 14, 23, 59, tzinfo=UTC)
    closed = DueRule(due)
    before, after = due - dt.timedelta(seconds=1), due + dt.timedelta(microseconds=1)
    assert closed.state(due) == OPEN and closed.state(after) == CLOSED
    assert closed.notice(before) == "Due 2025-03-14 23:59 UTC; after it, saving is closed."
    assert "takes no late work" in closed.notice(after)
    late = DueRule(due, late=True)
    assert late.state(after) == LATE and late.state(after + dt.timedelta(days=400)) == LATE
    assert "recorded as late" in late.notice(after)
    until = DueRule(due, late=True, late_until=due + dt.timedelta(days=2))
    assert until.state(due + dt.timedelta(days=1)) == LATE
    assert until.state(due + dt.timedelta(days=3)) == CLOSED
    assert "time for late work (2025-03-16 23:59 UTC)" in until.refusal()
    assert DueRule().state(after) == OPEN and DueRule().notice(after) == ""


def test_a_due_date_that_names_no_instant_is_not_kept_and_says_why():
    assert due_rule("Friday in class", PageSettings()).unread.startswith("due: 'Friday in class'")
    assert "time of day" in due_rule("23:59:00", PageSettings()).unread
    assert due_rule("", PageSettings()) == DueRule()
    rule = due_rule("2025-03-14", settings_from_table({"timezone": "UTC", "late": True}))
    assert rule.due == dt.datetime(2025, 3, 14, 23, 59, 59, 999_999, tzinfo=UTC) and rule.late
    assert shown(rule.due) == "2025-03-14 23:59:59 UTC"


def test_late_and_timezone_settings():
    until = settings_from_table(
        {"late": dt.datetime(2025, 3, 16, 12, 0), "timezone": "America/New_York"}
    )
    assert until.late and until.late_until == dt.datetime(2025, 3, 16, 16, 0, tzinfo=UTC)
    with pytest.raises(RequestError) as error:
        settings_from_table({"late": "soon", "timezone": "Mars/Olympus", "lates": 1})
    message = str(error.value)
    assert "late: 'soon' is not a date and time" in message
    assert "timezone: unknown time zone 'Mars/Olympus'" in message
    assert "lates: unknown field" in message


#: Daylight-saving transitions of 2026 from the IANA zone database (tzdata): the United States
#: spring forward on 8 March at 02:00 and fall back on 1 November at 02:00 (Energy Policy Act
#: of 2005); the European Union on 29 March and 25 October at 01:00 UTC.
@pytest.mark.parametrize(
    "text, where, expected",
    [
        ("2026-03-08T02:30", "America/New_York", "'2026-03-08T02:30' never happens in "
         "America/New_York: the clocks skip that hour when daylight saving begins (from -05:00 "
         "EST to -04:00 EDT)"),
        ("2026-03-29 02:15", "Europe/Berlin", "never happens in Europe/Berlin"),
        ("2026-11-01T01:30", "America/New_York", "'2026-11-01T01:30' happens twice in "
         "America/New_York, when the clocks go back (at -04:00 EDT and again at -05:00 EST): "
         "write the offset of the one you mean, e.g. 2026-11-01T01:30-04:00"),
        ("2026-10-25T02:30:00", "Europe/Berlin", "happens twice in Europe/Berlin"),
    ],
)  # fmt: skip
def test_a_time_in_a_daylight_saving_gap_or_fold_is_refused(text, where, expected):
    with pytest.raises(RequestError) as refused:
        read_instant(text, zone(where))
    assert expected in str(refused.value)
    rule = due_rule(text, settings_from_table({"timezone": where}))
    assert rule.due is None and expected in rule.unread  # the page says why it keeps no due


def test_the_hours_around_a_transition_and_a_written_offset_are_one_instant():
    new_york = zone("America/New_York")
    assert read_instant("2026-03-08T01:59", new_york) == dt.datetime(2026, 3, 8, 6, 59, tzinfo=UTC)
    assert read_instant("2026-03-08T03:00", new_york) == dt.datetime(2026, 3, 8, 7, 0, tzinfo=UTC)
    assert read_instant("2026-11-01T01:30-05:00", new_york) == dt.datetime(
        2026, 11, 1, 6, 30, tzinfo=UTC
    )
    assert read_instant("2026-11-01T02:30", new_york) == dt.datetime(2026, 11, 1, 7, 30, tzinfo=UTC)
    assert read_instant("2026-03-08", new_york) == dt.datetime(
        2026, 3, 9, 3, 59, 59, 999_999, tzinfo=UTC
    )


def test_in_this_computer_s_zone_too(monkeypatch):
    """No `[answer_page] timezone`: the computer's own zone, with its transitions."""
    import time

    monkeypatch.setenv("TZ", "America/New_York")
    time.tzset()
    try:
        with pytest.raises(RequestError, match="never happens in this computer's time zone"):
            read_instant("2026-03-08T02:30")
        with pytest.raises(RequestError, match="happens twice"):
            read_instant("2026-11-01T01:30")
        assert read_instant("2026-03-08T03:30") == dt.datetime(2026, 3, 8, 7, 30, tzinfo=UTC)
    finally:
        monkeypatch.undo()
        time.tzset()
