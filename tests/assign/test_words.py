"""Words a newcomer reads first: a count agrees with its noun ("1 point", "1 constraint"); the
energy function is not called h where h is a height; a variant's solution lists only the
parameters it uses."""

from __future__ import annotations

import re

import pytest

from lagrade.assign import generate
from lagrade.assign.solution import solution_data, solution_latex, solution_text
from lagrade.bank import get_scene

from .conftest import write_assignment, write_roster


@pytest.mark.parametrize("fmt", ["md", "html", "tex"])
def test_a_one_point_problem_says_one_point(tmp_path, fmt):
    assignment = write_assignment(
        tmp_path / "a.toml",
        [
            {"scene": "simple_pendulum", "parts": ["dof"]},
            {"scene": "wedge", "parts": ["dof", "cyclic"]},
        ],
    )
    roster = write_roster(tmp_path / "r.csv", [("s001", "Ada Lovelace")])
    generate(assignment, roster, 1, tmp_path / "out", formats=(fmt,))
    for kind in ("handouts", "keys"):
        text = (tmp_path / "out" / kind / f"s001.{fmt}").read_text(encoding="utf-8")
        assert not re.search(r"\b1 points\b", text), kind
        assert "(1 point)" in text and "(2 points)" in text, kind


def test_one_constraint_is_singular():
    text = solution_text(get_scene("kepler").default)
    k = len(solution_data(get_scene("kepler").default)["constraints"])
    assert k == 1 and "k = 1 constraint)" in text, text


def test_the_energy_function_is_not_called_h_where_h_is_a_height():
    wedge = get_scene("wedge").default
    assert "h" in wedge.parameter_symbols  # the wedge's height
    text = solution_text(wedge)
    assert "h (energy function)" not in text and "H (energy function)" in text
    latex = solution_latex(wedge)
    assert not re.search(r"^h &=", latex, flags=re.M) and re.search(r"^H &=", latex, flags=re.M)
    hoop = solution_text(get_scene("hoop").default)  # no parameter h: the usual name
    assert "h (energy function)" in hoop


def test_a_variant_lists_only_the_parameters_it_uses():
    scene = get_scene("free_particle")
    for seed in range(6):
        variant = scene.variant(seed)
        listed = solution_data(variant)["parameters"]
        assert set(listed) == set(variant.used_parameters), (seed, variant.options)
        line = next(ln for ln in solution_text(variant).splitlines() if ln.startswith("param"))
        unused = set(variant.parameter_symbols) - set(variant.used_parameters)
        assert unused and not any(re.search(rf"\b{n}\b", line) for n in unused), line
