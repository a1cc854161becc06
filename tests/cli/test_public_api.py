"""The front doors: what `problem_bank` and `grader` export is pinned, so a change is a decision."""

import grader
import problem_bank


def test_problem_bank_exports():
    assert sorted(problem_bank.__all__) == [
        "Domain",
        "Jet",
        "LagradeError",
        "LagrangianSystem",
        "Scene",
        "SceneError",
        "SceneVariant",
        "UnknownSceneError",
        "generate",
        "get_scene",
        "jet",
        "scene_ids",
        "total_derivative",
    ]


def test_grader_exports():
    assert sorted(grader.__all__) == [
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


def test_every_export_exists():
    for module in (problem_bank, grader):
        for name in module.__all__:
            assert getattr(module, name) is not None


def test_bank_never_imports_the_grader():
    import pathlib
    import re

    root = pathlib.Path(problem_bank.__file__).parent
    offenders = [
        p.name
        for p in root.rglob("*.py")
        if re.search(r"^\s*(from|import)\s+grader\b", p.read_text(), re.M)
    ]
    assert offenders == []
