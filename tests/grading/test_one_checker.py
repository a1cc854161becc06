"""One rule per part, whichever command asks: `lagrade check` (the `check` API, as the command
and `check --batch` use it) and `lagrade grade` (`grade_part`, as the batch runs it) give the
same verdict, score, feedback and named mistakes on the same answer, for every part, numeric
follow-ups included (the wedge's block acceleration written as a number, with or without its
unit, off by a few per cent, and as a closed form)."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.assign.views import MULTILINE
from lagrade.bank import get_scene
from lagrade.grading.rubric import Rubric
from lagrade.grading.student import grade_part
from lagrade.judge.check import check
from lagrade.judge.driver import forget_problems
from lagrade.judge.key import key_answer
from lagrade.judge.parts import PARTS

SEED = 3
VARIANT = get_scene("wedge").variant(SEED)
ENTRY = {"scene": "wedge", "seed": SEED, "coordinates": list(VARIANT.coordinates)}
VALUE = float(sp.N(VARIANT.quantities["block_acceleration"].xreplace(VARIANT.numeric_values)))
L_TEXT = key_answer(VARIANT, "lagrangian")


@pytest.fixture(autouse=True)
def _questions_built_here():
    """`grade` shares a question among a class, built from the first student asked it; a run
    earlier in this process (another test's class) may have built this one from another seed,
    whose sample points the feedback would quote. Each test starts from none, as a command does."""
    forget_problems()


def _answers() -> list[tuple[str, object]]:
    cases = []
    for part in PARTS:
        if part == "expression":
            continue
        try:
            right = key_answer(VARIANT, part)
        except KeyError:  # the wedge has no stable equilibrium: no equilibrium, no modes
            continue
        cases.append((part, right))
    cases += [
        ("dof", "3"),
        ("coordinates", "x_M"),
        ("lagrangian", "1/2 M x_M_dot^2 + 1/2 m q_dot^2"),
        ("T", "M x_M_dot^2"),
        ("V", "m g q"),
        ("eom", ["x_M_ddot = 0", "q_ddot = g sin(alpha)"]),
        ("momenta", ["p_x_M = M x_M_dot", "p_q = m q_dot"]),
        ("cyclic", "q"),
        ("conserved", ["x_M_dot"]),
        ("hamiltonian", "p_q^2/(2 m) + p_x_M^2/(2 M)"),
        ("hamilton_equations", ["q_dot = p_q/m", "x_M_dot = p_x_M/M"]),
        ("expression", f"{VALUE:.4g}"),
        ("expression", f"{VALUE:.4g} m/s^2"),
        ("expression", f"{1.05 * VALUE:.4g}"),
        ("expression", f"{-VALUE:.4g}"),
        ("expression", key_answer(VARIANT, "expression", "block_acceleration")),
        ("expression", "g sin(alpha)"),
    ]
    return cases


def _sheet_form(part: str, answer: object) -> str:
    """The answer as an answer sheet holds it: one string, one item per line."""
    if isinstance(answer, list):
        return "\n".join(answer)
    return str(answer)


@pytest.mark.parametrize(("part", "answer"), _answers(), ids=lambda x: str(x)[:40])
def test_check_and_grade_agree(part, answer):
    spec = {"scene": "wedge", "seed": SEED}
    quantity = "block_acceleration" if part == "expression" else None
    if quantity:
        spec["quantity"] = quantity
    own_l = {"lagrangian": L_TEXT} if part in ("eom", "momenta", "cyclic", "conserved") else None
    asked = [answer] if part in MULTILINE and isinstance(answer, str) else answer
    by_check = check(spec, part, asked, time_limit=None, given=own_l)
    row = {"part": part, "key": quantity or part, "points": 1, "quantity": quantity}
    by_grade = grade_part(ENTRY, row, _sheet_form(part, answer), dict(own_l or {}), Rubric(), 5.0)
    assert by_grade["verdict"] == by_check.status
    assert by_grade["points"] == pytest.approx(by_check.score)
    assert by_grade["feedback"] == list(by_check.feedback)
    assert by_grade["mistakes"] == list(by_check.mistakes)


def test_a_right_value_is_right_in_both():
    """The case that used to differ: a number for the block's acceleration was `incorrect`
    under `check` (compared with the closed form) and `correct` under `grade`."""
    spec = {"scene": "wedge", "seed": SEED, "quantity": "block_acceleration"}
    assert check(spec, "expression", f"{VALUE:.4g}", time_limit=None).status == "correct"
    assert check(spec, "expression", f"{1.05 * VALUE:.4g}", time_limit=None).status == "incorrect"


def test_every_part_has_its_one_reader():
    """The reading step (`lagrade.judge.read`) reads each part with the reader its checker reads
    with: a part registered without one could not be previewed or parsed by PrairieLearn."""
    from lagrade.judge.parts import PARTS
    from lagrade.judge.read import READERS

    assert set(READERS) == set(PARTS)
