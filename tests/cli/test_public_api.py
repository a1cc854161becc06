"""The front doors: what `lagrade` and each layer export is pinned, so a change is a decision."""

import importlib

import pytest

EXPORTS = {
    "lagrade": [
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
    ],
    "lagrade.mechanics": [
        "Domain",
        "Equilibrium",
        "HamiltonianSystem",
        "Jet",
        "LagrangianSystem",
        "NotQuadratic",
        "PointMass",
        "Quantity",
        "RigidBody",
        "Scene",
        "SceneVariant",
        "SmallOscillations",
        "frequencies_from",
        "jet",
        "momentum_jet",
        "momentum_name",
        "total_derivative",
        "variant_oscillations",
    ],
    "lagrade.bank": ["get_scene", "scene_ids"],
    "lagrade.notation": [
        "Parsed",
        "Vocabulary",
        "parse_answer",
        "parse_equation",
        "parse_equations",
        "parse_expression",
    ],
    "lagrade.judge": [
        "PARTS",
        "Problem",
        "Verdict",
        "build_problem",
        "check",
        "key_answer",
        "run_checker",
        "verify_variant",
    ],
    "lagrade.assign": ["Assignment", "Student", "generate", "load_assignment", "load_roster"],
    "lagrade.grading": ["BatchSummary", "grade"],
    "lagrade.cli": ["main"],
}


@pytest.mark.parametrize("module", sorted(EXPORTS))
def test_exports_are_pinned(module):
    assert sorted(importlib.import_module(module).__all__) == sorted(EXPORTS[module])


@pytest.mark.parametrize("module", sorted(EXPORTS))
def test_every_export_exists(module):
    loaded = importlib.import_module(module)
    for name in loaded.__all__:
        assert getattr(loaded, name) is not None
