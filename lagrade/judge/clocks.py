"""The clocks of judging: a part's time limit (`time_limit`, an alarm that interrupts Python-level
work), a question's preparation budget (`Budget`, with `set_aside` for the question's work done on
demand inside a part), and the item's deadline and progress notes a worker reports to the parent
that kills it (`deadline`, `note`). Kept apart from the process pool (`lagrade.judge.worker`),
so that a domain object that charges its work to a budget (the mistake catalogue) needs no pool.

The rule. A part gets its time limit once its question is prepared; instructor-side work done on
demand (the catalogue for a wrong answer) is charged to the question's budget, not the student's
clock. The alarm interrupts Python-level work; the parent kills a worker that has not answered
`GRACE` seconds after its deadline (C code the alarm cannot stop).
"""

from __future__ import annotations

import signal
import time
from contextlib import contextmanager
from dataclasses import dataclass
from multiprocessing.connection import Connection
from typing import Any

#: Seconds past a part's time limit before the parent kills the worker (the alarm comes first).
GRACE = 2.0
#: Seconds of instructor-side work a question may take in one process (deriving its reference,
#: sample points and, for wrong answers, its mistake catalogue): its `Budget`.
PREPARE_LIMIT = 60.0


class PartTimeout(BaseException):
    """A part's time limit ran out (raised by the alarm inside the process doing the work). A
    BaseException, like KeyboardInterrupt, so that no `except Exception` on the way swallows it."""


class PreparationTimeout(PartTimeout):
    """A question's preparation budget ran out (in `set_aside` work): the question, not the
    answer, is what took too long."""


@dataclass
class Budget:
    """The seconds of instructor-side work a question may still take, and what it has spent. One
    per question and process: once `left` is used up, every later answer to the question gets
    the same timeout at once instead of trying again."""

    left: float
    spent: float = 0.0

    @property
    def exhausted(self) -> bool:
        return self.left <= 0

    def charge(self, seconds: float) -> None:
        """Count `seconds` of the question's work against it."""
        self.left -= seconds
        self.spent += seconds


_aside = False  # inside set_aside: nested instructor work is charged by the outer one


@contextmanager
def set_aside(budget: Budget, timed: bool | None = None):
    """Run the block as the question's work, not the student's: a running part clock stops and
    the question's remaining budget applies instead (PreparationTimeout when it runs out), then
    the part clock goes on with the time it had left. The time is charged to `budget`.
    `timed`: whether to enforce the budget (default: only when a part clock is running, so that
    an untimed in-process check stays untimed)."""
    global _aside
    if _aside:
        yield
        return
    remaining = signal.getitimer(signal.ITIMER_REAL)[0]
    if timed is None:
        timed = remaining > 0
    if timed and budget.exhausted:
        raise PreparationTimeout
    previous = None
    if timed:

        def ring(signum, frame):
            raise PreparationTimeout

        previous = signal.signal(signal.SIGALRM, ring)
        signal.setitimer(signal.ITIMER_REAL, budget.left)
        if remaining > 0:  # before any part clock, the item's first deadline covers the budget
            deadline(budget.left + GRACE)
    _aside = True
    start = time.perf_counter()
    try:
        yield
    finally:
        _aside = False
        budget.charge(time.perf_counter() - start)
        if timed:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
            if remaining > 0:
                signal.setitimer(signal.ITIMER_REAL, remaining)
                deadline(remaining + GRACE)


@contextmanager
def time_limit(seconds: float | None):
    """Interrupt Python-level work after `seconds` with PartTimeout (None: no limit). The
    parent's kill at the deadline backs this up for C code that never returns to Python."""
    if seconds is None:
        yield
        return

    def ring(signum, frame):
        raise PartTimeout

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


_parent: Connection | None = None  # set inside a worker: where deadline() reports to


def report_to(conn: Connection | None) -> None:
    """Inside a worker: send `deadline` and `note` reports to `conn` (the pool's pipe)."""
    global _parent
    _parent = conn


def deadline(seconds: float) -> None:
    """Inside a worker: the item in hand must finish within `seconds` from now, else the parent
    kills the worker. Outside a worker (work run in-process) it does nothing."""
    if _parent is not None:
        _parent.send(("deadline", float(seconds)))


def note(value: Any, then_within: float | None = None) -> None:
    """Inside a worker: record `value` (picklable, small) as progress of the item in hand. If the
    worker is killed before the item finishes, its `timeout` Outcome's value is the tuple of
    these notes in order. `then_within`: what follows must finish within these seconds from
    now (`deadline`), in the same message: one pipe round a request, not two. Outside a worker
    it does nothing."""
    if _parent is not None:
        if then_within is None:
            _parent.send(("note", value))
        else:
            _parent.send(("note", value, float(then_within)))
