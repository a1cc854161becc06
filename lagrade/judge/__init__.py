"""Layer 2: judging answers by their physics. One checker per part (`lagrade.judge.parts`), the
question a request is about (`Problem`), the one driver every entry point judges through
(`judge`), reading as a step of its own (`read_answer`), numeric equivalence, the mistake
catalogue, the clocks (`lagrade.judge.clocks`) and the killable workers that run untrusted work
(`lagrade.judge.worker`).

Names are loaded on first use (as `lagrade`'s own are), so that a command that needs only the
pool and the request reader (`check --batch` on its way to its workers) does not import sympy."""

from __future__ import annotations

from lagrade.exports import lazy_exports

# a name that is also a module of this package is bound here, so that importing the module (which
# sets the package's attribute to it) never shadows it
from lagrade.judge.check import check
from lagrade.judge.deriving import deriving

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "GRACE": "lagrade.judge.clocks",
    "deadline": "lagrade.judge.clocks",
    "build_problem": "lagrade.judge.problem",
    "cached_problem": "lagrade.judge.driver",
    "check_pool": "lagrade.judge.check",
    "FOLLOWING": "lagrade.judge.parts.own_coordinates",
    "forget_problems": "lagrade.judge.driver",
    "is_unreadable_line": "lagrade.judge.verdict",
    "judge": "lagrade.judge.driver",
    "key_answer": "lagrade.notation.keys",
    "Limits": "lagrade.judge.worker",
    "LivePool": "lagrade.judge.live",
    "MAX_ID_LENGTH": "lagrade.judge.check",
    "note": "lagrade.judge.clocks",
    "NUMERIC_TOLERANCE": "lagrade.judge.parts.expression",
    "Outcome": "lagrade.judge.worker",
    "OWN_COORDINATES": "lagrade.judge.parts.own_coordinates",
    "PARTS": "lagrade.judge.parts",
    "PartTimeout": "lagrade.judge.clocks",
    "Pool": "lagrade.judge.worker",
    "prepare": "lagrade.judge.driver",
    "PREPARE_LIMIT": "lagrade.judge.clocks",
    "Problem": "lagrade.judge.problem",
    "read_answer": "lagrade.judge.read",
    "run_batch": "lagrade.judge.check",
    "run_checker": "lagrade.judge.parts",
    "time_limit": "lagrade.judge.clocks",
    "timeout_verdict": "lagrade.judge.verdict",
    "Verdict": "lagrade.judge.verdict",
    "verify_variant": "lagrade.judge.verify",
}
#: The modules exported as a whole.
_MODULES = {}

__all__ = [
    "build_problem",
    "cached_problem",
    "check",
    "check_pool",
    "deadline",
    "deriving",
    "FOLLOWING",
    "forget_problems",
    "GRACE",
    "is_unreadable_line",
    "judge",
    "key_answer",
    "Limits",
    "LivePool",
    "MAX_ID_LENGTH",
    "note",
    "NUMERIC_TOLERANCE",
    "Outcome",
    "OWN_COORDINATES",
    "PARTS",
    "PartTimeout",
    "Pool",
    "prepare",
    "PREPARE_LIMIT",
    "Problem",
    "read_answer",
    "run_batch",
    "run_checker",
    "time_limit",
    "timeout_verdict",
    "Verdict",
    "verify_variant",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
