"""A busy worker is sent its next item ahead, so it never waits for the parent between items; an
item sent ahead is never lost or run twice: not when the item in hand times out and its worker
is killed, not when the worker is recycled, and an item too large for the pipe waits instead."""

import os
import time

from lagrade.judge.worker import AHEAD_BYTES, Limits, Pool


def _record(item):
    """(pid, the item's tag), after sleeping as long as the item says."""
    tag, pause, _padding = item
    time.sleep(pause)
    return os.getpid(), tag


def _items(pauses, padding=""):
    return [(i, (i, pause, padding)) for i, pause in enumerate(pauses)]


def test_every_item_once_and_in_order():
    with Pool(_record, jobs=1) as pool:
        outcomes = list(pool.run(_items([0.0] * 30), in_order=True))
    assert [o.key for o in outcomes] == list(range(30))
    assert [o.value[1] for o in outcomes] == list(range(30))
    assert len({o.value[0] for o in outcomes}) == 1  # one worker served them all


def test_a_timed_out_item_does_not_take_the_item_sent_ahead_with_it():
    # item 1 sleeps past the kill; item 2 was already waiting in the killed worker's pipe
    with Pool(_record, jobs=1, limits=Limits(seconds=0.5)) as pool:
        outcomes = list(pool.run(_items([0.0, 5.0, 0.0, 0.0]), in_order=True))
    assert [o.status for o in outcomes] == ["ok", "timeout", "ok", "ok"]
    assert [o.value[1] for o in outcomes if o.status == "ok"] == [0, 2, 3]
    assert outcomes[0].value[0] != outcomes[2].value[0]  # a fresh worker took item 2


def test_a_recycled_worker_is_sent_nothing_ahead():
    with Pool(_record, jobs=1, limits=Limits(recycle=3)) as pool:
        outcomes = list(pool.run(_items([0.01] * 7), in_order=True))
    assert [o.value[1] for o in outcomes] == list(range(7))
    pids = [o.value[0] for o in outcomes]
    assert pids[0] == pids[2] != pids[3] == pids[5] != pids[6]  # three items per worker


def test_large_items_wait_for_the_worker_instead():
    padding = "x" * (2 * AHEAD_BYTES)
    with Pool(_record, jobs=2) as pool:
        outcomes = list(pool.run(_items([0.01] * 6, padding), in_order=True))
    assert [o.value[1] for o in outcomes] == list(range(6))
