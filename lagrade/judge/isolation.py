"""Run untrusted-input work in forked child processes with CPU, memory and wall-clock limits.

A submission that makes sympy spin in C code, allocate without bound or crash the interpreter
costs only its own child: the parent kills it at its deadline and reports why, and the other
jobs go on. Children are forked, so what the parent derived and cached before (reference
solutions) is shared with them for free.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import resource
import signal
import time
import traceback
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from typing import Any

_FORK = mp.get_context("fork")


@dataclass(frozen=True)
class Limits:
    """Per-job limits: CPU seconds (enforced by the kernel), extra memory in MiB over what the
    parent already uses, and wall-clock seconds after which the parent kills the child."""

    cpu_seconds: int = 20
    memory_mib: int = 2048
    wall_seconds: float = 30.0


@dataclass(frozen=True)
class Outcome:
    """What became of one job: `ok` with its value, or `timeout` / `error` with a reason."""

    key: Any
    status: str  # "ok" | "timeout" | "error"
    value: Any = None
    reason: str = ""
    seconds: float = 0.0


def _address_space_in_use() -> int:
    """Virtual memory of this process in bytes (Linux), so a memory limit adds to it."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except OSError:
        return 0


def _child(conn: Connection, work: Callable[[Any], Any], chunk: list, limits: Limits) -> None:
    """Run each item of `chunk` in turn, sending ("ok" | "error", value) after each one."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and kills us
    try:
        cpu = limits.cpu_seconds * len(chunk)
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
        ceiling = _address_space_in_use() + limits.memory_mib * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (ceiling, ceiling))
    except (ValueError, OSError):
        pass  # a platform without these limits still has the wall-clock kill
    for _key, item in chunk:
        try:
            result: tuple[str, Any] = ("ok", work(item))
        except MemoryError:
            result = ("error", "ran out of memory (limit exceeded)")
        except BaseException as error:  # noqa: BLE001 - the child reports everything
            result = ("error", f"{type(error).__name__}: {error}\n{traceback.format_exc(limit=8)}")
        try:
            conn.send(result)
        except Exception as error:  # noqa: BLE001 - an unpicklable result is still an answer
            conn.send(("error", f"result could not be sent back: {error}"))
    conn.close()


@dataclass
class _Running:
    """A child at work on a chunk: which item it is on, and since when."""

    process: mp.Process
    chunk: list
    position: int
    since: float


def run_isolated(
    work: Callable[[Any], Any],
    items: Iterable[tuple[Any, Any]],
    *,
    jobs: int = 1,
    limits: Limits = Limits(),
    chunk_size: int | None = None,
) -> Iterator[Outcome]:
    """Run `work(item)` for each (key, item) in forked children, at most `jobs` at a time,
    yielding an Outcome per item as each finishes (not in input order).

    A child takes a chunk of items (forking and warming a process per item would cost more than
    the work); each item still has its own wall-clock limit. When a child is killed or dies,
    its current item gets `timeout` or `error` and the rest of its chunk is handed to a fresh
    child, so one bad item costs only itself.
    """
    pending = list(items)
    if chunk_size is None:
        chunk_size = max(1, min(16, len(pending) // (4 * max(1, jobs)) or 1))
    pending.reverse()
    running: dict[Connection, _Running] = {}
    try:
        while pending or running:
            while pending and len(running) < max(1, jobs):
                chunk = [pending.pop() for _ in range(min(chunk_size, len(pending)))]
                reader, writer = _FORK.Pipe(duplex=False)
                process = _FORK.Process(
                    target=_child, args=(writer, work, chunk, limits), daemon=True
                )
                process.start()
                writer.close()
                running[reader] = _Running(process, chunk, 0, time.monotonic())
            soonest = min(r.since + limits.wall_seconds for r in running.values())
            ready = wait(list(running), timeout=max(0.0, soonest - time.monotonic()))
            for conn in ready:
                job = running[conn]
                key, _ = job.chunk[job.position]
                now = time.monotonic()
                try:
                    status, value = conn.recv()
                except (EOFError, OSError):
                    del running[conn]
                    conn.close()
                    yield _died(job, key, now)
                    pending.extend(reversed(job.chunk[job.position + 1 :]))
                    continue
                yield (
                    Outcome(key, "ok", value=value, seconds=now - job.since)
                    if status == "ok"
                    else (Outcome(key, "error", reason=str(value), seconds=now - job.since))
                )
                job.position += 1
                job.since = now
                if job.position == len(job.chunk):
                    del running[conn]
                    conn.close()
                    job.process.join(1.0)
                    _kill(job.process)
            now = time.monotonic()
            for conn, job in list(running.items()):
                if now - job.since >= limits.wall_seconds:
                    del running[conn]
                    _kill(job.process)
                    conn.close()
                    key, _ = job.chunk[job.position]
                    yield Outcome(
                        key,
                        "timeout",
                        reason=f"took longer than {limits.wall_seconds:g} s and was stopped",
                        seconds=now - job.since,
                    )
                    pending.extend(reversed(job.chunk[job.position + 1 :]))
    finally:
        for conn, job in running.items():
            _kill(job.process)
            conn.close()


def _died(job: _Running, key: Any, now: float) -> Outcome:
    job.process.join(1.0)
    code = job.process.exitcode
    elapsed = now - job.since
    if code is not None and code < 0 and -code in (signal.SIGXCPU, signal.SIGKILL):
        return Outcome(
            key, "timeout", reason="used up its CPU-time limit and was stopped", seconds=elapsed
        )
    return Outcome(
        key, "error", reason=f"the grading process died (exit code {code})", seconds=elapsed
    )


def _kill(process: mp.Process) -> None:
    if process.is_alive():
        process.kill()
    process.join(2.0)
