"""Diagnosis only for wrong answers, and only as far as needed; the question's preparation has
its own budget, reported as `prepare_ms` and separate from the answer's `ms`."""

import time

import sympy as sp

from lagrade.judge.check import check_request
from lagrade.judge.driver import cached_problem
from lagrade.judge.key import key_answer
from lagrade.judge.problem import build_problem
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


def test_a_wrong_answer_builds_the_catalogue_only_up_to_an_explanation_of_one_term():
    """Of the true explanations the one that changes the fewest terms is named (issue 25), so
    the search ends at one that changes a single term: none can beat it."""
    spec = {"scene": "double_pendulum", "seed": 9013}
    problem = _problem(spec)
    T, V = problem.catalogue.split.T, problem.catalogue.split.V
    half = next(t for t in sp.Add.make_args(sp.expand(T)) if t.as_coeff_Mul()[0].q == 2)
    answer = plain(T + half - V)
    verdict = check_request({"problem": spec, "part": "lagrangian", "answer": answer}, 2.0)
    assert verdict.status == "incorrect"
    assert verdict.mistakes == ("dropped_half",), verdict
    assert verdict.prepare_ms > 0  # the catalogue's first chunk was built for this answer
    assert not problem.catalogue.lagrangian.complete


def test_an_explanation_of_several_terms_is_named_when_none_changes_fewer():
    spec = {"scene": "double_pendulum", "seed": 9019}
    problem = _problem(spec)
    T, V = problem.catalogue.split.T, problem.catalogue.split.V
    verdict = check_request({"problem": spec, "part": "lagrangian", "answer": plain(T + V)}, 2.0)
    assert verdict.status == "incorrect"
    assert verdict.mistakes == ("sign_of_V",)


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


def test_reading_the_question_counts_as_its_preparation():
    """Parsing an ad-hoc problem's L is the instructor's side of the work: the first answer's
    `prepare_ms` includes it (it once fell outside both clocks)."""
    from lagrade.judge.driver import _problems
    from lagrade.judge.problem import problem_key

    spec = {
        "lagrangian": "m*l^2*theta_dot^2/2 + m*g*l*cos(theta) + 0*k_9021",
        "coordinates": ["theta"],
        "parameters": {"m": "positive", "g": "positive", "l": "positive", "k_9021": "positive"},
    }
    first = check_request({"problem": spec, "part": "cyclic", "answer": "none"}, 2.0)
    problem = _problems[problem_key(spec)]
    assert first.status == "correct"
    # cyclic needs no derivation: what it reports is the reading of the question, and all of it
    start = time.perf_counter()
    build_problem(spec)
    reading_ms = (time.perf_counter() - start) * 1e3
    assert first.prepare_ms >= 0.3 * reading_ms > 0
    assert abs(first.prepare_ms - problem.budget.spent * 1e3) < 1e-6
