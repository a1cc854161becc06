"""The killable workers of `lagrade.judge.worker`, fed one item at a time as requests arrive: for
a server, where items come while others are being judged (the answer page). The same rule holds
for every item: the worker's alarm at the part's limit, the parent's kill at its deadline
(limit + `GRACE`), the memory limit, recycling.

A slow item must not hold up the quick ones behind it: when items wait and every worker has
been on its item for longer than `slow` seconds, up to `burst` extra workers start for them
(and retire once idle), so k slow answers hold k workers, not the queue. How many items one user
may have in flight at once is the caller's rule (the answer page lets each student have one).

Workers start from a forkserver by default: a dispatching thread starts them, and forking a
process that runs threads (a web server's) can copy a lock some other thread holds."""

from __future__ import annotations

import asyncio
import itertools
import os
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable
from concurrent.futures import Future
from multiprocessing.connection import Connection, wait
from multiprocessing.reduction import ForkingPickler
from typing import Any

from lagrade.judge.worker import Limits, Outcome, Pool, _Worker

#: Seconds every worker must have spent on its item before a waiting item gets an extra worker.
SLOW = 0.2


class LivePool(Pool):
    """`jobs` workers (plus up to `burst` while they are all held by slow items) running
    `work(item)` for items submitted one at a time, from any thread (`submit`) or an asyncio
    task (`outcome`), first come first served."""

    def __init__(
        self,
        work: Callable[[Any], Any],
        *,
        jobs: int = 1,
        burst: int = 0,
        slow: float = SLOW,
        limits: Limits | None = None,
        context: str = "forkserver",
        preload: Iterable[str] = (),
    ) -> None:
        super().__init__(work, jobs=jobs, limits=limits, context=context, preload=preload)
        self.burst = max(0, int(burst))
        self.slow = slow
        self._waiting: deque[tuple[Any, Any, Future]] = deque()
        self._lock = threading.Lock()
        self._wake_r, self._wake_w = os.pipe()
        os.set_blocking(self._wake_w, False)
        self._thread: threading.Thread | None = None
        self._stopping = False
        self._slots = itertools.count()

    # --- the callers' side ----------------------------------------------------------------
    def start(self) -> None:
        """Start the workers now rather than at the first item (a forkserver takes a second or
        two to import what it preloads; better before the first student waits for it)."""
        with self._lock:
            if self._thread is None and not self._stopping:
                self._thread = threading.Thread(target=self._dispatch, name="lagrade-workers")
                self._thread.daemon = True
                self._thread.start()

    def submit(self, key: Any, item: Any) -> Future:
        """A future for the item's Outcome. Cancelling it before a worker has begun the item
        drops the item; once begun, the item runs to its end or its deadline."""
        future: Future = Future()
        with self._lock:
            if self._stopping:
                future.set_result(Outcome(key, "error", reason="the workers have stopped"))
                return future
            self._waiting.append((key, item, future))
        self.start()
        self._wake()
        return future

    async def outcome(self, key: Any, item: Any) -> Outcome:
        """The item's Outcome, awaited on the running event loop."""
        return await asyncio.wrap_future(self.submit(key, item))

    def close(self) -> None:
        """Stop: items in hand are killed (their Outcome is `error`), waiting ones cancelled."""
        with self._lock:
            self._stopping = True
            thread = self._thread
        self._wake()
        if thread is not None:
            thread.join()
        else:
            super().close()
        for fd in (self._wake_r, self._wake_w):
            try:
                os.close(fd)
            except OSError:
                pass

    def _wake(self) -> None:
        try:
            os.write(self._wake_w, b"!")
        except (BlockingIOError, OSError):
            pass  # a full pipe wakes the thread all the same; a closed one: we are stopping

    # --- the dispatching thread -----------------------------------------------------------
    def _dispatch(self) -> None:
        busy: dict[Connection, tuple[_Worker, Future]] = {}
        try:
            while len(self._idle) < self.jobs and not self._waiting:
                slot = next(self._slots)
                self._idle[slot] = self._fork(slot)
            while True:
                with self._lock:
                    if self._stopping:
                        break
                self._begin_waiting(busy)
                self._retire_spares(busy)
                for ready in wait([*busy, self._wake_r], timeout=self._next_wake(busy)):
                    if ready == self._wake_r:
                        os.read(self._wake_r, 4096)
                        continue
                    worker, future = busy[ready]
                    outcome = self._receive(worker)
                    if outcome is not None:
                        del busy[ready]
                        future.set_result(outcome)
                now = time.monotonic()
                for conn, (worker, future) in list(busy.items()):
                    if now >= worker.until:
                        del busy[conn]
                        self._retire(worker, kill=True)
                        future.set_result(self._killed(worker))
        finally:
            for worker, future in busy.values():
                self._retire(worker, kill=True)
                future.set_result(Outcome(worker.key[0], "error", reason="the workers stopped"))
            with self._lock:
                waiting, self._waiting = list(self._waiting), deque()
            for _key, _item, future in waiting:
                future.cancel()
            Pool.close(self)

    def _may_start(self, busy: dict) -> bool:
        if len(busy) < self.jobs:
            return True
        if len(busy) >= self.jobs + self.burst:
            return False
        now = time.monotonic()
        return all(now - worker.since >= self.slow for worker, _ in busy.values())

    def _begin_waiting(self, busy: dict) -> None:
        """Hand waiting items to idle (or new) workers while the rule allows."""
        while True:
            with self._lock:
                if not self._waiting or not self._may_start(busy):
                    return
                key, item, future = self._waiting.popleft()
            if not future.set_running_or_notify_cancel():
                continue  # cancelled while it waited
            try:
                data = ForkingPickler.dumps(item)
                worker = self._send(data)
            except Exception as error:  # noqa: BLE001 - one item that cannot be sent fails alone
                future.set_result(Outcome(key, "error", reason=f"could not be sent: {error}"))
                continue
            self._start(worker, 0, key)
            busy[worker.conn] = (worker, future)

    def _send(self, data: bytes | memoryview) -> _Worker:
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
        with self._lock:
            if self._waiting:
                return
        while self._idle and len(self._idle) + len(busy) > self.jobs:
            self._retire(self._idle.pop(max(self._idle)))

    def _next_wake(self, busy: dict) -> float | None:
        """Seconds until the next deadline, or until a waiting item may get an extra worker;
        None: nothing to wait for but a message or a submission."""
        moments = [worker.until for worker, _ in busy.values()]
        with self._lock:
            waiting = bool(self._waiting)
        if waiting and self.jobs <= len(busy) < self.jobs + self.burst:
            moments.append(max(worker.since for worker, _ in busy.values()) + self.slow)
        if not moments:
            return None
        return max(0.0, min(moments) - time.monotonic())
