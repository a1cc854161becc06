"""Untrusted work in killable processes, for `check --batch`, the `check()` API and `grade` alike.

A worker runs items one at a time under the clocks of `lagrade.judge.clocks`: inside, an alarm
interrupts Python-level work at a part's limit; here, the parent kills a worker that has not
answered `GRACE` seconds after the item's deadline (SIGKILL stops sympy or numpy stuck in C code);
the item in hand then gets `timeout`, a fresh worker takes the rest. A worker moves the parent's
deadline for the item in hand with `clocks.deadline(seconds)`, and tells the parent what the item
has achieved so far with `clocks.note(value)`: a killed item's `timeout` Outcome carries those
notes, so work done before the kill (the parts of a sheet already judged) is kept and only the
rest is done again.

Workers are forked and persistent: what the parent derived before the pool started is shared,
what a worker derives stays for its next items, and a worker is replaced after `Limits.recycle`
items so that the memory of a long run stays bounded. A memory limit backs up the wall clock.
"""

from __future__ import annotations

import gc
import multiprocessing as mp
import os
import resource
import signal
import time
import traceback
from collections import deque
from collections.abc import Callable, Hashable, Iterable, Iterator
from dataclasses import dataclass, field
from multiprocessing.connection import Connection, wait
from multiprocessing.reduction import ForkingPickler
from typing import Any

from lagrade.errors import LagradeError
from lagrade.judge.clocks import report_to

_FORK = mp.get_context("fork")

#: Allocations between collections of the youngest generation in a worker (Python's default:
#: 700).
GC_THRESHOLD = 10_000
#: Seconds an idle worker waits between checks that its parent is still alive.
ORPHAN_CHECK = 1.0


@dataclass(frozen=True)
class Limits:
    """Per-item deadline (seconds from when a worker starts the item, until the item moves it),
    extra memory in MiB over what the parent used when it forked, and the number of items after
    which a worker is replaced."""

    seconds: float = 30.0
    memory_mib: int = 2048
    recycle: int = 1000


@dataclass(frozen=True)
class Outcome:
    """What became of one item: `ok` with its value; `refused` with the LagradeError the work
    raised (a user's error, to be reported as such); `timeout` or `error` (a bug of ours, or a
    worker that died) with a reason. A `timeout` whose worker was killed, and an `error` whose
    worker died or reported one, has as value the notes the item sent before (`note`), a
    tuple, empty when it sent none."""

    key: Any
    status: str  # "ok" | "refused" | "timeout" | "error"
    value: Any = None
    reason: str = ""
    seconds: float = 0.0


def address_space_in_use() -> int:
    """Virtual memory of this process in bytes (Linux), so a memory limit adds to it."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except OSError:
        return 0


def _serve(conn: Connection, work: Callable[[Any], Any], limits: Limits) -> None:
    """The worker loop: an item in, ("done", status, value) out, until None or EOF."""
    report_to(conn)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and kills us
    # The parent stops us with SIGTERM: die quietly, not through the CLI's handler (inherited
    # by the fork), which would raise KeyboardInterrupt and print a traceback from the child.
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        ceiling = address_space_in_use() + limits.memory_mib * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (ceiling, ceiling))
    except (ValueError, OSError):
        pass  # a platform without the limit still has the wall-clock kill
    # Judging builds and drops sympy trees by the thousand: with the default threshold the cycle
    # collector runs every 700 allocations and rescans everything inherited from the parent.
    # Freezing what was inherited and collecting less often took 3-5 % off a cold batch.
    gc.freeze()
    gc.set_threshold(GC_THRESHOLD, 20, 20)
    parent_pid = os.getppid()
    while True:
        try:
            # A parent killed outright (SIGKILL) never closes our pipe: forked siblings hold
            # copies of its end. So wait in slices and leave once the parent is gone.
            while not conn.poll(ORPHAN_CHECK):
                if os.getppid() != parent_pid:
                    return
            item = conn.recv()
        except (EOFError, OSError):
            return
        if item is None:
            return
        try:
            reply: tuple[str, Any] = ("ok", work(item))
        except LagradeError as error:
            reply = ("refused", error)
        except MemoryError:
            reply = ("error", "ran out of memory (limit exceeded)")
        except BaseException as error:  # noqa: BLE001 - the worker reports everything
            reply = ("error", f"{type(error).__name__}: {error}\n{traceback.format_exc(limit=8)}")
        try:
            conn.send(("done", *reply))
        except Exception as error:  # noqa: BLE001 - an unpicklable result is still an answer
            conn.send(("done", "error", f"result could not be sent back: {error}"))


@dataclass
class _Worker:
    process: Any
    conn: Connection
    slot: int = 0
    served: int = 0
    key: Any = None
    since: float = 0.0
    until: float = 0.0
    queued: tuple | None = None  # (position, key, item) sent ahead, waiting in the pipe
    notes: list = field(default_factory=list)  # what the item in hand has noted so far


#: Largest pickled item sent to a busy worker ahead of time. The worker reads it only when it
#: is done with the item in hand, so it must fit the pipe's buffer: a parent blocked on a full
#: pipe while the worker blocks sending its result would wait forever.
AHEAD_BYTES = 16_384


class Pool:
    """`jobs` persistent forked workers running `work(item)`; `run` yields one Outcome per item.
    `work` and everything the parent holds when a worker is forked are inherited, not pickled;
    items and results cross a pipe.

    With `affinity` (a function of an item), items of the same affinity go to the worker slot
    that has had one before while there are other items for the idle workers: a worker's caches
    (a question derived once) serve all the answers to that question, and distinct questions
    are spread over the workers. A worker that finds only items owned by busy workers takes
    the first of them (a question with many answers is then shared)."""

    def __init__(
        self,
        work: Callable[[Any], Any],
        *,
        jobs: int = 1,
        limits: Limits | None = None,
        affinity: Callable[[Any], Hashable] | None = None,
    ) -> None:
        self.work = work
        self.jobs = max(1, int(jobs))
        self.limits = limits or Limits()
        self.affinity = affinity
        self._idle: dict[int, _Worker] = {}
        self._owners: dict[Hashable, set[int]] = {}

    def _fork(self, slot: int) -> _Worker:
        parent, child = _FORK.Pipe()
        process = _FORK.Process(target=_serve, args=(child, self.work, self.limits), daemon=True)
        process.start()
        child.close()
        return _Worker(process, parent, slot)

    def _retire(self, worker: _Worker, kill: bool = False) -> None:
        if not kill and worker.process.is_alive():
            try:
                worker.conn.send(None)
                worker.process.join(1.0)
            except OSError:
                pass
        if worker.process.is_alive():
            worker.process.kill()
        worker.process.join(2.0)
        worker.conn.close()

    def _take(self, slot: int, pending: dict) -> tuple[int, Any, Any]:
        """The next (position, key, item) for the worker in `slot`: the first pending item whose
        affinity is its own or no one's, else the first pending item."""
        chosen = None
        for group in pending:
            owners = self._owners.get(group)
            if not owners or slot in owners:
                chosen = group
                break
        if chosen is None:
            chosen = next(iter(pending))
        queue = pending[chosen]
        entry = queue.popleft()
        if not queue:
            del pending[chosen]
        if self.affinity is not None:
            self._owners.setdefault(chosen, set()).add(slot)
        return entry

    def run(self, items: Iterable[tuple[Any, Any]], *, in_order: bool = False) -> Iterator[Outcome]:
        """An Outcome for each (key, item): as each finishes, or in input order (`in_order`)."""
        pending: dict[Hashable, deque] = {}  # by affinity, in order of each group's first item
        for position, (key, item) in enumerate(items):
            group = position if self.affinity is None else self.affinity(item)
            pending.setdefault(group, deque()).append((position, key, item))
        busy: dict[Connection, _Worker] = {}
        held: dict[int, Outcome] = {}
        next_out = 0
        try:
            while pending or busy:
                while pending and len(busy) < self.jobs:
                    taken = {w.slot for w in busy.values()}
                    slot = next(s for s in range(self.jobs) if s not in taken)
                    position, key, item = self._take(slot, pending)
                    worker = self._idle.pop(slot, None) or self._fork(slot)
                    try:
                        worker.conn.send(item)
                    except OSError:  # it died while idle: a fresh one takes the item
                        self._retire(worker, kill=True)
                        worker = self._fork(slot)
                        worker.conn.send(item)
                    self._start(worker, position, key)
                    busy[worker.conn] = worker
                self._send_ahead(busy, pending)
                soonest = min(w.until for w in busy.values())
                for conn in wait(list(busy), timeout=max(0.0, soonest - time.monotonic())):
                    worker = busy[conn]
                    done = self._receive(worker)
                    while done is None and conn.poll(0):  # its next messages, already sent
                        done = self._receive(worker)
                    if done is None:
                        continue
                    del busy[conn]
                    held[worker.key[1]] = done
                    if worker.queued is not None:  # it has begun the item sent ahead
                        if self._idle.get(worker.slot) is worker:
                            del self._idle[worker.slot]
                            self._start(worker, *worker.queued[:2])
                            worker.queued = None
                            busy[conn] = worker
                        else:  # it died before it could take it (none is sent to its last)
                            self._requeue(worker, pending)
                for conn, worker in list(busy.items()):
                    if time.monotonic() >= worker.until:
                        del busy[conn]
                        self._retire(worker, kill=True)
                        self._requeue(worker, pending)
                        held[worker.key[1]] = self._killed(worker)
                if in_order:
                    while next_out in held:
                        yield held.pop(next_out)
                        next_out += 1
                else:
                    for k in sorted(held):
                        yield held.pop(k)
        finally:
            for worker in busy.values():
                self._retire(worker, kill=True)

    def _start(self, worker: _Worker, position: int, key: Any) -> None:
        """The worker has begun the item at `position`: its clock starts now."""
        now = time.monotonic()
        worker.key, worker.since, worker.until = (key, position), now, now + self.limits.seconds
        worker.notes = []

    def _killed(self, worker: _Worker) -> Outcome:
        """The Outcome of the item in hand of a worker killed at its deadline: `timeout`, with
        the notes the item sent before (the worker itself is retired by the caller)."""
        return Outcome(
            worker.key[0],
            "timeout",
            value=tuple(worker.notes),
            reason="took longer than its time limit and was stopped",
            seconds=time.monotonic() - worker.since,
        )

    def _send_ahead(self, busy: dict[Connection, _Worker], pending: dict) -> None:
        """Give each busy worker its next item now, so that it begins it the moment it sends
        its result instead of waiting for the parent to read that result and reply (a pipe round
        trip per item, about a tenth of a short batch's time). Only a small item goes ahead:
        it waits in the pipe, whose buffer must hold it (`AHEAD_BYTES`)."""
        for worker in busy.values():
            if worker.queued is not None or not pending:
                continue
            if worker.served + 1 >= self.limits.recycle:
                continue  # its item in hand is its last: a fresh worker takes the next
            position, key, item = self._take(worker.slot, pending)
            data = ForkingPickler.dumps(item)
            if len(data) > AHEAD_BYTES:
                self._requeue_item(position, key, item, pending)
                continue
            try:
                worker.conn.send_bytes(data)
            except OSError:  # it died: the item waits for the next worker
                self._requeue_item(position, key, item, pending)
                continue
            worker.queued = (position, key, item)

    def _requeue(self, worker: _Worker, pending: dict) -> None:
        """Put back the item sent ahead to a worker that will never begin it."""
        if worker.queued is not None:
            self._requeue_item(*worker.queued, pending)
            worker.queued = None

    def _requeue_item(self, position: int, key: Any, item: Any, pending: dict) -> None:
        group = position if self.affinity is None else self.affinity(item)
        pending.setdefault(group, deque()).appendleft((position, key, item))

    def _receive(self, worker: _Worker) -> Outcome | None:
        """The worker's message: None after a deadline change or a note, else the item's Outcome
        (the worker goes back to the idle list, or is retired once it has served `recycle`
        items)."""
        key = worker.key[0]
        try:
            message = worker.conn.recv()
        except (EOFError, OSError):
            self._retire(worker, kill=True)
            code = worker.process.exitcode
            died = "was killed" if code == -signal.SIGKILL else f"died (exit code {code})"
            elapsed = time.monotonic() - worker.since
            notes = tuple(worker.notes)  # what the item had noted before its worker died
            return Outcome(
                key, "error", notes, reason=f"the worker process {died}", seconds=elapsed
            )
        if message[0] == "deadline":
            worker.until = time.monotonic() + message[1]
            return None
        if message[0] == "note":
            worker.notes.append(message[1])
            if len(message) > 2:  # and the deadline of what follows
                worker.until = time.monotonic() + message[2]
            return None
        _, status, value = message
        elapsed = time.monotonic() - worker.since
        worker.served += 1
        if worker.served >= self.limits.recycle:
            self._retire(worker)
        else:
            self._idle[worker.slot] = worker
        if status == "ok":
            return Outcome(key, "ok", value=value, seconds=elapsed)
        if status == "refused":
            return Outcome(key, "refused", value=value, reason=str(value), seconds=elapsed)
        return Outcome(key, "error", tuple(worker.notes), reason=str(value), seconds=elapsed)

    def close(self) -> None:
        while self._idle:
            self._retire(self._idle.popitem()[1])

    def __enter__(self) -> Pool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
