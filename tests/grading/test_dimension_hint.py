"""Dimensions, as a hint (issue 25; `lagrade.judge.dimensions`): parameters carry SI units,
coordinates get theirs from the positions, so the terms of a Lagrangian, an equation of motion or
a momentum must share one dimension; a wrong answer whose terms do not is told which term has
which. Correctness is still the physics'; the hint only explains, and must never fire on a
right answer: it is run here over every key answer of every bank scene in every presentation
(each option's every choice, the coordinates' other names) and over the right answers of the
labelled corpora — zero firings."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.judge.dimensions import (
    ENERGY,
    LENGTH,
    NONE,
    hint_for,
    read_unit,
    symbol_dimensions,
    unit_text,
)
from lagrade.judge.driver import cached_problem
from lagrade.judge.key import key_answer
from lagrade.judge.parts.reading import read, read_labelled
from lagrade.mechanics.scene import SceneVariant

from .conftest import judge
from .corpus import corpus, expected_status

SIMPLE = {"scene": "simple_pendulum"}


@pytest.mark.parametrize(
    "text, shown",
    [
        ("kg", "kg"),
        ("m/s^2", "m/s²"),
        ("N/m", "kg/s²"),
        ("rad/s", "1/s"),
        ("kg m^2", "kg·m²"),
        ("m^3/(kg s^2)", "m³/(kg·s²)"),
        ("T", "kg/(s²·A)"),  # tesla
        ("rad", "no units"),
    ],
)
def test_scene_units_are_read(text, shown):
    assert unit_text(read_unit(text)) == shown


@pytest.mark.parametrize("text", ["", "furlong", "m^", "(kg", "m//s", "import os"])
def test_a_unit_it_cannot_read_gives_no_dimension(text):
    assert read_unit(text) is None


def test_coordinates_take_their_dimension_from_the_positions():
    wedge = symbol_dimensions(get_scene("wedge").default)
    kepler = symbol_dimensions(get_scene("kepler").default)
    by_name = {s.name: d for s, d in {**wedge, **kepler}.items()}
    assert by_name["x_M"] == by_name["q"] == by_name["r"] == LENGTH  # in a position: a length
    assert by_name["theta"] == NONE  # in r cos(theta): an angle
    assert unit_text(by_name["q_dot"]) == "m/s" and unit_text(by_name["theta_ddot"]) == "1/s²"


@pytest.mark.parametrize(
    "part, answer, says",
    [
        # the brief's own example: m l θ̇² is a force, the other terms energies
        ("eom", ["m l^2 theta_ddot + m l theta_dot^2 + m g l sin(theta) = 0"],
         "l*m*theta_dot^2 has units of kg·m/s², a force; the other terms kg·m²/s², an energy"),
        ("lagrangian", "1/2 m l^2 theta_dot^2 + m g cos(theta)",
         "g*m*cos(theta) has units of kg·m/s², a force; the other term kg·m²/s², an energy"),
        ("momenta", ["p_theta = m l^2 theta_dot + m l"],
         "p_theta: l*m has units of kg·m; the other term kg·m²/s, an angular momentum"),
        ("T", "1/2 m l^2 theta_dot^2 + m g",
         "g*m has units of kg·m/s², a force; the other term kg·m²/s², an energy"),
        ("lagrangian", "1/2 m l^2 theta_dot^2 + m g l cos(theta + l)",
         "theta (no units) and l (m) are added but have different units"),
    ],
)  # fmt: skip
def test_a_wrong_answer_whose_terms_disagree_is_told_which_term_has_which_units(part, answer, says):
    verdict = judge(SIMPLE, part, answer)
    assert verdict.status == "incorrect"
    assert any(says in f for f in verdict.feedback), verdict.feedback


def test_a_wrong_answer_whose_terms_agree_gets_no_dimension_sentence():
    verdict = judge(SIMPLE, "lagrangian", "1/2 m l^2 theta_dot^2 - m g l cos(theta)")
    assert verdict.status == "incorrect"
    assert not any("units" in f for f in verdict.feedback)


def test_an_ad_hoc_problem_declares_no_units_and_gets_no_hint():
    problem = {
        "lagrangian": "m*l^2*theta_dot^2/2 + m*g*l*cos(theta)",
        "coordinates": ["theta"],
        "parameters": {"m": "positive", "g": "positive", "l": "positive"},
    }
    verdict = judge(problem, "lagrangian", "1/2 m l^2 theta_dot^2 + m g cos(theta)")
    assert verdict.status == "incorrect" and not any("units" in f for f in verdict.feedback)


# --- never on a right answer --------------------------------------------------------------------


def _presentations(scene):
    """The declared variant, every choice of every option, and the coordinates' other names."""
    yield scene.default
    for option, choices in scene.options.items():
        for choice in choices[1:]:
            yield SceneVariant(scene, options={option: choice})
    for coordinate, names in scene.renames.items():
        for name in names[1:]:
            yield SceneVariant(scene, names={coordinate: name})


_PARTS = {"lagrangian": "energy", "T": "kinetic", "V": "energy"}


def _key_hints(problem, variant) -> list[tuple]:
    """Every dimension hint the key answers of a variant would get: there must be none."""
    found = []
    for part, expected in _PARTS.items():
        expr = read_labelled(problem, key_answer(variant, part)).expr
        found.append((part, hint_for(problem, expr, expected)))
    for line in key_answer(variant, "eom"):
        got = read(problem, line)
        found.append(("eom", hint_for(problem, got.expr - got.rhs, "equation")))
    for k, line in enumerate(key_answer(variant, "momenta")):
        found.append(
            ("momenta", hint_for(problem, read_labelled(problem, line).expr, f"momentum:{k}"))
        )
    for name in variant.quantities:
        key = key_answer(variant, "expression", name)
        found.append(("expression", hint_for(problem, read_labelled(problem, key).expr)))
    return [(part, hint) for part, hint in found if hint]


@pytest.mark.parametrize("sid", scene_ids())
def test_no_key_answer_of_any_presentation_gets_a_dimension_hint(sid):
    scene = get_scene(sid)
    for variant in _presentations(scene):
        problem = _problem_of(variant)  # the variant's own names and options, the scene's units
        assert symbol_dimensions(variant), sid
        assert _key_hints(problem, variant) == [], (sid, variant.options, variant.names)


def _problem_of(variant: SceneVariant):
    from lagrade.judge.problem import Problem

    params = dict(variant.parameter_symbols)
    return Problem(
        f"dims:{variant.scene.id}:{variant.options}:{variant.names}",
        "scene",
        variant.jets,
        params,
        {params[n]: d for n, d in variant.domains.items()},
        {},
        lagrangian=variant.lagrangian,
        variant=variant,
    )


def test_no_right_answer_of_the_corpora_gets_a_dimension_hint():
    expected = {"lagrangian": "energy", "T": "kinetic", "V": "energy", "eom": "equation"}
    checked = 0
    for item in corpus(per_part=4):
        if expected_status(item) != "correct" or item.part not in (*expected, "momenta"):
            continue
        problem = cached_problem(item.problem)
        lines = item.answer if isinstance(item.answer, list) else [item.answer]
        for k, line in enumerate(lines):
            got = read(problem, line)
            expr = got.expr - got.rhs if got.rhs is not None else got.expr
            if item.part == "momenta":
                expr = read_labelled(problem, line).expr
            what = f"momentum:{k}" if item.part == "momenta" else expected[item.part]
            assert hint_for(problem, expr, what) == "", (item.problem, item.part, line)
            checked += 1
    judged = Path(__file__).parents[2] / "benchmarks/corpus/judged.jsonl"
    for case in map(json.loads, judged.open()):
        if case["status"] != "correct" or case["part"] not in expected:
            continue
        problem = cached_problem(case["problem"])
        lines = case["answer"] if isinstance(case["answer"], list) else [case["answer"]]
        for line in lines:
            got = read(problem, line)
            expr = got.expr - got.rhs if got.rhs is not None else got.expr
            assert hint_for(problem, expr, expected[case["part"]]) == "", case["id"]
            checked += 1
    assert checked > 300


def test_energy_is_kilogram_metre_squared_per_second_squared():
    assert unit_text(ENERGY) == "kg·m²/s²" and unit_text(read_unit("kg^(1/2)")) == "kg¹ᐟ²"
    assert sp.Symbol("x") not in symbol_dimensions(get_scene("wheel").default)
