"""Issue 24: `export prairielearn` writes server.py as fixed code holding data. A problem title is
a value (`TITLE = '…'`), never text spliced into code: a title with `\"\"\"` ran as Python on the
PrairieLearn server, one with `\\u` or `\\N{` (`see \\underline{notes}`) was a SyntaxError.

Each exported server.py is loaded the way PrairieLearn loads it (a module from the file) and its
generate/parse/grade are called with PrairieLearn's `data` dictionaries; info.json is read back
as strict JSON and the folder names stay plain."""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.assign.templating import toml_string
from lagrade.bank import scene_ids
from lagrade.cli.main import main
from lagrade.grading.prairielearn import export_prairielearn

from .test_prairielearn import new_data

#: Titles an instructor might type, innocently or not (each a failure of the old export).
HOSTILE_TITLES = {
    "triple double quotes": 'a """ + __import__("os").system("touch PWNED") + """ b',
    "triple single quotes": "a ''' + __import__('os').system('touch PWNED') + ''' b",
    "backslash u": r"see \underline{notes}",
    "backslash N": r"\N{GREEK SMALL LETTER ALPHA} and \N{",
    "backslash x": r"\x41 \xZZ",
    "trailing backslash": "ends with \\",
    "quotes": """it's "quoted" """,
    "control characters": "bell\x07 escape\x1b[2J nul\x00 del\x7f",
    "line separators": "one\u2028two\u2029three\x85four",
    "lone newline": "first line\nsecond line",
    "carriage return": "a\rb",
    "non-ASCII": "Đặng Thị Ngọc Hà, 王小明, Αλέξανδρος",
}


def assignment_with_title(path: Path, problem_title: str, scene: str = "simple_pendulum") -> Path:
    path.write_text(
        f"title = {toml_string(problem_title)}\n\n[[problems]]\nscene = {toml_string(scene)}\n"
        f"title = {toml_string(problem_title)}\n"
        'parts = ["dof", "lagrangian", "eom"]\nvariants = 2\n',
        encoding="utf-8",
    )
    return path


def load_module(server: Path):
    """server.py as PrairieLearn loads it: a module executed from the file."""
    name = "pl_" + re.sub(r"\W", "_", str(server.parent))
    spec = importlib.util.spec_from_file_location(name, server)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def strict_json(path: Path):
    def refuse(constant):
        raise ValueError(f"{constant} is not JSON")

    return json.loads(path.read_bytes().decode("utf-8"), parse_constant=refuse)


@pytest.mark.parametrize("title", HOSTILE_TITLES.values(), ids=HOSTILE_TITLES.keys())
def test_a_hostile_title_is_data_and_the_question_loads_and_grades(tmp_path, title, monkeypatch):
    monkeypatch.chdir(tmp_path)  # where an injected `touch PWNED` would leave its mark
    source = assignment_with_title(tmp_path / "a.toml", title)
    (folder,) = export_prairielearn(source, 5, tmp_path / "questions")
    assert re.fullmatch(r"[a-z0-9_-]+", folder.name), folder.name
    info = strict_json(folder / "info.json")
    assert info["title"] == title and info["type"] == "v3"

    server = load_module(folder / "server.py")
    assert server.TITLE == title
    assert not (tmp_path / "PWNED").exists()
    data = new_data(11)
    server.generate(data)
    assert data["params"]["seed"] in server.SEEDS
    data["submitted_answers"] = {"dof": "1", "lagrangian": "1/2 m (l theta_dot^2", "eom": ""}
    data["format_errors"] = {}
    server.parse(data)
    assert set(data["format_errors"]) == {"lagrangian"}
    data = {**data, "submitted_answers": {"dof": "1"}, "partial_scores": {}}
    server.grade(data)
    assert data["partial_scores"]["dof"]["score"] == 1.0
    json.dumps(data, allow_nan=False)  # PrairieLearn stores data as JSON
    assert not (tmp_path / "PWNED").exists()


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(title=st.text(st.characters(exclude_categories=["Cs"]), min_size=1, max_size=40))
def test_any_title_exports_a_server_py_that_loads_with_that_title(tmp_path_factory, title):
    root = tmp_path_factory.mktemp("pl-any")
    source = assignment_with_title(root / "a.toml", title)
    (folder,) = export_prairielearn(source, 1, root / "questions")
    assert re.fullmatch(r"[a-z0-9_-]+", folder.name)
    assert strict_json(folder / "info.json")["title"] == title
    server = load_module(folder / "server.py")
    assert server.TITLE == title
    assert server.ASSIGNMENT == source.read_text(encoding="utf-8")


def test_the_export_of_every_bank_scene_loads_and_runs(tmp_path):
    lines = ['title = "Every scene"']
    for scene in scene_ids():
        lines += [
            "",
            "[[problems]]",
            f"scene = {toml_string(scene)}",
            'parts = ["dof", "lagrangian"]',
        ]
        lines.append("variants = 2")
    (tmp_path / "bank.toml").write_text("\n".join(lines) + "\n", encoding="utf-8")
    folders = export_prairielearn(tmp_path / "bank.toml", 7, tmp_path / "questions")
    assert len(folders) == len(scene_ids())
    for folder in folders:
        assert re.fullmatch(r"[a-z0-9_-]+", folder.name)
        strict_json(folder / "info.json")
        server = load_module(folder / "server.py")
        data = new_data(3)
        server.generate(data)
        data["submitted_answers"] = {"dof": "1", "lagrangian": ""}
        data["format_errors"], data["partial_scores"] = {}, {}
        server.parse(data)
        server.grade(data)
        assert set(data["partial_scores"]) == {"dof", "lagrangian"}, folder.name
        assert 0.0 <= data["score"] <= 1.0


def test_a_manifest_nested_100000_deep_is_one_line_and_exit_2(tmp_path, capsys):
    """The manifest is read by the untrusted-input rules (json.loads recursed: a traceback)."""
    (tmp_path / "manifest.json").write_text("[" * 100_000 + "]" * 100_000)
    status = main(["export", "prairielearn", str(tmp_path / "manifest.json"), "--out", "q"])
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1 and "nests more than 64 deep" in err
