"""Layer 2: judging answers by their physics. One checker per part (`lagrade.judge.parts`), the
question a request is about (`Problem`), numeric equivalence, the mistake catalogue, and the
killable workers that run untrusted work under one time-limit rule (`lagrade.judge.worker`)."""

from lagrade.judge.check import check
from lagrade.judge.key import key_answer
from lagrade.judge.parts import PARTS, run_checker
from lagrade.judge.problem import Problem, build_problem
from lagrade.judge.verdict import Verdict
from lagrade.judge.verify import verify_variant
from lagrade.judge.worker import deriving

__all__ = [
    "PARTS",
    "Problem",
    "Verdict",
    "build_problem",
    "check",
    "deriving",
    "key_answer",
    "run_checker",
    "verify_variant",
]
