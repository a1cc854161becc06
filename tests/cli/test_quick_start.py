"""The README's quick start, taken literally: two commands (set up and run the main job; run
the tests), after which every later `lagrade …` command of the README, and every command the
demo prints as its next step, runs as written. `.ci/run` runs the README's own test command."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from lagrade.cli import demo

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _quick_start() -> list[str]:
    section = README.split("## Quick start", 1)[1]
    block = re.search(r"```sh\n(.*?)```", section, flags=re.S).group(1)
    return [ln for ln in block.splitlines() if ln.strip()]


def _steps(command: str) -> list[str]:
    return [s.strip() for s in command.split("&&")]


def test_the_quick_start_is_two_commands_setting_up_then_testing():
    setup, tests = _quick_start()
    steps = _steps(setup)
    assert steps[-1] == "lagrade demo", steps  # the main job, run last
    assert "pytest" in tests and "&&" not in tests


def test_bare_lagrade_follows_an_activation_of_the_venv():
    """Every bare `lagrade …` in the README comes after the quick start has put the installed
    `lagrade` on PATH: the venv is activated before anything calls `lagrade` or `python`."""
    steps = _steps(_quick_start()[0])
    activation = steps.index(". .venv/bin/activate")
    assert steps[0].startswith("python3 -m venv .venv") and activation == 1, steps
    assert all(not s.startswith((".venv/", "lagrade", "python ")) for s in steps[:activation])
    later = [
        ln
        for block in re.findall(r"```sh\n(.*?)```", README, flags=re.S)
        for ln in block.splitlines()
        if ln.startswith("lagrade ")
    ]
    assert later, "the README shows commands after the quick start"


@pytest.mark.skipif(not (ROOT / ".venv" / "bin" / "activate").exists(), reason="no .venv here")
def test_after_the_activation_lagrade_is_the_installed_one():
    """The quick start's own activation step, run by a shell with a bare PATH: `lagrade` and
    `python` are then the venv's (before the fix, the README never activated the venv)."""
    steps = _steps(_quick_start()[0])
    script = " && ".join(steps[1:2] + ["command -v lagrade", "command -v python"])
    found = subprocess.run(
        ["sh", "-c", script],
        cwd=ROOT,
        env={"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp")},
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    assert found == [str(ROOT / ".venv/bin/lagrade"), str(ROOT / ".venv/bin/python")]


def test_ci_runs_the_readmes_test_command():
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    tests = _quick_start()[1]
    at = ci.index(tests)
    assert ". .venv/bin/activate" in ci[:at]  # the same shell the quick start leaves


def _console_script() -> Path:
    script = Path(sys.executable).parent / "lagrade"
    if not script.is_file():
        pytest.skip("lagrade is not installed beside this interpreter")
    return script


def test_demo_hints_say_lagrade_when_it_is_on_path(monkeypatch):
    script = _console_script()
    monkeypatch.setattr(sys, "argv", [str(script), "demo"])
    monkeypatch.setenv("PATH", f"{script.parent}{os.pathsep}/usr/bin:/bin")
    assert demo.how_to_run() == "lagrade"


def test_demo_hints_name_the_script_when_lagrade_is_not_on_path(monkeypatch, tmp_path):
    """Right after the quick start in a new shell: the hints must still run as printed."""
    script = _console_script()
    monkeypatch.chdir(script.parent.parent.parent)  # the folder holding .venv
    relative = Path(os.path.relpath(script))
    monkeypatch.setattr(sys, "argv", [str(relative), "demo"])
    monkeypatch.setenv("PATH", "/usr/bin:/bin")
    hints = demo._next_steps(Path("lagrade-demo"))
    commands = [ln.split(":", 1)[1].strip() for ln in hints.splitlines() if ln.startswith("  ")]
    assert len(commands) == 4
    for command in commands:
        program = shlex.split(command)[0]
        assert program == str(relative), command
        version = subprocess.run([program, "--version"], capture_output=True, text=True)
        assert version.returncode == 0 and version.stdout.startswith("lagrade "), version


def test_demo_hints_under_python_dash_m(monkeypatch):
    monkeypatch.setattr(sys, "argv", ["/somewhere/lagrade/__main__.py", "demo"])
    assert demo.how_to_run() == f"{shlex.quote(sys.executable)} -m lagrade"
