"""The conserved rule (issue 12): each quantity given is judged on its own — right when it is not
constant and D_t Q = 0 on the reference motion — and completeness counts only when the request
asks for it (`given = {"all": True}`), in the score and the feedback, not in what was given."""

from __future__ import annotations

import json

import pytest

from lagrade.judge.check import check_pool, run_batch

from .conftest import WEDGE, judge

KEPLER = {"scene": "kepler"}
P_X = "p_x = (M + m) x_M_dot + m q_dot cos(alpha)"
L_Z = "m r^2 theta_dot"
ALL = {"all": True}


@pytest.mark.parametrize(
    "problem, answer",
    [
        (WEDGE, [P_X]),
        (WEDGE, ["(M + m) x_M_dot + m q_dot cos(alpha)"]),
        (KEPLER, [L_Z]),
        (KEPLER, ["l = m r^2 theta_dot"]),
        (KEPLER, ["1/2 m (r_dot^2 + r^2 theta_dot^2) - G M m / r"]),
    ],
)
def test_one_true_quantity_alone_is_correct(problem, answer):
    v = judge(problem, "conserved", answer)
    assert v.status == "correct" and v.score == 1.0 and v.feedback == ()


@pytest.mark.parametrize("problem, answer", [(WEDGE, [P_X]), (KEPLER, [L_Z])])
def test_with_all_a_missing_quantity_lowers_the_score_and_names_the_count(problem, answer):
    v = judge(problem, "conserved", answer, given=ALL)
    assert v.status == "incorrect" and v.score == pytest.approx(0.5)
    assert "missing_conserved" in v.mistakes
    assert any("2 independent conserved quantities" in f and "you gave 1" in f for f in v.feedback)
    # the one given is still right: nothing says it is not conserved
    assert not any("not conserved" in f for f in v.feedback)


def test_with_all_the_whole_set_is_correct():
    energy = "1/2 m (r_dot^2 + r^2 theta_dot^2) - G M m / r"
    assert judge(KEPLER, "conserved", [L_Z, energy], given=ALL).status == "correct"
    assert judge(KEPLER, "conserved", [L_Z, energy]).status == "correct"


@pytest.mark.parametrize("given", [None, ALL])
def test_dependent_quantities_are_not_both_counted(given):
    v = judge(KEPLER, "conserved", [L_Z, "2 m r^2 theta_dot"], given=given)
    assert v.status == "incorrect" and v.score < 1
    assert "dependent" in v.mistakes
    assert any("2 m r^2 theta_dot" in f.replace("*", " ") or "function of" in f for f in v.feedback)
    # Q + const is no more independent than 2Q
    w = judge(WEDGE, "conserved", [P_X, "(M + m) x_M_dot + m q_dot cos(alpha) + 3 m g h"])
    assert w.status == "incorrect" and "dependent" in w.mistakes
    assert w.score == pytest.approx(0.5)


def test_a_named_nonlinear_function_of_another_is_not_a_duplicate():
    # the free wheel: p = I theta_dot and E = p^2/(2I), both named in the bank's key
    v = judge({"scene": "wheel"}, "conserved", ["I theta_dot", "1/2 I theta_dot^2"], given=ALL)
    assert v.status == "correct"


def test_a_non_conserved_quantity_is_incorrect():
    v = judge(KEPLER, "conserved", ["m r_dot"])
    assert v.status == "incorrect" and v.score == 0
    mixed = judge(KEPLER, "conserved", [L_Z, "m r_dot"])
    assert mixed.status == "incorrect" and mixed.score == pytest.approx(0.5)
    assert any("not conserved" in f for f in mixed.feedback)


def test_all_in_a_batch_request_and_a_bad_all_is_invalid():
    base = {"problem": WEDGE, "part": "conserved", "answer": [P_X]}
    lines = [
        json.dumps({**base, "id": 1}),
        json.dumps({**base, "id": 2, "given": {"all": True}}),
        json.dumps({**base, "id": 3, "given": {"all": "yes"}}),
    ]
    with check_pool() as pool:
        one, every, bad = run_batch(lines, pool=pool)
    assert one["verdict"] == "correct" and one["score"] == 1.0
    assert every["verdict"] == "incorrect" and every["score"] == pytest.approx(0.5)
    assert bad["verdict"] == "invalid" and '"all"' in bad["feedback"][0]


_ONE_OR_ALL = """\
title = "Conserved"
points = 1

[[problems]]
scene = "kepler"
parts = [{{ part = "conserved"{extra} }}]
variants = 1
"""


@pytest.mark.parametrize("extra, asks_all", [("", True), (", all = false", False)])
def test_whether_all_are_asked_is_a_field_of_the_part(tmp_path, extra, asks_all):
    """The rule "all the conserved quantities" is the part's `all` field (default true), carried
    by the manifest and read by `grade` — never read from the prompt's wording: the same one
    quantity (ℓ, where ℓ and the energy are conserved) is complete for `all = false` and half
    of the set for the default."""
    from lagrade.assign import generate
    from lagrade.grading.batch import grade

    (tmp_path / "a.toml").write_text(_ONE_OR_ALL.format(extra=extra))
    (tmp_path / "roster.csv").write_text("id,name\ns1,Ada\n")
    generate(tmp_path / "a.toml", tmp_path / "roster.csv", 1, tmp_path / "out", formats=("md",))
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    (part,) = manifest["problems"][0]["parts"]
    assert part["all"] is asks_all
    handout = next((tmp_path / "out" / "handouts").glob("*.md")).read_text()
    assert ("any one" in handout) is not asks_all
    (tmp_path / "subs").mkdir()
    names = manifest["students"][0]["problems"][0]["names"]  # the variant's (r may be rho)
    angular = f"m {names['r']}^2 {names['theta']}_dot"
    (tmp_path / "subs" / "s1.toml").write_text(
        f'student_id = "s1"\n[problem1]\nconserved = "{angular}"\n'
    )
    summary = grade(tmp_path / "out" / "manifest.json", tmp_path / "subs", tmp_path / "g", jobs=1)
    (result,) = summary.results
    (graded,) = result["problems"][0]["parts"]
    assert graded["verdict"] == ("incorrect" if asks_all else "correct"), graded
    assert graded["points"] == pytest.approx(0.5 if asks_all else 1.0)


def test_all_is_refused_on_another_part(tmp_path):
    from lagrade.assign.assignment import load_assignment
    from lagrade.errors import AssignmentError

    path = tmp_path / "a.toml"
    path.write_text(
        _ONE_OR_ALL.format(extra="").replace('part = "conserved"', 'part = "eom", all = false')
    )
    with pytest.raises(AssignmentError, match=r"parts\[1\]\.all: only the 'conserved' part"):
        load_assignment(path)


def test_the_command_line_asks_for_completeness_with_all(capsys):
    from lagrade.cli.main import main

    answer = "M*x_M_dot + m*x_M_dot + m*q_dot*cos(alpha)"
    base = ["check", "--scene", "wedge", "--part", "conserved", "--answer", answer]
    assert main(base) == 0
    assert main([*base, "--all"]) == 1
    assert "you gave 1" in capsys.readouterr().out


@pytest.mark.parametrize(
    "problem, answer",
    [
        # ℓ and ℓ/m (the angular momentum per unit mass, r² θ̇): one quantity, whatever m is
        (KEPLER, [L_Z, "r^2 theta_dot"]),
        (KEPLER, [L_Z, "G M r^2 theta_dot"]),
        # the wedge's momentum and the velocity of the centre of mass, p_x/(M + m)
        (WEDGE, [P_X, "((M + m) x_M_dot + m q_dot cos(alpha))/(M + m)"]),
        (WEDGE, [P_X, "((M + m) x_M_dot + m q_dot cos(alpha))/m + g"]),
        # the energy per unit mass beside the energy
        (
            KEPLER,
            [
                "1/2 m (r_dot^2 + r^2 theta_dot^2) - G M m / r",
                "1/2 (r_dot^2 + r^2 theta_dot^2) - G M / r",
            ],
        ),
    ],
)
def test_quantities_differing_by_a_parameter_factor_are_one_quantity(problem, answer):
    """Independence on phase space: the parameters are fixed numbers, so Q and Q/m have
    proportional gradients at every point of a parameter group; taken as variables they were
    counted as two (fails on c5b4539: correct, score 1)."""
    v = judge(problem, "conserved", answer)
    assert v.status == "incorrect" and v.score == pytest.approx(0.5)
    assert v.mistakes == ("dependent",)
    assert "fixed combination" in v.feedback[0]


def test_with_all_a_parameter_multiple_does_not_complete_the_set():
    v = judge(KEPLER, "conserved", [L_Z, "r^2 theta_dot"], given=ALL)
    assert v.status == "incorrect" and v.score == pytest.approx(0.25)
    assert any("you gave 1" in f for f in v.feedback)


def test_independent_quantities_with_parameters_stay_independent():
    # ℓ and E/m: different functions on phase space, whatever the parameters
    energy_per_mass = "1/2 (r_dot^2 + r^2 theta_dot^2) - G M / r"
    assert judge(KEPLER, "conserved", [L_Z, energy_per_mass], given=ALL).status == "correct"
