"""`lagrade check`: one answer from the command line, or `--batch REQUESTS.jsonl` for many (one
result line per request, in order). The judging itself is `lagrade.judge.check`.

The judge (sympy, numpy) is imported when a check runs, not when the command line is built:
`lagrade --help` and `lagrade parse` must not pay for it. So the part names and the default
time limit are repeated here, and a test holds them equal to the judge's."""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

import lagrade.untrusted as untrusted
from lagrade.cli.arguments import count, seconds
from lagrade.errors import RequestError

if TYPE_CHECKING:
    from lagrade.judge import Verdict

#: `lagrade.judge.parts.PARTS`, by name (tests/cli/test_startup.py pins the two equal).
PART_NAMES = (
    "dof",
    "coordinates",
    "transformation",
    "lagrangian",
    "T",
    "V",
    "eom",
    "momenta",
    "cyclic",
    "conserved",
    "expression",
    "hamiltonian",
    "hamilton_equations",
    "equilibrium",
    "normal_modes",
    "mode_shapes",
)
#: `lagrade.judge.check.DEFAULT_TIME_LIMIT` (pinned equal by the same test).
DEFAULT_TIME_LIMIT = 2.0
#: `lagrade.judge.problem.IMAGINARY_UNITS` (pinned equal by the same test).
IMAGINARY_UNITS = ("I", "i", "j")


#: The problem's fields as this command line spells them, for the judge's errors about them.
FLAGS = {
    "lagrangian": "--lagrangian",
    "expression": "--expression",
    "coordinates": "--coordinates, e.g. --coordinates theta",
    "parameters": "--parameters, e.g. --parameters m,g,R",
}

#: Request lines judged per round: the parent holds one round's requests and results at a time,
#: so a batch of any size runs in bounded memory (a 39 MB file held ~500 MB when read whole).
BATCH_CHUNK = 5_000


def check_batch_file(
    requests: str | Path,
    out: str | Path | None = None,
    *,
    time_limit: float = DEFAULT_TIME_LIMIT,
    jobs: int = 1,
    dask: str | None = None,
) -> tuple[int, str]:
    """`lagrade check --batch`: results to `out` (written whole or not at all) or, without it,
    to standard output as they come. Requests are read and judged a chunk at a time by one pool
    of workers, so memory stays bounded whatever the batch's size; with `dask`, by the workers
    of a Dask cluster (`lagrade.grading.cluster`). Returns (exit status, the summary line to
    print: empty when the results went to standard output)."""
    from lagrade.grading import atomic

    if dask is not None:  # a cluster that cannot be used stops the run before it starts
        from lagrade.grading import require

        require(dask, jobs)
    source = sys.stdin.buffer if str(requests) == "-" else _open_requests(Path(requests))
    counts: dict[str, int] = {}
    with contextlib.ExitStack() as stack:
        stack.enter_context(source)
        if out is not None:
            sink = stack.enter_context(atomic.writing(Path(out)))
        else:  # standard output: each result as soon as it is known, in order
            sink = sys.stdout.buffer
            sys.stdout.flush()
        for results in _judged(source, time_limit, jobs, dask, stack):
            for result in results:
                counts[result["verdict"]] = counts.get(result["verdict"], 0) + 1
                sink.write(json.dumps(result, ensure_ascii=False).encode("utf-8") + b"\n")
            if out is None:
                sink.flush()
    if out is None:
        return 0, ""
    total = sum(counts.values())
    summary = f"{total} requests: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items()))
    return 0, f"{summary}; results in {out}"


def _judged(
    source: BinaryIO, time_limit: float, jobs: int, dask: str | None, stack: contextlib.ExitStack
) -> Iterator[Iterable[dict[str, Any]]]:
    """The results of the requests in `source`, in order, a round at a time: by this machine's
    pool, or by a Dask cluster's workers."""
    if dask is None:
        from lagrade.judge import check_pool, run_batch

        pool = stack.enter_context(check_pool(jobs))
        for first_line, chunk in _chunks(source):
            yield run_batch(chunk, time_limit=time_limit, pool=pool, first_line=first_line)
        return
    from lagrade.assign import project_version
    from lagrade.grading import check_on_cluster

    records = untrusted.split_records(source)
    version = project_version()
    yield check_on_cluster(dask, records, time_limit=time_limit, jobs=jobs, version=version)


def _open_requests(path: Path) -> BinaryIO:
    try:
        return path.open("rb")
    except OSError as error:
        raise RequestError(f"cannot read {path}: {error.strerror}") from None


def _chunks(source: BinaryIO) -> Iterator[tuple[int, list[bytes]]]:
    """(number of the first line, up to BATCH_CHUNK records of the stream)."""
    chunk: list[bytes] = []
    first = 1
    for number, record in untrusted.split_records(source):
        chunk.append(record)
        if len(chunk) == BATCH_CHUNK:
            yield first, chunk
            first, chunk = number + 1, []
    if chunk:
        yield first, chunk


# --- the command line -----------------------------------------------------------------------------


def add_check_arguments(parser: argparse.ArgumentParser) -> None:
    """The arguments of `lagrade check` (for the CLI to add to its `check` subcommand)."""
    parser.add_argument(
        "--batch",
        metavar="REQUESTS.jsonl",
        help="check every request of a JSON-lines file ('-' for standard input), one result "
        "line each, in order",
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
    parser.add_argument(
        "--imaginary-unit",
        choices=IMAGINARY_UNITS,
        help="with --expression: how the imaginary unit is spelled in a question about complex "
        "numbers (otherwise I, i, j are ordinary names)",
    )
    parser.add_argument("--coordinates", default="", help="comma-separated coordinates, e.g. theta")
    parser.add_argument(
        "--parameters",
        default="",
        help="name=domain pairs, e.g. m=positive,alpha=(0, pi/2); a bare name is positive",
    )
    parser.add_argument("--part", choices=PART_NAMES, help="the part the answer is for")
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
        "--given-transformation",
        action="append",
        default=None,
        metavar="EQUATION",
        help="the student's own transformation equations (repeat, one per equation, e.g. "
        '"x_bob = l sin(theta)"): when they are valid and not the statement\'s, L, T, V, eom, '
        "momenta, cyclic and conserved are judged in the student's coordinates",
    )
    parser.add_argument(
        "--all",
        action="store_true",
        help="with --part conserved: the answer should give every independent conserved "
        "quantity (fewer lowers the score; each given one is still judged on its own)",
    )
    parser.add_argument(
        "--time-limit",
        type=seconds,
        default=DEFAULT_TIME_LIMIT,
        help="seconds per request (default 2)",
    )
    parser.add_argument(
        "--jobs",
        type=count,
        default=1,
        help="with --batch: worker processes (results stay in request order; default 1)",
    )
    parser.add_argument(
        "--dask",
        metavar="SCHEDULER",
        default=None,
        help="with --batch: check on a Dask cluster: 'local' starts one here (--jobs workers), "
        "tcp://host:port joins a running one; needs pip install 'lagrade[dask]'",
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
    if chosen[0] == "expression" and args.imaginary_unit:
        spec["imaginary_unit"] = args.imaginary_unit
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
    if args.batch:  # the judging modules load only where a request is judged
        return check_batch_file(
            args.batch, args.out, time_limit=args.time_limit, jobs=args.jobs, dask=args.dask
        )
    from lagrade.judge import build_problem, check

    if args.dask is not None:
        raise RequestError("--dask is for --batch REQUESTS.jsonl; one answer is checked here")
    if not args.part or args.answer is None:
        raise RequestError("give --part and --answer (or --batch REQUESTS.jsonl)")
    spec = problem_from_arguments(args)
    answer: Any = args.answer[0] if len(args.answer) == 1 else list(args.answer)
    if args.part in ("eom", "momenta", "conserved", "transformation") and isinstance(answer, str):
        answer = [answer]
    given: dict[str, Any] = {"lagrangian": args.given_lagrangian} if args.given_lagrangian else {}
    if args.given_transformation:
        given["transformation"] = list(args.given_transformation)
    if args.all:
        given["all"] = True
    build_problem(spec, FLAGS)  # a malformed problem is a usage error here, not a verdict
    verdict = check(spec, args.part, answer, time_limit=args.time_limit, given=given or None)
    text = (
        json.dumps(verdict.to_dict(), ensure_ascii=False, indent=2)
        if args.json
        else format_verdict(verdict)
    )
    return (0 if verdict.status == "correct" else 1), text


def run(args: argparse.Namespace) -> int:
    status, text = run_check_command(args)
    if text:
        print(text)
    return status


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    check = commands.add_parser(
        "check",
        help="judge one answer, or a JSON-lines file of requests",
        description="Judge an answer against a bank scene (--scene), an ad-hoc Lagrangian "
        "(--lagrangian with --coordinates and --parameters) or a reference expression "
        "(--expression). Exit 0 when correct (or when a --batch ran to its end), 1 otherwise.",
        epilog="examples:\n  lagrade check --scene wedge --part cyclic --answer x_M\n"
        '  lagrade check --scene hoop --part eom --answer "theta_ddot = omega^2 sin(theta) '
        'cos(theta) - (g/R) sin(theta)"\n'
        "  lagrade check --batch requests.jsonl --out results.jsonl",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_check_arguments(check)
    check.set_defaults(run=run)
