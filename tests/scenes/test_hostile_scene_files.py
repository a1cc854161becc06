# ruff: noqa: E501 (the table holds one case per line)
"""Hostile and broken scene files: each is refused by `lagrade scene check` with exit status 2
and a message naming the problem (its key, and for an expression the parser's caret), never a
traceback, and nothing in the file is ever run. One case per line."""

from __future__ import annotations

import pathlib
import time

import pytest

from lagrade.cli.main import main
from tests.scene_texts import PENDULUM

#: (what the case plants, the file's text, a fragment the one error must hold)
CASES = [
    ("code in an expression", PENDULUM.replace('"m"', '''"__import__('os').system('touch PWNED')"'''), "mass: Unexpected character"),
    ("a call of a function that is not one", PENDULUM.replace('"m"', '"exec(m)"'), "Unknown symbol 'exec'"),
    ("a dunder name", PENDULUM.replace('"m"', '"__class__"'), "bodies.bob.mass"),
    ("an unknown name", PENDULUM.replace("l sin(theta)", "l sin(theta) + b"), "position[1]: Unknown symbol 'b'"),
    ("a body that violates a constraint", PENDULUM.replace("- l^2", "- 4 l^2"), "is not satisfied by the transformation equations"),
    ("a coordinate in no position", PENDULUM.replace('["theta"]', '["theta", "psi"]'), "'psi' appears in no position"),
    ("an inconsistent DOF", PENDULUM.replace('constraints = ["x_bob^2 + y_bob^2 - l^2"]', "constraints = []"), "3N - k gives 2 degrees of freedom"),
    ("10 MB of text", PENDULUM + "# " + "x" * 10_000_000 + "\n", "larger than 256 KiB"),
    ("brackets nested deep", PENDULUM + "deep = " + "[" * 200 + "]" * 200 + "\n", "nests more than 64 deep"),
    ("an expression nested deep", PENDULUM.replace('"m"', '"' + "(" * 80 + "m" + ")" * 80 + '"'), "mass"),
    ("a huge power", PENDULUM.replace('"m"', '"m^(10^100)"'), "Exponent too large"),
    ("a 200-digit number", PENDULUM.replace("[1.0] }\nl", "[" + "9" * 200 + "] }\nl"), "more than 100 digits"),
    ("not TOML", "title = \n", "is not valid TOML"),
    ("a velocity in a position", PENDULUM.replace("l sin(theta)", "l theta_dot"), "uses theta_dot, a velocity"),
    ("an acceleration in the potential", PENDULUM.replace('"gravity"', '"theta_ddot"'), "uses theta_ddot, an acceleration"),
    ("a Cartesian coordinate in a position", PENDULUM.replace("l sin(theta)", "x_bob"), "a body's Cartesian coordinate"),
    ("an ambiguous fraction", PENDULUM.replace("l sin(theta)", "l/2l sin(theta)"), "must be unambiguous"),
    ("a misspelt key", PENDULUM.replace("constraints =", "constrains ="), "constrains: unknown key"),
    ("a statement field that is code", PENDULUM.replace("{theta}", "{theta.__class__}"), "is not a field"),
    ("a parameter without a domain", PENDULUM.replace('domain = "positive", unit = "kg", ', 'unit = "kg", '), "parameters.m.domain: missing"),
    ("a value outside its domain", PENDULUM.replace("[1.0] }\nl", "[-1.0] }\nl"), "outside the domain positive"),
    ("bodies and a Lagrangian", 'lagrangian = "m"\n' + PENDULUM, "declares no bodies, potential or constraints"),
    ("a body named to clash", PENDULUM.replace('["theta"]', '["x_M"]').replace("theta", "x_M").replace("[bodies.bob]", "[bodies.M]"), "one name to the reader"),
    ("gravity without g", PENDULUM.replace("g = {", "G = {"), "gravity needs a parameter g"),
    ("a reserved name", PENDULUM.replace("l = {", "pi = {"), "'pi' is reserved"),
    ("choices that bind different names", PENDULUM + '[options.o.a]\nlet = { u = "1" }\n[options.o.b]\n', "every choice must bind the same names"),
    ("a domain for no coordinate", 'domains = { psi = "positive" }\n' + PENDULUM, "domains.psi: 'psi' is not a coordinate"),
    ("a domain that is code", 'domains = { theta = "__import__(1)" }\n' + PENDULUM, "domains.theta: unknown domain"),
    ("domains that are not a table", 'domains = ["positive"]\n' + PENDULUM, "domains: ['positive'] is not a table"),
    ("code in a dissipation function", 'dissipation = "exec(theta_dot)"\n' + PENDULUM, "Unknown symbol 'exec'"),
    ("a Cartesian coordinate in a dissipation function", 'dissipation = "x_bob^2"\n' + PENDULUM, "dissipation: uses x_bob"),
    ("a force along no coordinate", 'forces = { psi = "1" }\n' + PENDULUM, "forces.psi: 'psi' is not a coordinate"),
    ("a force that is a table", 'forces = { theta = { a = 1 } }\n' + PENDULUM, "forces.theta: {'a': 1} is not an expression"),
    ("a body in space with two angles", PENDULUM.replace('position = ["l sin(theta)", "-l cos(theta)"]', 'position = ["l sin(theta)", "-l cos(theta)", 0]\ninertia = ["m", "m", "m"]\nangles = ["theta", 0]'), "bodies.bob.angles: a rigid body in space declares a list of 3"),
    ("a body in space in a plane", PENDULUM.replace('position = ["l sin(theta)", "-l cos(theta)"]', 'position = ["l sin(theta)", "-l cos(theta)"]\ninertia = ["m", "m", "m"]\nangles = ["theta", 0, 0]'), "a rigid body in space: give x, y and z"),
    ("a line break in a unit", PENDULUM.replace('unit = "kg"', 'unit = "kg\\nkg"'), "parameters.m.unit: holds a line break (\\n) at character 3"),
    ("a line separator in a unit", PENDULUM.replace('unit = "kg"', 'unit = "kg\\u2028evil"'), "parameters.m.unit: holds a line break (\\u2028)"),
    ("a paragraph separator in a title", PENDULUM.replace('title = "Pendulum"', 'title = "Pen\\u2029dulum"'), "title: holds a line break (\\u2029)"),
    ("an escape sequence in a title", PENDULUM.replace('title = "Pendulum"', 'title = "\\u001b[2JPendulum"'), "title: holds an invisible control character (\\x1b)"),
    ("a C1 control in a description", PENDULUM.replace('unit = "m", ', 'unit = "m", description = "length\\u0085of the rod", '), "parameters.l.description: holds a line break (\\x85)"),
    ("a right-to-left override in a unit", PENDULUM.replace('unit = "kg"', 'unit = "\\u202egk"'), "parameters.m.unit: holds an invisible control character (\\u202e)"),
    ("a tab in a quantity's description", PENDULUM + '[quantities.w]\ndescription = "angular\\tfrequency"\nvalue = "sqrt(g/l)"\n', "quantities.w.description: holds a tab"),
    ("a control character in a statement", PENDULUM.replace("Use {theta}.", "Use {theta}.\\u0007"), "statement: holds an invisible control character (\\x07)"),
    ("a label placed nowhere", PENDULUM + '[figure]\nlabels = { bob = "top" }\n', "figure.labels.bob: 'top' is not a place for a label (above, below, left or right)"),
    ("a label for no body", PENDULUM + '[figure]\nlabels = { rod = "left" }\n', "figure.labels.rod: 'rod' is not a body of the scene"),
    ("a label place that is code", PENDULUM + '[figure]\nlabels = { bob = { __class__ = 1 } }\n', "figure.labels.bob: {'__class__': 1} is not a place for a label"),
    ("labels that are not a table", PENDULUM + '[figure]\nlabels = ["left"]\n', "figure.labels: is not a table"),
    ("a dashpot with one end", PENDULUM + '[figure]\nfixtures = [{ kind = "dashpot", points = [[0, 0]] }]\n', "figure.fixtures[1].points: is not a list of 2 entries"),
    ("a line break in an option's wording", PENDULUM + '[options.o.a]\nwording = "one\\ntwo"\n[options.o.b]\n', "wording: holds a line break"),
]  # fmt: skip


@pytest.mark.parametrize("case, text, expected", CASES, ids=[c[0] for c in CASES])
def test_refused_with_one_message(case, text, expected, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    start = time.perf_counter()
    assert main(["scene", "check", str(path)]) == 2, case
    assert time.perf_counter() - start < 30
    err = capsys.readouterr().err
    assert err.startswith("lagrade: error: ") and "Traceback" not in err
    assert expected in err, err
    assert not (tmp_path / "PWNED").exists() and not pathlib.Path("PWNED").exists()
    assert not (tmp_path / "scene.svg").exists()  # nothing drawn for a refused file


def test_every_problem_is_reported_at_once(tmp_path, capsys):
    text = (
        PENDULUM.replace('"m"', '"m + b"')
        .replace("l^2", "4 l^2")
        .replace("[1.0] }\nl", "[-1] }\nl")
    )
    text = text.replace("constraints =", "constraint =")
    path = tmp_path / "scene.toml"
    path.write_text(text)
    assert main(["scene", "check", str(path)]) == 2
    err = capsys.readouterr().err
    for key in (
        "bodies.bob.mass: Unknown symbol 'b'",
        "parameters.m.values[1]",
        "constraint: unknown key",
    ):
        assert key in err
    assert "        m + b\n            ^\n" in err  # the caret under the unknown name


def test_not_utf8_and_a_folder_are_refused(tmp_path, capsys):
    path = tmp_path / "scene.toml"
    path.write_bytes(b"title = '\xff\xfe'\n")
    assert main(["scene", "check", str(path)]) == 2
    assert "is not UTF-8 text (byte 0xff at position 9)" in capsys.readouterr().err
    (tmp_path / "dir.toml").mkdir()
    assert main(["scene", "check", str(tmp_path / "dir.toml")]) == 2
    assert "is a folder" in capsys.readouterr().err
