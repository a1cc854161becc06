"""Layer 3: a class graded: every roster student's sheet read, judged part by part in isolated
workers, and written out as a gradebook, per-student results, feedback pages and reports.

`grade` and `BatchSummary` are loaded on first use, so that a command needing only a leaf of
this package (`check --batch` writes its results with `lagrade.grading.atomic`) does not import
the reports, templates and charts (about 65 ms of start-up)."""

from __future__ import annotations

from typing import Any

__all__ = ["BatchSummary", "grade"]


def __getattr__(name: str) -> Any:
    if name in __all__:
        from lagrade.grading import batch

        return getattr(batch, name)
    raise AttributeError(f"module 'lagrade.grading' has no attribute {name!r}")
