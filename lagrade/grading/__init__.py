"""Layer 3: a class graded: every roster student's sheet read, judged part by part in isolated
workers, and written out as a gradebook, per-student results, feedback pages and reports.

`grade` and `BatchSummary` are loaded on first use, so that a command needing only a leaf of
this package (`check --batch` writes its results with `lagrade.grading.atomic`) does not import
the reports, templates and charts (about 65 ms of start-up)."""

from __future__ import annotations

from lagrade.exports import lazy_exports

#: Each exported name, by the module that defines it (a module exported as a whole: its own
#: name). Loaded on first use, so that importing the layer costs nothing it does not use.
_EXPORTS = {
    "as_of_instant": "lagrade.grading.answer_page.due",
    "atomic": "lagrade.grading.atomic",  # the module
    "BatchSummary": "lagrade.grading.batch",
    "build_classroom": "lagrade.grading.answer_page.room",
    "carried_scene_texts": "lagrade.grading.manifest",
    "check_on_cluster": "lagrade.grading.cluster.checking",
    "entry_variant": "lagrade.grading.manifest",
    "export_file_name": "lagrade.grading.gradebooks",
    "export_gradescope": "lagrade.grading.gradescope",
    "export_prairielearn": "lagrade.grading.prairielearn",
    "ExportOptions": "lagrade.grading.lms",
    "grade": "lagrade.grading.batch",
    "info_json": "lagrade.grading.prairielearn",
    "links_csv": "lagrade.grading.answer_page.tokens",
    "load_manifest": "lagrade.grading.manifest",
    "load_or_create_secret": "lagrade.grading.answer_page.tokens",
    "LOG_NAME": "lagrade.grading.savelog",
    "make_app": "lagrade.grading.answer_page.app",
    "question": "lagrade.grading.student",
    "QUESTIONS": "lagrade.grading.prairielearn",
    "ReadDeadlines": "lagrade.grading.answer_page.deadlines",
    "readme_file_name": "lagrade.grading.gradebooks",
    "require": "lagrade.grading.cluster.connect",
    "SECRET_NAME": "lagrade.grading.answer_page.tokens",
    "SERVER_FILES": "lagrade.grading.prairielearn",
    "shown": "lagrade.grading.instants",
    "vendored_folder": "lagrade.grading.prairielearn",
}
#: The modules exported as a whole.
_MODULES = {"atomic"}

__all__ = [
    "as_of_instant",
    "atomic",
    "BatchSummary",
    "build_classroom",
    "carried_scene_texts",
    "check_on_cluster",
    "entry_variant",
    "export_file_name",
    "export_gradescope",
    "export_prairielearn",
    "ExportOptions",
    "grade",
    "info_json",
    "links_csv",
    "load_manifest",
    "load_or_create_secret",
    "LOG_NAME",
    "make_app",
    "question",
    "QUESTIONS",
    "ReadDeadlines",
    "readme_file_name",
    "require",
    "SECRET_NAME",
    "SERVER_FILES",
    "shown",
    "vendored_folder",
]

__getattr__ = lazy_exports(__name__, _EXPORTS, _MODULES)
