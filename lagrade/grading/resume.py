"""A kill costs only the part it stopped. A worker judging the parts of a submission one after
another notes each part as it begins and as it is judged (`lagrade.judge.clocks.note`); when the
parent kills the worker at a part's limit + grace, `resumed` turns those notes into the task for
a fresh worker: the parts judged keep their results, the part that was running is marked
stopped (its verdict `timeout`), and the rest is judged again. Each round settles at least one
part, so a submission of n parts takes at most n + 1 rounds.

`lagrade grade`, the answer page's graded saves and PrairieLearn's `grade()` share this rule;
the task is a dict that crosses the pipe, its parts named by ids the caller chooses."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from lagrade.judge import Outcome, note


def begin(part_id: str) -> None:
    """Inside the worker: the part `part_id` is being judged now."""
    note(("begin", part_id))


def judged(part_id: str, result: Any) -> None:
    """Inside the worker: the part `part_id` has its result (kept if the worker is killed)."""
    note(("judged", part_id, result))


def earlier(task: Mapping[str, Any], part_id: str) -> Any | None:
    """The result of a part judged in an earlier round, or None."""
    return task.get("judged", {}).get(part_id)


def stopped(task: Mapping[str, Any], part_id: str) -> bool:
    """Whether a worker was killed while it judged this part (its verdict is `timeout`)."""
    return part_id in task.get("stopped", ())


def resumed(task: Mapping[str, Any], outcome: Outcome) -> dict[str, Any] | None:
    """The task that judges the rest after `outcome` killed its worker in the middle of a part;
    None when the outcome is no such kill (it finished, or was stopped outside any part, for
    example while a sheet was read)."""
    if outcome.status != "timeout" or not isinstance(outcome.value, tuple):
        return None
    done = dict(task.get("judged", {}))
    running = None
    for entry in outcome.value:
        if entry[0] == "begin":
            running = entry[1]
        elif entry[0] == "judged":
            done[entry[1]] = entry[2]
            running = None
    if running is None:
        return None
    return {**task, "judged": done, "stopped": [*task.get("stopped", ()), running]}
