"""The batch path (`lagrade check --batch`): one result per line in order, malformed lines are
`invalid` and the batch goes on, time limits kill the worker and the rest still runs."""

from __future__ import annotations

import argparse
import importlib
import json

import pytest

from lagrade.cli.check import add_check_arguments, check_batch_file, run_check_command
from lagrade.errors import RequestError
from lagrade.judge.check import check, check_pool, run_batch

from .conftest import HOOP_ADHOC

ISSUE_EXAMPLES = [
    {
        "id": "s1-L",
        "problem": {"scene": "wedge"},
        "part": "lagrangian",
        "answer": "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2 "
        "- m g (h - q sin(alpha))",
    },
    {
        "id": "s2-eom",
        "problem": HOOP_ADHOC,
        "part": "eom",
        "answer": ["theta_ddot = omega^2 sin(theta) cos(theta) - (g/R) sin(theta)"],
    },
    {
        "id": "s3-x",
        "problem": {
            "expression": "g*sin(alpha)*(M+m)/(M+m*sin(alpha)**2)",
            "parameters": {"g": "positive", "M": "positive", "m": "positive", "alpha": "(0, pi/2)"},
        },
        "part": "expression",
        "answer": "g sin(alpha) (m+M)/(M + m sin(alpha)^2)",
    },
]


@pytest.fixture(scope="module")
def worker():
    with check_pool() as w:
        yield w


def test_batch_results_in_order_and_malformed_lines_do_not_stop_it(worker):
    lines = [json.dumps(r) for r in ISSUE_EXAMPLES[:1]]
    lines += [
        "{not json",
        json.dumps({"id": "no-part", "problem": {"scene": "wedge"}, "answer": "x"}),
        json.dumps({"id": "bad-scene", "problem": {"scene": "nope"}, "part": "dof", "answer": "1"}),
        "",
        json.dumps({"id": "bad-part", "problem": {"scene": "wedge"}, "part": "zzz", "answer": "1"}),
    ]
    lines += [json.dumps(r) for r in ISSUE_EXAMPLES[1:]]
    results = list(run_batch(lines, pool=worker))
    assert [r["id"] for r in results] == [
        "s1-L",
        None,
        "no-part",
        "bad-scene",
        "bad-part",
        "s2-eom",
        "s3-x",
    ]
    assert [r["verdict"] for r in results] == [
        "correct",
        "invalid",
        "invalid",
        "invalid",
        "invalid",
        "correct",
        "correct",
    ]
    assert "not valid JSON" in results[1]["feedback"][0]
    assert "unknown scene" in results[3]["feedback"][0]
    for r in results:
        assert set(r) >= {"id", "verdict", "score", "feedback", "interpreted", "method", "ms"}


def test_timeout_kills_the_worker_and_the_batch_goes_on(worker):
    slow = {
        "id": "slow",
        "problem": {"scene": "double_pendulum"},
        "part": "conserved",
        "answer": ["+".join(f"sin(theta_1)^{k}" for k in range(1, 60))],
        "time_limit": 1e-4,
    }
    lines = [json.dumps(slow), json.dumps(ISSUE_EXAMPLES[0])]
    results = list(run_batch(lines, pool=worker))
    assert results[0]["verdict"] == "timeout" and results[0]["score"] == 0
    assert results[1]["verdict"] == "correct"


def test_bad_time_limit_is_invalid(worker):
    (r,) = run_batch([json.dumps({**ISSUE_EXAMPLES[0], "time_limit": -1})], pool=worker)
    assert r["verdict"] == "invalid" and "time_limit" in r["feedback"][0]


def test_batch_file_written_whole(tmp_path):
    requests = tmp_path / "req.jsonl"
    requests.write_text("\n".join(json.dumps(r) for r in ISSUE_EXAMPLES) + "\n")
    out = tmp_path / "out" / "res.jsonl"
    status, text = check_batch_file(requests, out)
    assert status == 0 and "3 requests: 3 correct" in text
    lines = out.read_text().splitlines()
    assert [json.loads(x)["id"] for x in lines] == ["s1-L", "s2-eom", "s3-x"]
    assert not list(out.parent.glob(".*tmp"))


def test_python_api_with_worker_and_inline():
    v = check({"scene": "wedge"}, "cyclic", ["x_M"])
    assert v.status == "correct" and v.ms >= 0
    with pytest.raises(RequestError):
        check({"scene": "nope"}, "dof", "1", time_limit=None)


def _args(*argv):
    parser = argparse.ArgumentParser()
    add_check_arguments(parser)
    return parser.parse_args(argv)


def test_single_form_of_the_command():
    status, text = run_check_command(
        _args("--scene", "wedge", "--part", "cyclic", "--answer", "x_M")
    )
    assert status == 0 and "cyclic: correct" in text
    status, text = run_check_command(
        _args(
            "--lagrangian",
            "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
            "--coordinates",
            "theta",
            "--parameters",
            "m=positive,g,l",
            "--part",
            "eom",
            "--answer",
            "theta_ddot = -(g/l) sin(theta)",
            "--json",
        )
    )
    assert status == 0 and json.loads(text)["verdict"] == "correct"
    status, text = run_check_command(
        _args(
            "--expression",
            "cos(a)",
            "--parameters",
            "a=(0, pi/2)",
            "--part",
            "expression",
            "--answer",
            "sin(a)",
        )
    )
    assert status == 1 and "incorrect" in text
    with pytest.raises(RequestError):
        run_check_command(_args("--part", "dof", "--answer", "1"))


def test_batch_in_chunks_keeps_order_and_line_numbers(tmp_path, monkeypatch):
    """A batch is judged a chunk at a time (bounded memory); results stay one per line, in
    order, and a bad line is named by its number in the whole file, not in its chunk."""
    import lagrade.cli.check as cli_check

    monkeypatch.setattr(cli_check, "BATCH_CHUNK", 3)
    good = '{"id": %d, "problem": {"scene": "hoop"}, "part": "dof", "answer": "1"}'
    lines = [(good % i).encode() for i in range(1, 8)]
    lines[4] = b'{"id": 5, "answer": "\xff"}'  # line 5, in the second chunk
    requests = tmp_path / "r.jsonl"
    requests.write_bytes(b"\n".join(lines) + b"\n")
    out = tmp_path / "out.jsonl"
    status, text = check_batch_file(requests, out)
    results = [json.loads(line) for line in out.read_text().splitlines()]
    assert status == 0 and "7 requests" in text
    assert [r["id"] for r in results] == [1, 2, 3, 4, None, 6, 7]
    assert results[4]["verdict"] == "invalid" and "line 5 " in results[4]["feedback"][0]
    assert all(r["verdict"] == "correct" for k, r in enumerate(results) if k != 4)


def test_a_request_held_in_c_code_costs_only_itself_inside_its_chunk(monkeypatch):
    """Requests to one question travel to a worker together (one message per chunk): a request
    the planted checker holds in one C call is killed at its limit + grace and gets `timeout`,
    the requests judged before it in the chunk keep their verdicts, and those after it are
    judged by a fresh worker — in order, each once."""
    check_module = importlib.import_module("lagrade.judge.check")  # the package binds `check`
    import lagrade.judge.driver as driver
    from tests.planted import HANG, spinning

    monkeypatch.setattr(driver, "run_checker", spinning(driver.run_checker))
    answers = ["1", "2", HANG, "1", "3", "1"]
    lines = [
        json.dumps(
            {"id": k, "problem": {"scene": "hoop"}, "part": "dof", "answer": a, "time_limit": 0.5}
        )
        for k, a in enumerate(answers)
    ]
    assert len(lines) <= check_module.CHUNK  # one chunk
    with check_pool() as pool:
        results = list(run_batch(lines, pool=pool))
    assert [r["id"] for r in results] == list(range(len(answers)))
    verdicts = [r["verdict"] for r in results]
    assert verdicts == ["correct", "incorrect", "timeout", "correct", "incorrect", "correct"]
