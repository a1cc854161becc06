"""Saving on the answer page, in headless Chromium as a student meets it: three saves are
three rows of the log and `lagrade grade --as-of` grades the right one; what is typed while a
save is in flight is never marked saved; in graded mode Enter does not save and a double-click
spends one attempt; a lost connection says what to do and keeps the answers, restored on
reload; after the due date saves are refused with a sentence, or recorded as late."""

from __future__ import annotations

import datetime as dt
import json
import time

import pytest

from lagrade.cli.main import main
from lagrade.grading.savelog import SaveLog, log_path
from lagrade.grading.submission import read_sheet
from tests.serve.chromium import (
    NEEDS_CHROMIUM,
    By,
    network,
    start_browser,
    wait_for,
)
from tests.serve.conftest import generate_class, start_server, stop_server

pytestmark = NEEDS_CHROMIUM
KEYS = {1: ["dof", "lagrangian", "eom", "momenta"]}
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    driver = start_browser(tmp_path_factory.mktemp("chromium"))
    yield driver
    driver.quit()


@pytest.fixture(autouse=True)
def fast_network(browser):
    network(browser)
    yield
    network(browser)


def _open(browser, url: str) -> None:
    """Open `url` in a fresh tab (a page with unsaved answers asks before it unloads)."""
    old = browser.current_window_handle
    browser.switch_to.new_window("tab")
    if old in browser.window_handles and len(browser.window_handles) > 1:
        browser.switch_to.window(old)
        browser.close()
        browser.switch_to.window(browser.window_handles[-1])
    browser.get(url)
    wait_for(browser, lambda d: d.execute_script("return document.readyState") == "complete")


def _type(browser, field_id: str, text: str, clear: bool = True) -> None:
    field = browser.find_element(By.ID, field_id)
    if clear:
        field.send_keys(Keys.CONTROL, "a")
        field.send_keys(Keys.DELETE)
    field.send_keys(text)


def _status(browser) -> str:
    return browser.find_element(By.ID, "status").text


def _saved(browser, after: str = "") -> str:
    """Wait for the status to say a save finished (and is not `after`); return it."""
    wait_for(browser, lambda d: _status(d).startswith(("Saved at", "Not saved", "The server")))
    wait_for(browser, lambda d: _status(d) != after)
    return _status(browser)


def _save(browser) -> str:
    before = _status(browser)
    browser.find_element(By.ID, "save").click()
    return _saved(browser, before)


# --- the log and `grade --as-of` -------------------------------------------------------------


def test_three_saves_are_three_rows_and_as_of_grades_the_right_one(browser, served, tmp_path):
    _open(browser, served.url("s001"))
    for dof in ("3", "1", "2"):
        _type(browser, "p1-dof", dof)
        _type(browser, "p1-lagrangian", f"1/2 m l^2 theta_dot^2 + m g l cos(theta) + {dof}")
        assert _save(browser).startswith("Saved at")
        time.sleep(0.05)
    every = SaveLog(log_path(served.sheets), create=False).saves("s001")
    rows = every[-3:]
    assert [r.answers["1"]["dof"] for r in rows] == ["3", "1", "2"]
    assert all(r.origin == "page" and not r.late for r in rows)
    assert rows[-1].sheet == (served.sheets / "s001.toml").read_bytes()
    assert rows[0].saved_at < rows[1].saved_at < rows[2].saved_at
    between = rows[1].saved_at + (rows[2].saved_at - rows[1].saved_at) / 2
    out = tmp_path / "grades"
    status = main(
        ["grade", str(served.manifest), str(served.sheets), "--out", str(out),
         "--as-of", between.isoformat()]
    )  # fmt: skip
    assert status in (0, 1)  # 1: the other students have no save before then
    result = json.loads((out / "students" / "s001.json").read_text())
    dof = next(p for p in result["problems"][0]["parts"] if p["key"] == "dof")
    assert dof["verdict"] == "correct"  # the second save, dof = 1; the first and third are wrong
    main(["grade", str(served.manifest), str(served.sheets), "--out", str(out),
          "--as-of", (every[0].saved_at - dt.timedelta(seconds=1)).isoformat()])  # fmt: skip
    before = json.loads((out / "students" / "s001.json").read_text())
    assert before["status"] == "missing" and "nothing was saved by" in before["reason"]


# --- edits typed while a save is in flight ---------------------------------------------------


def test_typing_during_a_slow_save_stays_unsaved_and_is_kept(browser, served):
    _open(browser, served.url("s002"))
    _type(browser, "p1-lagrangian", "m l^2 theta_dot^2/2")
    network(browser, latency_ms=1500)
    browser.find_element(By.ID, "save").click()
    _type(browser, "p1-lagrangian", " + m g l cos(theta)", clear=False)  # while it is in flight
    said = _saved(browser)
    network(browser)
    # the old page said "Saved at …" and forgot the edit: closing the tab lost it silently
    assert "press Save again" in said, said
    assert "unsaved" in browser.find_element(By.ID, "status").get_attribute("class")
    sheet = read_sheet(served.sheets / "s002.toml", "s002", 1, KEYS)
    assert sheet.answers[1]["lagrangian"] == "m l^2 theta_dot^2/2"  # what was sent, no more
    draft = browser.execute_script(
        "return JSON.parse(localStorage.getItem('lagrade-draft:' + document.body.dataset.base))"
    )
    assert draft["answers"]["1"]["lagrangian"] == "m l^2 theta_dot^2/2 + m g l cos(theta)"
    assert "press Save again" not in _save(browser)
    sheet = read_sheet(served.sheets / "s002.toml", "s002", 1, KEYS)
    assert sheet.answers[1]["lagrangian"] == "m l^2 theta_dot^2/2 + m g l cos(theta)"
    assert (
        browser.execute_script(
            "return localStorage.getItem('lagrade-draft:' + document.body.dataset.base)"
        )
        is None
    )  # everything typed is saved: nothing left to restore


# --- a lost connection ------------------------------------------------------------------------


def test_a_lost_connection_says_what_to_do_and_the_answers_come_back(browser, served):
    _open(browser, served.url("s003"))
    network(browser, offline=True)
    _type(browser, "p1-momenta", "p_theta = m l^2 theta_dot")
    browser.find_element(By.ID, "save").click()
    said = _saved(browser)
    assert said.startswith("The server could not be reached, so nothing was saved")
    assert "kept in this browser" in said and "press Save again" in said
    assert "Failed to fetch" not in said
    network(browser)
    _open(browser, served.url("s003"))  # the tab closed, opened again
    notice = browser.find_element(By.ID, "draft-notice")
    assert notice.is_displayed() and "Restored the answers you typed" in notice.text
    field = browser.find_element(By.ID, "p1-momenta")
    assert field.get_attribute("value") == "p_theta = m l^2 theta_dot"
    assert _status(browser) == "Unsaved changes."
    assert _save(browser).startswith("Saved at")
    sheet = read_sheet(served.sheets / "s003.toml", "s003", 1, KEYS)
    assert sheet.answers[1]["momenta"] == "p_theta = m l^2 theta_dot"


# --- graded mode: one press, at most one attempt ---------------------------------------------


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    root = tmp_path_factory.mktemp("graded")
    manifest = generate_class(root, "[answer_page]\nfeedback = true\nattempts = 3\n")
    server = start_server(root, manifest)
    yield server
    assert stop_server(server) == 0


def test_enter_and_a_double_click_spend_one_attempt(browser, graded):
    _open(browser, graded.url("s001"))
    network(browser, latency_ms=800)
    _type(browser, "p1-dof", "1")
    browser.find_element(By.ID, "p1-dof").send_keys(Keys.ENTER)  # does not save
    time.sleep(2.5)
    assert _status(browser) == "Unsaved changes."
    button = browser.find_element(By.ID, "save")
    ActionChains(browser).double_click(button).perform()
    assert button.get_attribute("aria-disabled") == "true"  # while the save is in flight
    ActionChains(browser).click(button).perform()
    browser.find_element(By.ID, "p1-dof").send_keys(Keys.ENTER)
    said = _saved(browser)
    network(browser)
    assert said.startswith("Saved at"), said
    wait_for(browser, lambda d: "left: 2" in d.find_element(By.ID, "attempts").text)
    time.sleep(1.5)  # any second request would have arrived by now
    log = SaveLog(log_path(graded.sheets), create=False)
    assert len(log.saves("s001")) == 1 and log.attempts_used("s001") == 1
    assert button.get_attribute("aria-disabled") == "false"
    feedback = browser.find_element(By.ID, "p1-dof-feedback")
    assert "1 / 1 points" in feedback.text
    # the same answers again: their feedback again, no attempt spent
    _save(browser)
    assert "no attempt spent" in _status(browser)
    assert log.attempts_used("s001") == 1


# --- the due date -----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def past_due(tmp_path_factory):
    """Two servers of one class whose due date has passed: one takes no late work, one does."""
    servers = {}
    due = (dt.datetime.now(dt.UTC) - dt.timedelta(hours=1)).replace(microsecond=0)
    for name, late in (("closed", ""), ("late", "[answer_page]\nlate = true\n")):
        root = tmp_path_factory.mktemp(name)
        manifest = generate_class(root, late, top=f"due = {due.isoformat()}")
        servers[name] = start_server(root, manifest)
    yield servers
    for server in servers.values():
        assert stop_server(server) == 0


def test_after_the_due_date_a_save_is_refused_with_a_sentence(browser, past_due):
    server = past_due["closed"]
    _open(browser, server.url("s001"))
    notice = browser.find_element(By.ID, "due-notice").text
    assert "has passed" in notice and "saving is closed" in notice
    assert not browser.find_element(By.ID, "save").is_enabled()
    _type(browser, "p1-dof", "1")
    browser.execute_script("document.getElementById('save').disabled = false")  # a stale page
    said = _save(browser)
    assert said.startswith("Not saved: The due date") and "takes no late work" in said
    assert not (server.sheets / "s001.toml").exists()
    assert SaveLog(log_path(server.sheets), create=False).saves("s001") == []


def test_after_the_due_date_a_late_save_is_recorded_as_late(browser, past_due):
    server = past_due["late"]
    _open(browser, server.url("s001"))
    notice = browser.find_element(By.ID, "due-notice").text
    assert "has passed" in notice and "recorded as late" in notice
    _type(browser, "p1-dof", "1")
    said = _save(browser)
    assert said.startswith("Saved at") and "Recorded as late" in said
    (row,) = SaveLog(log_path(server.sheets), create=False).saves("s001")
    assert row.late
    assert b"late (after the due date)" in (server.sheets / "s001.toml").read_bytes()
