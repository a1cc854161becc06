"""Layer 3: a class graded: every roster student's sheet read, judged part by part in isolated
workers, and written out as a gradebook, per-student results, feedback pages and reports."""

from lagrade.grading.batch import BatchSummary, grade

__all__ = ["BatchSummary", "grade"]
