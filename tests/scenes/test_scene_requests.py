"""A judge request can carry a scene file (`{"scene": id, "scene_text": …}`): the text is read by
the scene-file reader, and the question is judged like a bank scene's; a text that is not a
scene is a malformed request, never a crash."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.bank.scenefile import read_scene_file
from lagrade.errors import RequestError
from lagrade.judge.check import check
from lagrade.judge.key import key_answer

TEXT = (Path(__file__).parent / "files" / "parabola.toml").read_text()


def test_a_request_carrying_a_scene_file_is_judged():
    problem = {"scene": "parabola", "scene_text": TEXT, "seed": 3}
    variant = read_scene_file(Path(__file__).parent / "files" / "parabola.toml").variant(3)
    key = key_answer(variant, "lagrangian")
    assert check(problem, "lagrangian", key, time_limit=None).status == "correct"
    wrong = key.replace("*g*", "*2*g*", 1)
    assert wrong != key
    assert check(problem, "lagrangian", wrong, time_limit=None).status == "incorrect"
    eom = key_answer(variant, "eom")
    assert check(problem, "eom", eom, time_limit=None).status == "correct"
    quantity = {**problem, "quantity": "oscillation_frequency"}
    assert check(quantity, "expression", "sqrt(2 g a - omega^2)", time_limit=None).score == 1


@pytest.mark.parametrize(
    "text, message",
    [
        ("title = ", "is not valid TOML"),
        (TEXT.replace('a r^2"]', 'a r^2 + b"]'), "'b'"),
        (7, "must be the text"),
    ],
)
def test_a_scene_text_that_is_no_scene_is_a_malformed_request(text, message):
    with pytest.raises(RequestError, match=message):
        check({"scene": "parabola", "scene_text": text}, "lagrangian", "0", time_limit=None)


def test_a_carried_text_is_known_by_its_hash_in_a_workers_memory():
    """The keys a worker remembers answers by stay small however long the carried text is."""
    from lagrade.judge.problem import problem_key

    short = problem_key({"scene": "parabola", "scene_text": TEXT, "seed": 3})
    longer = problem_key({"scene": "parabola", "scene_text": TEXT + "#" * 100_000, "seed": 3})
    assert len(short) == len(longer) < 200 and short != longer
