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
        "phase_space",
        "small_oscillations",
        "Anchor",
        "DDOT",
        "DOT",
        "Domain",
        "Equilibrium",
        "FIXTURE_KINDS",
        "FigureHint",
        "Fixture",
        "HamiltonianSystem",
        "Jet",
        "LABEL_PLACES",
        "LAGRANGIAN_PARTS",
        "LagrangianSystem",
        "NotQuadratic",
        "Parameter",
        "PointMass",
        "Quantity",
        "REAL",
        "Reparametrized",
        "RigidBody",
        "Scene",
        "SceneVariant",
        "SmallOscillations",
        "SpatialRigidBody",
        "ZERO_MODE",
        "as_expr",
        "cartesian_symbols",
        "collapse_trig",
        "coordinates_through_positions",
        "coordinates_to_carry",
        "exact_number",
        "deciding_values",
        "frequencies_from",
        "generalized_eigenvalues",
        "generalized_modes",
        "identically_zero",
        "jet",
        "lagrange",
        "momentum_jet",
        "momentum_name",
        "t",
        "total_derivative",
        "variant_oscillations",
    ],
    "lagrade.bank": [
        "SCENE_ID",
        "check_claim",
        "find_scene",
        "get_scene",
        "is_bank_scene",
        "is_scene_path",
        "list_scenes",
        "read_scene_file",
        "scene_from_text",
        "scene_id_of",
        "scene_ids",
        "scene_reference",
        "sha256",
        "template",
    ],
    "lagrade.notation": [
        "COMMANDS",
        "FUNCTIONS",
        "GREEK",
        "MAX_TOTAL_LENGTH",
        "NameRead",
        "Parsed",
        "Vocabulary",
        "fold",
        "is_latex",
        "key_answer",
        "name_latex",
        "parse",
        "parse_answer",
        "parse_equation",
        "parse_equations",
        "parse_expression",
        "plain",
        "printer",
        "symbol_names",
    ],
    "lagrade.judge": [
        "FOLLOWING",
        "GRACE",
        "Limits",
        "LivePool",
        "MAX_ID_LENGTH",
        "NUMERIC_TOLERANCE",
        "OWN_COORDINATES",
        "Outcome",
        "PARTS",
        "PREPARE_LIMIT",
        "PartTimeout",
        "Pool",
        "Problem",
        "Verdict",
        "build_problem",
        "cached_problem",
        "check",
        "check_pool",
        "deadline",
        "deriving",
        "forget_problems",
        "is_unreadable_line",
        "judge",
        "key_answer",
        "note",
        "prepare",
        "read_answer",
        "run_batch",
        "run_checker",
        "time_limit",
        "timeout_verdict",
        "verify_variant",
    ],
    "lagrade.assign": [
        "AssignedProblem",
        "Assignment",
        "EXPRESSION",
        "MULTILINE",
        "Part",
        "Student",
        "VariantChoice",
        "assignment_table",
        "build_pool",
        "check_scene_file",
        "environment",
        "generate",
        "key_answers",
        "latex_symbol_names",
        "load_assignment",
        "load_roster",
        "md_block",
        "md_code",
        "md_escape",
        "new_scene_file",
        "one_line",
        "parse_assignment",
        "problem_view",
        "project_version",
        "scene_resolver",
        "solution",
        "toml_literal",
        "toml_string",
    ],
    "lagrade.grading": [
        "BatchSummary",
        "ExportOptions",
        "LOG_NAME",
        "QUESTIONS",
        "ReadDeadlines",
        "SECRET_NAME",
        "SERVER_FILES",
        "as_of_instant",
        "atomic",
        "build_classroom",
        "carried_scene_texts",
        "check_on_cluster",
        "entry_variant",
        "export_file_name",
        "export_gradescope",
        "export_prairielearn",
        "grade",
        "info_json",
        "links_csv",
        "load_manifest",
        "load_or_create_secret",
        "make_app",
        "question",
        "readme_file_name",
        "require",
        "shown",
        "vendored_folder",
    ],
    "lagrade.cli": [
        "entry",
        "main",
    ],
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
