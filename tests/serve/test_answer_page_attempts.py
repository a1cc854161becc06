"""One press, at most one attempt, at the HTTP level: a save request carries the page's attempt
token, and the same token again (a double submit, a retry whose first reply was lost) is the
same save — one row, one grading, the same reply — even when the two arrive at once; the same
answers as the last graded save show its feedback again without spending an attempt; once the
attempts are spent, saves are written and not graded."""

from __future__ import annotations

import threading

import pytest

from lagrade.grading.savelog import SaveLog, log_path
from tests.serve.conftest import generate_class, post, start_server, stop_server

RIGHT = {"1": {"dof": "1", "lagrangian": "1/2 m l^2 theta_dot^2 + m g l cos(theta)"}}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    root = tmp_path_factory.mktemp("attempts")
    manifest = generate_class(root, "[answer_page]\nfeedback = true\nattempts = 2\n")
    server = start_server(root, manifest)
    yield server
    assert stop_server(server) == 0


def _log(server) -> SaveLog:
    return SaveLog(log_path(server.sheets), create=False)


def test_the_same_token_twice_at_once_is_one_save_and_one_attempt(graded):
    url = graded.url("s001") + "/save"
    replies = []

    def press() -> None:
        replies.append(post(url, {"answers": RIGHT, "attempt": "a" * 32}, timeout=120))

    threads = [threading.Thread(target=press) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert [status for status, _ in replies] == [200, 200, 200]
    first = replies[0][1]
    assert all(reply == first for _, reply in replies), replies  # the same save, told thrice
    assert first["attempts_left"] == 1 and first["feedback"]["parts"]["1/dof"]["verdict"]
    assert len(_log(graded).saves("s001")) == 1 and _log(graded).attempts_used("s001") == 1


def test_the_same_answers_again_spend_no_attempt_and_the_last_is_not_graded(graded):
    url = graded.url("s002") + "/save"
    status, first = post(url, {"answers": RIGHT, "attempt": "b" * 32}, timeout=120)
    assert status == 200 and first["attempts_left"] == 1
    status, again = post(url, {"answers": RIGHT, "attempt": "c" * 32}, timeout=120)
    assert again["feedback"] == first["feedback"] and again["attempts_left"] == 1
    assert "no attempt spent" in again["repeated"]
    wrong = {"1": {"dof": "2"}}
    status, second = post(url, {"answers": wrong, "attempt": "d" * 32}, timeout=120)
    assert second["attempts_left"] == 0 and second["feedback"]["parts"]["1/dof"]["points"] == 0
    status, spent = post(url, {"answers": {"1": {"dof": "3"}}, "attempt": "e" * 32})
    assert status == 200 and spent["feedback"] is None and spent["attempts_left"] == 0
    assert "dof = '3'" in (graded.sheets / "s002.toml").read_text()  # saved all the same
    log = _log(graded)
    assert len(log.saves("s002")) == 4 and log.attempts_used("s002") == 2


@pytest.mark.parametrize("token", ["short", "x" * 65, "has space in it", 12345678, ["a" * 10]])
def test_a_malformed_attempt_token_is_refused_and_nothing_is_written(graded, token):
    status, reply = post(graded.url("s003") + "/save", {"answers": RIGHT, "attempt": token})
    assert status == 400 and "attempt token" in reply["message"]
    assert _log(graded).saves("s003") == []
