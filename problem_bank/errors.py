"""The project's errors, all under one base so that the command line catches exactly these.

    LagradeError                 anything a user can fix; str() says what to do next
    ├── DomainError              a parameter domain that cannot be read ('(0, pi/2)' is fine)
    ├── SceneError               a scene definition that is inconsistent (lists every problem)
    ├── UnknownSceneError        a scene id that is not in the bank (lists the ids)
    ├── AssignmentError          an assignment file, roster or output folder that is unusable
    └── grader errors            grader.errors: ParseError, RequestError, …

A broken invariant in our own code is an assertion, never one of these.
"""

from __future__ import annotations


class LagradeError(Exception):
    """Base of every error a user of lagrade can act on."""


class DomainError(LagradeError, ValueError):
    """A parameter domain that cannot be read."""


class SceneError(LagradeError):
    """A scene whose declaration is inconsistent; `problems` lists each one, naming its field."""

    def __init__(self, scene_id: str, problems: list[str]):
        self.scene_id = scene_id
        self.problems = list(problems)
        lines = "\n".join(f"  - {p}" for p in self.problems)
        super().__init__(f"scene {scene_id!r} is not valid:\n{lines}")

    def __reduce__(self):
        return (SceneError, (self.scene_id, self.problems))


class UnknownSceneError(LagradeError, KeyError):
    """A scene id that the bank does not have."""

    def __init__(self, scene_id: str, known: list[str]):
        self.scene_id = scene_id
        self.known = list(known)
        super().__init__(scene_id)

    def __str__(self) -> str:
        return f"unknown scene {self.scene_id!r}; the bank has: {', '.join(self.known)}"

    def __reduce__(self):
        return (UnknownSceneError, (self.scene_id, self.known))


class AssignmentError(LagradeError):
    """An assignment file, roster or output location that cannot be used as given."""
