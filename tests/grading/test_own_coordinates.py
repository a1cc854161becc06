"""A solution in the coordinates the student chose (issue 27). When the student's transformation
equations are valid but not the statement's, the later parts are judged in the student's own
coordinates: right answers there get full credit, the same with a sign or factor error stay
wrong, and answers right for the statement's coordinates but not for the student's own map are
wrong and told why. Labels come from `own_coordinates_cases` (plain sympy from the bodies'
Cartesian positions, never lagrade's judge); which parts of the statement's answers must fail
in the student's coordinates is decided here the same way, numerically with sympy and numpy."""

from __future__ import annotations

import functools
import random

import numpy as np
import pytest
import sympy as sp

from lagrade.judge.check import check

from .own_coordinates_cases import CASES, Case, P, answers, derivation, in_jets, t

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


@functools.cache
def _symbolic(case: Case, which: str) -> dict:
    """T, V, the Euler–Lagrange expressions, momenta, cyclic coordinates and the time
    derivatives of the conserved quantities (cyclic momenta, h) from the labels of `which`
    coordinates, in plain symbols (theta, theta_dot, theta_ddot) — sympy, no lagrade."""
    d = derivation(case, which)
    conserved = [sp.diff(Q, t) for Q in [*(d.momenta[n] for n in d.cyclic), d.h]]
    return {
        "T": in_jets(d.T, d.q),
        "V": in_jets(d.V, d.q),
        "el": [in_jets(e, d.q) for e in d.equations.values()],
        "momenta": [in_jets(p, d.q) for p in d.momenta.values()],
        "conserved": [in_jets(dQ, d.q) for dQ in conserved],
        "cyclic": set(d.cyclic),
    }


def _values(case: Case, which: str, point: dict) -> dict:
    """The quantities of `_symbolic` at a numeric point, and the accelerations solved from the
    Euler–Lagrange equations there (E = A q̈ − b)."""
    s = _symbolic(case, which)
    names = [sp.Symbol(f"{n}_ddot") for n in case.coordinates]
    rows = [e.xreplace(point) for e in s["el"]]
    A = np.array([[float(sp.diff(r, a)) for a in names] for r in rows])
    b = -np.array([float(r.xreplace({a: 0 for a in names})) for r in rows])
    accelerations = dict(zip(names, np.linalg.solve(A, b), strict=True))
    return {
        "T": float(s["T"].xreplace(point)),
        "V": float(s["V"].xreplace(point)),
        "accelerations": np.array(list(accelerations.values())),
        "momenta": np.array([float(p.xreplace(point)) for p in s["momenta"]]),
        "conserved": s["conserved"],
        "acc": accelerations,
        "cyclic": s["cyclic"],
    }


def _point(case: Case, rng: random.Random) -> dict:
    """Parameters, coordinates and velocities at random (exact rationals)."""

    def draw(lo, hi):
        return sp.Rational(rng.randint(int(lo * 100), int(hi * 100)), 100)

    point = {s: draw(0.6, 1.4) for s in P.values()}
    point |= {sp.Symbol(n, positive=True): draw(0.6, 1.4) for n in ("l_1", "l_2")}
    point[P["alpha"]] = draw(0.3, 1.2)
    for n in case.coordinates:
        point[sp.Symbol(n)] = draw(0.4, 1.3)
        point[sp.Symbol(f"{n}_dot")] = draw(-1, 1)
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
        on_mine = {**point, **mine["acc"]}
        if any(abs(float(dQ.xreplace(on_mine))) > 1e-9 for dQ in theirs["conserved"]):
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
