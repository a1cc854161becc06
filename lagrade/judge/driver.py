"""The one driver around the door: (question, part, raw answer, given) → Verdict, with one clock,
one question key, one problem builder and one result shape, for every entry point — `check`,
`check --batch`, `grade`, the answer page, PrairieLearn, Gradescope and a Dask worker all judge a
part through `judge`, so that one answer to one variant gets one verdict and one feedback,
byte for byte, whoever asks.

The question key is the whole problem field (`problem_key`): a bank or scene-file variant is
keyed by its seed, so the handout values a verdict's feedback puts in are the student's own.
What depends only on a question's structure — the scene and its presentation, not the handout's
values — is shared between its variants (`Problem.structure`, `Problem.shared`): the reference
compiled, the sample points (drawn over the parameters' domains, seeded by the structure, so
`check --seed` and `grade` quote the same points), the catalogue and the vocabulary. A class of
many variants derives and compiles each structure once (below this layer, `lagrade.mechanics`
derives T, V and L once per presentation too).

Verdicts are remembered at two levels: by the answer's text, and by the content of its reading
(`same_reading`: the parser's tree without positions, the echo and the parser's notes), so that
an answer spelled otherwise than one judged before, and read the same, is not judged again.

Two clocks (`lagrade.judge.clocks`): the question's preparation (its reference, points and, for
a wrong answer, the mistake catalogue) is charged to the question's budget and reported as
`prepare_ms`; the student's part gets the time limit and is reported as `ms`.
"""

from __future__ import annotations

import json
import time
from collections.abc import Mapping
from typing import Any

import lagrade.untrusted as untrusted
from lagrade.errors import DerivationLimit, LagradeError, ReferenceUndefined, RequestError
from lagrade.judge.clocks import (
    GRACE,
    PREPARE_LIMIT,
    Budget,
    PartTimeout,
    PreparationTimeout,
    deadline,
    set_aside,
    time_limit,
)
from lagrade.judge.deriving import derivation_limits, deriving
from lagrade.judge.parts import PARTS, missing_reference, run_checker
from lagrade.judge.parts.oscillation import prepare_oscillations
from lagrade.judge.parts.phase import POINTS, phase_points
from lagrade.judge.parts.reading import parsed_once
from lagrade.judge.problem import Problem, build_problem, problem_key
from lagrade.judge.same_reading import SAME_READING_PARTS, reading_key
from lagrade.judge.verdict import Verdict, timeout_verdict
from lagrade.judge.worker import Limits
from lagrade.recent import Recent

#: Questions kept per process (most recently used last).
_CACHE_SIZE = 256
#: Verdicts kept per process for answers that come again (same question, part, answer, given).
_VERDICT_CACHE_SIZE = 4_096

# --- the question, cached per process -------------------------------------------------------------

_problems: Recent = Recent(_CACHE_SIZE)
#: What the questions of one structure share (`Problem.shared`), by `Problem.structure`: a
#: class of many variants derives its reference, points and catalogue once.
_structures: Recent = Recent(_CACHE_SIZE)
_prepared: set[tuple[str, str]] = set()
#: Questions that could not be derived within the scene rule's limits, with why.
_underived: Recent = Recent(_CACHE_SIZE)


def cached_problem(spec: Any, key: str | None = None) -> Problem:
    """The Problem for a request's problem field, from this process's one cache when seen before
    (keyed by `problem_key`: the variant included; `key`, when the caller has it already, so
    that a request's problem field is not encoded twice)."""
    if isinstance(spec, Problem):
        return spec
    if not isinstance(spec, Mapping):
        raise RequestError('"problem" must be an object such as {"scene": "wedge", "seed": 3}')
    key = problem_key(spec) if key is None else key
    found = _problems.recalled(key)
    if found is None:
        start = time.perf_counter()
        found = build_problem(spec)
        found.share(_structures.made(found.structure, lambda: found.shared))
        # Reading the question (parsing its L or closed form, its domains) is preparation too:
        # charged to its budget, so that `prepare_ms` hides none of it.
        found.budget.charge(time.perf_counter() - start)
        dropped = _problems.keep(key, found)
        if dropped is not None:
            _prepared.difference_update({k for k in _prepared if k[0] == dropped[0]})
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
            if part in ("equilibrium", "normal_modes", "mode_shapes"):
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
    """Drop every question this process has derived and every verdict it remembers (a process
    that outlives one grading run, a Dask worker, starts the next from nothing)."""
    _problems.clear()
    _structures.clear()
    _prepared.clear()
    _verdicts.clear()
    _by_reading.clear()
    _hits.update(dict.fromkeys(_hits, 0))
    _underived.clear()


# --- answers seen before -------------------------------------------------------------------------

#: What was decided for an answer, by (question, part, answer, given): a class types the same
#: answer many times over, and judging is a function of these alone (the sample points are
#: seeded by the question's key).
_verdicts: Recent = Recent(_VERDICT_CACHE_SIZE)
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


def _remember(key, verdict: Verdict, cache: Recent | None = None) -> None:
    if key is None or verdict.status not in _SETTLED:
        return
    cache = _verdicts if cache is None else cache
    shown = verdict.interpreted if isinstance(verdict.interpreted, list) else [verdict.interpreted]
    held = sum(len(k) for k in key[2:])  # the answer's text; or the given and the reading's key
    if held + sum(len(t) for t in (*verdict.feedback, *shown)) > _REMEMBERED_CHARS:
        return
    cache.keep(key, verdict)


#: What was decided for an answer, by (question, part, given, the key of its reading): the
#: second level, for an answer spelled otherwise than one judged before but read the same
#: (`same_reading`: a function of the key alone). Only a right or wrong verdict: an `invalid`
#: one may quote the text it could not read.
_by_reading: Recent = Recent(_VERDICT_CACHE_SIZE)
#: Verdicts given again, by the level that found them (`verdict_cache_hits`).
_hits = {"answer": 0, "reading": 0}


def verdict_cache_hits() -> dict[str, int]:
    """How many verdicts this process gave again since it started (or `forget_problems`):
    by the answer's text ("answer") and by its reading ("reading")."""
    return dict(_hits)


def _reading_key(problem: Problem, part: str, answer: Any, given: Any, seen) -> tuple | None:
    """The second level's key of an answer, or None: none for an answer the first level does
    not remember (too long: reading it for a key would cost what judging does) or judged in
    the student's own coordinates (read against another vocabulary than the statement's)."""
    if seen is None or part not in SAME_READING_PARTS:
        return None
    if missing_reference(problem, part) is not None:
        return None  # refused by `run_checker`, whatever the answer
    if isinstance(given, Mapping) and given.get("transformation") is not None:
        return None
    read = reading_key(problem, part, answer)
    if read is None:
        return None
    return (seen[0], part, json.dumps(given, sort_keys=True, separators=(",", ":")), read)


# --- one part ------------------------------------------------------------------------------------


def judge(
    spec: Mapping[str, Any] | Problem,
    part: str,
    answer: Any,
    given: Mapping[str, Any] | None = None,
    *,
    limit: float | None = None,
    diagnosis: bool = False,
) -> Verdict:
    """Judge `answer` to `part` of the question `spec` (a request's problem field, or a Problem)
    in this process: the one function every entry point calls. A malformed problem raises
    RequestError (or another LagradeError); a student's mistake never raises.

    `limit`: the part's seconds (None: untimed, as the Python API checks in-process).
    `diagnosis`: build the part's whole mistake catalogue after judging, for a question that
    has many answers to come. A question whose budget has run out gets the same timeout at once
    for every later answer, so it holds a batch up once, not per answer. An answer this process
    has decided before (same question, part, answer and given) gets that verdict again without
    being judged: `ms` is then the lookup, `prepare_ms` 0; so does an answer read the same as
    one decided before (`same_reading`), and `ms` is then its reading."""
    received = time.perf_counter()
    try:
        key = problem_key(spec) if isinstance(spec, Mapping) else None
        question = spec.key if isinstance(spec, Problem) else key
        seen = _answer_key(question, part, answer, given)
        known = _verdicts.recalled(seen)
        if known is not None:  # judged before: the same verdict, for the time of a lookup
            _hits["answer"] += 1
            ms = (time.perf_counter() - received) * 1e3
            return Verdict(**{**known.__dict__, "ms": ms, "prepare_ms": 0.0})
        new = key is not None and key not in _problems
        if key in _underived:
            return _underivable(part, _underived[key], 0.0)
        if new and limit is not None:  # a question read now is derived under the scene rule
            try:
                with deriving(_question_named(spec), _reading_limits()):
                    cached_problem(spec, key)
            except DerivationLimit as error:
                _underived.keep(key, error)
                return _underivable(part, error, time.perf_counter() - received)
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
        read = None
        try:
            with time_limit(limit), parsed_once():  # read for the key, then judged: one parse
                read = _reading_key(problem, part, answer, given, seen)
                verdict = _by_reading.recalled(read) if read is not None else None
                if verdict is None:
                    verdict = run_checker(problem, part, answer, given)
                else:  # read the same as an answer judged before: its verdict, unjudged
                    _hits["reading"] += 1
        except PreparationTimeout:
            return _preparation_timeout(part, budget, spent)
        except PartTimeout:
            return timeout_verdict(part, limit)  # type: ignore[arg-type]
        ms = (time.perf_counter() - start - (budget.spent - before)) * 1e3
        if diagnosis:
            _diagnose(problem, part, budget, limit)
    except ReferenceUndefined as error:
        raise RequestError(f"the problem cannot be graded: {error}") from None
    prepare_ms = (budget.spent - spent) * 1e3
    verdict = Verdict(**{**verdict.__dict__, "ms": ms, "prepare_ms": prepare_ms})
    _remember(seen, verdict)
    if verdict.status in ("correct", "incorrect"):
        _remember(read, verdict, _by_reading)
    return verdict


def _question_named(spec: Any) -> str:
    """How a refusal names the question being read: its scene (and that it came as text)."""
    if isinstance(spec, Mapping) and isinstance(spec.get("scene"), str):
        carried = " (its scene_text)" if "scene_text" in spec else ""
        return f"the question's scene {untrusted.clip(spec['scene'], 40)!r}{carried}"
    return "the question"


def _reading_limits() -> Limits:
    """Deriving a question read from a request: the scene rule's limits, within its budget."""
    limits = derivation_limits()
    return Limits(seconds=min(limits.seconds, PREPARE_LIMIT), memory_mib=limits.memory_mib)


def _underivable(part: str, error: DerivationLimit, seconds: float) -> Verdict:
    """The verdict of an answer to a question that could not be derived in time or memory: the
    question ran out, not the answer (every later answer to it gets the same at once)."""
    return Verdict(
        part,
        "timeout",
        0.0,
        (f"This question could not be derived, so no answer to it can be checked: {error}.",),
        "",
        "timeout",
        prepare_ms=seconds * 1e3,
    )


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
