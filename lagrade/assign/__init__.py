"""Layer 2: assignments from the bank: the assignment file and roster, one variant per student,
figures, jinja2 templates, and the generation of handouts, keys, answer sheets and manifest."""

from __future__ import annotations

from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "Assignment": "lagrade.assign.assignment",
    "assignment_table": "lagrade.assign.assignment",
    "build_pool": "lagrade.assign.variants",
    "check_scene_file": "lagrade.assign.scene_check",
    "environment": "lagrade.assign.templating",
    "generate": "lagrade.assign.generation",
    "EXPRESSION": "lagrade.assign.assignment",
    "key_answers": "lagrade.assign.views",
    "latex_symbol_names": "lagrade.assign.solution",
    "load_assignment": "lagrade.assign.assignment",
    "load_roster": "lagrade.assign.roster",
    "md_block": "lagrade.assign.templating",
    "md_code": "lagrade.assign.templating",
    "md_escape": "lagrade.assign.templating",
    "MULTILINE": "lagrade.assign.views",
    "new_scene_file": "lagrade.assign.scene_check",
    "one_line": "lagrade.assign.templating",
    "parse_assignment": "lagrade.assign.assignment",
    "Part": "lagrade.assign.assignment",
    "AssignedProblem": "lagrade.assign.assignment",
    "problem_view": "lagrade.assign.views",
    "project_version": "lagrade.assign.manifest",
    "scene_resolver": "lagrade.assign.assignment",
    "solution": "lagrade.assign.solution",  # the module
    "Student": "lagrade.assign.roster",
    "toml_literal": "lagrade.assign.templating",
    "toml_string": "lagrade.assign.templating",
    "VariantChoice": "lagrade.assign.variants",
}
#: The modules exported as a whole.
_MODULES = {"solution"}

__all__ = [
    "Assignment",
    "assignment_table",
    "build_pool",
    "check_scene_file",
    "environment",
    "EXPRESSION",
    "generate",
    "key_answers",
    "latex_symbol_names",
    "load_assignment",
    "load_roster",
    "md_block",
    "md_code",
    "md_escape",
    "MULTILINE",
    "new_scene_file",
    "one_line",
    "parse_assignment",
    "Part",
    "AssignedProblem",
    "problem_view",
    "project_version",
    "scene_resolver",
    "solution",
    "Student",
    "toml_literal",
    "toml_string",
    "VariantChoice",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
