"""Diagnosis only for wrong answers, and only as far as needed; the question's preparation has
its own budget, reported as `prepare_ms` and separate from the answer's `ms`."""

from lagrade.judge.check import cached_problem, check_request
from lagrade.judge.key import key_answer
from lagrade.notation.printer import plain


def _problem(spec):
    return cached_problem(spec)


def test_a_right_answer_builds_no_mistake_catalogue():
    spec = {"scene": "wedge", "seed": 9011}  # a question no other test asks
    problem = _problem(spec)
    answer = key_answer(problem.variant, "lagrangian")
    verdict = check_request({"problem": spec, "part": "lagrangian", "answer": answer}, 2.0)
    assert verdict.status == "correct", verdict
    assert "lagrangian" not in problem.catalogue.__dict__  # the lazy list was never made


def test_a_wrong_answer_builds_the_catalogue_only_up_to_its_match():
    spec = {"scene": "double_pendulum", "seed": 9013}
    problem = _problem(spec)
    T, V = problem.catalogue.split.T, problem.catalogue.split.V
    verdict = check_request({"problem": spec, "part": "lagrangian", "answer": plain(T + V)}, 2.0)
    assert verdict.status == "incorrect"
    assert verdict.mistakes == ("sign_of_V",)
    assert verdict.prepare_ms > 0  # the catalogue's first chunk was built for this answer
    assert not problem.catalogue.lagrangian.complete


def test_a_question_whose_budget_ran_out_times_out_at_once_for_later_answers():
    spec = {"scene": "wedge", "seed": 9017}
    problem = _problem(spec)
    problem.budget.left = 0.0
    verdict = check_request({"problem": spec, "part": "eom", "answer": ["q_ddot = 0"]}, 2.0)
    assert verdict.status == "timeout"
    assert verdict.feedback == (
        "The check ran out of time (deriving the question took longer than 60 s).",
    )


def test_results_report_prepare_ms_beside_ms():
    spec = {"expression": "g*sin(alpha)", "parameters": {"g": "positive", "alpha": "(0, 0.9)"}}
    first = check_request({"problem": spec, "part": "expression", "answer": "g sin(alpha)"}, 2.0)
    again = check_request({"problem": spec, "part": "expression", "answer": "sin(alpha) g"}, 2.0)
    assert list(first.to_dict())[5:7] == ["ms", "prepare_ms"]
    assert first.prepare_ms > 0 and again.prepare_ms == 0
