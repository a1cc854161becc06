"""An answer a process has decided before is not judged again: the same question, part, answer
and given get the same verdict, with `ms` the lookup and `prepare_ms` 0. What may not happen
again (a timeout) is not remembered."""

import importlib

import pytest

from lagrade.judge.check import check_request
from lagrade.judge.driver import cached_problem, forget_problems

check_module = importlib.import_module("lagrade.judge.driver")


@pytest.fixture
def judged(monkeypatch):
    """The requests that reached a checker."""
    calls = []
    real = check_module.run_checker

    def counting(problem, part, answer, given):
        calls.append((part, answer, given))
        return real(problem, part, answer, given)

    monkeypatch.setattr(check_module, "run_checker", counting)
    return calls


EXPRESSION = {"expression": "g*sin(alpha)/3", "parameters": {"g": "positive", "alpha": "(0, 1)"}}


def test_a_repeated_answer_gets_the_same_verdict_without_judging(judged):
    request = {"problem": EXPRESSION, "part": "expression", "answer": "g cos(alpha)/3"}
    first = check_request(request, 2.0)
    again = check_request(dict(request), 2.0)
    assert len(judged) == 1
    assert first.status == "incorrect" and first.mistakes == ("sin_cos_swapped",)
    timing = ("ms", "prepare_ms")
    assert {k: v for k, v in again.__dict__.items() if k not in timing} == {
        k: v for k, v in first.__dict__.items() if k not in timing
    }
    assert again.prepare_ms == 0 and again.ms < first.ms


@pytest.mark.parametrize(
    ("power", "other"),
    [
        (2, {"answer": "alpha^2*g"}),  # other text read otherwise, though equal
        (3, {"part": "lagrangian"}),  # another part (refused: the problem has no L)
        (4, {"given": {"lagrangian": "x"}}),
    ],
)
def test_only_the_very_same_request_is_remembered(judged, power, other):
    spec = {"expression": f"g*alpha^{power}", "parameters": {"g": "positive", "alpha": "(0, 1)"}}
    request = {"problem": spec, "part": "expression", "answer": f"g alpha^{power}"}
    check_request(request, 2.0)
    try:
        check_request({**request, **other}, 2.0)
    except Exception:  # noqa: BLE001 - a refused request was still not answered from memory
        pass
    assert len(judged) == 2


def test_a_timeout_is_not_remembered(judged):
    spec = {"scene": "wedge", "seed": 9101}
    problem = cached_problem(spec)
    request = {"problem": spec, "part": "dof", "answer": "2"}
    left = problem.budget.left
    problem.budget.left = 0.0  # the question's budget has run out: every answer times out
    assert check_request(request, 2.0).status == "timeout"
    problem.budget.left = left
    assert check_request(request, 2.0).status == "correct"
    assert len(judged) == 1


def test_a_long_answer_is_judged_every_time(judged):
    """The memory stays bounded: an answer longer than `_REMEMBERED_CHARS` is not kept."""
    spec = {"expression": "g*alpha^5", "parameters": {"g": "positive", "alpha": "(0, 1)"}}
    long = " + ".join(["g alpha^5"] + ["0"] * (check_module._REMEMBERED_CHARS // 3))
    request = {"problem": spec, "part": "expression", "answer": long}
    first = check_request(request, 10.0)  # too long to parse, too: `invalid`, which is settled
    assert check_request(request, 10.0).status == first.status == "invalid"
    assert len(judged) == 2


def test_a_remembered_answer_needs_no_question(judged, monkeypatch):
    """The answer's key is the problem field's: a question dropped from the process's cache is
    not read again for an answer already decided."""
    spec = {"expression": "g*alpha^6", "parameters": {"g": "positive", "alpha": "(0, 1)"}}
    request = {"problem": spec, "part": "expression", "answer": "g alpha^6"}
    check_request(request, 2.0)
    check_module._problems.clear()
    check_module._prepared.clear()
    monkeypatch.setattr(check_module, "build_problem", lambda spec: pytest.fail("read again"))
    assert check_request(request, 2.0).status == "correct"
    assert len(judged) == 1


def test_a_request_encodes_its_problem_field_once(monkeypatch):
    """The question's key is made once per request (the driver hands it to its cache)."""
    keys = []
    real = check_module.problem_key
    monkeypatch.setattr(check_module, "problem_key", lambda spec: keys.append(spec) or real(spec))
    request = {"problem": EXPRESSION, "part": "expression", "answer": "g*sin(alpha)/3 + 0"}
    check_request(request, 2.0)
    keys.clear()
    check_request({**request, "answer": "g sin(alpha) / 3 + 0*g"}, 2.0)
    assert len(keys) == 1


def test_an_expression_spelled_otherwise_but_read_the_same_is_not_judged_again(judged):
    """The second level (`same_reading`): `g*alpha^2 ` reads as `g alpha^2` does, and an
    expression question without a unit reads nothing of the text beside the parser."""
    forget_problems()  # nothing judged before in this process
    spec = {"expression": "g*alpha^2", "parameters": {"g": "positive", "alpha": "(0, 1)"}}
    request = {"problem": spec, "part": "expression", "answer": "g alpha^2"}
    first = check_request(request, 2.0)
    again = check_request({**request, "answer": "g*alpha^2 "}, 2.0)
    assert len(judged) == 1
    assert again.to_dict(timings=False) == first.to_dict(timings=False)
