"""The front door of answer checking: `check(...)` from Python, `lagrade check` for one answer,
and `lagrade check --batch REQUESTS.jsonl` for many, one result per request line, in order.

Time limits stop C-level work too: checks run in one persistent worker process fed over a pipe;
the parent waits with a deadline and, when it passes, kills the worker (SIGKILL), reports
`timeout` for that request and starts a fresh worker for the rest. The worker keeps every
problem it has seen (variants, derivations, reference values at the sample points), so a batch
of a thousand answers to a few questions derives each question once. Deriving a question is the
instructor's side of the work and gets its own, larger budget (`PREPARE_LIMIT`); the student's
answer gets `time_limit`.

A request line:  {"id": …, "problem": {…}, "part": "eom", "answer": "…" | ["…"], "given": {…}}
A result line:   {"id", "verdict", "score", "feedback", "interpreted", "method", "ms", …}
verdict: correct | incorrect | invalid | timeout (and `error`, with the traceback on stderr,
only for a bug of ours).
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import sys
import tempfile
import time
import traceback
from collections import OrderedDict
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

from lagrade.errors import LagradeError, ReferenceUndefined, RequestError
from lagrade.judge.checks import CHECKERS, Verdict, run_checker
from lagrade.judge.problem import Problem, build_problem, problem_key

__all__ = [
    "Verdict",
    "check",
    "check_request",
    "run_batch",
    "run_check_command",
    "Worker",
    "add_check_arguments",
]

DEFAULT_TIME_LIMIT = 2.0
#: Seconds a worker may spend deriving a question (L, EL, sample points, mistake catalogue).
PREPARE_LIMIT = 60.0
MAX_TIME_LIMIT = 120.0
_CACHE_SIZE = 64

# --- inside the worker ----------------------------------------------------------------------------

_problems: OrderedDict[str, Problem] = OrderedDict()
_prepared: set[tuple[str, str]] = set()


def _problem(spec: Any) -> Problem:
    """The Problem for a request's problem field, from the cache when seen before."""
    if isinstance(spec, Problem):
        return spec
    if not isinstance(spec, Mapping):
        raise RequestError('"problem" must be an object such as {"scene": "wedge", "seed": 3}')
    key = problem_key(spec)
    found = _problems.get(key)
    if found is None:
        found = build_problem(spec)
        _problems[key] = found
        if len(_problems) > _CACHE_SIZE:
            old, _ = _problems.popitem(last=False)
            _prepared.difference_update({k for k in _prepared if k[0] == old})
    else:
        _problems.move_to_end(key)
    return found


def prepare(problem: Problem, part: str) -> None:
    """Derive what `part` needs before the student's clock starts: the reference, its sample
    points and values, and the mistake catalogue the feedback draws on."""
    key = (problem.key, part)
    if key in _prepared:
        return
    if part == "expression":
        problem.catalogue.warm(part, problem.points("expression"))
    elif part in CHECKERS and problem.lagrangian is not None:
        system = problem.system
        _ = system.euler_lagrange
        if part in ("lagrangian", "momenta", "eom", "conserved", "T", "V", "transformation"):
            problem.points(part)
        if part == "conserved":
            _ = system.conserved_quantities
        if part in ("lagrangian", "momenta", "eom", "conserved") or (
            part in ("T", "V") and problem.variant is not None
        ):  # the mistake catalogue, evaluated at the part's points
            problem.catalogue.warm(part, problem.points(part))
    _prepared.add(key)


def _validate(request: Any) -> tuple[Any, str, Any, Mapping | None]:
    if not isinstance(request, Mapping):
        raise RequestError("a request must be a JSON object")
    for name in ("problem", "part", "answer"):
        if name not in request:
            raise RequestError(f'the request has no "{name}"')
    part = request["part"]
    if part not in CHECKERS:
        raise RequestError(f"unknown part {part!r}; parts: {', '.join(CHECKERS)}")
    given = request.get("given")
    if given is not None and not isinstance(given, Mapping):
        raise RequestError('"given" must be an object such as {"lagrangian": "..."}')
    return request["problem"], part, request["answer"], given


def _verdict_for_request_error(part: str, message: str) -> Verdict:
    return Verdict(
        part if isinstance(part, str) else "?", "invalid", 0.0, (message,), "", "request"
    )


def check_request(request: Mapping[str, Any], on_ready=None) -> Verdict:
    """Judge one request in this process (the worker's body; no time limit here).
    `on_ready()` is called once the question is derived, before the answer is judged."""
    part = request.get("part", "?") if isinstance(request, Mapping) else "?"
    try:
        spec, part, answer, given = _validate(request)
        problem = _problem(spec)
        prepare(problem, part)
        if on_ready is not None:
            on_ready()
        start = time.perf_counter()
        verdict = run_checker(problem, part, answer, given)
        ms = (time.perf_counter() - start) * 1e3
    except ReferenceUndefined as error:
        return _verdict_for_request_error(part, f"the problem cannot be graded: {error}")
    except (RequestError, LagradeError) as error:
        return _verdict_for_request_error(part, str(error))
    return Verdict(**{**verdict.__dict__, "ms": ms})


def _serve(conn) -> None:
    """The worker loop: requests in, ("ready",) then ("done", verdict) out."""
    while True:
        try:
            request = conn.recv()
        except (EOFError, OSError):
            return
        if request is None:
            return
        try:
            verdict = check_request(request, on_ready=lambda: conn.send(("ready",)))
            conn.send(("done", verdict))
        except Exception:  # noqa: BLE001 - a bug of ours: report it, keep serving
            conn.send(("error", traceback.format_exc()))


# --- the parent side ------------------------------------------------------------------------------


class Worker:
    """One persistent worker process; `submit` enforces a deadline and replaces a worker that
    runs out or dies."""

    def __init__(self, context: str | None = None):
        method = context or ("fork" if "fork" in mp.get_all_start_methods() else "spawn")
        self._ctx = mp.get_context(method)
        self._proc = None
        self._conn = None
        self.restarts = 0

    def _start(self) -> None:
        parent, child = self._ctx.Pipe()
        proc = self._ctx.Process(target=_serve, args=(child,), daemon=True)
        proc.start()
        child.close()
        self._proc, self._conn = proc, parent

    def _kill(self) -> None:
        if self._proc is not None:
            if self._proc.is_alive():
                self._proc.kill()  # SIGKILL: stops sympy or numpy stuck in C code
            self._proc.join(5)
        if self._conn is not None:
            self._conn.close()
        self._proc = self._conn = None

    def close(self) -> None:
        if self._conn is not None and self._proc is not None and self._proc.is_alive():
            try:
                self._conn.send(None)
                self._proc.join(1)
            except (OSError, BrokenPipeError):
                pass
        self._kill()

    def submit(self, request: Mapping[str, Any], time_limit: float) -> Verdict:
        """The verdict for `request`, or `timeout` when judging takes longer than time_limit."""
        if self._proc is None or not self._proc.is_alive():
            self._start()
        part = request.get("part", "?") if isinstance(request, Mapping) else "?"
        start = time.perf_counter()
        try:
            self._conn.send(request)
        except (OSError, BrokenPipeError):
            self._kill()
            self._start()
            self._conn.send(request)
        deadline = PREPARE_LIMIT
        while True:
            if not self._conn.poll(deadline):
                self._kill()
                self.restarts += 1
                waited = (time.perf_counter() - start) * 1e3
                what = (
                    "deriving the question" if deadline == PREPARE_LIMIT else "judging the answer"
                )
                return Verdict(
                    str(part),
                    "timeout",
                    0.0,
                    (f"The check ran out of time ({what} took longer than {deadline:g} s).",),
                    "",
                    "timeout",
                    waited,
                )
            try:
                message = self._conn.recv()
            except (EOFError, OSError):
                self._kill()
                self.restarts += 1
                return Verdict(
                    str(part),
                    "error",
                    0.0,
                    ("The checking process died.",),
                    "",
                    "error",
                    (time.perf_counter() - start) * 1e3,
                )
            if message[0] == "ready":
                deadline = time_limit
                continue
            if message[0] == "done":
                return message[1]
            print(message[1], file=sys.stderr)
            return Verdict(
                str(part),
                "error",
                0.0,
                ("Internal error while checking; the details are in the log.",),
                "",
                "error",
                (time.perf_counter() - start) * 1e3,
            )

    def __enter__(self) -> Worker:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


_shared: Worker | None = None


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
        verdict = check_request(request)
    else:
        global _shared
        if _shared is None:
            _shared = Worker()
        verdict = _shared.submit(request, float(time_limit))
    if verdict.method == "request":
        raise RequestError(verdict.feedback[0])
    return verdict


# --- batch ----------------------------------------------------------------------------------------


def result_line(request_id: Any, verdict: Verdict) -> dict[str, Any]:
    """The JSON object of one result: id first, then the verdict's fields."""
    return {"id": request_id, **verdict.to_dict()}


def run_batch(
    lines: Iterable[str], *, time_limit: float = DEFAULT_TIME_LIMIT, worker: Worker | None = None
) -> Iterator[dict[str, Any]]:
    """One result per input line, in order (blank lines are skipped). A line that is not a
    valid request gets `invalid` with the reason, and the batch goes on."""
    own = worker is None
    worker = worker or Worker()
    try:
        for number, line in enumerate(lines, 1):
            if not line.strip():
                continue
            try:
                request = json.loads(line)
            except json.JSONDecodeError as error:
                yield result_line(
                    None,
                    _verdict_for_request_error(
                        "?", f"line {number} is not valid JSON: {error.msg} (column {error.colno})"
                    ),
                )
                continue
            request_id = request.get("id") if isinstance(request, dict) else None
            try:
                limit = _time_limit(request, time_limit)
            except RequestError as error:
                yield result_line(request_id, _verdict_for_request_error("?", str(error)))
                continue
            yield result_line(request_id, worker.submit(request, limit))
    finally:
        if own:
            worker.close()


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


def check_batch_file(
    requests: str | Path, out: str | Path | None = None, *, time_limit: float = DEFAULT_TIME_LIMIT
) -> tuple[int, str]:
    """`lagrade check --batch`: results to `out` (written whole or not at all) or, without it,
    as the returned text. Returns (exit status, text)."""
    path = Path(requests)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise RequestError(f"cannot read {path}: {error.strerror}") from None
    counts: dict[str, int] = {}
    results = []
    for result in run_batch(text.splitlines(), time_limit=time_limit):
        counts[result["verdict"]] = counts.get(result["verdict"], 0) + 1
        results.append(json.dumps(result, ensure_ascii=False))
    body = "\n".join(results) + ("\n" if results else "")
    summary = f"{len(results)} requests: " + ", ".join(
        f"{v} {k}" for k, v in sorted(counts.items())
    )
    if out is None:
        return 0, body.rstrip("\n")
    _write_atomically(Path(out), body)
    return 0, f"{summary}; results in {out}"


def _write_atomically(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


# --- the command line -----------------------------------------------------------------------------


def add_check_arguments(parser: argparse.ArgumentParser) -> None:
    """The arguments of `lagrade check` (for the CLI to add to its `check` subcommand)."""
    parser.add_argument(
        "--batch",
        metavar="REQUESTS.jsonl",
        help="check every request of a JSON-lines file, one result line each",
    )
    parser.add_argument(
        "--out",
        metavar="RESULTS.jsonl",
        help="with --batch: write the results here (default: standard output)",
    )
    parser.add_argument("--scene", help="a bank scene id, e.g. wedge")
    parser.add_argument("--seed", type=int, default=None, help="the variant seed of --scene")
    parser.add_argument("--quantity", help="with --scene and --part expression: which quantity")
    parser.add_argument("--lagrangian", help="an ad-hoc reference Lagrangian (with --coordinates)")
    parser.add_argument("--expression", help="an ad-hoc reference expression (with --parameters)")
    parser.add_argument("--coordinates", default="", help="comma-separated coordinates, e.g. theta")
    parser.add_argument(
        "--parameters",
        default="",
        help="name=domain pairs, e.g. m=positive,alpha=(0, pi/2); a bare name is positive",
    )
    parser.add_argument("--part", choices=tuple(CHECKERS), help="the part the answer is for")
    parser.add_argument(
        "--answer",
        action="append",
        default=None,
        help="the answer; repeat for parts that take a list (eom, momenta, …)",
    )
    parser.add_argument(
        "--given-lagrangian",
        default=None,
        help="the student's own L, for follow-through on later parts",
    )
    parser.add_argument(
        "--time-limit",
        type=float,
        default=DEFAULT_TIME_LIMIT,
        help="seconds per request (default 2)",
    )
    parser.add_argument("--json", action="store_true", help="print the result as JSON")


def _parameters(text: str) -> dict[str, str]:
    """'m=positive,alpha=(0, pi/2),g' → {"m": "positive", "alpha": "(0, pi/2)", "g": "positive"}
    (commas inside brackets belong to an interval)."""
    out: dict[str, str] = {}
    depth, piece, pieces = 0, "", []
    for ch in text:
        depth += ch in "([" and 1 or (ch in ")]" and -1 or 0)
        if ch == "," and depth == 0:
            pieces.append(piece)
            piece = ""
        else:
            piece += ch
    pieces.append(piece)
    for p in (p.strip() for p in pieces):
        if not p:
            continue
        name, _, domain = p.partition("=")
        out[name.strip()] = domain.strip() or "positive"
    return out


def problem_from_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The problem field that the single form of `lagrade check` describes."""
    chosen = [k for k in ("scene", "lagrangian", "expression") if getattr(args, k, None)]
    if len(chosen) != 1:
        raise RequestError("give exactly one of --scene, --lagrangian or --expression")
    if chosen[0] == "scene":
        spec: dict[str, Any] = {"scene": args.scene}
        if args.seed is not None:
            spec["seed"] = args.seed
        if args.quantity:
            spec["quantity"] = args.quantity
        return spec
    spec = {chosen[0]: getattr(args, chosen[0]), "parameters": _parameters(args.parameters)}
    coords = [c.strip() for c in args.coordinates.split(",") if c.strip()]
    if coords or chosen[0] == "lagrangian":
        spec["coordinates"] = coords
    return spec


def format_verdict(verdict: Verdict) -> str:
    """A result as a person reads it."""
    lines = [f"{verdict.part}: {verdict.status} (score {verdict.score:g})"]
    shown = verdict.interpreted
    if shown:
        shown = "; ".join(shown) if isinstance(shown, list) else shown
        lines.append(f"  read as: {shown}")
    lines += [f"  - {f}" for f in verdict.feedback]
    if verdict.follows_from_own_answer:
        lines.append("  (follows from your own earlier answer)")
    lines.append(f"  decided by {verdict.method} in {verdict.ms:.1f} ms")
    return "\n".join(lines)


def run_check_command(args: argparse.Namespace) -> tuple[int, str]:
    """`lagrade check`: (exit status, text to print). Exit 0 when the answer is correct (or a
    batch ran to its end), 1 when it is not; a malformed request raises RequestError (the CLI
    prints it and exits 2)."""
    if args.batch:
        return check_batch_file(args.batch, args.out, time_limit=args.time_limit)
    if not args.part or args.answer is None:
        raise RequestError("give --part and --answer (or --batch REQUESTS.jsonl)")
    spec = problem_from_arguments(args)
    answer: Any = args.answer[0] if len(args.answer) == 1 else list(args.answer)
    if args.part in ("eom", "momenta", "conserved", "transformation") and isinstance(answer, str):
        answer = [answer]
    given = {"lagrangian": args.given_lagrangian} if args.given_lagrangian else None
    build_problem(spec)  # a malformed problem is a usage error here, not a verdict
    with Worker() as worker:
        verdict = worker.submit(
            {"problem": spec, "part": args.part, "answer": answer, "given": given}, args.time_limit
        )
    if verdict.method == "request":
        raise RequestError(verdict.feedback[0])
    text = (
        json.dumps(verdict.to_dict(), ensure_ascii=False, indent=2)
        if args.json
        else format_verdict(verdict)
    )
    return (0 if verdict.status == "correct" else 1), text
