"""`lagrade bank list` and `lagrade bank show`: what an instructor browsing the bank sees."""

import json

import pytest

from lagrade.bank import scene_ids
from lagrade.cli.main import main

REQUIRED_JSON_KEYS = {
    "coordinates",
    "parameters",
    "dof",
    "T",
    "V",
    "L",
    "momenta",
    "eom",
    "cyclic",
    "conserved",
}


def test_bank_list_names_every_scene(capsys):
    assert main(["bank", "list"]) == 0
    out = capsys.readouterr().out
    for sid in scene_ids():
        assert sid in out


@pytest.mark.parametrize("scene_id", scene_ids())
def test_bank_show_json_holds_the_whole_solution(scene_id, capsys):
    assert main(["bank", "show", scene_id, "--seed", "2", "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert REQUIRED_JSON_KEYS <= set(data)
    assert len(data["eom"]) == len(data["coordinates"]) == data["dof"]
    assert all("Derivative" not in e and "(t)" not in e for e in data["eom"])  # jets, not functions


def test_bank_show_wedge_text_and_latex(capsys):
    assert main(["bank", "show", "wedge"]) == 0
    text = capsys.readouterr().out
    assert "cyclic: x_M" in text and "p_x_M = M*x_M_dot + m*q_dot*cos(alpha) + m*x_M_dot" in text
    assert main(["bank", "show", "wedge", "--format", "latex"]) == 0
    assert r"\dot{x}_{M}" in capsys.readouterr().out


def test_unknown_scene_is_an_error_that_lists_the_bank(capsys):
    assert main(["bank", "show", "wedgie"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("lagrade: error: unknown scene 'wedgie'; did you mean 'wedge'? ")
    assert "hoop" in err
