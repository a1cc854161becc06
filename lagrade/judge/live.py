"""The killable workers of `lagrade.judge.worker`, fed one item at a time as requests arrive: for
a server, where items come while others are being judged (the answer page). Every item is under
the same rule as in `check --batch` and `grade`: the part's alarm, the kill at its deadline
(limit + `GRACE`), the memory limit, recycling.

The workers belong to a host process, forked by `start` before the server has threads or
sockets: it derives what `warm` derives (a class's questions), then forks its workers, which
share that and start in milliseconds (a kill costs a fork, not a derivation). The server talks
to the host over one pipe, from two threads of its own, so that a submission never blocks it.
The host closes the sockets it inherits, its workers die with it, and a host that dies (the
system's OOM killer) is started again by the next submission.

A slow item must not hold up the quick ones: once an item has run `slow` seconds its worker's
scheduling priority is lowered (nice 10, so quick items get the processors first; the worker is
replaced after that item), and while items wait and every worker is on a slow item, up to
`burst` extra workers start for them (retired once idle). So k slow answers hold k workers, not
the queue. How many items one user may have in flight is the caller's rule."""

from __future__ import annotations

import asyncio
import atexit
import ctypes
import dataclasses
import gc
import itertools
import os
import queue
import signal
import stat
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from multiprocessing.connection import Connection, wait
from multiprocessing.reduction import ForkingPickler
from typing import Any

from lagrade.judge.worker import _FORK, Limits, Outcome, Pool, _serve, _Worker

#: Seconds after which an item counts as slow (its worker niced; burst workers allowed).
SLOW = 0.25
#: The niceness of a worker on a slow item.
SLOW_NICE = 10


class LivePool:
    """`jobs` workers (plus up to `burst` while all are on slow items) in a host process, running
    `work(item)` for items submitted one at a time, first come first served: from any thread
    (`submit`) or an asyncio task (`outcome`). `warm()` runs in the host before it forks."""

    def __init__(
        self,
        work: Callable[[Any], Any],
        *,
        jobs: int = 1,
        burst: int = 0,
        slow: float = SLOW,
        limits: Limits | None = None,
        warm: Callable[[], Any] | None = None,
    ) -> None:
        self.work, self.jobs, self.burst, self.slow = work, max(1, int(jobs)), burst, slow
        self.limits = limits or Limits()
        self.warm = warm
        self._lock = threading.Lock()
        self._ids = itertools.count()
        self._futures: dict[int, tuple[Any, Future]] = {}
        self._outbox: queue.SimpleQueue | None = None  # the running host's
        self._host: Any = None
        self._stopped = False

    def start(self) -> None:
        """Fork the host now (idempotent). Call it before the process starts threads where it
        can: the host, and each worker it forks, is a copy of this process (the sockets it
        inherits it closes). A host that died is started again by the next submission."""
        with self._lock:
            if self._host is not None or self._stopped:
                return
            parent, child = _FORK.Pipe()
            settings = (self.work, self.jobs, self.burst, self.slow, self.limits, self.warm)
            # not a daemon: a daemonic process may not start the workers
            self._host = _FORK.Process(target=_host_main, args=(child, *settings))
            self._host.start()
            child.close()
            self._outbox = outbox = queue.SimpleQueue()
            host = self._host
        atexit.register(self.close)  # before multiprocessing's own exit joins the host
        threading.Thread(target=self._write, args=(parent, outbox), daemon=True).start()
        threading.Thread(target=self._read, args=(parent, outbox, host), daemon=True).start()

    def submit(self, key: Any, item: Any) -> Future:
        """A future for the item's Outcome (an item once submitted runs to its end or its
        deadline; cancelling the future only drops the answer)."""
        self.start()
        future: Future = Future()
        with self._lock:
            if self._stopped or self._outbox is None:
                future.set_result(Outcome(key, "error", reason="the workers have stopped"))
                return future
            number = next(self._ids)
            self._futures[number] = (key, future)
            self._outbox.put(("item", number, item))
        return future

    async def outcome(self, key: Any, item: Any) -> Outcome:
        """The item's Outcome, awaited on the running event loop."""
        return await asyncio.wrap_future(self.submit(key, item))

    def close(self) -> None:
        """Stop the host: items in hand are killed, and every open future gets `error`."""
        with self._lock:
            self._stopped = True
            host, outbox = self._host, self._outbox
        if host is None:
            return
        outbox.put(("stop",))
        host.join(10.0)
        if host.is_alive():
            host.kill()
            host.join(2.0)

    @staticmethod
    def _write(conn: Connection, outbox: queue.SimpleQueue) -> None:
        """Send submissions to the host: a full pipe (while the host warms up) blocks this
        thread, never the caller's."""
        while True:
            message = outbox.get()
            try:
                conn.send(message)
            except (OSError, ValueError):
                return
            if message[0] == "stop":
                return

    def _read(self, conn: Connection, outbox: queue.SimpleQueue, host: Any) -> None:
        """Hand each Outcome from the host to its future. When the host is gone, the items it
        had get `error`, and the next submission starts a new host (unless we are closing)."""
        while True:
            try:
                _, number, outcome = conn.recv()
            except (EOFError, OSError):
                break
            with self._lock:
                key, future = self._futures.pop(number)
            if not future.done():
                future.set_result(dataclasses.replace(outcome, key=key))
        with self._lock:
            left, self._futures = list(self._futures.values()), {}
            if self._host is host:
                self._host, self._outbox = None, None
        outbox.put(("stop",))  # ends this host's writer
        for key, future in left:
            if not future.done():
                future.set_result(Outcome(key, "error", reason="the workers stopped"))
        conn.close()
        host.join(2.0)


def _host_main(conn: Connection, work, jobs, burst, slow, limits, warm) -> None:
    """The host process: warm up, then serve items from `conn` until it says stop or closes."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the server handles Ctrl-C and stops us
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _close_sockets(keep=conn.fileno())
    if warm is not None:
        try:
            warm()
        except Exception:  # noqa: BLE001 - a colder start for the workers, not a stopped server
            pass
    gc.collect()
    gc.freeze()  # the workers' collector leaves what they inherit alone (see batch.warm_up)
    _Host(work, jobs=jobs, limits=limits, burst=burst, slow=slow, server=conn).serve(conn)


def _worker_main(server: Connection, conn: Connection, work, limits: Limits) -> None:
    """A worker of the host: it dies with the host (a host killed by the system leaves no
    worker running an item without its deadline), and keeps no copy of the host's pipe to the
    server, so the server sees at once that the host is gone."""
    server.close()
    try:
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):
        pass  # not Linux: the worker leaves after its item, when it sees the host gone
    _serve(conn, work, limits)


_PR_SET_PDEATHSIG = 1


def _close_sockets(keep: int) -> None:
    """Close the sockets inherited from the server (its listener, its clients' connections):
    held open here and in every worker, a connection the server closes would stay open."""
    for name in os.listdir("/proc/self/fd") if os.path.isdir("/proc/self/fd") else ():
        fd = int(name)
        try:
            if fd != keep and fd > 2 and stat.S_ISSOCK(os.fstat(fd).st_mode):
                os.close(fd)
        except OSError:
            pass  # the directory's own descriptor, already closed


class _Host(Pool):
    """The host's dispatcher: Pool's workers, fed from the server's pipe in arrival order."""

    def __init__(
        self, work, *, jobs: int, limits: Limits, burst: int, slow: float, server: Connection
    ) -> None:
        super().__init__(work, jobs=jobs, limits=limits)
        self.burst, self.slow, self.server = max(0, int(burst)), slow, server
        self._slots = itertools.count()
        self._waiting: deque[tuple[int, Any]] = deque()
        self._niced: set[int] = set()  # slots of workers on a slow item

    def serve(self, conn: Connection) -> None:
        busy: dict[Connection, tuple[_Worker, int]] = {}
        try:
            for _ in range(self.jobs):
                slot = next(self._slots)
                self._idle[slot] = self._fork(slot)
            while True:
                self._begin_waiting(busy, conn)
                self._retire_spares(busy)
                for ready in wait([*busy, conn], timeout=self._next_wake(busy)):
                    if ready is conn:
                        try:
                            message = conn.recv()
                        except (EOFError, OSError):
                            return
                        if message[0] == "stop":
                            return
                        self._waiting.append(message[1:])
                        continue
                    worker, number = busy[ready]
                    outcome = self._receive(worker)
                    if outcome is not None:
                        del busy[ready]
                        self._spent(worker)
                        conn.send(("outcome", number, outcome))
                self._watch(busy, conn)
        finally:
            for worker, _number in busy.values():
                self._retire(worker, kill=True)
            self.close()

    def _fork(self, slot: int) -> _Worker:
        parent, child = _FORK.Pipe()
        args = (self.server, child, self.work, self.limits)
        process = _FORK.Process(target=_worker_main, args=args, daemon=True)
        process.start()
        child.close()
        return _Worker(process, parent, slot)

    def _watch(self, busy: dict, conn: Connection) -> None:
        """Kill the workers past their deadline; lower the priority of those on a slow item."""
        now = time.monotonic()
        for key, (worker, number) in list(busy.items()):
            if now >= worker.until:
                del busy[key]
                self._retire(worker, kill=True)
                self._niced.discard(worker.slot)
                conn.send(("outcome", number, self._killed(worker)))
            elif now - worker.since >= self.slow and worker.slot not in self._niced:
                self._niced.add(worker.slot)
                try:
                    os.setpriority(os.PRIO_PROCESS, worker.process.pid, SLOW_NICE)
                except OSError:
                    pass

    def _spent(self, worker: _Worker) -> None:
        """A worker that was niced for a slow item is replaced (its priority cannot be raised
        again without privileges); a fresh fork of the host is as warm."""
        if worker.slot in self._niced:
            self._niced.discard(worker.slot)
            if self._idle.get(worker.slot) is worker:
                self._retire(self._idle.pop(worker.slot))

    def _may_start(self, busy: dict) -> bool:
        if len(busy) < self.jobs:
            return True
        if len(busy) >= self.jobs + self.burst:
            return False
        now = time.monotonic()
        return all(now - worker.since >= self.slow for worker, _ in busy.values())

    def _begin_waiting(self, busy: dict, conn: Connection) -> None:
        """Hand waiting items to idle (or new) workers while the rule allows."""
        while self._waiting and self._may_start(busy):
            number, item = self._waiting.popleft()
            try:
                worker = self._send(ForkingPickler.dumps(item))
            except Exception as error:  # noqa: BLE001 - one item that cannot be sent fails alone
                reason = f"could not be sent to a worker: {error}"
                conn.send(("outcome", number, Outcome(None, "error", reason=reason)))
                continue
            self._start(worker, 0, None)
            busy[worker.conn] = (worker, number)

    def _send(self, data) -> _Worker:
        """Send a pickled item to an idle worker, or a new one (one that died idle is replaced)."""
        if self._idle:
            worker = self._idle.pop(next(iter(self._idle)))
            try:
                worker.conn.send_bytes(data)
                return worker
            except OSError:
                self._retire(worker, kill=True)
        worker = self._fork(next(self._slots))
        try:
            worker.conn.send_bytes(data)
        except OSError:
            self._retire(worker, kill=True)
            raise
        return worker

    def _retire_spares(self, busy: dict) -> None:
        """Retire idle workers beyond `jobs` once nothing waits: the burst is over."""
        while not self._waiting and self._idle and len(self._idle) + len(busy) > self.jobs:
            self._retire(self._idle.pop(max(self._idle)))

    def _next_wake(self, busy: dict) -> float | None:
        """Seconds until a deadline, an item turning slow, or a waiting item's extra worker;
        None: nothing to wait for but a message."""
        moments = [w.until for w, _ in busy.values()]
        moments += [w.since + self.slow for w, _ in busy.values() if w.slot not in self._niced]
        if not moments:
            return None
        return max(0.0, min(moments) - time.monotonic())
