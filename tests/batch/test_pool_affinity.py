"""`--jobs N` really spreads distinct questions over N processes, keeps all the answers to one
question in the process that derived it, and still returns the results in request order."""

import os
import time
from collections import deque

from lagrade.judge.worker import Pool


def _pid_after(item):
    _question, pause = item
    time.sleep(pause)
    return os.getpid()


def test_distinct_questions_use_distinct_workers_and_keep_request_order():
    """Real processes: the first answers to two questions start on two workers at once, and
    the results come back in request order. (Which worker takes the last answers depends on
    which finishes first, so that is pinned below on the scheduling rule itself.)"""
    items = [(i, (q, 0.02)) for i, q in enumerate("aaaabbbbccccdddd")]
    with Pool(_pid_after, jobs=2, affinity=lambda item: item[0]) as pool:
        outcomes = list(pool.run(items, in_order=True))
    assert [o.key for o in outcomes] == list(range(16))  # request order
    pids = [o.value for o in outcomes]
    assert pids[0] != pids[4]  # a and b were handed to the two workers first
    assert len(set(pids)) == 2


def _pending(groups: str) -> dict:
    pending: dict = {}
    for position, group in enumerate(groups):
        pending.setdefault(group, deque()).append((position, position, (group, 0)))
    return pending


def test_a_worker_keeps_to_its_own_question_while_others_are_unowned():
    """The scheduling rule, without timing: a slot takes its own question's answers first,
    then a question nobody owns, and another worker's question only when nothing else is left."""
    pool = Pool(_pid_after, jobs=2, affinity=lambda item: item[0])
    pending = _pending("aabbcc")
    taken = [pool._take(slot, pending)[2][0] for slot in (0, 1)]
    assert taken == ["a", "b"]  # distinct questions to distinct slots
    assert pool._take(0, pending)[2][0] == "a"  # its own before anything else
    assert pool._take(1, pending)[2][0] == "b"
    assert pool._take(0, pending)[2][0] == "c"  # a is done: an unowned question, not b
    assert pool._take(0, pending)[2][0] == "c"
    pending = _pending("bb")
    assert pool._take(0, pending)[2][0] == "b"  # only slot 1's question is left: shared


def test_a_question_with_many_answers_is_shared_when_nothing_else_is_left():
    items = [(i, ("a", 0.02)) for i in range(12)]
    with Pool(_pid_after, jobs=2, affinity=lambda item: item[0]) as pool:
        pids = [o.value for o in pool.run(items, in_order=True)]
    assert len(set(pids)) == 2


def test_without_affinity_items_go_first_come_first_served():
    items = [(i, ("a", 0.0)) for i in range(6)]
    with Pool(_pid_after, jobs=1) as pool:
        assert [o.key for o in pool.run(items, in_order=True)] == list(range(6))
