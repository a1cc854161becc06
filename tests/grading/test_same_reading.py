"""Verdicts found again by the content of an answer's reading (issue 35): an answer spelled
otherwise than one judged before (spaces, `*` left out, `**` for `^`, θ for phi) but read the
same gets that verdict without being judged — every field what a fresh judgement in a fresh
process gives — while an answer read otherwise, or with other notes from the parser, is judged.
"""

from __future__ import annotations

import functools
import json
import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.judge.driver import cached_problem, forget_problems, judge, verdict_cache_hits
from lagrade.judge.same_reading import MAX_KEYED_CHARS, SAME_READING_PARTS, reading_key

from .corpus import corpus

PENDULUM = {"scene": "simple_pendulum", "seed": 1}
#: A right L and a wrong one (the potential's sign), each in two spellings that read the same.
RIGHT = ("m*l^2*phi_dot^2/2 + m*g*l*cos(phi)", "m l**2 phi_dot^2 / 2+m g l cos(φ)")
WRONG = ("m*l^2*phi_dot^2/2 - m*g*l*cos(phi)", "m  l^2 phi_dot**2/2 - m g l cos( phi )")


def _fields(verdict) -> dict:
    """Every field of a verdict but its two times."""
    return verdict.to_dict(timings=False)


def _fresh(problem, part, answer, given=None):
    """The verdict of a process that has judged nothing yet."""
    forget_problems()
    return judge(problem, part, answer, given)


def _hits(before: dict) -> int:
    return verdict_cache_hits()["reading"] - before["reading"]


@pytest.mark.parametrize("first, second", [RIGHT, WRONG])
def test_a_respelled_lagrangian_gets_the_verdict_of_a_fresh_judgement(first, second):
    forget_problems()
    judge(PENDULUM, "lagrangian", first)
    before = verdict_cache_hits()
    again = judge(PENDULUM, "lagrangian", second)
    assert _hits(before) == 1
    assert again.prepare_ms == 0.0
    assert _fields(again) == _fields(_fresh(PENDULUM, "lagrangian", second))


def test_the_hit_is_not_judged():
    """Found again, an answer costs its reading: no decision, no diagnosis."""
    forget_problems()
    judge(PENDULUM, "lagrangian", WRONG[0])
    again = judge(PENDULUM, "lagrangian", WRONG[1])
    fresh = _fresh(PENDULUM, "lagrangian", WRONG[1])
    assert again.ms < fresh.ms


def test_equations_of_motion_in_another_spelling_are_found_again():
    forget_problems()
    judge(PENDULUM, "eom", ["m*l^2*phi_ddot + m*g*l*sin(phi) = 0"])
    before = verdict_cache_hits()
    again = judge(PENDULUM, "eom", ["m l^2 phi_ddot+m g l sin(phi)=0"])
    assert _hits(before) == 1
    assert again.interpreted == ["m*l^2*phi_ddot + m*g*l*sin(phi) = 0"]


@pytest.mark.parametrize(
    "other",
    [
        "m*l^2*phi_dot^2/2 + 2*m*g*l*cos(phi)",  # another coefficient
        "m*l^2*phi_dot^2/2 + m*g*l*sin(phi)",  # another function
        "m*l^2*phi_dot^2/2 + m*g*l*cos(phi) + 0",  # the same value, another tree
        "1/2*m*l^2*phi_dot^2 + m*g*l*cos(phi)",  # the same value, another tree
        "m*l^2*phi_dot^2/2 + m*g*l*cos(phi) + 2.50",  # a number written otherwise
    ],
)
def test_an_answer_read_otherwise_is_judged(other):
    forget_problems()
    judge(PENDULUM, "lagrangian", RIGHT[0])
    before = verdict_cache_hits()
    got = judge(PENDULUM, "lagrangian", other)
    assert _hits(before) == 0
    assert _fields(got) == _fields(_fresh(PENDULUM, "lagrangian", other))


def test_the_parsers_notes_are_this_answers():
    """`phi(t)` reads as phi, with a note that a wrong answer's feedback ends with: the same
    tree and echo as `phi`, but not the same verdict, so it is judged; a respelling with the
    same note is found again."""
    forget_problems()
    plain = judge(PENDULUM, "lagrangian", WRONG[0])
    before = verdict_cache_hits()
    noted = judge(PENDULUM, "lagrangian", WRONG[0].replace("(phi)", "(phi(t))"))
    assert _hits(before) == 0
    assert noted.feedback == (*plain.feedback, "phi(t) is read as phi.")
    again = judge(PENDULUM, "lagrangian", "m l^2 phi_dot^2/2 - m g l cos(phi(t))")
    assert _hits(before) == 1
    assert _fields(again) == _fields(noted)


def test_an_unreadable_line_is_not_keyed():
    """Its message quotes the text and puts a caret under it: judged every time."""
    forget_problems()
    first = ["m*l^2*phi_ddot + m*g*l*sin(phi) = 0", "x +* 2"]
    judge(PENDULUM, "eom", first)
    before = verdict_cache_hits()
    second = ["m l^2 phi_ddot + m g l sin(phi) = 0", "x +*  2"]
    got = judge(PENDULUM, "eom", second)
    assert _hits(before) == 0
    assert "x +*  2" in " ".join(got.feedback)


def test_parts_that_read_the_raw_text_are_not_keyed():
    """A number's unit is read from the text beside the parser (converted, or named as the wrong
    unit), and so is the remark of a transformation: judged every time."""
    assert "transformation" not in SAME_READING_PARTS
    problem = {"scene": "wedge", "seed": 1, "quantity": "block_acceleration"}
    forget_problems()
    judge(problem, "expression", "5.39 m/s^2")
    before = verdict_cache_hits()
    judge(problem, "expression", "5.39  m/s^2")
    assert _hits(before) == 0
    assert reading_key(cached_problem(problem), "expression", "539 cm/s^2") is None


def test_a_closed_form_to_a_question_with_a_unit_is_keyed():
    """Without a number and its unit, the checker reads the closed form as the reader does."""
    problem = {"scene": "wedge", "seed": 1, "quantity": "block_acceleration"}
    forget_problems()
    judge(problem, "expression", "2*g*sin(alpha)")
    before = verdict_cache_hits()
    again = judge(problem, "expression", "2 g sin(alpha)")
    assert _hits(before) == 1
    assert _fields(again) == _fields(_fresh(problem, "expression", "2 g sin(alpha)"))


#: An expression question without a unit: its checker sees nothing of a plain answer but its
#: reading.
ENERGY = {
    "expression": "m*l^2*phi_dot^2/2 - m*g*l*cos(phi)",
    "parameters": {"m": "positive", "g": "positive", "l": "positive"},
    "coordinates": ["phi"],
}


@pytest.mark.parametrize(
    "first, second",
    [
        ("m*l^2*phi_dot^2/2 - m*g*l*cos(phi)", "m l**2 phi_dot^2/2 - m g l cos(φ)"),
        ("m*l^2*phi_dot^2/2 + m*g*l*cos(phi)", "m l^2 phi_dot**2 / 2 + m g l cos( phi )"),
        ("2*m*l^2*phi_dot^2 - m*g*l*cos(phi)", "2 m l^2 phi_dot^2 - m g l cos(phi)"),
    ],
)
def test_a_respelled_expression_gets_the_verdict_of_a_fresh_judgement(first, second):
    """Right or wrong (a named slip, an example point), every field what a fresh process
    gives the second spelling."""
    forget_problems()
    judge(ENERGY, "expression", first, limit=10.0)
    before = verdict_cache_hits()
    again = judge(ENERGY, "expression", second, limit=10.0)
    assert _hits(before) == 1
    forget_problems()
    assert _fields(again) == _fields(judge(ENERGY, "expression", second, limit=10.0))


@pytest.mark.parametrize(
    "first, second",
    [
        ("60°", "60 °"),  # an angle in degrees: read with a note from the text
        ("m*l^2*phi_dot^2/2 - m*g*l*cos(phi) = 1.5", "m l^2 phi_dot^2/2 - m g l cos(phi) = 1.5"),
    ],
)
def test_an_expression_read_beside_the_parser_is_not_keyed(first, second):
    """A degree sign, or a closed form and its value after `=`: the checker reads the text."""
    forget_problems()
    judge(ENERGY, "expression", first, limit=10.0)
    before = verdict_cache_hits()
    judge(ENERGY, "expression", second, limit=10.0)
    assert _hits(before) == 0
    assert reading_key(cached_problem(ENERGY), "expression", second) is None


def test_own_coordinates_are_not_keyed():
    """Judged in the student's own coordinates, an answer is read in another vocabulary."""
    forget_problems()
    given = {"transformation": ["x = l*sin(phi)", "y = -l*cos(phi)"]}
    judge(PENDULUM, "lagrangian", RIGHT[0], given)
    before = verdict_cache_hits()
    judge(PENDULUM, "lagrangian", RIGHT[1], given)
    assert _hits(before) == 0


@pytest.mark.parametrize(
    "hostile",
    [
        "__import__('os').system('true')",
        "eval(phi)",
        "m*g*l*cos(phi)" + ")" * 60,
        "(" * 45 + "phi" + ")" * 45,
        "phi^" * 40 + "2",
        "1" * 1_990,
        ["m*g*l*sin(phi) = 0"] * 200,
        {"not": "text"},
        12,
    ],
)
def test_hostile_text_gets_no_key_or_a_bounded_one(hostile):
    """Keying is the part's own reader and a walk over its tree: what the parser refuses has no
    key, and what it reads is keyed in a bounded walk, or not at all past the bound."""
    forget_problems()
    problem = cached_problem(PENDULUM)
    for part in ("lagrangian", "eom"):
        key = reading_key(problem, part, hostile)
        assert key is None or len(key) < 5 * len(json.dumps(hostile)) + 1_000


def test_a_long_answer_is_not_read_for_a_key():
    """On a miss the checker reads the answer again: past MAX_KEYED_CHARS, no key."""
    line = "m*l^2*phi_ddot + " + " + ".join(["m*g*l*sin(phi)/80"] * 80) + " = 0"
    assert 3 * len(line) > MAX_KEYED_CHARS
    problem = cached_problem(PENDULUM)
    assert reading_key(problem, "eom", [line] * 3) is None
    assert reading_key(problem, "eom", [line]) is not None


# --- a property over respellings ------------------------------------------------------------

SCENES = ("atwood", "spring_pendulum")


@functools.cache
def _items() -> list:
    return [item for item in corpus(SCENES, per_part=4) if item.part in SAME_READING_PARTS]


_BETWEEN_NAMES = re.compile(r"(?<=[A-Za-z0-9_)])\*(?=[A-Za-z(])")
_AROUND = re.compile(r"\s*([+=]|(?<![\^*(e])-)\s*")


@st.composite
def respelled(draw, text: str) -> str:
    """`text` spelled another way that reads the same: spaces around +, - and =, a `*`
    between two factors written as a space, `^` written `**`."""
    out = _AROUND.sub(lambda m: draw(st.sampled_from(["", " ", "  "])).join(["", m[1], ""]), text)
    out = _BETWEEN_NAMES.sub(lambda m: draw(st.sampled_from(["*", " ", " * "])), out)
    return re.sub(r"\^", lambda m: draw(st.sampled_from(["^", "**"])), out)


@st.composite
def respellings(draw):
    item = draw(st.sampled_from(_items()))
    lines = item.answer if isinstance(item.answer, list) else [item.answer]
    other = [draw(respelled(line)) for line in lines]
    return item, other if isinstance(item.answer, list) else other[0]


@pytest.mark.slow
@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(respellings())
def test_a_verdict_found_again_is_a_fresh_judgement(case):
    item, other = case
    forget_problems()
    first = judge(item.problem, item.part, item.answer)
    before = verdict_cache_hits()
    found = judge(item.problem, item.part, other)
    problem = cached_problem(item.problem)
    read = reading_key(problem, item.part, item.answer)
    if read is not None and read == reading_key(problem, item.part, other) and other != item.answer:
        assert _hits(before) == (first.status in ("correct", "incorrect"))
    assert _fields(found) == _fields(_fresh(item.problem, item.part, other))


def test_a_part_the_question_cannot_be_asked_is_refused_not_keyed():
    """`missing_reference` is the one rule: the driver keys no answer that `run_checker` refuses
    (a Lagrangian part of an expression question), and the refusal says why, every time."""
    from lagrade.errors import RequestError

    forget_problems()
    for answer in ("m*l^2*phi_dot^2/2", "m l^2 phi_dot^2/2"):
        with pytest.raises(RequestError, match="needs a scene or a Lagrangian"):
            judge(ENERGY, "lagrangian", answer, limit=10.0)
    assert verdict_cache_hits()["reading"] == 0
