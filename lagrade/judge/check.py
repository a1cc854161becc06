"""Checking answers from outside: `check(...)` from Python and `run_batch` behind
`lagrade check --batch`, one result per request line, in order.

A request:  {"id": …, "problem": {…}, "part": "eom", "answer": "…" | ["…"], "given": {…},
             "time_limit": 2}
A result:   {"id", "verdict", "score", "feedback", "interpreted", "method", "ms", "prepare_ms", …}
verdict: correct | incorrect | invalid | timeout, and `error` (with the traceback on stderr)
only for a bug of ours.

Checks run in killable workers (`lagrade.judge.worker`) that keep every problem they have seen
(variants, derivations, reference values at the sample points), so a batch of a thousand answers
to a few questions derives each question once. Deriving a question is the instructor's side of
the work and has its own budget per question (`PREPARE_LIMIT`, reported as `prepare_ms`); the
student's answer then gets `time_limit` (reported as `ms`).
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable, Iterator, Mapping
from typing import TYPE_CHECKING, Any

import lagrade.untrusted as untrusted
from lagrade.errors import LagradeError, RequestError, UnreadableInput
from lagrade.judge.clocks import GRACE, PREPARE_LIMIT, deadline, note
from lagrade.judge.verdict import Verdict, timeout_verdict
from lagrade.judge.worker import Limits, Outcome, Pool

if TYPE_CHECKING:
    from lagrade.judge.problem import Problem

DEFAULT_TIME_LIMIT = 2.0
MAX_TIME_LIMIT = 120.0


# --- one request ---------------------------------------------------------------------------------


def _validate(request: Any) -> tuple[Any, str, Any, Mapping | None]:
    from lagrade.judge.parts import PARTS

    if not isinstance(request, Mapping):
        raise RequestError("a request must be a JSON object")
    for name in ("problem", "part", "answer"):
        if name not in request:
            raise RequestError(f'the request has no "{name}"')
    part = request["part"]
    if not isinstance(part, str) or part not in PARTS:
        shown = untrusted.clip(part, 40) if isinstance(part, str) else type(part).__name__
        raise RequestError(f"unknown part {shown!r}; parts: {', '.join(PARTS)}")
    given = request.get("given")
    if given is not None and not isinstance(given, Mapping):
        raise RequestError('"given" must be an object such as {"lagrangian": "..."}')
    if given is not None and "all" in given and not isinstance(given["all"], bool):
        raise RequestError('"given": "all" must be true or false')
    transformation = given.get("transformation") if given is not None else None
    if transformation is not None and not (
        isinstance(transformation, str)
        or (isinstance(transformation, list) and all(isinstance(x, str) for x in transformation))
    ):
        raise RequestError(
            '"given": "transformation" must be the transformation equations, a string or a '
            'list of strings such as ["x_bob = l sin(theta)", "y_bob = -l cos(theta)"]'
        )
    return request["problem"], part, request["answer"], given


def check_request(
    request: Mapping[str, Any], limit: float | None = None, diagnosis: bool = False
) -> Verdict:
    """Judge one request in this process (the body of a worker, and of `check` without a time
    limit): its fields checked, then the one driver (`lagrade.judge.driver.judge`). A malformed
    request or problem raises RequestError (or another LagradeError)."""
    from lagrade.judge.driver import judge  # the judging modules, only where one judges

    spec, part, answer, given = _validate(request)
    return judge(spec, part, answer, given, limit=limit, diagnosis=diagnosis)


#: Requests to one question that go to a worker in one message (a chunk): one pipe round trip
#: for them all instead of one each (about 0.6 ms a request, measured), each still under its
#: own deadline, and a kill still costs only the request in hand.
CHUNK = 16


def _judge_chunk(entries: list[tuple[int, tuple]]) -> list[tuple[int, str, Any]]:
    """A worker's item: a chunk of (position, (request, time limit[, diagnosis])), judged in
    order. Each request gets a fresh deadline, as a request of its own would, and its result is
    noted as soon as it is known, so that a worker killed later in the chunk loses none of it
    (`_settle`)."""
    results = []
    deadline(PREPARE_LIMIT + GRACE)
    for k, (position, item) in enumerate(entries):
        try:
            result: tuple[int, str, Any] = (position, "ok", check_request(*item))
        except LagradeError as error:
            result = (position, "refused", error)
        except Exception as error:  # noqa: BLE001 - a bug of ours costs its request only
            result = (position, "error", f"{type(error).__name__}: {error}")
        # noted, with the next request's deadline in the same message
        note(result, PREPARE_LIMIT + GRACE if k + 1 < len(entries) else None)
        results.append(result)
    return results


def _settle(outcome: Outcome, entries: list[tuple[int, tuple]]):
    """(each settled request's Outcome by position, the entries still to judge) from a chunk's
    Outcome: all of them when it finished; when its worker was killed or died, those it noted,
    the request in hand with the chunk's outcome (`timeout`, or `error`), the rest again."""
    if outcome.status == "ok":
        noted = outcome.value
    else:
        noted = outcome.value if isinstance(outcome.value, tuple) else ()
    settled = {  # a reason only where there is one to give (a verdict's repr is no reason)
        position: Outcome(
            position, status, value=value, reason="" if status == "ok" else str(value)
        )
        for position, status, value in noted
    }
    rest = [entry for entry in entries if entry[0] not in settled]
    if outcome.status == "ok" or not rest:
        return settled, []
    in_hand, *after = rest
    settled[in_hand[0]] = Outcome(in_hand[0], outcome.status, reason=outcome.reason)
    return settled, after


def _question_of(item: Any) -> str:
    """A request's (or a chunk's first request's) question, for sending all answers to one
    question to one worker (which derives it once) and distinct questions to distinct workers."""
    if isinstance(item, list):
        item = item[0][1]
    request = item[0]
    problem = request.get("problem") if isinstance(request, Mapping) else None
    try:
        return json.dumps(problem, sort_keys=True, separators=(",", ":"))
    except (TypeError, ValueError):
        return ""


def check_pool(jobs: int = 1) -> Pool:
    """Workers for checking requests (what `run_batch` uses when it is given none)."""
    return Pool(
        _judge_chunk,
        jobs=jobs,
        limits=Limits(seconds=PREPARE_LIMIT + GRACE),
        affinity=_question_of,
    )


_shared: Pool | None = None


def check(
    problem: Mapping[str, Any] | Problem,
    part: str,
    answer: Any,
    *,
    time_limit: float | None = DEFAULT_TIME_LIMIT,
    given: Mapping[str, Any] | None = None,
) -> Verdict:
    """Judge one answer. `problem` is a request's problem field ({"scene": "wedge", "seed": 3},
    an ad-hoc {"lagrangian", "coordinates", "parameters"} or {"expression", "parameters"}).
    With a time limit the check runs in a persistent worker process that is killed when the
    limit passes (verdict `timeout`); `time_limit=None`, or a Problem object, checks in this
    process. A malformed problem or part raises RequestError."""
    request = {"problem": problem, "part": part, "answer": answer, "given": given}
    if time_limit is None or not isinstance(problem, Mapping):  # a Problem: in this process
        return check_request(request)
    global _shared
    if _shared is None:
        _shared = check_pool()
    entries = [(0, (request, float(time_limit)))]
    (outcome,) = _shared.run([(0, entries)])
    settled, _rest = _settle(outcome, entries)
    return _verdict(settled[0], part, float(time_limit))


def _verdict(outcome: Outcome, part: Any, limit: float) -> Verdict:
    """The verdict an Outcome stands for; a refused request raises its error again."""
    if outcome.status == "ok":
        return outcome.value
    if outcome.status == "refused":
        raise outcome.value
    name = part if isinstance(part, str) else "?"
    if outcome.status == "timeout":
        return timeout_verdict(name, limit)
    print(outcome.reason, file=sys.stderr)
    return Verdict(
        name,
        "error",
        0.0,
        ("Internal error while checking; the details are in the log.",),
        "",
        "error",
        outcome.seconds * 1e3,
    )


# --- many requests -------------------------------------------------------------------------------


def refused(request_id: Any, part: Any, message: str) -> dict[str, Any]:
    """The result line of a request that cannot be checked as given: `invalid`, with why."""
    name = untrusted.bounded(part, 40) if isinstance(part, str) else "?"
    verdict = Verdict(name, "invalid", 0.0, (message,), "", "request")
    return {"id": request_id, **verdict.to_dict()}


def _time_limit(request: Any, default: float) -> float:
    if not isinstance(request, dict) or "time_limit" not in request:
        return default
    value = request["time_limit"]
    if (
        not isinstance(value, int | float)
        or isinstance(value, bool)
        or not 0 < value <= MAX_TIME_LIMIT
    ):
        raise RequestError(f'"time_limit" must be a number of seconds in (0, {MAX_TIME_LIMIT:g}]')
    return float(value)


#: Answers to one question and part in a batch from which its mistake catalogue is built whole
#: when the question is prepared (as `lagrade grade` does): with that many answers a few wrong
#: ones are all but certain, and no single answer then waits for the catalogue to be built.
DIAGNOSE_AT = 8


def _diagnose_early(work: list[tuple[int, tuple]]) -> list[tuple[int, tuple]]:
    """`work` with the first request to each question and part that has `DIAGNOSE_AT` or more
    answers in it marked to build the part's catalogue with its preparation."""
    groups: dict[tuple[str, str], list[int]] = {}
    for k, (_position, item) in enumerate(work):
        part = item[0].get("part")
        if isinstance(part, str):
            groups.setdefault((_question_of(item), part), []).append(k)
    for members in groups.values():
        if len(members) >= DIAGNOSE_AT:
            position, (request, limit) = work[members[0]]
            work[members[0]] = (position, (request, limit, True))
    return work


#: The longest request id echoed back, in characters of its JSON form.
MAX_ID_LENGTH = 1_000


def _request(number: int, record: str | bytes) -> Any:
    """The parsed request of input line `number`; UnreadableInput says why it is not one."""
    what = f"line {number}"
    text = untrusted.decode(record, what) if isinstance(record, bytes) else record
    request = untrusted.load_json(text, what)
    if isinstance(request, dict) and len(json.dumps(request.get("id"))) > MAX_ID_LENGTH:
        raise UnreadableInput(f'{what}: the "id" is longer than {MAX_ID_LENGTH} characters')
    return request


def _chunked(work: list[tuple[int, tuple]]) -> list[list[tuple[int, tuple]]]:
    """The requests in chunks of at most CHUNK, each of one question, in order of each
    question's first request."""
    by_question: dict[str, list[tuple[int, tuple]]] = {}
    for entry in work:
        by_question.setdefault(_question_of(entry[1]), []).append(entry)
    return [
        entries[k : k + CHUNK]
        for entries in by_question.values()
        for k in range(0, len(entries), CHUNK)
    ]


def _judged_chunks(pool: Pool, work: list[tuple[int, tuple]]):
    """The Outcomes settled (by position) as each chunk comes back, until every request is
    settled: the rest of a chunk whose worker was killed goes round again, to a fresh worker."""
    chunks = _chunked(work)
    while chunks:
        by_key = dict(enumerate(chunks))
        chunks = []
        for outcome in pool.run(list(by_key.items())):
            settled, rest = _settle(outcome, by_key[outcome.key])
            if rest:
                chunks.append(rest)
            yield settled


def _result(identity: tuple[Any, Any], outcome: Outcome, limit: float) -> dict[str, Any]:
    """A request's result line from its Outcome."""
    request_id, part = identity
    try:
        verdict = _verdict(outcome, part, limit)
    except LagradeError as error:
        return refused(request_id, part, str(error))
    return {"id": request_id, **verdict.to_dict()}


def run_batch(
    lines: Iterable[str | bytes],
    *,
    time_limit: float = DEFAULT_TIME_LIMIT,
    jobs: int = 1,
    pool: Pool | None = None,
    first_line: int = 1,
    numbers: Iterable[int] | None = None,
) -> Iterator[dict[str, Any]]:
    """One result per input record, in order (blank records are skipped). Records may be bytes
    (split on b"\n" only, see `lagrade.untrusted`): one that is not UTF-8, not JSON, or past
    the bounds gets `invalid` with the reason, and the batch goes on. `numbers`: each record's
    line number in its file, for records that are not consecutive lines (a cluster's chunk of
    one question's requests); default: consecutive from `first_line`."""
    answers: dict[int, dict[str, Any]] = {}  # lines settled without a worker, by position
    work = []
    ids: list[tuple[Any, Any]] = []
    numbered = enumerate(lines, first_line) if numbers is None else zip(numbers, lines, strict=True)
    for number, line in numbered:
        if not line.strip():
            continue
        position = len(ids)
        try:
            request = _request(number, line)
        except UnreadableInput as error:
            ids.append((None, "?"))
            answers[position] = refused(None, "?", str(error))
            continue
        request_id = request.get("id") if isinstance(request, dict) else None
        part = request.get("part", "?") if isinstance(request, dict) else "?"
        ids.append((request_id, part))
        try:
            if not isinstance(request, dict):
                raise RequestError("a request must be a JSON object")
            limit = _time_limit(request, time_limit)
        except RequestError as error:
            answers[position] = refused(request_id, "?", str(error))
            continue
        work.append((position, (request, limit)))
    limits = {position: item[1] for position, item in work}
    work = _diagnose_early(work)
    if work:  # the judging modules, loaded once here so that the forked workers share them
        import lagrade.judge.driver  # noqa: F401
    own = pool is None
    pool = pool or check_pool(jobs)
    try:
        settled: dict[int, Outcome] = {}
        waiting = 0  # the next position to yield
        for outcome_of in _judged_chunks(pool, work):
            settled.update(outcome_of)
            while waiting < len(ids) and (waiting in answers or waiting in settled):
                if waiting in answers:
                    yield answers.pop(waiting)
                else:
                    yield _result(ids[waiting], settled.pop(waiting), limits[waiting])
                waiting += 1
        while waiting < len(ids):  # what follows the last judged request
            yield answers.pop(waiting)
            waiting += 1
    finally:
        if own:
            pool.close()
