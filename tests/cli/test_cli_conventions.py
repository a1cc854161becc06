"""The command line's conventions, as a newcomer meets them: `--version`; usage errors in one
line (the README promises `lagrade: error: …`); messages that name the flags the user typed,
not the JSON fields behind them; arguments no run could use refused up front; swapped
arguments named as swapped."""

from __future__ import annotations

import subprocess
import sys
from importlib.metadata import version

import pytest

from lagrade.cli.main import EXIT_BAD_INPUT, main


def _run(argv: list[str], capfd) -> tuple[int, str, str]:
    try:
        status = main(argv)
    except SystemExit as stop:  # argparse's own exits (--version, usage errors)
        status = stop.code
    out, err = capfd.readouterr()
    return status, out, err


def test_version_prints_the_installed_version(capfd):
    status, out, _ = _run(["--version"], capfd)
    assert status == 0 and out.strip() == f"lagrade {version('lagrade')}"


@pytest.mark.parametrize(
    "argv",
    [
        [],
        ["no-such-command"],
        ["check", "--part", "bogus"],
        ["bank", "show"],
        ["grade", "ps3/manifest.json"],
        ["generate", "a.toml", "--seed", "x"],
    ],
    ids=["no command", "unknown command", "bad choice", "missing argument", "one of two", "int"],
)
def test_a_usage_error_is_one_line(argv, capfd):
    status, out, err = _run(argv, capfd)
    assert status == EXIT_BAD_INPUT and out == ""
    assert err.count("\n") == 1 and err.startswith("lagrade: error: "), err
    assert "--help" in err  # where the usage is, instead of the usage block itself


def test_an_adhoc_lagrangian_without_parameters_points_to_the_flag(capfd):
    argv = ["check", "--lagrangian", "1/2 m x_dot^2", "--coordinates", "x", "--part", "eom"]
    status, _, err = _run([*argv, "--answer", "m x_ddot = 0"], capfd)
    assert status == EXIT_BAD_INPUT
    assert "Unknown symbol 'm'" in err and "--parameters" in err, err
    assert '"lagrangian"' not in err and "--lagrangian" in err, err


def test_parse_points_to_the_flags_for_an_undeclared_name(capfd):
    status, out, _ = _run(["parse", "m g", "--coordinates", "x"], capfd)
    assert status == 1 and "Unknown symbol 'm'" in out and "--parameters" in out, out


def test_errors_name_flags_not_json_fields(capfd):
    status, _, err = _run(
        ["check", "--lagrangian", "x_dot^2", "--part", "eom", "--answer", "x"], capfd
    )
    assert status == EXIT_BAD_INPUT and "--coordinates" in err and '"coordinates"' not in err, err
    status, _, err = _run(
        ["check", "--expression", " ", "--part", "expression", "--answer", "1"], capfd
    )
    assert status == EXIT_BAD_INPUT and "--expression" in err and '"expression"' not in err, err


def test_a_json_request_still_names_its_fields():
    from lagrade.errors import RequestError
    from lagrade.judge.problem import build_problem

    with pytest.raises(RequestError, match='"coordinates"'):
        build_problem({"lagrangian": "x_dot^2"})
    with pytest.raises(RequestError, match='"parameters"'):
        build_problem({"lagrangian": "m x_dot^2", "coordinates": ["x"]})


@pytest.mark.parametrize("command", ["grade", "check", "serve", "demo"])
@pytest.mark.parametrize("jobs", ["0", "-2", "two"])
def test_jobs_must_be_at_least_one(command, jobs, capfd, tmp_path):
    argv = {
        "grade": ["grade", "m.json", "subs"],
        "check": ["check", "--batch", "r.jsonl"],
        "serve": ["serve", "m.json", "--submissions", "s"],
        "demo": ["demo", str(tmp_path / "demo")],
    }[command]
    status, _, err = _run([*argv, "--jobs", jobs], capfd)
    assert status == EXIT_BAD_INPUT and "--jobs" in err, err
    assert not (tmp_path / "demo").exists()  # refused before anything ran


@pytest.mark.parametrize("limit", ["0", "-1", "nan", "inf"])
def test_time_limits_must_be_positive_seconds(limit, capfd):
    status, _, err = _run(["grade", "m.json", "subs", "--part-time-limit", limit], capfd)
    assert status == EXIT_BAD_INPUT and "--part-time-limit" in err, err


def test_swapped_grade_arguments_are_named_as_swapped(tmp_path, capfd):
    manifest_dir = tmp_path / "ps3"
    manifest_dir.mkdir()
    (manifest_dir / "manifest.json").write_text("{}")
    submissions = tmp_path / "submissions"
    submissions.mkdir()
    status, _, err = _run(["grade", str(submissions), str(manifest_dir / "manifest.json")], capfd)
    assert status == EXIT_BAD_INPUT
    assert "does not exist" not in err and "manifest comes first" in err, err


def test_a_missing_submissions_folder_still_does_not_exist(tmp_path, capfd):
    status, _, err = _run(["grade", str(tmp_path / "m.json"), str(tmp_path / "nowhere")], capfd)
    assert status == EXIT_BAD_INPUT and "does not exist" in err, err


def test_the_console_script_prints_the_version():
    out = subprocess.run(
        [sys.executable, "-m", "lagrade", "--version"], capture_output=True, text=True
    )
    assert out.returncode == 0 and out.stdout.startswith("lagrade "), out


def test_help_and_readme_name_what_the_commands_do(capfd):
    """`generate`'s default formats are one value, said alike by --help and the README (Markdown,
    HTML and their LaTeX source); `demo --help` names its folder DIR, as the README's
    `lagrade demo [DIR]` does, in the usage line and the description alike."""
    from pathlib import Path

    from lagrade.assign.generation import DEFAULT_FORMATS

    status, out, _ = _run(["generate", "--help"], capfd)
    assert status == 0
    assert f"(default {','.join(DEFAULT_FORMATS)}:" in " ".join(out.split())
    readme = " ".join((Path(__file__).parents[2] / "README.md").read_text().split())
    assert "Markdown, HTML and their LaTeX source by default" in readme
    assert DEFAULT_FORMATS == ("md", "html", "tex")
    status, out, _ = _run(["demo", "--help"], capfd)
    assert status == 0 and "[DIR]" in out and "In DIR:" in out and "FOLDER" not in out
    assert "`lagrade demo [DIR]`" in readme
