"""Items cut into chunks for a Dask cluster, and the chunks run there with a bounded number in
flight.

Items of one group (a question, a sheet's set of questions) go into the same chunks, in the
order of the groups' first items, as the local pool's affinity sends them to one process: a
Dask worker then derives a question once for many answers. A chunk is one Dask task, so it
must be long enough to pay for its round trip (a few milliseconds) and short enough that the
workers finish together: `chunk_size` aims at CHUNKS_PER_THREAD chunks per thread of the
cluster, within [MIN_CHUNK, MAX_CHUNK] items (measured in benchmarks/bench_dask.py).

A Dask worker that dies takes its chunk with it; the scheduler runs the chunk again on another
worker (`distributed.scheduler.allowed-failures` times, 3 by default). A chunk that still cannot
be run comes back as the error it raised, for the caller to give each of its items a result."""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

from lagrade.errors import ClusterError

T = TypeVar("T")

#: Chunks per thread of the cluster that a run aims at: enough for the fast workers to take
#: over the slow ones' share at the end.
CHUNKS_PER_THREAD = 4
MIN_CHUNK = 4
MAX_CHUNK = 200


def chunk_size(items: int, threads: int) -> int:
    """Items per chunk for `items` on a cluster of `threads` threads."""
    wanted = math.ceil(items / (CHUNKS_PER_THREAD * max(1, threads)))
    return max(MIN_CHUNK, min(MAX_CHUNK, wanted))


def cut(items: Sequence[T], group: Callable[[T], Hashable], size: int) -> list[list[T]]:
    """`items` in chunks of at most `size`, each group's items together and in their order, the
    groups in the order of their first items (a chunk may end one group and begin the next)."""
    groups: dict[Hashable, list[T]] = {}
    for item in items:
        groups.setdefault(group(item), []).append(item)
    ordered = [item for members in groups.values() for item in members]
    return [ordered[k : k + size] for k in range(0, len(ordered), size)]


def run_chunks(
    client: Any,
    function: Callable[..., Any],
    chunks: Iterable[tuple[T, tuple]],
    ahead: int,
) -> Iterator[tuple[T, Any]]:
    """Run `function(*arguments)` on the cluster for each (label, arguments) of `chunks`, at most
    `ahead` at a time (the arguments of the rest are not built yet: `chunks` may read files as
    it goes), and yield (label, result) as each finishes; the result is the exception when the
    chunk could not be run. A ClusterError raised by a chunk (a worker of another version) stops
    the run, and so does a lost scheduler."""
    from distributed import as_completed

    source = iter(chunks)
    labels: dict[Any, T] = {}
    running = as_completed()

    def submit_next() -> None:
        for label, arguments in source:
            future = client.submit(function, *arguments, pure=False)
            labels[future.key] = label
            running.add(future)
            return

    try:
        for _ in range(max(1, ahead)):
            submit_next()
        for future in running:
            label = labels.pop(future.key)
            yield label, settled(future)
            submit_next()
    finally:
        for future in list(running.futures):
            future.cancel()


def settled(future: Any) -> Any:
    """A future's result once it is done, or the exception that stands for its chunk's items
    (its Dask workers kept dying, or the chunk raised); a ClusterError and a lost scheduler
    are raised (they stop the run)."""
    from distributed import KilledWorker

    try:
        return future.result()
    except ClusterError:
        raise
    except KilledWorker as error:
        return error
    except Exception as error:  # noqa: BLE001 - sorted below
        if future.status == "cancelled" or _is_lost_connection(error):
            raise ClusterError(
                f"lost the Dask scheduler ({type(error).__name__}: {error}); the results "
                f"written so far are kept, and a rerun judges the rest"
            ) from None
        return error


def _is_lost_connection(error: BaseException) -> bool:
    from distributed.comm.core import CommClosedError

    return isinstance(error, CommClosedError | OSError | TimeoutError)


def describe(error: BaseException) -> str:
    """What became of a chunk that could not be run, for its items' results."""
    from distributed import KilledWorker

    if isinstance(error, KilledWorker):
        return "the Dask workers that took it died, each time it was tried"
    return f"{type(error).__name__}: {error}"
