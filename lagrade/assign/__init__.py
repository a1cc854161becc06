"""Layer 2: assignments from the bank: the assignment file and roster, one variant per student,
figures, jinja2 templates, and the generation of handouts, keys, answer sheets and manifest."""

from lagrade.assign.assignment import Assignment, load_assignment
from lagrade.assign.generate import generate
from lagrade.assign.roster import Student, load_roster

__all__ = ["Assignment", "Student", "generate", "load_assignment", "load_roster"]
