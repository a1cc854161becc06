"""Hostile input at volume: 100,000 generated request lines through `lagrade check --batch`.

Most lines are valid requests to a few bank scenes and reference expressions whose answers are
the key's, mutated (characters inserted, dropped or swapped; tokens of the grammar, LaTeX,
lone surrogates, Unicode line separators, backticks, controls, huge numbers spliced in); the
rest are malformed lines: truncated or garbage JSON, bytes that are not UTF-8, escaped lone
surrogates, 5,000-digit ids and time limits, ids such as 1e400, nesting up to 100,000 deep,
JSON scalars, wrong field types, raw controls inside strings, CRLF endings and blank lines. The
file is seeded, so a run is reproducible.

The command runs as a child process, and the tree it starts (the batch and its workers) is
sampled from /proc for resident memory. Reported: requests, results, missing (and extra),
misaligned (a result whose id is not its request's: a line whose id cannot be read may carry
null), result lines that are not UTF-8 or not strict JSON, `error` verdicts, timeouts (over the
time limit), invalid, the exit status, peak RSS, wall time and requests/s. Target (issue 14):
missing, extra, misaligned, not-JSON, error and timeouts all 0.

Run: python benchmarks/bench_fuzz.py [--requests N] [--jobs J] [--seed S] [--source DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import random
import re
import resource
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from rss import tree_rss

ROOT = Path(__file__).resolve().parent.parent

SCENES = ["simple_pendulum", "harmonic_oscillator", "atwood", "hoop", "free_particle"]
SEEDS = [1, 2, 3]
PARTS = ["dof", "lagrangian", "eom", "momenta", "cyclic"]
EXPRESSIONS = [
    (
        {"expression": "m*g*cos(theta)", "parameters": {"m": "positive", "theta": "(0, 1)"}},
        "g*m*cos(theta)",
    ),
    ({"expression": "sqrt(g/l)", "parameters": {"g": "positive", "l": "positive"}}, "(g/l)^(1/2)"),
    (
        {"expression": "exp(-k*t)*x", "parameters": {"k": "positive", "t": "real", "x": "real"}},
        "x/exp(k t)",
    ),
]
#: Pieces spliced into answers: grammar tokens, LaTeX, and what has broken readers and writers.
PIECES = [
    "theta", "_dot", "_ddot", "^", "**", "*", "/", "+", "-", "(", ")", "=", "sin(", "cos(",
    "sqrt(", "exp(", "0^theta", "1/0", "\\frac{1}{2}", "\\dot{\\theta}", "{", "}", ",", ";",
    "\ud800", "\udfff", "\u2028", "\u2029", "\u0085", "\x0b", "\x0c", "\x1c", "\x00", "\r",
    "\t", "`", "```", "\u202e", "\ufeff", "θ", "ｍ", "9" * 50, "9" * 5000, "e999", "nan",
    "inf", "(" * 200, "<script>", "=HYPERLINK(", "__import__('os')",
]  # fmt: skip


def key_answers() -> list[tuple[dict, str, object]]:
    """(problem, part, the key's answer) for every scene, seed and part, and the expressions."""
    sys.path.insert(0, str(ROOT))
    from lagrade.bank.registry import get_scene
    from lagrade.judge.key import key_answer

    keys = []
    for scene in SCENES:
        for seed in SEEDS:
            variant = get_scene(scene).variant(seed)
            for part in PARTS:
                keys.append(({"scene": scene, "seed": seed}, part, key_answer(variant, part)))
    keys += [(problem, "expression", answer) for problem, answer in EXPRESSIONS]
    return keys


def mutate(rng: random.Random, text: str) -> str:
    """The text with 0–4 random edits (a third of answers stay the key's)."""
    for _ in range(rng.choice([0, 0, 1, 1, 2, 4])):
        at = rng.randrange(len(text) + 1)
        edit = rng.randrange(5)
        if edit == 0:
            text = text[:at] + rng.choice(PIECES) + text[at:]
        elif edit == 1:
            text = text[:at] + text[at + rng.randrange(1, 6) :]
        elif edit == 2 and text:
            text = text[:at] + text[rng.randrange(len(text))] + text[at + 1 :]
        elif edit == 3:
            text = text[:at]
        else:
            text = "".join(rng.choice(PIECES) for _ in range(rng.randrange(1, 12)))
    return text


def fuzzed_request(rng: random.Random, rid: int, keys) -> tuple[bytes, bool]:
    """A valid request with a mutated answer; strict unless it holds a lone surrogate (which a
    reader may refuse before it reads the id)."""
    problem, part, answer = rng.choice(keys)
    answer = [mutate(rng, a) for a in answer] if isinstance(answer, list) else mutate(rng, answer)
    body = {"id": rid, "problem": problem, "part": part, "answer": answer}
    text = json.dumps(body, ensure_ascii=rng.random() < 0.5)
    surrogate = any(0xD800 <= ord(c) <= 0xDFFF for c in text) or "\\ud" in text
    if surrogate and not text.isascii():
        text = json.dumps(body)  # raw surrogates cannot be UTF-8: write them escaped
    return text.encode(), not surrogate


def malformed_line(rng: random.Random, rid: int) -> tuple[bytes, bool]:
    """A line that is not a valid request, and whether its id must still come back."""
    pendulum = b'{"scene": "simple_pendulum", "seed": 1}'
    good = b'{"id": %d, "problem": %s, "part": "dof", "answer": "1"}' % (rid, pendulum)
    kind = rng.randrange(12)
    if kind == 0:
        return good[: rng.randrange(1, len(good))], False
    if kind == 1:
        return b"{" + bytes(rng.randrange(256) for _ in range(rng.randrange(40))).replace(
            b"\n", b""
        ), False
    if kind == 2:
        bad = rng.choice([b"\xff", b"\xc0\x80", b"\xed\xa0\x80", b"\xe2\x80", b"\x80"])
        return good.replace(b'"1"', b'"1' + bad + b'"'), False
    if kind == 3:
        return good.replace(b'"1"', b'"\\ud800"'), False
    if kind == 4:
        digits = rng.choice([b"9" * 101, b"9" * 4301, b"9" * 5000, b"9" * 101 + b".5", b"1e400"])
        field = rng.choice([b'"id": %d' % rid, b'"answer": "1"'])
        return good.replace(field, field.split(b":")[0] + b": " + digits), False
    if kind == 5:
        digits = b"9" * rng.choice([101, 5000])
        return good[:-1] + b', "time_limit": ' + digits + b"}", False
    if kind == 6:
        depth = rng.choice([65, 1000, 100_000]) if rng.random() < 0.01 else rng.choice([65, 1000])
        return good.replace(b'"1"', b"[" * depth + b"]" * depth), False
    if kind == 7:
        return rng.choice([b"null", b"[]", b"[1, 2]", b"3", b'"x"', b"true", b"{}"]), False
    if kind == 8:
        field, value = rng.choice(
            [
                (b'"part": "dof"', b'"part": ["eom"]'),
                (b'"answer": "1"', b'"answer": {"a": 1}'),
                (b'"answer": "1"', b'"answer": null'),
                (pendulum, b'"simple_pendulum"'),
                (pendulum, b'{"scene": "no_such_scene"}'),
            ]
        )
        return good.replace(field, value), True
    if kind == 9:
        raw = rng.choice([b"\x0b", b"\x0c", b"\x1c", b"\x00"])
        return good.replace(b'"1"', b'"1' + raw + b'"'), False
    if kind == 10:
        return good + b"\r", True  # a CRLF file
    return good.replace(b'"1"', b'"1' + rng.choice(["\u2028", "\u0085"]).encode() + b'"'), True


def build(count: int, seed: int) -> tuple[bytes, list[tuple[int, bool]]]:
    """The request file and, per request line, (its id, whether the result must echo it)."""
    rng = random.Random(seed)
    keys = key_answers()
    lines, expected = [], []
    for rid in range(count):
        if rng.random() < 0.005:
            lines.append(rng.choice([b"", b"   ", b"\r"]))  # blank: no result expected
        line, strict = (
            fuzzed_request(rng, rid, keys) if rng.random() < 0.8 else malformed_line(rng, rid)
        )
        lines.append(line)
        expected.append((rid, strict))
    return b"\n".join(lines) + b"\n", expected


# --- running it and watching its memory -----------------------------------------------------------


def rss_of_tree(root: int) -> tuple[int, int, int]:
    """(total, parent, largest child) resident set in kB of `root` and its descendants."""
    parent, children = tree_rss(root)
    return parent + sum(children.values()), parent, max(children.values(), default=0)


def run(requests: Path, results: Path, jobs: int, source: Path) -> dict:
    env = {**os.environ, "PYTHONPATH": str(source), "PYTHONDONTWRITEBYTECODE": "1"}
    command = [sys.executable, "-m", "lagrade", "check", "--batch", str(requests)]
    command += ["--out", str(results), "--jobs", str(jobs)]
    peak = {"total": 0, "parent": 0, "child": 0}
    with tempfile.TemporaryFile() as stderr:
        start = time.perf_counter()
        proc = subprocess.Popen(
            command, cwd=requests.parent, env=env, stdout=subprocess.DEVNULL, stderr=stderr
        )  # not run from a source tree: `python -m` would import the lagrade found there
        while proc.poll() is None:
            total, parent, child = rss_of_tree(proc.pid)
            peak = {
                "total": max(peak["total"], total),
                "parent": max(peak["parent"], parent),
                "child": max(peak["child"], child),
            }
            time.sleep(0.25)
        wall = time.perf_counter() - start
        stderr.seek(0)
        err = stderr.read().decode("utf-8", "replace")
    maxrss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # kB, largest one process
    return {"status": proc.returncode, "wall": wall, "peak": peak, "maxrss": maxrss, "err": err}


def _not_json(constant: str) -> None:
    raise ValueError(constant)


def tally(data: bytes, expected: list[tuple[int, bool]]) -> Counter:
    counts: Counter = Counter()
    lines = data.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    counts["results"] = len(lines)
    counts["missing"] = max(0, len(expected) - len(lines))
    counts["extra"] = max(0, len(lines) - len(expected))
    for line, (rid, strict) in zip(lines, expected, strict=False):
        try:
            result = json.loads(line.decode("utf-8"), parse_constant=_not_json)
        except UnicodeDecodeError:
            counts["not UTF-8"] += 1
            continue
        except ValueError:
            counts["not strict JSON"] += 1
            continue
        got = result.get("id") if isinstance(result, dict) else "?"
        if got != rid and (strict or got is not None):
            counts["misaligned"] += 1
        counts[f"verdict {result.get('verdict')}"] += 1
    return counts


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--requests", type=int, default=100_000)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--seed", type=int, default=14)
    parser.add_argument(
        "--source", type=Path, default=ROOT, help="the lagrade tree to run (default: this one)"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="lagrade-bench-fuzz-") as folder:
        requests, results = Path(folder) / "requests.jsonl", Path(folder) / "results.jsonl"
        t0 = time.perf_counter()
        data, expected = build(args.requests, args.seed)
        requests.write_bytes(data)
        print(
            f"{len(expected)} request lines ({len(data) / 1e6:.1f} MB, seed {args.seed}) built "
            f"in {time.perf_counter() - t0:.1f} s (not timed below); lagrade from {args.source}"
        )
        outcome = run(requests, results, args.jobs, args.source)
        counts = tally(results.read_bytes() if results.exists() else b"", expected)
    verdicts = {k[8:]: v for k, v in counts.items() if k.startswith("verdict ")}
    print(f"exit status {outcome['status']}; --jobs {args.jobs}")
    if outcome["status"] != 0 or "Traceback" in outcome["err"]:
        print("stderr ends:", outcome["err"].strip().splitlines()[-1:] or ["(empty)"])
    kinds = Counter()  # the exception that ends each traceback on stderr
    for block in outcome["err"].split("Traceback (most recent call last):")[1:]:
        ends = [line for line in block.splitlines() if re.match(r"\w+(Error|Exception)\b", line)]
        kinds[ends[-1][:90] if ends else "?"] += 1
    for kind, n in kinds.most_common(5):
        print(f"stderr: {n} × {kind}")
    print(f"requests        {len(expected)}")
    print(f"results         {counts['results']}")
    for name in ("missing", "extra", "misaligned", "not UTF-8", "not strict JSON"):
        print(f"{name:<15} {counts[name]}")
    print(f"error           {verdicts.get('error', 0)}")
    print(f"timeout         {verdicts.get('timeout', 0)}  (over the time limit)")
    print(f"invalid         {verdicts.get('invalid', 0)}")
    print(f"verdicts        {dict(sorted(verdicts.items()))}")
    peak = outcome["peak"]
    print(
        f"peak RSS        {peak['total'] / 1024:.0f} MB for the process tree (sampled every "
        f"0.25 s; parent {peak['parent'] / 1024:.0f} MB, largest worker "
        f"{peak['child'] / 1024:.0f} MB); largest single process {outcome['maxrss'] / 1024:.0f} "
        "MB (ru_maxrss)"
    )
    print(f"wall time       {outcome['wall']:.1f} s")
    print(f"requests/s      {len(expected) / outcome['wall']:.0f}")
    bad = sum(counts[k] for k in ("missing", "extra", "misaligned", "not UTF-8", "not strict JSON"))
    bad += verdicts.get("error", 0) + verdicts.get("timeout", 0)
    print("target (all of the above counts 0):", "met" if bad == 0 else "NOT met")


if __name__ == "__main__":
    main()
