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
import time
from collections import OrderedDict
from collections.abc import Iterable, Iterator, Mapping
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.errors import LagradeError, ReferenceUndefined, RequestError, UnreadableInput
from lagrade.judge.parts import PARTS, run_checker
from lagrade.judge.parts.oscillation import prepare_oscillations
from lagrade.judge.parts.phase import POINTS, phase_points
from lagrade.judge.problem import Problem, build_problem, problem_key
from lagrade.judge.verdict import Verdict
from lagrade.judge.worker import (
    GRACE,
    PREPARE_LIMIT,
    Budget,
    Limits,
    Outcome,
    PartTimeout,
    Pool,
    PreparationTimeout,
    deadline,
    set_aside,
    time_limit,
)

DEFAULT_TIME_LIMIT = 2.0
MAX_TIME_LIMIT = 120.0
_CACHE_SIZE = 256
#: Verdicts kept per process for answers that come again (same question, part, answer, given).
_VERDICT_CACHE_SIZE = 4_096

# --- the question a request is about, cached per process -----------------------------------------

_problems: OrderedDict[str, Problem] = OrderedDict()
_prepared: set[tuple[str, str]] = set()


def cached_problem(spec: Any, key: str | None = None) -> Problem:
    """The Problem for a request's problem field, from this process's one cache when seen before.
    `key` names what the problem depends on (default: the whole field); `grade` passes one that
    leaves out the seed, so that a class shares each symbolic question."""
    if isinstance(spec, Problem):
        return spec
    if not isinstance(spec, Mapping):
        raise RequestError('"problem" must be an object such as {"scene": "wedge", "seed": 3}')
    key = problem_key(spec) if key is None else key
    found = _problems.get(key)
    if found is None:
        start = time.perf_counter()
        found = build_problem(spec)
        # Reading the question (parsing its L or closed form, its domains) is preparation too:
        # charged to its budget, so that `prepare_ms` hides none of it.
        found.budget.charge(time.perf_counter() - start)
        _problems[key] = found
        if len(_problems) > _CACHE_SIZE:
            old, _ = _problems.popitem(last=False)
            _prepared.difference_update({k for k in _prepared if k[0] == old})
    else:
        _problems.move_to_end(key)
    return found


def prepare(problem: Problem, part: str, diagnosis: bool = False) -> None:
    """Derive what judging `part` needs before the student's clock starts, and no more: the
    sample points of the parts judged at points (drawing them needs the reference and, for
    the parts of a Lagrangian, its Euler–Lagrange expressions; for `eom` and `conserved` the
    mass matrix), the conserved quantities of `conserved`. `dof`, `coordinates` and `cyclic`
    need no derivation; no part needs the solved accelerations.

    The mistake catalogue is not built here: only a wrong answer needs it, and the checker
    builds as much of it as that answer's diagnosis reads (charged to the question's budget,
    not to the student's clock). `diagnosis=True` builds it whole now, for a parent process
    whose forked workers then share it (`lagrade grade`)."""
    key = (problem.key, part)
    if key not in _prepared:
        if part == "expression":
            problem.points("expression")
        elif part in PARTS and problem.lagrangian is not None:
            if part in ("lagrangian", "momenta", "eom", "conserved", "T", "V", "transformation"):
                problem.points(part)
            if part == "conserved":
                _ = problem.system.conserved_quantities
            if part in ("hamiltonian", "hamilton_equations"):  # the points on phase space
                phase_points(problem, problem.points(POINTS))
            if part in ("equilibrium", "normal_modes"):
                prepare_oscillations(problem)
        _prepared.add(key)
    if diagnosis:
        if part == "expression":
            problem.catalogue.warm(part, problem.points("expression"))
        elif part in ("lagrangian", "momenta", "eom", "conserved") or (
            part in ("T", "V") and problem.has_bodies
        ):
            problem.catalogue.warm(part, problem.points(part))


def forget_problems() -> None:
    """Drop every question this process has derived and every verdict it remembers: a process
    that outlives one grading run (a Dask worker) then builds each question of the next run
    from that run's own first student, as a fresh process does."""
    _problems.clear()
    _prepared.clear()
    _verdicts.clear()


# --- answers seen before -------------------------------------------------------------------------

#: What was decided for an answer, by (question, part, answer, given): a class types the same
#: answer many times over (a sixth of the benchmark batch repeats an earlier request), and
#: judging is a function of these alone (the sample points are seeded by the question).
_verdicts: OrderedDict[tuple[str, str, str], Verdict] = OrderedDict()
#: Statuses worth remembering: a timeout or an error may not happen again.
_SETTLED = ("correct", "incorrect", "invalid")
#: The most characters of answer and verdict text one remembered answer may hold, so that the
#: memory stays bounded (4,096 × 16 KiB at most) whatever a batch sends.
_REMEMBERED_CHARS = 16_384


def _answer_key(question: str | None, part: str, answer: Any, given: Mapping | None):
    """The key of a decided answer to the question with key `question`; None when there is no
    such key, or no canonical JSON form, or it is too long to remember."""
    if question is None or (isinstance(answer, str) and len(answer) > _REMEMBERED_CHARS):
        return None
    try:
        text = json.dumps([answer, given], sort_keys=True, separators=(",", ":"))
    except (TypeError, ValueError):
        return None
    return (question, part, text) if len(text) <= _REMEMBERED_CHARS else None


def _remember(key, verdict: Verdict) -> None:
    if key is None or verdict.status not in _SETTLED:
        return
    shown = verdict.interpreted if isinstance(verdict.interpreted, list) else [verdict.interpreted]
    if len(key[2]) + sum(len(t) for t in (*verdict.feedback, *shown)) > _REMEMBERED_CHARS:
        return
    _verdicts[key] = verdict
    if len(_verdicts) > _VERDICT_CACHE_SIZE:
        _verdicts.popitem(last=False)


# --- one request ---------------------------------------------------------------------------------


def _validate(request: Any) -> tuple[Any, str, Any, Mapping | None]:
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


def timeout_verdict(part: str, seconds: float, what: str = "judging the answer") -> Verdict:
    """The verdict of a part whose time ran out: one wording wherever the limit struck."""
    return Verdict(
        part,
        "timeout",
        0.0,
        (f"The check ran out of time ({what} took longer than {seconds:g} s).",),
        "",
        "timeout",
    )


def check_request(
    request: Mapping[str, Any], limit: float | None = None, diagnosis: bool = False
) -> Verdict:
    """Judge one request in this process: the body of a worker, and of `check` without a time
    limit. A malformed request or problem raises RequestError (or another LagradeError).
    `diagnosis`: build the part's whole mistake catalogue with its preparation (`prepare`),
    for a question that has many answers to come.

    Two clocks: the question's preparation (`prepare`, and catalogue work a wrong answer sets
    aside) is charged to the question's budget and reported as `prepare_ms`; the student's
    part gets `limit` and is reported as `ms`. A question whose budget has run out gets the
    same timeout at once for every later answer, so it holds a batch up once, not per answer.
    An answer this process has decided before (same question, part, answer and given) gets that
    verdict again without being judged: `ms` is then the lookup, `prepare_ms` 0."""
    received = time.perf_counter()
    spec, part, answer, given = _validate(request)
    try:
        key = problem_key(spec) if isinstance(spec, Mapping) else None
        question = spec.key if isinstance(spec, Problem) else key
        seen = _answer_key(question, part, answer, given)
        if seen in _verdicts:  # judged before: the same verdict, for the time of a lookup
            _verdicts.move_to_end(seen)
            ms = (time.perf_counter() - received) * 1e3
            return Verdict(**{**_verdicts[seen].__dict__, "ms": ms, "prepare_ms": 0.0})
        new = key is not None and key not in _problems
        problem = cached_problem(spec, key)
        budget = problem.budget
        spent = 0.0 if new else budget.spent  # a question read just now: its reading counts
        if budget.exhausted:
            return _preparation_timeout(part, budget, spent)
        if (problem.key, part) not in _prepared:
            try:
                with set_aside(budget, timed=limit is not None):
                    prepare(problem, part)
            except PartTimeout:
                return _preparation_timeout(part, budget, spent)
        if limit is not None:
            deadline(limit + GRACE)
        start = time.perf_counter()
        before = budget.spent
        try:
            with time_limit(limit):
                verdict = run_checker(problem, part, answer, given)
        except PreparationTimeout:
            return _preparation_timeout(part, budget, spent)
        except PartTimeout:
            return timeout_verdict(part, limit)
        ms = (time.perf_counter() - start - (budget.spent - before)) * 1e3
        if diagnosis:
            _diagnose(problem, part, budget, limit)
    except ReferenceUndefined as error:
        raise RequestError(f"the problem cannot be graded: {error}") from None
    prepare_ms = (budget.spent - spent) * 1e3
    verdict = Verdict(**{**verdict.__dict__, "ms": ms, "prepare_ms": prepare_ms})
    _remember(seen, verdict)
    return verdict


def _diagnose(problem: Problem, part: str, budget: Budget, limit: float | None) -> None:
    """Build the part's whole mistake catalogue now (after the answer in hand is judged, on the
    question's budget), so that the answers to come find it ready. Optional work: a budget
    that runs out here times out the later answers as lazy building would."""
    try:
        with set_aside(budget, timed=limit is not None):
            prepare(problem, part, diagnosis=True)
    except (PartTimeout, LagradeError):
        pass


def _preparation_timeout(part: str, budget: Budget, spent: float) -> Verdict:
    verdict = timeout_verdict(part, PREPARE_LIMIT, "deriving the question")
    return Verdict(**{**verdict.__dict__, "prepare_ms": (budget.spent - spent) * 1e3})


def _limited(item: tuple) -> Verdict:
    """A worker's item: (request, time limit) or (request, time limit, diagnosis)."""
    return check_request(*item)


def _question_of(item: Any) -> str:
    """A request's question, for sending all answers to one question to one worker (which
    derives it once) and distinct questions to distinct workers."""
    request = item[0]
    problem = request.get("problem") if isinstance(request, Mapping) else None
    try:
        return json.dumps(problem, sort_keys=True, separators=(",", ":"))
    except (TypeError, ValueError):
        return ""


def check_pool(jobs: int = 1) -> Pool:
    """Workers for checking requests (what `run_batch` uses when it is given none)."""
    return Pool(
        _limited,
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
    if time_limit is None or isinstance(problem, Problem):
        return check_request(request)
    global _shared
    if _shared is None:
        _shared = check_pool()
    (outcome,) = _shared.run([(0, (request, float(time_limit)))])
    return _verdict(outcome, part, float(time_limit))


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
    return {
        "id": request_id,
        "verdict": "invalid",
        "score": 0.0,
        "feedback": [untrusted.bounded(message)],
        "interpreted": "",
        "method": "request",
        "ms": 0.0,
        "prepare_ms": 0.0,
        "part": untrusted.bounded(part, 40) if isinstance(part, str) else "?",
        "witness": None,
        "follows_from_own_answer": False,
        "mistakes": [],
    }


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
    own = pool is None
    pool = pool or check_pool(jobs)
    try:
        outcomes = pool.run(work, in_order=True)
        for position in range(len(ids)):
            if position in answers:
                yield answers.pop(position)
                continue
            outcome = next(outcomes)
            request_id, part = ids[position]
            try:
                verdict = _verdict(outcome, part, limits[position])
            except LagradeError as error:
                yield refused(request_id, part, str(error))
                continue
            yield {"id": request_id, **verdict.to_dict()}
    finally:
        if own:
            pool.close()
