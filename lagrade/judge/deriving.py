"""Deriving a question's scene under limits, in this process: a scene file is text from outside
like an answer (`(a + m + g + omega + r)^40` in a position expands into 10⁵ terms and held
`scene check` for minutes), so `scene check`, `bank show`, `generate` and a request's own scene
text derive it under an alarm and an address-space cap, and a scene that runs out is refused in
one sentence (`DerivationLimit`) naming it and what ran out."""

from __future__ import annotations

import os
import resource
import signal
import threading
from contextlib import contextmanager

from lagrade.errors import DerivationLimit
from lagrade.judge.clocks import PREPARE_LIMIT, PartTimeout
from lagrade.judge.worker import Limits, address_space_in_use

#: What deriving one scene may take (`scene check`, `generate`, a request's own scene text):
#: seconds of work and MiB of memory beyond what the process holds when it starts. The
#: environment variables LAGRADE_DERIVE_SECONDS and LAGRADE_DERIVE_MEMORY_MIB lower or raise
#: them (a test sets a small one).
DERIVE_LIMIT = PREPARE_LIMIT
DERIVE_MEMORY_MIB = 2048


#: Seconds between rings of an alarm that was not heard (`_insistent_alarm`).
RING_AGAIN = 0.5


@contextmanager
def _insistent_alarm(seconds: float):
    """`time_limit` for work with no parent to kill it (a command deriving in its own process):
    after `seconds` the alarm rings, and rings again every `RING_AGAIN` seconds until the block
    has ended, for a PartTimeout raised where Python swallows it (a finalizer run by the
    collector, whose exceptions are only printed) would otherwise leave the work running."""

    def ring(signum, frame):
        raise PartTimeout

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds, RING_AGAIN)
    try:
        yield
    finally:
        while True:  # a ring may come while the alarm is being put away: put it away again
            try:
                signal.setitimer(signal.ITIMER_REAL, 0)
                signal.signal(signal.SIGALRM, previous)
                break
            except PartTimeout:
                continue


def derivation_limits() -> Limits:
    """The seconds and memory a scene's derivation may take, read from the environment when it
    says (LAGRADE_DERIVE_SECONDS, LAGRADE_DERIVE_MEMORY_MIB), else `DERIVE_LIMIT` and
    `DERIVE_MEMORY_MIB`."""
    seconds, memory = DERIVE_LIMIT, DERIVE_MEMORY_MIB
    try:
        seconds = float(os.environ.get("LAGRADE_DERIVE_SECONDS", seconds))
        memory = int(os.environ.get("LAGRADE_DERIVE_MEMORY_MIB", memory))
    except ValueError:
        pass  # an unreadable setting keeps the defaults
    return Limits(seconds=max(seconds, 0.01), memory_mib=max(memory, 1))


@contextmanager
def deriving(what: str, limits: Limits | None = None):
    """Derive `what` (a scene, named as its reader knows it: "scene file ps/hoop.toml") under
    the rule, in this process: the alarm after `limits.seconds` for Python-level work (sympy is
    Python) and at most `limits.memory_mib` more address space; raise DerivationLimit, one
    sentence naming `what` and what ran out. Default limits: `derivation_limits()`.

    A scene file is text from outside like an answer: `(a + m + g + omega + r)^40` in a
    position expands into 10⁵ terms and held `scene check` for minutes."""
    if threading.current_thread() is not threading.main_thread():
        yield  # the alarm rings in the main thread only: a thread's caller bounds its work
        return
    limits = limits or derivation_limits()
    previous = resource.getrlimit(resource.RLIMIT_AS)
    try:
        ceiling = address_space_in_use() + limits.memory_mib * 1024 * 1024
        hard = previous[1]
        soft = ceiling if hard == resource.RLIM_INFINITY else min(ceiling, hard)
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))
    except (ValueError, OSError):
        previous = None  # a platform without the limit still has the alarm
    try:
        with _insistent_alarm(limits.seconds):
            yield
    except PartTimeout:
        raise DerivationLimit(
            f"{what} could not be derived: its time ran out (limit {limits.seconds:g} s); "
            "simplify its expressions"
        ) from None
    except (MemoryError, SystemError):  # an allocation refused in C can surface as either
        raise DerivationLimit(
            f"{what} could not be derived: its memory ran out (limit {limits.memory_mib} MiB "
            "more); simplify its expressions"
        ) from None
    finally:
        if previous is not None:
            resource.setrlimit(resource.RLIMIT_AS, previous)
