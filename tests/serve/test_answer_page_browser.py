"""The answer page in a real browser: headless Chromium (Debian's chromium and
chromium-driver) driven by selenium opens a student's private link, types answers in several
notations, sees each preview typeset, saves, and the sheet is on disk as `grade` reads it.
Skipped, saying why, where Chromium or its driver is not installed (`.ci/run` installs both)."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.grading.submission import read_sheet

webdriver = pytest.importorskip("selenium.webdriver")
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support import expected_conditions as ec  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

from tests.serve.chromium import CHROMIUM, DRIVER, start_browser  # noqa: E402

pytestmark = pytest.mark.skipif(
    not (CHROMIUM and DRIVER),
    reason="needs Debian's chromium and chromium-driver (apt-get install chromium-driver)",
)
SCREENSHOTS = Path(__file__).resolve().parents[2] / "build" / "screenshots"


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    driver = start_browser(tmp_path_factory.mktemp("chromium"), hide_scrollbars=False)
    yield driver
    driver.quit()


def _type(driver, field_id: str, text: str) -> None:
    field = driver.find_element(By.ID, field_id)
    field.clear()
    field.send_keys(text)


def _preview(driver, field_id: str, what: str):
    """Wait until the field's preview shows `what` ("math" or "error") and return the box."""
    box = driver.find_element(By.ID, f"{field_id}-preview")
    selector = "math" if what == "math" else "pre.error"
    WebDriverWait(driver, 30).until(
        lambda d: (
            box.find_elements(By.CSS_SELECTOR, selector)
            and "busy" not in box.get_attribute("class")
        )
    )
    return box


def test_student_types_previews_and_saves(browser, served):
    browser.get(served.url("s002"))
    assert "Emmy Noether" in browser.page_source
    _type(browser, "p1-lagrangian", "1/2 m l^2 theta_dot^2 + m g l cos(theta)")
    box = _preview(browser, "p1-lagrangian", "math")
    assert "Read as" in box.text
    _type(browser, "p1-eom", "m l^2 (theta_ddot = 0")
    error = _preview(browser, "p1-eom", "error")
    assert "missing" in error.text and error.text.rstrip().endswith("^")  # the caret
    _type(browser, "p1-eom", r"m l^2 \ddot{\theta} + m g l \sin{\theta} = 0")
    _preview(browser, "p1-eom", "math")
    _type(browser, "p1-momenta", "p_theta = m l^2 θ̇")
    _preview(browser, "p1-momenta", "math")
    _type(browser, "p1-dof", "(1")
    error = _preview(browser, "p1-dof", "error")
    assert "whole number" in error.text
    _type(browser, "p1-dof", "1")
    dof = browser.find_element(By.ID, "p1-dof-preview")
    WebDriverWait(browser, 30).until(lambda d: dof.text.startswith("Read as"))
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SCREENSHOTS / "answer_page_typed.png"))
    browser.find_element(By.ID, "save").click()
    WebDriverWait(browser, 30).until(
        ec.text_to_be_present_in_element((By.ID, "status"), "Saved at")
    )
    keys = {1: ["dof", "lagrangian", "eom", "momenta"]}
    sheet = read_sheet(served.sheets / "s002.toml", "s002", 1, keys)
    assert sheet.readable
    assert sheet.answers[1] == {
        "dof": "1",
        "lagrangian": "1/2 m l^2 theta_dot^2 + m g l cos(theta)",
        "eom": r"m l^2 \ddot{\theta} + m g l \sin{\theta} = 0",
        "momenta": "p_theta = m l^2 θ̇",
    }
    browser.refresh()  # the saved answers come back in the fields
    assert browser.find_element(By.ID, "p1-dof").get_attribute("value") == "1"
    _preview(browser, "p1-lagrangian", "math")
    browser.save_screenshot(str(SCREENSHOTS / "answer_page_reloaded.png"))


def test_wrong_token_shows_nothing(browser, served):
    token = served.url("s001").rsplit("/", 1)[1]
    browser.get(f"{served.base}/s/{token[::-1]}")
    assert browser.find_element(By.TAG_NAME, "body").text == "Not found."


def test_the_preview_shows_the_parsers_notes_right_or_wrong(browser, served):
    """The notes on a reading the student may not have meant, under the preview, whatever the
    verdict: (g/2)·l, a mixed number, a LaTeX run of letters split into names."""
    browser.get(served.url("s002"))  # s002's coordinate is theta
    cases = {
        "p1-eom": ("theta_ddot + g/2l sin(theta) = 0", "g/2l is read as (g/2)*l"),
        "p1-lagrangian": (
            r"\frac{1}{2} ml^2 \dot{\theta}^2 + mgl\cos\theta",  # right, as written
            "mgl is read as m*g*l",
        ),
        "p1-momenta": ("p_theta = m l^2 theta_dot + 2½ - 2½", "2½ is read as the mixed number"),
    }
    for field_id, (text, note) in cases.items():
        _type(browser, field_id, text)
        box = _preview(browser, field_id, "math")
        WebDriverWait(browser, 30).until(lambda d, b=box, n=note: n in b.text)
        notes = [p.text for p in box.find_elements(By.CSS_SELECTOR, "p.note")]
        assert any(n.startswith("Note: ") and note in n for n in notes), notes
    # the LaTeX Lagrangian is right: the note is about the reading, not the verdict
    from lagrade.judge import check

    verdict = check({"scene": "simple_pendulum"}, "lagrangian", cases["p1-lagrangian"][0])
    assert verdict.status == "correct" and not any("mgl" in f for f in verdict.feedback)
