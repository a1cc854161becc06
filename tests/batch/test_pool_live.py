"""`LivePool`, the killable workers fed one item at a time (the answer page's): a quick item is
not held behind slow ones, an item held in C code is killed at its deadline with the notes it
sent, a slow item's worker yields the processors and is replaced, and closing answers every
open item."""

from __future__ import annotations

import asyncio
import os
import signal
import socket
import time
from pathlib import Path

from lagrade.judge.clocks import note
from lagrade.judge.live import SLOW_NICE, LivePool
from lagrade.judge.worker import Limits


def _work(item):
    """("quick",) | ("spin",) one C call no signal interrupts | ("sleep", s) | ("notes",)."""
    kind = item[0]
    if kind == "spin":
        sum(range(10**13))
    elif kind == "sleep":
        time.sleep(item[1])
    elif kind == "notes":
        note("first part judged")
        note("second part begun")
        sum(range(10**13))
    return os.getpid(), os.getpriority(os.PRIO_PROCESS, 0)


def test_a_quick_item_is_not_held_behind_items_held_in_c():
    with_limit = Limits(seconds=3.0)
    pool = LivePool(_work, jobs=1, burst=2, limits=with_limit)
    try:
        start = time.monotonic()
        spins = [pool.submit(k, ("spin",)) for k in range(2)]
        time.sleep(1.0)
        quick = pool.submit("quick", ("quick",))
        assert quick.result(timeout=30).status == "ok"
        quick_done = time.monotonic() - start
        outcomes = [f.result(timeout=30) for f in spins]
        assert [o.status for o in outcomes] == ["timeout", "timeout"]
        assert all(3.0 <= o.seconds < 4.5 for o in outcomes), outcomes
        assert quick_done < 2.0  # not after the spins' 3 s
    finally:
        pool.close()


def test_without_a_burst_the_quick_item_waits_for_the_kill():
    """The control: one worker and no burst, the quick item waits for the spin's deadline."""
    pool = LivePool(_work, jobs=1, burst=0, limits=Limits(seconds=2.0))
    try:
        start = time.monotonic()
        spin = pool.submit("spin", ("spin",))
        time.sleep(0.5)
        assert pool.submit("quick", ("quick",)).result(timeout=30).status == "ok"
        assert time.monotonic() - start >= 2.0
        assert spin.result(timeout=30).status == "timeout"
    finally:
        pool.close()


def test_a_killed_item_carries_the_notes_it_sent():
    pool = LivePool(_work, jobs=1, limits=Limits(seconds=1.0))
    try:
        outcome = pool.submit("sheet", ("notes",)).result(timeout=30)
    finally:
        pool.close()
    assert outcome.key == "sheet" and outcome.status == "timeout"
    assert outcome.value == ("first part judged", "second part begun")


def test_a_slow_items_worker_runs_niced_and_is_replaced_after_it():
    pool = LivePool(_work, jobs=1, limits=Limits(seconds=10.0))
    try:
        first_pid, first_nice = pool.submit(0, ("quick",)).result(timeout=30).value
        slow_pid, slow_nice = pool.submit(1, ("sleep", 1.0)).result(timeout=30).value
        next_pid, next_nice = pool.submit(2, ("quick",)).result(timeout=30).value
    finally:
        pool.close()
    assert first_pid == slow_pid  # the same warm worker, until its item turned slow
    assert (first_nice, slow_nice, next_nice) == (0, SLOW_NICE, 0)
    assert next_pid != slow_pid


def test_outcomes_are_awaited_on_an_event_loop_and_close_answers_the_rest():
    pool = LivePool(_work, jobs=2, limits=Limits(seconds=30.0))

    async def ask():
        return await asyncio.gather(*(pool.outcome(k, ("quick",)) for k in range(5)))

    try:
        outcomes = asyncio.run(ask())
        assert [o.key for o in outcomes] == list(range(5))
        assert all(o.status == "ok" for o in outcomes)
        held = pool.submit("held", ("sleep", 20))
        time.sleep(0.5)
    finally:
        pool.close()
    assert held.result(timeout=5).status == "error"
    assert pool.submit("late", ("quick",)).result(timeout=5).status == "error"


def _running(pid: int) -> bool:
    """Whether a process exists and is not a zombie waiting for its new parent to reap it."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def test_a_host_that_died_is_started_again():
    pool = LivePool(_work, jobs=1, limits=Limits(seconds=30.0))
    try:
        first_pid, _ = pool.submit(0, ("quick",)).result(timeout=30).value
        held = pool.submit(1, ("sleep", 20))
        time.sleep(0.5)
        host = pool._host.pid
        workers = [int(p) for p in Path(f"/proc/{host}/task/{host}/children").read_text().split()]
        assert workers
        os.kill(host, signal.SIGKILL)  # as the system's OOM killer would
        assert held.result(timeout=10).status == "error"
        time.sleep(1.0)
        assert not [pid for pid in workers if _running(pid)]  # they died with it
        again = pool.submit(2, ("quick",)).result(timeout=30)
        assert again.status == "ok" and again.value[0] != first_pid
    finally:
        pool.close()


def test_the_host_does_not_hold_the_servers_sockets():
    """A connection the server closes must close: the host and its workers keep no copy."""
    listener = socket.create_server(("127.0.0.1", 0))
    pool = LivePool(_work, jobs=1, limits=Limits(seconds=30.0))
    try:
        worker_pid, _ = pool.submit(0, ("quick",)).result(timeout=30).value
        inode = os.fstat(listener.fileno()).st_ino
        for pid in (pool._host.pid, worker_pid):
            links = [os.readlink(f"/proc/{pid}/fd/{fd}") for fd in os.listdir(f"/proc/{pid}/fd")]
            assert f"socket:[{inode}]" not in links, pid
    finally:
        pool.close()
        listener.close()
