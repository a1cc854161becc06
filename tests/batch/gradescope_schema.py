"""Gradescope's results.json format as its documentation gives it ("Autograder Specifications",
`docs/specs.md` in gradescope/autograder_samples: Output format, Controlling Test Case
Visibility, Test case status, Output String Formatting), as a checker that lists every way a
payload departs from it."""

from __future__ import annotations

import math
from typing import Any

TOP_LEVEL = {
    "score",
    "execution_time",
    "output",
    "output_format",
    "test_output_format",
    "test_name_format",
    "visibility",
    "stdout_visibility",
    "extra_data",
    "tests",
    "leaderboard",
}
TEST = {
    "score",
    "max_score",
    "status",
    "name",
    "name_format",
    "number",
    "output",
    "output_format",
    "tags",
    "visibility",
    "extra_data",
}
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
FORMATS = {"text", "simple_format", "html", "md", "ansi"}
STATUS = {"passed", "failed"}


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def problems(payload: Any) -> list[str]:
    """Every departure from the documented format; [] when the payload conforms."""
    if not isinstance(payload, dict):
        return ["results.json must be an object"]
    found = [f"unknown top-level key {k!r}" for k in sorted(set(payload) - TOP_LEVEL)]
    tests = payload.get("tests", [])
    if "score" in payload and not _number(payload["score"]):
        found.append("score must be a number")
    if "execution_time" in payload and not _number(payload["execution_time"]):
        found.append("execution_time must be a number of seconds")
    for key in ("output",):
        if key in payload and not isinstance(payload[key], str):
            found.append(f"{key} must be a string")
    for key in ("output_format", "test_output_format", "test_name_format"):
        if key in payload and payload[key] not in FORMATS:
            found.append(f"{key} must be one of {sorted(FORMATS)}")
    for key in ("visibility", "stdout_visibility"):
        if key in payload and payload[key] not in VISIBILITY:
            found.append(f"{key} must be one of {sorted(VISIBILITY)}")
    if "extra_data" in payload and not isinstance(payload["extra_data"], dict):
        found.append("extra_data must be an object")
    if not isinstance(tests, list):
        return [*found, "tests must be a list"]
    if "score" not in payload and not (tests and all("score" in t for t in tests)):
        found.append("a score is required at the top level or on every test")
    for n, test in enumerate(tests, 1):
        if not isinstance(test, dict):
            found.append(f"test {n} must be an object")
            continue
        found += [f"test {n}: unknown key {k!r}" for k in sorted(set(test) - TEST)]
        for key in ("score", "max_score"):
            if key in test and not _number(test[key]):
                found.append(f"test {n}: {key} must be a number")
        for key in ("name", "output", "number"):
            if key in test and not isinstance(test[key], str):
                found.append(f"test {n}: {key} must be a string")
        for key in ("name_format", "output_format"):
            if key in test and test[key] not in FORMATS:
                found.append(f"test {n}: {key} must be one of {sorted(FORMATS)}")
        if "visibility" in test and test["visibility"] not in VISIBILITY:
            found.append(f"test {n}: visibility must be one of {sorted(VISIBILITY)}")
        if "status" in test and test["status"] not in STATUS:
            found.append(f"test {n}: status must be passed or failed")
        if "tags" in test and not (
            isinstance(test["tags"], list) and all(isinstance(t, str) for t in test["tags"])
        ):
            found.append(f"test {n}: tags must be a list of strings")
    return found
