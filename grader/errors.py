"""The grader's errors, under the project's single base `LagradeError` (see problem_bank.errors
for the whole tree).

    LagradeError
    └── GraderError          anything the grader reports to a user
        ├── ParseError       student text that does not parse (message, span, source, hint)
        └── RequestError     a grading request or problem definition that is malformed
"""

from __future__ import annotations

from problem_bank.errors import LagradeError


class GraderError(LagradeError):
    """Base of the grader's user-facing errors."""


class RequestError(GraderError):
    """A grading request (problem definition, part name, answer shape) that cannot be used."""
