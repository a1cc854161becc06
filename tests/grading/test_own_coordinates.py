"""A solution in the coordinates the student chose (issue 27). When the student's transformation
equations are valid but not the statement's, the later parts are judged in the student's own
coordinates: right answers there get full credit, the same with a sign or factor error stay
wrong, and answers right for the statement's coordinates but not for the student's own map are
wrong and told why. Labels come from `own_coordinates_cases` (plain sympy from the bodies'
Cartesian positions, never lagrade's judge); which parts of the statement's answers must fail
in the student's coordinates is decided here the same way, numerically with sympy and numpy."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp

from lagrade.judge.check import check

from .own_coordinates_cases import CASES, Case, P, answers, functions, t

LATER = ["lagrangian", "T", "V", "eom", "momenta", "cyclic", "conserved"]
NOTE = "Judged in your coordinates"
TOLD = "right in the statement's coordinates, not in yours"


def judge(case: Case, part: str, answer, given=None):
    return check({"scene": case.scene}, part, answer, time_limit=None, given=given)


def given_of(case: Case) -> dict:
    mine = answers(case)
    return {"transformation": mine.transformation, "lagrangian": mine.lagrangian}


IDS = [f"{c.scene}: {c.convention}" for c in CASES]


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_a_valid_transformation_in_other_coordinates_is_right_and_says_how(case):
    verdict = judge(case, "transformation", answers(case).transformation)
    assert verdict.status == "correct" and verdict.score == 1.0
    assert "own_coordinates" in verdict.mistakes  # what the rubric may charge (default: nothing)
    (remark,) = verdict.feedback
    assert remark.startswith("Your coordinates are not the statement's")
    assert case.words in remark
    assert "the later parts are judged in your coordinates" in remark


@pytest.mark.parametrize("case", CASES, ids=IDS)
@pytest.mark.parametrize("part", LATER)
def test_right_answers_in_the_students_coordinates_get_full_credit(case, part):
    verdict = judge(case, part, getattr(answers(case), part), given_of(case))
    assert verdict.status == "correct", verdict.feedback
    assert verdict.score == 1.0
    assert verdict.feedback[0].startswith(NOTE) and case.words in verdict.feedback[0]


@pytest.mark.parametrize("case", CASES, ids=IDS)
@pytest.mark.parametrize("part", [p for p in LATER if p != "cyclic"])
def test_the_same_answers_with_a_sign_or_factor_error_are_still_wrong(case, part):
    verdict = judge(case, part, answers(case).wrong[part], given_of(case))
    assert verdict.status == "incorrect"
    assert verdict.feedback[0].startswith(NOTE)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_a_wrong_set_of_cyclic_coordinates_is_still_wrong(case):
    mine = answers(case)
    others = [c for c in case.coordinates if c not in mine.cyclic]
    wrong = mine.cyclic + others[:1] if others else mine.cyclic[1:]
    assert judge(case, "cyclic", wrong, given_of(case)).status == "incorrect"


# --- the statement's answers against the student's own map --------------------------------------


def _values(case: Case, which: str, point: dict) -> dict:
    """T, V, accelerations, momenta and D_t h (on the student's motion) at a numeric point,
    from the labels of `which` coordinates — sympy and numpy, no lagrade."""
    q = functions(case.coordinates)
    velocity = {n: sp.diff(f, t) for n, f in q.items()}
    acceleration = {n: sp.diff(f, t, 2) for n, f in q.items()}
    bodies = (case.student if which == "student" else case.statement)(q)
    T = sum(
        b[0] * sum(sp.diff(x, t) ** 2 for x in b[1]) / 2
        + (b[2][0] * sp.diff(b[2][1], t) ** 2 / 2 if len(b) > 2 else 0)
        for b in bodies.values()
    )
    V = case.potential(bodies, q)
    L = T - V
    p = {n: sp.diff(L, velocity[n]) for n in q}
    el = [sp.diff(p[n], t) - sp.diff(L, q[n]) for n in q]
    h = sum(velocity[n] * p[n] for n in q) - L
    cyclic = {n for n in q if sp.simplify(sp.diff(L, q[n])) == 0}

    def at(e, accelerations=None):
        e = e.subs({acceleration[n]: sp.Symbol(f"{n}_a") for n in q})
        e = e.subs({velocity[n]: point[f"{n}_dot"] for n in q})
        e = e.subs({q[n]: point[n] for n in q}).subs(point["parameters"])
        if accelerations is not None:
            e = e.subs({sp.Symbol(f"{n}_a"): accelerations[n] for n in q})
        return e

    # E = A q̈ − b: solve the Euler–Lagrange equations for the accelerations
    rows = [at(e) for e in el]
    names = [sp.Symbol(f"{n}_a") for n in q]
    A = np.array([[float(sp.diff(r, s)) for s in names] for r in rows])
    b = -np.array([float(r.subs({s: 0 for s in names})) for r in rows])
    acc = dict(zip(q, np.linalg.solve(A, b), strict=True))
    return {
        "T": float(at(T)),
        "V": float(at(V)),
        "accelerations": np.array(list(acc.values())),
        "momenta": np.array([float(at(p[n])) for n in q]),
        "conserved": [sp.diff(Q, t) for Q in [*(p[n] for n in sorted(cyclic)), h]],
        "at": at,
        "acc": acc,
        "cyclic": cyclic,
    }


def _point(case: Case, rng: random.Random) -> dict:
    point = {"parameters": {s: rng.uniform(0.6, 1.4) for s in P.values()}}
    point["parameters"] |= {
        sp.Symbol(n, positive=True): rng.uniform(0.6, 1.4) for n in ("l_1", "l_2")
    }
    point["parameters"][P["alpha"]] = rng.uniform(0.3, 1.2)
    for n in case.coordinates:
        point[n] = rng.uniform(0.4, 1.3)
        point[f"{n}_dot"] = rng.uniform(-1, 1)
    return point


def statement_answers_that_fail(case: Case) -> set[str]:
    """The parts whose statement-coordinate answer is not right in the student's coordinates,
    decided at random points: T differs; V differs by more than a constant; the motion
    (accelerations) differs, and with it L and the equations of motion; a momentum differs;
    the statement's h is not conserved on the student's motion; the cyclic sets differ."""
    rng = random.Random(f"{case.scene}:{case.convention}")
    fails: set[str] = set()
    offsets = []
    for _ in range(3):
        point = _point(case, rng)
        mine, theirs = _values(case, "student", point), _values(case, "statement", point)
        if abs(mine["T"] - theirs["T"]) > 1e-9:
            fails.add("T")
        offsets.append(mine["V"] - theirs["V"])
        if not np.allclose(mine["accelerations"], theirs["accelerations"], atol=1e-9):
            fails |= {"lagrangian", "eom"}
        if not np.allclose(mine["momenta"], theirs["momenta"], atol=1e-9):
            fails.add("momenta")
        if any(abs(float(mine["at"](dQ, mine["acc"]))) > 1e-9 for dQ in theirs["conserved"]):
            fails.add("conserved")
        if mine["cyclic"] != theirs["cyclic"]:
            fails.add("cyclic")
    if max(offsets) - min(offsets) > 1e-9:
        fails.add("V")
    return fails


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_answers_right_for_the_statement_but_not_for_the_students_map_are_wrong_and_told_why(
    case,
):
    theirs = answers(case, "statement")
    fails = statement_answers_that_fail(case)
    assert bool(fails) == case.statement_differs
    for part in LATER:
        verdict = judge(case, part, getattr(theirs, part), given_of(case))
        if part in fails:
            assert verdict.status == "incorrect", part
            assert verdict.feedback[0].startswith(NOTE)
            assert any(TOLD in f for f in verdict.feedback), (part, verdict.feedback)
        else:  # the statement's answer is right in the student's coordinates too
            assert verdict.status == "correct", (part, verdict.feedback)


def test_the_statements_answers_are_right_in_the_statements_coordinates():
    """The labels of the statement's coordinates are right without a transformation: the
    independent derivation agrees with lagrade's reference where nothing changes."""
    for case in CASES:
        theirs = answers(case, "statement")
        for part in LATER:
            verdict = judge(case, part, getattr(theirs, part))
            assert verdict.status == "correct", (case.scene, part, verdict.feedback)
            assert not any(NOTE in f for f in verdict.feedback)


# --- when the student is not followed -----------------------------------------------------------

CASE = CASES[0]  # incline_pendulum, the angle towards the bottom of the incline


def test_an_invalid_transformation_means_the_statements_coordinates():
    broken = answers(CASE).transformation[:-1] + ["y_bob = -s sin(alpha) - 2 l cos(phi)"]
    assert judge(CASE, "transformation", broken).status == "incorrect"
    given = {"transformation": broken}
    theirs, mine = answers(CASE, "statement"), answers(CASE)
    right = judge(CASE, "lagrangian", theirs.lagrangian, given)
    assert right.status == "correct" and not right.feedback
    wrong = judge(CASE, "lagrangian", mine.lagrangian, given)
    assert wrong.status == "incorrect" and not any(NOTE in f for f in wrong.feedback)


def test_no_transformation_means_the_statements_coordinates():
    mine = answers(CASE)
    verdict = judge(CASE, "eom", mine.eom, {"lagrangian": mine.lagrangian})
    assert verdict.status == "incorrect"
    assert not any(NOTE in f for f in verdict.feedback)


def test_the_statements_own_transformation_adds_nothing():
    theirs = answers(CASE, "statement")
    assert judge(CASE, "transformation", theirs.transformation).feedback == ()
    verdict = judge(CASE, "momenta", theirs.momenta, {"transformation": theirs.transformation})
    assert verdict.status == "correct" and verdict.feedback == ()


def test_the_same_map_written_otherwise_is_the_statements():
    """cos(pi/2 - phi) for sin(phi): the same positions, so no remark and no note."""
    lines = answers(CASE, "statement").transformation
    lines = [ln.replace("l*sin(phi)", "l*cos(pi/2 - phi)") for ln in lines]
    assert any("cos(pi/2 - phi)" in ln for ln in lines)
    assert judge(CASE, "transformation", lines).feedback == ()
