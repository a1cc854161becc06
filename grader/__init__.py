"""lagrade's grader: parse student answers safely and judge them by their physics.

    parse_answer(text, Vocabulary)      student text → sympy, or ParseError with a caret
    check(problem, part, answer)        one answer judged: a Verdict
    grade(manifest, submissions, out)   a class graded: gradebook, feedback, results.json
"""

from .batch import grade
from .check import check
from .checks import Verdict
from .errors import GraderError, ParseError, RequestError
from .parse import Parsed, Vocabulary, parse_answer, parse_equations, parse_expression

__all__ = [
    "GraderError",
    "ParseError",
    "Parsed",
    "RequestError",
    "Verdict",
    "Vocabulary",
    "check",
    "grade",
    "parse_answer",
    "parse_equations",
    "parse_expression",
]
