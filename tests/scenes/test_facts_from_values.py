"""Scenes whose potential is written in the bodies' Cartesian coordinates (as docs/scenes.md
recommends for springs and central forces) or whose L holds an identity in a coordinate: the
facts — cyclic coordinates, conserved quantities and their number — come from values (issue 35),
and `scene check`, `bank show`, the key and the `cyclic` and `conserved` checkers say the same.

The systems (sources in each file's header, `cartesian/`): the Kepler problem in polar coordinates
with V = −G M m/sqrt(x² + y²) (Taylor §8.4; Goldstein §3.2: θ cyclic); two pucks joined by a
spring, its potential the pucks' distance, in centre-of-mass and turning relative coordinates
(Taylor §8.2–8.3; Goldstein §3.1: X, Y, θ cyclic); a bead on a spinning hoop held by a spring
from the centre, k/2 (x² + y² + z²) (Taylor Example 7.6; Goldstein §2.7: no explicit t, h
conserved, θ not cyclic); a rotor whose L holds m g l (sin²φ + cos²φ) (Landau & Lifshitz §2).
Before issue 35 every one of them had the wrong facts (`L.has(q)` decided them)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from lagrade.bank.scenefile import read_scene_file
from lagrade.cli.main import main
from lagrade.judge.check import check
from lagrade.judge.key import key_answer

FILES = Path(__file__).parent / "cartesian"

#: scene → (its cyclic coordinates, its conserved quantities' key names, how many of them are
#: independent: the rotor's h = p_φ²/(2 m l²) adds none)
FACTS = {
    "kepler_cartesian": ({"theta"}, {"p_theta", "h"}, 2),
    "spring_pair_cartesian": ({"X", "Y", "theta"}, {"p_X", "p_Y", "p_theta", "h"}, 4),
    "hoop_cartesian": (set(), {"h"}, 1),
    "rotor_identity": ({"phi"}, {"p_phi", "h"}, 1),
}
#: Each scene's energy function written by hand (what a student types for "the energy").
ENERGY = {
    "kepler_cartesian": "m (r_dot^2 + r^2 theta_dot^2)/2 - G M m/r",
    "spring_pair_cartesian": (
        "(m_1 + m_2)(X_dot^2 + Y_dot^2)/2 + m_1 m_2/(m_1 + m_2) (r_dot^2 + r^2 theta_dot^2)/2"
        " + k (r - l_0)^2/2"
    ),
    "hoop_cartesian": "m R^2 (theta_dot^2 - omega^2 sin(theta)^2)/2 - m g R cos(theta)",
    "rotor_identity": "m l^2 phi_dot^2/2",
}
#: The conserved momenta written by hand.
MOMENTA = {
    "kepler_cartesian": ["m r^2 theta_dot"],
    "spring_pair_cartesian": [
        "(m_1 + m_2) X_dot",
        "(m_1 + m_2) Y_dot",
        "m_1 m_2/(m_1 + m_2) r^2 theta_dot",
    ],
    "hoop_cartesian": [],
    "rotor_identity": ["m l^2 phi_dot"],
}


def _request(scene: str) -> dict:
    return {"scene": scene, "scene_text": (FILES / f"{scene}.toml").read_text()}


@pytest.mark.parametrize("scene", FACTS)
def test_the_derivation_has_the_facts_and_prints_no_absent_coordinate(scene):
    variant = read_scene_file(FILES / f"{scene}.toml").default
    cyclic, conserved, independent = FACTS[scene]
    assert set(variant.cyclic_coordinates) == cyclic
    assert set(variant.conserved_quantities) == conserved
    names = {str(s) for s in variant.lagrangian.free_symbols}
    assert not names & cyclic, variant.lagrangian  # the key's L is written without them
    assert "t" not in names
    for e in (*variant.euler_lagrange, *variant.generalized_momenta):
        assert not {str(s) for s in e.free_symbols} & cyclic


@pytest.mark.parametrize("scene", FACTS)
def test_scene_check_and_bank_show_print_the_same_facts(scene, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    path = FILES / f"{scene}.toml"
    assert main(["scene", "check", str(path)]) == 0
    checked = capsys.readouterr().out
    assert main(["bank", "show", str(path)]) == 0
    shown = capsys.readouterr().out
    cyclic, conserved, independent = FACTS[scene]
    for out in (checked, shown):
        line = re.search(r"^cyclic: (.*)$", out, flags=re.M)[1]
        assert set(line.split(", ")) - {"none"} == cyclic
        section = out.split("\nconserved:", 1)[1].split("\nH = ", 1)[0]  # not Hamilton's
        listed = re.findall(r"^  (p_\w+|h) ", section, flags=re.M)
        assert set(listed) == conserved


@pytest.mark.parametrize("scene", FACTS)
def test_the_key_and_the_checkers_agree_on_the_facts(scene):
    variant = read_scene_file(FILES / f"{scene}.toml").default
    problem = _request(scene)
    cyclic, conserved, independent = FACTS[scene]
    key = key_answer(variant, "cyclic")
    assert set(key.split(", ")) - {"none"} == cyclic
    assert check(problem, "cyclic", key, time_limit=None).status == "correct"
    if cyclic:
        verdict = check(problem, "cyclic", "none", time_limit=None)
        assert verdict.status == "incorrect" and verdict.score == 0
    everything = ", ".join(variant.coordinates)
    if cyclic != set(variant.coordinates):
        assert check(problem, "cyclic", everything, time_limit=None).status == "incorrect"
    keyed = key_answer(variant, "conserved")
    assert len(keyed) == len(conserved)
    ALL = {"all": True}
    assert check(problem, "conserved", keyed, time_limit=None, given=ALL).status == "correct"
    by_hand = [*MOMENTA[scene], ENERGY[scene]]
    verdict = check(problem, "conserved", by_hand, time_limit=None, given=ALL)
    assert verdict.status == "correct", verdict.feedback
    energy_alone = check(problem, "conserved", [ENERGY[scene]], time_limit=None, given=ALL)
    if independent > 1:  # energy alone is a true quantity, but not all of them
        assert energy_alone.status == "incorrect" and "missing_conserved" in energy_alone.mistakes
        assert energy_alone.score == pytest.approx(1 / independent)
        assert f"has {independent} independent conserved" in " ".join(energy_alone.feedback)
    else:
        assert energy_alone.status == "correct"
    none = check(problem, "conserved", "none", time_limit=None, given=ALL)
    assert none.status == "incorrect" and none.score == 0


def test_an_adhoc_lagrangian_with_an_identity_has_its_cyclic_coordinate():
    """The same facts for an instructor's ad-hoc L (no scene, L's text kept as given): the
    Kepler L with the distance written as sqrt(r² sin²θ + r² cos²θ) (Goldstein §3.2)."""
    problem = {
        "lagrangian": (
            "m (r_dot^2 + r^2 theta_dot^2)/2 + G M m/sqrt(r^2 sin(theta)^2 + r^2 cos(theta)^2)"
        ),
        "coordinates": {"r": "positive", "theta": None},
        "parameters": {"m": "positive", "M": "positive", "G": "positive"},
    }
    assert check(problem, "cyclic", "theta", time_limit=None).status == "correct"
    assert check(problem, "cyclic", "none", time_limit=None).status == "incorrect"
    all_ = {"all": True}
    energy = ENERGY["kepler_cartesian"]
    alone = check(problem, "conserved", [energy], time_limit=None, given=all_)
    assert alone.status == "incorrect" and "missing_conserved" in alone.mistakes
    both = check(problem, "conserved", [energy, "m r^2 theta_dot"], time_limit=None, given=all_)
    assert both.status == "correct"


def test_own_lagrangian_follow_through_reads_facts_by_values():
    """A student whose own L holds the identity and who names its cyclic coordinate is told the
    set follows from their own L only when it truly does: here it is the right set."""
    problem = _request("kepler_cartesian")
    own = {
        "lagrangian": "m (r_dot^2 + r^2 theta_dot^2)/2"
        " + G M m/sqrt(r^2 sin(theta)^2 + r^2 cos(theta)^2)"
    }
    verdict = check(problem, "cyclic", "theta", time_limit=None, given=own)
    assert verdict.status == "correct"


def test_generate_writes_the_facts_into_every_key(tmp_path):
    """`generate` verifies every key with the grader: the cyclic coordinate and the conserved
    momentum are in the Kepler key, and `none` is not."""
    (tmp_path / "scenes").mkdir()
    for scene in ("kepler_cartesian", "hoop_cartesian"):
        text = (FILES / f"{scene}.toml").read_text()
        (tmp_path / "scenes" / f"{scene}.toml").write_text(text)
    (tmp_path / "a.toml").write_text(
        'title = "Facts"\n'
        '[[problems]]\nscene = "scenes/kepler_cartesian.toml"\nparts = ["cyclic", "conserved"]\n'
        '[[problems]]\nscene = "scenes/hoop_cartesian.toml"\nparts = ["cyclic", "conserved"]\n'
    )
    (tmp_path / "roster.csv").write_text("id,name\ns1,Ada Lovelace\n")
    argv = ["generate", str(tmp_path / "a.toml"), "--roster", str(tmp_path / "roster.csv")]
    assert main([*argv, "--seed", "3", "--out", str(tmp_path / "out"), "--formats", "md"]) == 0
    key = (tmp_path / "out" / "keys" / "s1.md").read_text()
    sheet = tomllib.loads("\n".join(re.findall(r"```toml\n(.*?)```", key, flags=re.S)))
    kepler, hoop = sheet["problem1"], sheet["problem2"]
    assert kepler["cyclic"] in ("theta", "phi")  # the variant may rename it
    momentum, energy = kepler["conserved"].strip().splitlines()
    assert "r^2*" in momentum and "Abs(r)" in energy and "sin" not in energy
    assert hoop["cyclic"] == "none"
    assert len(hoop["conserved"].strip().splitlines()) == 1  # h: L has no explicit t
    assert "omega*t" not in hoop["conserved"]
