"""`--jobs N` really spreads distinct questions over N processes, keeps all the answers to one
question in the process that derived it, and still returns the results in request order."""

import os
import time

from lagrade.judge.worker import Pool


def _pid_after(item):
    _question, pause = item
    time.sleep(pause)
    return os.getpid()


def test_distinct_questions_use_distinct_workers_and_one_question_one_worker():
    items = [(i, (q, 0.02)) for i, q in enumerate("aaaabbbbccccdddd")]
    with Pool(_pid_after, jobs=2, affinity=lambda item: item[0]) as pool:
        outcomes = list(pool.run(items, in_order=True))
    assert [o.key for o in outcomes] == list(range(16))  # request order
    pids = [o.value for o in outcomes]
    by_question = {q: {pids[i] for i in range(16) if "aaaabbbbccccdddd"[i] == q} for q in "abcd"}
    assert all(len(p) == 1 for p in by_question.values()), by_question
    assert len(set(pids)) == 2  # both processes were used


def test_a_question_with_many_answers_is_shared_when_nothing_else_is_left():
    items = [(i, ("a", 0.02)) for i in range(12)]
    with Pool(_pid_after, jobs=2, affinity=lambda item: item[0]) as pool:
        pids = [o.value for o in pool.run(items, in_order=True)]
    assert len(set(pids)) == 2


def test_without_affinity_items_go_first_come_first_served():
    items = [(i, ("a", 0.0)) for i in range(6)]
    with Pool(_pid_after, jobs=1) as pool:
        assert [o.key for o in pool.run(items, in_order=True)] == list(range(6))
