"""A scene whose derivation runs out of time or memory (issue 35): `scene check`, `generate`
and `bank show` refuse it in one sentence naming the scene and what ran out (exit status 2), and
a request that carries it as `scene_text` gets a verdict saying the question — not the answer —
could not be derived. The limits are the scene rule's (`lagrade.judge.deriving.deriving`); the
tests lower them with LAGRADE_DERIVE_SECONDS / LAGRADE_DERIVE_MEMORY_MIB so that they stay
quick.

The hostile position is the issue's: (a + m + g + omega + r)^40 expands into C(44, 4) = 135,751
terms, which held `scene check` and `generate` past 100 s."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from lagrade.cli.main import main
from lagrade.judge.check import check_pool, run_batch

HOSTILE = """\
title = "Hostile"
statement = "A bead of mass m. Use {r}."
coordinates = ["r"]
potential = "gravity"
constraints = ["y_bead - x_bead"]

[parameters]
a = { domain = "positive" }
m = { domain = "positive" }
g = { domain = "positive" }
omega = { domain = "positive" }

[bodies.bead]
mass = "m"
position = ["(a + m + g + omega + r)^40", "(a + m + g + omega + r)^40"]
"""


@pytest.fixture
def hostile(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "hostile.toml"
    path.write_text(HOSTILE)
    return path


def _one_sentence(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("lagrade: error: "), err
    assert "Traceback" not in err
    return lines[0]


def test_scene_check_refuses_a_scene_that_runs_out_of_time(hostile, monkeypatch, capsys):
    monkeypatch.setenv("LAGRADE_DERIVE_SECONDS", "1")
    assert main(["scene", "check", str(hostile)]) == 2
    out, err = capsys.readouterr()
    line = _one_sentence(err)
    assert f"scene file {hostile} could not be derived: its time ran out (limit 1 s)" in line
    assert out == "" and not (hostile.parent / "hostile.svg").exists()


def test_bank_show_refuses_it_too(hostile, monkeypatch, capsys):
    monkeypatch.setenv("LAGRADE_DERIVE_SECONDS", "1")
    assert main(["bank", "show", str(hostile)]) == 2
    line = _one_sentence(capsys.readouterr().err)
    assert f"scene {hostile} could not be derived: its time ran out (limit 1 s)" in line


def test_scene_check_refuses_a_scene_that_runs_out_of_memory(hostile):
    """In a process of its own: an allocation refused deep in C may leave that process's
    interpreter in no state to go on with other tests."""
    env = {**os.environ, "LAGRADE_DERIVE_SECONDS": "60", "LAGRADE_DERIVE_MEMORY_MIB": "30"}
    run = subprocess.run(
        [sys.executable, "-m", "lagrade", "scene", "check", str(hostile)],
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    assert run.returncode == 2, run.stderr
    line = _one_sentence(run.stderr)
    assert "could not be derived: its memory ran out (limit 30 MiB more)" in line


def test_generate_refuses_it_before_writing_anything(hostile, monkeypatch, capsys):
    monkeypatch.setenv("LAGRADE_DERIVE_SECONDS", "1")
    folder = hostile.parent
    (folder / "a.toml").write_text(
        'title = "H"\n[[problems]]\nscene = "hostile.toml"\nparts = ["lagrangian"]\n'
    )
    (folder / "roster.csv").write_text("id,name\ns1,Ada Lovelace\n")
    argv = ["generate", str(folder / "a.toml"), "--roster", str(folder / "roster.csv")]
    assert main([*argv, "--seed", "1", "--out", str(folder / "out")]) == 2
    err = capsys.readouterr().err
    assert "scene 'hostile.toml' could not be derived: its time ran out (limit 1 s)" in err
    assert "Traceback" not in err and not (folder / "out").exists()


def test_a_request_carrying_it_blames_the_question_not_the_answer(monkeypatch):
    """In a worker with a 2 s part limit: the question's derivation stops at its own limit,
    the verdict says the question could not be derived, and the next answer to the same
    question gets that verdict at once (it is not derived again)."""
    monkeypatch.setenv("LAGRADE_DERIVE_SECONDS", "1")  # read by the worker forked below
    problem = {"scene": "hostile", "scene_text": HOSTILE}
    lines = [
        json.dumps({"id": k, "problem": problem, "part": "lagrangian", "answer": "m g r"})
        for k in (1, 2)
    ]
    with check_pool() as pool:
        first, second = run_batch(lines, time_limit=2, pool=pool)
    for result in (first, second):
        assert result["verdict"] == "timeout"
        (sentence,) = result["feedback"]
        assert sentence.startswith("This question could not be derived")
        assert "scene 'hostile' (its scene_text)" in sentence and "time ran out" in sentence
        assert "answer took" not in sentence and "judging the answer" not in sentence
    assert first["prepare_ms"] >= 900 and second["prepare_ms"] == 0
