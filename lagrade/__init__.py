"""lagrade: generate and grade problem sets in Lagrangian mechanics.

The front door, for scripts that use lagrade as a library:

    get_scene(id), scene_ids()                 the bank's scenes (solutions derived on demand)
    parse_answer(text, Vocabulary)             student text → sympy, or ParseError with a caret
    check(problem, part, answer)               one answer judged: a Verdict
    generate(assignment, roster, seed, out)    handouts, keys, answer sheets and a manifest
    grade(manifest, submissions, out)          a class graded: gradebook, feedback, results.json

The package is layered; a layer imports only the layers below it:

    cli        the `lagrade` command                                     layer 4
    grading    a folder of submissions → results and reports             layer 3
    judge      one checker per part, equivalence, the mistake catalogue  layer 2
    assign     assignments, variants, figures, templates                 layer 2
    notation   student text → sympy, safely; one printer                 layer 1
    bank       the scenes                                                layer 1
    mechanics  jets, D_t, Lagrangian systems, domains, the Scene type    layer 0

Names are loaded on first use, so `import lagrade` (and `lagrade --help`) stays cheap.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

from lagrade.errors import (
    AssignmentError,
    GraderError,
    LagradeError,
    ParseError,
    RequestError,
    SceneError,
    UnknownSceneError,
)

__version__ = "0.1.0"

_LAZY = {
    "get_scene": "lagrade.bank",
    "scene_ids": "lagrade.bank",
    "Vocabulary": "lagrade.notation",
    "Parsed": "lagrade.notation",
    "parse_answer": "lagrade.notation",
    "parse_equations": "lagrade.notation",
    "parse_expression": "lagrade.notation",
    "Verdict": "lagrade.judge",
    "check": "lagrade.judge",
    "generate": "lagrade.assign",
    "grade": "lagrade.grading",
}

__all__ = [
    "AssignmentError",
    "GraderError",
    "LagradeError",
    "ParseError",
    "Parsed",
    "RequestError",
    "SceneError",
    "UnknownSceneError",
    "Verdict",
    "Vocabulary",
    "__version__",
    "check",
    "generate",
    "get_scene",
    "grade",
    "parse_answer",
    "parse_equations",
    "parse_expression",
    "scene_ids",
]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'lagrade' has no attribute {name!r}")
