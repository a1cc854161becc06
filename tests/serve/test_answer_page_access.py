"""WCAG 2.1 AA on the answer page and the feedback pages, in headless Chromium: axe-core finds
no violation in any state the page takes (typed answers with previews, notes and a parser's
caret, graded feedback, a restored draft; at desktop and phone width), and the checks axe
cannot make: every formula and figure has a text alternative (a field's name keeps its
formula: "which exists when omega^2 R > g", not "which exists when >"), the fixed save bar
never hides the focused element (WCAG 2.2 2.4.11), nothing scrolls sideways at 320 and 390 CSS
px but boxes that a keyboard reaches, field borders reach 3:1 and figure labels 4.5:1, math
fields do not capitalise or correct. Screenshots at phone width go to build/screenshots/."""

from __future__ import annotations

import re
import time

import pytest

from lagrade.cli.main import main
from tests.serve.chromium import (
    NEEDS_CHROMIUM,
    By,
    accessible_names,
    axe_violations,
    desktop,
    phone,
    screenshot,
    sideways_overflow,
    start_browser,
    wait_for,
)
from tests.serve.conftest import generate_class, post, start_server, stop_server

pytestmark = NEEDS_CHROMIUM
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

ASSIGNMENT = """\
title = "Access test"
points = 1

[[problems]]
scene = "hoop"
parts = ["dof", "lagrangian", "eom", "conserved", { quantity = "equilibrium_angle" }]

[[problems]]
scene = "kepler"
parts = ["lagrangian", "momenta", { quantity = "circular_angular_velocity" }]

[answer_page]
feedback = true
"""
LONG_L = (
    "1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta) "
    "+ 1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta)"
)
UNREADABLE_LINE = "theta_ddot = omega^2 sin(theta) cos(theta) - g/R sin(theta) + ((((((((((x"
TYPED = {
    "p1-dof": "1",
    "p1-lagrangian": LONG_L,
    "p1-eom": "m R^2 theta_ddot = m R^2 omega^2 sin(theta) cos(theta) - m g R sin(theta)\n"
    + UNREADABLE_LINE * 2,
    "p1-conserved": "theta_dot^2 - omega^2 sin(theta)^2 - 2 g/2R cos(theta)",
    "p2-lagrangian": r"\frac{1}{2} m (\dot{r}^2 + r^2 \dot{\theta}^2) + GMm/r",
}


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    root = tmp_path_factory.mktemp("access")
    manifest = generate_class(root, assignment=ASSIGNMENT)
    server = start_server(root, manifest)
    yield server
    assert stop_server(server) == 0


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    driver = start_browser(tmp_path_factory.mktemp("chromium"))
    yield driver
    driver.quit()


def _load(browser, url: str, width: int | None) -> None:
    """Open `url` in a fresh tab at `width` (None: desktop); the tabs before it are closed
    (a page with unsaved answers would ask before it unloads)."""
    old = browser.window_handles
    browser.switch_to.new_window("tab")
    fresh = browser.current_window_handle
    for handle in old:
        browser.switch_to.window(handle)
        browser.close()
    browser.switch_to.window(fresh)
    if width is None:
        desktop(browser)
    else:
        phone(browser, width, 700)
    browser.get(url)
    wait_for(browser, lambda d: d.execute_script("return document.readyState") == "complete")


def _type_all(browser) -> None:
    for field_id, text in TYPED.items():
        field = browser.find_element(By.ID, field_id)
        field.send_keys(Keys.CONTROL, "a")
        field.send_keys(Keys.DELETE)
        field.send_keys(text)
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#p1-eom-preview pre.error"))
    wait_for(browser, lambda d: not d.find_elements(By.CSS_SELECTOR, ".preview.busy"))


def _no_violations(browser, state: str) -> None:
    found = axe_violations(browser)
    assert found == [], f"{state}: " + "\n".join(f"{v['id']}: {v['nodes']}" for v in found)


# --- axe-core ----------------------------------------------------------------------------------


@pytest.mark.parametrize("width", [None, 390], ids=["desktop", "phone"])
def test_axe_finds_no_violation_in_any_state(browser, page, width):
    student = "s001" if width is None else "s002"
    _load(browser, page.url(student), width)
    _no_violations(browser, "the page as opened")
    _type_all(browser)
    _no_violations(browser, "previews, notes and a caret shown")
    browser.find_element(By.ID, "save").click()
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, ".feedback.correct"), 90)
    _no_violations(browser, "graded feedback shown")
    if width is not None:
        screenshot(browser, f"answer_page_graded_{width}")
    field = browser.find_element(By.ID, "p2-momenta")
    field.send_keys("p_r = m r_dot")  # typed, not saved: the page opened again restores it
    _load(browser, page.url(student), width)
    wait_for(browser, lambda d: d.find_element(By.ID, "draft-notice").is_displayed())
    _no_violations(browser, "a restored draft")


# --- reflow ----------------------------------------------------------------------------------


@pytest.mark.parametrize("width", [320, 390])
def test_nothing_scrolls_sideways_on_a_phone(browser, page, width):
    _load(browser, page.url("s003"), width)
    assert sideways_overflow(browser) == 0, "the page as opened"
    _type_all(browser)
    browser.find_element(By.ID, "save").click()
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, ".feedback.correct"), 90)
    assert sideways_overflow(browser) == 0, "with long previews, a caret and feedback"
    screenshot(browser, f"answer_page_{width}")


def test_boxes_that_scroll_sideways_are_reached_by_keyboard(browser, page):
    _load(browser, page.url("s003"), 320)
    _type_all(browser)
    boxes = browser.execute_script(
        """return Array.from(document.querySelectorAll('.scroller, .preview .math, pre'))
             .filter(b => b.scrollWidth > b.clientWidth + 1)
             .map(b => [b.tabIndex, b.getAttribute('aria-label') || '', b.id]);"""
    )
    assert len(boxes) >= 2, boxes  # the long L's reading, the caret's message (at least)
    assert all(tab == 0 and label for tab, label, _ in boxes), boxes
    error = browser.find_element(By.CSS_SELECTOR, "#p1-eom-preview pre.error")
    for _ in range(60):  # Tab from the eom field until the message box has the focus
        ActionChains(browser).send_keys(Keys.TAB).perform()
        if browser.switch_to.active_element == error:
            break
    assert browser.switch_to.active_element == error
    ActionChains(browser).send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT).perform()
    wait_for(browser, lambda d: d.execute_script("return arguments[0].scrollLeft", error) > 0, 5)


# --- the save bar and the focus ----------------------------------------------------------------


def test_the_save_bar_never_hides_the_focus(browser, page):
    _load(browser, page.url("s003"), 390)
    _type_all(browser)
    browser.execute_script("window.scrollTo(0, 0); document.querySelector('summary').focus()")
    seen = []
    for _ in range(200):
        ActionChains(browser).send_keys(Keys.TAB).perform()
        where = browser.execute_script(
            """const el = document.activeElement, bar = document.querySelector('.savebar');
               if (el === document.body) return null;
               const r = el.getBoundingClientRect();
               return [el.id || el.tagName, r.top, r.bottom, bar.getBoundingClientRect().top,
                       bar.contains(el), window.innerHeight];"""
        )
        if where is None or (seen and where[0] == seen[0][0]):
            break
        seen.append(where)
        name, top, bottom, bar_top, in_bar, _height = where
        if not in_bar:
            assert top >= -1 and bottom <= bar_top + 1, f"{name} is under the save bar: {where}"
    reached = {where[0] for where in seen}
    fields = {f.get_attribute("id") for f in browser.find_elements(By.CSS_SELECTOR, ".answer")}
    assert fields | {"save"} <= reached, seen  # every field and the save button
    # typing into the last field of a problem: its preview appears above the bar too
    field = browser.find_element(By.ID, "p2-circular_angular_velocity")
    field.send_keys("(G M/a^3)^(1/2) +* 2")
    box = browser.find_element(By.ID, "p2-circular_angular_velocity-preview")
    wait_for(browser, lambda d: box.find_elements(By.CSS_SELECTOR, "pre.error"))
    time.sleep(0.3)
    bottom, bar_top = browser.execute_script(
        "return [arguments[0].getBoundingClientRect().bottom,"
        " document.querySelector('.savebar').getBoundingClientRect().top]",
        box,
    )
    assert bottom <= bar_top + 1


# --- what axe cannot check -----------------------------------------------------------------


def test_formulas_and_figures_have_text_alternatives(browser, page):
    _load(browser, page.url("s001"), None)
    names = accessible_names(browser, "textbox")
    angle = next(n for n in names if "equilibrium angle" in n)
    assert "which exists when omega^2 R > g" in angle, angle  # was "which exists when > :"
    orbit = next(n for n in names if "circular orbit" in n)
    assert re.search(r"orbit of radius a\b", orbit), orbit
    figures = accessible_names(browser, "image")
    assert len(figures) == 2, figures
    assert figures[0].startswith("Figure of problem 1, Bead on a rotating hoop")
    assert re.search(r"labelled R, (theta|phi), omega, m, g\b", figures[0]), figures[0]


def _ratio(first: str, second: str) -> float:
    def luminance(colour: str) -> float:
        channels = [int(c) / 255 for c in re.findall(r"\d+", colour)[:3]]
        linear = [c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]
        return 0.2126 * linear[0] + 0.7152 * linear[1] + 0.0722 * linear[2]

    high, low = sorted((luminance(first), luminance(second)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def test_field_borders_and_figure_labels_contrast(browser, page):
    _load(browser, page.url("s001"), None)
    borders = browser.execute_script(
        "return Array.from(document.querySelectorAll('.answer')).map(f =>"
        " [getComputedStyle(f).borderTopColor, getComputedStyle(document.body).backgroundColor])"
    )
    assert borders and all(_ratio(*pair) >= 3.0 for pair in borders), borders
    labels = browser.execute_script(
        "return Array.from(document.querySelectorAll('figure svg text')).map(t =>"
        " getComputedStyle(t).fill)"
    )
    assert labels, "the figures' labels are text"
    ratios = {fill: _ratio(fill, "rgb(255, 255, 255)") for fill in labels}
    assert all(r >= 4.5 for r in ratios.values()), ratios  # the axes' grey was 3.45:1


def test_math_fields_do_not_capitalise_or_correct(browser, page):
    _load(browser, page.url("s001"), None)
    fields = browser.find_elements(By.CSS_SELECTOR, ".answer")
    assert fields
    for field in fields:
        assert field.get_dom_attribute("autocapitalize") == "off"
        assert field.get_dom_attribute("autocorrect") == "off"
        assert field.get_dom_attribute("spellcheck") == "false"


# --- the feedback pages -------------------------------------------------------------------------


@pytest.fixture(scope="module")
def feedback_pages(page, tmp_path_factory):
    """`grade` over a sheet saved on the page: a long reading, a caret, feedback."""
    answers = {}
    for field_id, text in TYPED.items():
        problem, key = field_id[1:].split("-", 1)
        answers.setdefault(problem, {})[key] = text
    status, reply = post(page.url("s003") + "/save", {"answers": answers}, timeout=120)
    assert status == 200, reply
    out = tmp_path_factory.mktemp("grades")
    main(["grade", str(page.manifest), str(page.sheets), "--out", str(out)])
    return out / "feedback"


@pytest.mark.parametrize("width", [None, 320, 390], ids=["desktop", "320", "390"])
def test_feedback_pages_meet_wcag_at_every_width(browser, page, feedback_pages, width):
    html = (feedback_pages / "s003.html").read_text()
    assert '<meta name="viewport" content="width=device-width, initial-scale=1">' in html
    _load(browser, (feedback_pages / "s003.html").as_uri(), width)
    assert browser.find_elements(By.CSS_SELECTOR, "pre.source[tabindex='0']")  # the caret
    _no_violations(browser, f"feedback page at {width or 'desktop'}")
    assert sideways_overflow(browser) == 0
    if width is not None:
        screenshot(browser, f"feedback_page_{width}")
