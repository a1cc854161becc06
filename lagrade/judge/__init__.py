"""Layer 2: judging answers by their physics. One checker per part (`lagrade.judge.parts`), the
question a request is about (`Problem`), the one driver every entry point judges through
(`judge`), reading as a step of its own (`read_answer`), numeric equivalence, the mistake
catalogue, the clocks (`lagrade.judge.clocks`) and the killable workers that run untrusted work
(`lagrade.judge.worker`).

Names are loaded on first use (as `lagrade`'s own are), so that a command that needs only the
pool and the request reader (`check --batch` on its way to its workers) does not import sympy."""

from __future__ import annotations

from importlib import import_module
from typing import Any

# `check` and `deriving` name both a module of this package and the function it defines: bound
# here, so that importing the module (which sets the package's attribute to it) never shadows
# the function. Both modules are light (no sympy).
from lagrade.judge.check import check
from lagrade.judge.deriving import deriving

#: Each exported name, by the module that defines it.
_EXPORTS = {
    "PARTS": "lagrade.judge.parts",
    "Problem": "lagrade.judge.problem",
    "Verdict": "lagrade.judge.verdict",
    "build_problem": "lagrade.judge.problem",
    "key_answer": "lagrade.judge.key",
    "run_checker": "lagrade.judge.parts",
    "verify_variant": "lagrade.judge.verify",
}

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


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        value = getattr(import_module(_EXPORTS[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'lagrade.judge' has no attribute {name!r}")
