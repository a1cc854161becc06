"""Issue 24: `lagrade check --part transformation` on an ad-hoc Lagrangian was our `error` (an
AttributeError in a worker, with its traceback): an ad-hoc L has no bodies, so the part is a
clear refusal, exit 2 and one line, and in a batch that request's `invalid`."""

from __future__ import annotations

import json

from lagrade.cli.main import main

AD_HOC = ["--lagrangian", "m*x_dot^2/2 - k*x^2/2", "--coordinates", "x", "--parameters", "m,k"]


def test_transformation_on_an_ad_hoc_lagrangian_is_a_one_line_refusal(capsys):
    status = main(["check", *AD_HOC, "--part", "transformation", "--answer", "x_b = x"])
    out, err = capsys.readouterr()
    assert status == 2
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("lagrade: error: ")
    assert "needs a scene with bodies" in err and "Traceback" not in err


def test_in_a_batch_it_is_that_request_s_invalid(tmp_path, capsys):
    problem = {"lagrangian": "m*x_dot^2/2", "coordinates": ["x"], "parameters": {"m": "positive"}}
    lines = [
        {"id": 1, "problem": problem, "part": "transformation", "answer": ["x_b = x"]},
        {"id": 2, "problem": problem, "part": "coordinates", "answer": "x"},
    ]
    (tmp_path / "r.jsonl").write_text("".join(json.dumps(r) + "\n" for r in lines))
    status = main(["check", "--batch", str(tmp_path / "r.jsonl"), "--out", str(tmp_path / "o")])
    results = [json.loads(line) for line in (tmp_path / "o").read_text().splitlines()]
    assert status == 0
    assert results[0]["verdict"] == "invalid"
    assert "needs a scene with bodies" in results[0]["feedback"][0]
    assert results[1]["verdict"] == "correct"
