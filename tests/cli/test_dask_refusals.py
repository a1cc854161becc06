"""`--dask` refused before any work, in one line with exit status 2: Dask's distributed scheduler
not installed (the optional extra; hidden here, so these run whether it is installed or not), a
scheduler that is not `local` nor an address, `--jobs` for a cluster someone else runs, `--dask`
for a single `check`. The runs on a cluster are in tests/batch/test_dask.py."""

from __future__ import annotations

import sys

import pytest

from lagrade.cli.main import main

INSTALL = "pip install 'lagrade[dask]'"


@pytest.fixture
def paths(tmp_path):
    """A manifest file and a submissions folder: enough for `grade` to reach its --dask check,
    which comes before the manifest is read."""
    (tmp_path / "manifest.json").write_text("{}")
    (tmp_path / "subs").mkdir()
    (tmp_path / "requests.jsonl").write_text('{"problem": {"scene": "hoop"}}\n')
    return tmp_path


def _refused(capsys, argv: list[str]) -> str:
    status = main(argv)
    err = capsys.readouterr().err
    assert status == 2, err
    assert err.count("\n") == 1 and err.startswith("lagrade: error: "), err
    return err


@pytest.fixture
def no_dask(monkeypatch):
    """Dask's distributed scheduler as if it were not installed."""
    monkeypatch.setitem(sys.modules, "distributed", None)


def test_grade_without_the_extra_says_how_to_install_it(paths, capsys, no_dask):
    argv = ["grade", str(paths / "manifest.json"), str(paths / "subs"), "--dask", "local"]
    assert INSTALL in _refused(capsys, argv)
    assert not (paths / "grades").exists()


def test_check_batch_without_the_extra_says_how_to_install_it(paths, capsys, no_dask):
    out = paths / "results.jsonl"
    argv = ["check", "--batch", str(paths / "requests.jsonl"), "--out", str(out)]
    assert INSTALL in _refused(capsys, [*argv, "--dask", "local"])
    assert not out.exists()


@pytest.mark.parametrize("scheduler", ["lokal", "127.0.0.1:8786", "tcp://", ""])
def test_a_scheduler_that_is_no_address_is_refused(paths, capsys, scheduler):
    argv = ["grade", str(paths / "manifest.json"), str(paths / "subs"), "--dask", scheduler]
    assert "--dask takes 'local' or a scheduler's address" in _refused(capsys, argv)


def test_jobs_for_a_running_cluster_is_refused(paths, capsys):
    argv = ["check", "--batch", str(paths / "requests.jsonl"), "--dask", "tcp://10.0.0.5:8786"]
    assert "--jobs is for this machine or --dask local" in _refused(capsys, [*argv, "--jobs", "2"])


def test_dask_for_one_answer_is_refused(capsys):
    argv = ["check", "--scene", "hoop", "--part", "dof", "--answer", "1", "--dask", "local"]
    assert "--dask is for --batch" in _refused(capsys, argv)
