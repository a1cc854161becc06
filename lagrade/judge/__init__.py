"""Layer 2: judging answers by their physics. One checker per part (`lagrade.judge.parts`), the
question a request is about (`Problem`), numeric equivalence, the mistake catalogue, and the
killable worker that runs untrusted work under one time-limit rule."""

from lagrade.judge.check import check
from lagrade.judge.checks import CHECKERS, Verdict, run_checker
from lagrade.judge.key import key_answer
from lagrade.judge.problem import Problem, build_problem
from lagrade.judge.verify import verify_variant

__all__ = [
    "CHECKERS",
    "Problem",
    "Verdict",
    "build_problem",
    "check",
    "key_answer",
    "run_checker",
    "verify_variant",
]
