"""Headless Chromium for the answer page's browser tests: a driver (selenium and Debian's
chromium-driver), phone widths by device emulation, network conditions (a slow save, a lost
connection), the accessibility tree, and axe-core.

axe-core (Deque's accessibility engine, MPL-2.0) is not part of the repository: it is
installed with npm into `build/axe-core/` (git-ignored) the first time a test needs it, at the
pinned version, or read from `LAGRADE_AXE_CORE` (a path to `axe.min.js`). Without npm and
without that file the axe tests skip, saying why."""

from __future__ import annotations

import base64
import os
import shutil
import subprocess
from pathlib import Path

import pytest

webdriver = pytest.importorskip("selenium.webdriver")
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")
NEEDS_CHROMIUM = pytest.mark.skipif(
    not (CHROMIUM and DRIVER),
    reason="needs Debian's chromium and chromium-driver (apt-get install chromium-driver)",
)
REPOSITORY = Path(__file__).resolve().parents[2]
SCREENSHOTS = REPOSITORY / "build" / "screenshots"
AXE_VERSION = "4.14.1"
AXE_FOLDER = REPOSITORY / "build" / "axe-core"
#: What WCAG 2.1 AA asks, as axe-core tags its rules.
WCAG_21_AA = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]

__all__ = ["By", "WebDriverWait"]


def start_browser(profile: Path, hide_scrollbars: bool = True):
    """A headless Chromium with a profile of its own (localStorage lives there). Scrollbars are
    hidden as a phone's overlay ones take no width; `hide_scrollbars=False` shows them, as a
    desktop browser does (a screenshot then shows a box that scrolls)."""
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-dev-shm-usage",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--no-first-run",
        "--window-size=1100,1400",
        f"--user-data-dir={profile}",
        *(["--hide-scrollbars"] if hide_scrollbars else []),
    ):
        options.add_argument(flag)
    return webdriver.Chrome(options=options, service=Service(DRIVER))


def phone(driver, width: int, height: int = 800) -> None:
    """Lay the page out as a phone `width` CSS px wide (a mobile viewport: the meta viewport
    tag counts, as on a real phone)."""
    driver.execute_cdp_cmd(
        "Emulation.setDeviceMetricsOverride",
        {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": True},
    )


def desktop(driver) -> None:
    driver.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})


def network(driver, *, latency_ms: float = 0, offline: bool = False) -> None:
    """Slow every request by `latency_ms`, or cut the connection."""
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd(
        "Network.emulateNetworkConditions",
        {
            "offline": offline,
            "latency": latency_ms,
            "downloadThroughput": -1,
            "uploadThroughput": -1,
        },
    )


def sideways_overflow(driver) -> int:
    """How many CSS px the page scrolls sideways (0: it reflows)."""
    return driver.execute_script(
        "return document.documentElement.scrollWidth - document.documentElement.clientWidth"
    )


def screenshot(driver, name: str) -> Path:
    """The whole page (not just the viewport) as build/screenshots/<name>.png."""
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    size = driver.execute_script(
        "return [document.documentElement.clientWidth, document.documentElement.scrollHeight]"
    )
    shot = driver.execute_cdp_cmd(
        "Page.captureScreenshot",
        {
            "captureBeyondViewport": True,
            "clip": {"x": 0, "y": 0, "width": size[0], "height": min(size[1], 8000), "scale": 1},
        },
    )
    path = SCREENSHOTS / f"{name}.png"
    path.write_bytes(base64.b64decode(shot["data"]))
    return path


def accessible_names(driver, role: str) -> list[str]:
    """The accessible names Chromium computed for every node of `role` ("textbox", "image")."""
    tree = driver.execute_cdp_cmd("Accessibility.getFullAXTree", {})
    return [
        node.get("name", {}).get("value", "")
        for node in tree["nodes"]
        if node.get("role", {}).get("value") == role and not node.get("ignored")
    ]


def axe_source() -> str:
    """axe-core's script (module docstring), installed on first use."""
    given = os.environ.get("LAGRADE_AXE_CORE")
    if given:
        return Path(given).read_text(encoding="utf-8")
    script = AXE_FOLDER / "node_modules" / "axe-core" / "axe.min.js"
    if not script.exists():
        npm = shutil.which("npm")
        if npm is None:
            pytest.skip("axe-core needs npm to install it (or LAGRADE_AXE_CORE=path/axe.min.js)")
        AXE_FOLDER.mkdir(parents=True, exist_ok=True)
        done = subprocess.run(
            [npm, "install", "--no-audit", "--no-fund", "--prefix", str(AXE_FOLDER),
             f"axe-core@{AXE_VERSION}"],
            capture_output=True, text=True, timeout=300,
        )  # fmt: skip
        if done.returncode != 0 or not script.exists():
            pytest.skip(f"could not install axe-core with npm: {done.stderr.strip()[-300:]}")
    return script.read_text(encoding="utf-8")


def axe_violations(driver, tags: list[str] = WCAG_21_AA) -> list[dict]:
    """axe-core run on the page as it is now: each violation's rule, impact and first nodes."""
    if not driver.execute_script("return typeof window.axe === 'object'"):
        driver.execute_script(axe_source())
    return driver.execute_async_script(
        """
        const done = arguments[arguments.length - 1];
        axe.run(document, {runOnly: {type: "tag", values: arguments[0]}}).then(function (r) {
          done(r.violations.map(function (v) {
            return {id: v.id, impact: v.impact, help: v.help,
                    nodes: v.nodes.slice(0, 5).map(function (n) {
                      return n.html.slice(0, 200) + " :: " + (n.failureSummary || "");
                    })};
          }));
        }).catch(function (e) { done([{id: "axe-error", nodes: [String(e)]}]); });
        """,
        tags,
    )


def wait_for(driver, condition, seconds: float = 30):
    return WebDriverWait(driver, seconds, poll_frequency=0.1).until(condition)
