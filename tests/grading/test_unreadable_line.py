"""Issue 12: a multi-line part with one unreadable line is judged on the lines that read; the
unreadable line is named in the feedback with the parser's message, and counts as a wrong one.
Only an answer of which no line reads is `invalid`."""

from __future__ import annotations

import pytest

from lagrade.bank.registry import get_scene
from lagrade.judge.check import check
from lagrade.judge.key import key_answer

PROBLEM = {"scene": "wedge", "seed": 1}


@pytest.fixture(scope="module")
def variant():
    return get_scene("wedge").variant(1)


def _unbalanced(line: str) -> str:
    """The line with one ')' removed: an unclosed bracket."""
    assert ")" in line
    return line.replace(")", "", 1)


@pytest.mark.parametrize("part", ["eom", "momenta"])
def test_one_unreadable_line_is_judged_not_invalid(variant, part):
    key = key_answer(variant, part)
    assert len(key) == 2
    broken = _unbalanced(key[1])
    v = check(PROBLEM, part, [key[0], broken], time_limit=None)
    assert v.status == "incorrect"
    assert 0.0 < v.score < 1.0
    text = "\n".join(v.feedback)
    assert "Line 2" in text
    # the parser's own message, caret text included
    alone = check(PROBLEM, part, [broken], time_limit=None)
    assert alone.status == "invalid"
    message = alone.feedback[0]
    assert message in text
    assert "^" in text
    # one entry per line: the echo of line 1, "" for the unreadable line 2
    assert isinstance(v.interpreted, list) and len(v.interpreted) == 2
    assert v.interpreted[0] and v.interpreted[1] == ""


@pytest.mark.parametrize("part", ["eom", "momenta"])
def test_unreadable_first_line_keeps_its_place(variant, part):
    key = key_answer(variant, part)
    v = check(PROBLEM, part, [_unbalanced(key[0]), key[1]], time_limit=None)
    assert v.status == "incorrect"
    assert 0.0 < v.score < 1.0
    assert "Line 1" in "\n".join(v.feedback)
    assert v.interpreted[0] == "" and v.interpreted[1]


@pytest.mark.parametrize("part", ["eom", "momenta"])
def test_all_lines_unreadable_is_invalid(variant, part):
    key = key_answer(variant, part)
    v = check(PROBLEM, part, [_unbalanced(line) for line in key], time_limit=None)
    assert v.status == "invalid"
    assert v.score == 0.0
    text = "\n".join(v.feedback)
    assert "Line 1" in text and "Line 2" in text


def test_conserved_one_unreadable_line(variant):
    key = key_answer(variant, "conserved")
    lines = list(key) if isinstance(key, list) else [key]
    v = check(PROBLEM, "conserved", [*lines, "x_M_dot + ("], time_limit=None)
    assert v.status == "incorrect"
    assert 0.0 < v.score < 1.0
    assert f"Line {len(lines) + 1}" in "\n".join(v.feedback)
