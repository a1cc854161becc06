"""Shared fixtures for the grading tests: problems built once per session."""

from __future__ import annotations

import pytest

from lagrade.judge.check import check

WEDGE = {"scene": "wedge"}
HOOP = {"scene": "hoop"}
HOOP_ADHOC = {
    "lagrangian": "m*R**2*(theta_dot**2 + omega**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
    "coordinates": ["theta"],
    "parameters": {"m": "positive", "R": "positive", "g": "positive", "omega": "positive"},
}


def judge(problem, part, answer, given=None):
    """Check in this process (no worker): the tests of the judgement itself."""
    return check(problem, part, answer, time_limit=None, given=given)


@pytest.fixture
def wedge_L_text() -> str:
    return (
        "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2 "
        "- m g (h - q sin(alpha))"
    )
