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


def _child(conn: Connection, work: Callable[[Any], Any], item: Any, limits: Limits) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and kills us
    try:
        resource.setrlimit(resource.RLIMIT_CPU, (limits.cpu_seconds, limits.cpu_seconds + 1))
        ceiling = _address_space_in_use() + limits.memory_mib * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (ceiling, ceiling))
    except (ValueError, OSError):
        pass  # a platform without these limits still has the wall-clock kill
    try:
        result: tuple[str, Any] = ("ok", work(item))
    except MemoryError:
        result = ("error", "ran out of memory (limit exceeded)")
    except BaseException as error:  # noqa: BLE001 - the child reports everything to the parent
        result = ("error", f"{type(error).__name__}: {error}\n{traceback.format_exc(limit=8)}")
    try:
        conn.send(result)
    except Exception as error:  # noqa: BLE001 - an unpicklable result is still an answer
        conn.send(("error", f"result could not be sent back: {error}"))
    finally:
        conn.close()


def run_isolated(
    work: Callable[[Any], Any],
    items: Iterable[tuple[Any, Any]],
    *,
    jobs: int = 1,
    limits: Limits = Limits(),
) -> Iterator[Outcome]:
    """Run `work(item)` for each (key, item) in its own forked child, at most `jobs` at a time,
    yielding an Outcome per item as each finishes (not in input order)."""
    pending = list(items)
    pending.reverse()
    running: dict[Connection, tuple[Any, mp.Process, float]] = {}
    try:
        while pending or running:
            while pending and len(running) < max(1, jobs):
                key, item = pending.pop()
                reader, writer = _FORK.Pipe(duplex=False)
                process = _FORK.Process(target=_child, args=(writer, work, item, limits), daemon=True)
                process.start()
                writer.close()
                running[reader] = (key, process, time.monotonic())
            now = time.monotonic()
            soonest = min(start + limits.wall_seconds for _, _, start in running.values())
            ready = wait(list(running), timeout=max(0.0, soonest - now))
            for conn in ready:
                key, process, start = running.pop(conn)
                yield _collect(conn, key, process, start)
            now = time.monotonic()
            for conn, (key, process, start) in list(running.items()):
                if now - start >= limits.wall_seconds:
                    del running[conn]
                    _kill(process)
                    conn.close()
                    yield Outcome(key, "timeout", reason=f"took longer than {limits.wall_seconds:g} s and was stopped", seconds=now - start)
    finally:
        for conn, (_, process, _) in running.items():
            _kill(process)
            conn.close()


def _collect(conn: Connection, key: Any, process: mp.Process, start: float) -> Outcome:
    elapsed = time.monotonic() - start
    try:
        status, value = conn.recv()
    except (EOFError, OSError):
        process.join(1.0)
        code = process.exitcode
        if code is not None and code < 0 and -code in (signal.SIGXCPU, signal.SIGKILL):
            return Outcome(key, "timeout", reason="used up its CPU-time limit and was stopped", seconds=elapsed)
        return Outcome(key, "error", reason=f"the grading process died (exit code {code})", seconds=elapsed)
    finally:
        conn.close()
    process.join(1.0)
    if process.is_alive():
        _kill(process)
    if status == "ok":
        return Outcome(key, "ok", value=value, seconds=elapsed)
    return Outcome(key, "error", reason=str(value), seconds=elapsed)


def _kill(process: mp.Process) -> None:
    if process.is_alive():
        process.kill()
    process.join(2.0)
