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
        "identically_zero",
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
        "deriving",
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


def test_no_export_is_shadowed_by_a_module_of_the_same_name():
    """A layer exports a function that has the name of one of its modules (`lagrade.judge.check`
    defines `check`): importing the module sets the package's attribute to the module, so a lazy
    export would then give the module. With every module of lagrade imported, each exported name
    is still what it was (a module only where the layer exports a module)."""
    import importlib
    import pkgutil

    import lagrade

    for info in pkgutil.walk_packages(lagrade.__path__, "lagrade."):
        if not info.name.endswith("__main__"):  # that one runs the command
            importlib.import_module(info.name)
    for layer in ("mechanics", "notation", "bank", "judge", "assign", "grading", "cli"):
        package = importlib.import_module(f"lagrade.{layer}")
        modules = getattr(package, "_MODULES", set())
        for name in package.__all__:
            value = getattr(package, name)
            assert (type(value).__name__ == "module") == (name in modules), (
                f"lagrade.{layer}.{name}"
            )
