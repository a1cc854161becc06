"""`lagrade check --batch --dask`: request lines judged on a Dask cluster, one result each, in
request order.

The lines are read a round at a time (ROUND of them), each round cut into chunks of the same
question (a Dask worker's checking pool then derives it once), and two rounds are in flight at
once, so the cluster never waits for the parent to read, while the parent holds at most two
rounds of requests and results. Only the request lines cross, with their line numbers (for the
messages of an unreadable one); results come back as the dicts `run_batch` makes.
"""

from __future__ import annotations

import json
import sys
from collections import deque
from collections.abc import Iterable, Iterator
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.errors import LagradeError
from lagrade.grading.cluster.chunks import chunk_size, cut, describe, settled
from lagrade.grading.cluster.connect import connect, threads
from lagrade.grading.cluster.on_worker import check_chunk
from lagrade.judge import MAX_ID_LENGTH, Verdict

#: Request lines read, cut and sent per round (the parent holds two rounds at most).
ROUND = 5_000

Record = tuple[int, bytes]


def check_on_cluster(
    scheduler: str,
    records: Iterable[Record],
    *,
    time_limit: float,
    jobs: int,
    version: str,
) -> Iterator[dict[str, Any]]:
    """One result per non-blank (line number, record), in order, judged on the cluster
    `scheduler` names (`jobs`: the workers of a local one)."""
    with connect(scheduler, jobs) as client:
        width = threads(client)
        flight: deque[list] = deque()
        for batch in _rounds(records):
            flight.append(_submit(client, batch, width, time_limit, version))
            if len(flight) == 2:
                yield from _finish(flight.popleft())
        while flight:
            yield from _finish(flight.popleft())


def _rounds(records: Iterable[Record]) -> Iterator[list[Record]]:
    batch: list[Record] = []
    for number, record in records:
        if not record.strip():
            continue  # a blank line has no result, as without a cluster
        batch.append((number, record))
        if len(batch) == ROUND:
            yield batch
            batch = []
    if batch:
        yield batch


def _submit(client: Any, batch: list[Record], width: int, time_limit: float, version: str):
    """The round's chunks sent: [(chunk, future)] in the round's order of groups."""
    positioned = list(enumerate(batch))
    chunks = cut(positioned, lambda item: _question(item[1][1]), chunk_size(len(batch), width))
    sent = []
    for chunk in chunks:
        records = [record for _position, record in chunk]
        future = client.submit(check_chunk, records, time_limit, version, pure=False)
        sent.append((chunk, future))
    return sent


def _finish(sent: list) -> Iterator[dict[str, Any]]:
    """The round's results in request order, once each of its chunks is back."""
    results: dict[int, dict[str, Any]] = {}
    for chunk, future in sent:
        value = settled(future)
        if isinstance(value, BaseException):
            print(f"lagrade: a chunk failed on the cluster: {describe(value)}", file=sys.stderr)
            value = [_failed(record, describe(value)) for _position, record in chunk]
        for (position, _record), result in zip(chunk, value, strict=True):
            results[position] = result
    for position in range(len(results)):
        yield results[position]


def _question(record: bytes) -> str:
    """The problem a request line asks about, as canonical JSON ("" when the line cannot be
    read: it is refused with its reason where it is checked)."""
    request = _parsed(record)
    problem = request.get("problem") if isinstance(request, dict) else None
    try:
        return json.dumps(problem, sort_keys=True, separators=(",", ":"))
    except (TypeError, ValueError):
        return ""


def _parsed(record: bytes) -> Any:
    try:
        return untrusted.load_json(untrusted.decode(record))
    except LagradeError:
        return None


def _failed(record: Record, reason: str) -> dict[str, Any]:
    """The result line of a request whose chunk the cluster could not run: `error`, as a
    request that met a bug of ours, with the reason on stderr."""
    request = _parsed(record[1])
    request_id = request.get("id") if isinstance(request, dict) else None
    if len(json.dumps(request_id)) > MAX_ID_LENGTH:
        request_id = None
    part = request.get("part") if isinstance(request, dict) else None
    name = untrusted.bounded(part, 40) if isinstance(part, str) else "?"
    feedback = (f"The cluster could not check this request ({reason}).",)
    return {"id": request_id, **Verdict(name, "error", 0.0, feedback, "", "error").to_dict()}
