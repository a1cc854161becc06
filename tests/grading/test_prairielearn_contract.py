"""PrairieLearn's contract with a question, as its documentation states it, held by lagrade's
exported questions (issue 28). Run through `tests.prairielearn_node`, PrairieLearn's Node side
modelled, with server.py in this process and the documented behaviour of the elements used
(`Node.local`); `test_prairielearn_worker.py` runs the same against PrairieLearn's real worker.

From PrairieLearn's docs (docs/question/server.md, template.md, elements/pl-string-input.md):
- each phase may change only its own parts of `data` (the table in server.md), and `data` must
  be JSON without NaN; anything printed is a course issue;
- `correct_answers` is what the answer panel shows and what the question test submits: here the
  key's answers as a student types them, non-empty, and `grade` gives them full marks;
- a format error makes the submission invalid (not graded, no attempt used): an unreadable
  answer, and an answer with one unreadable line, are format errors; a format error is HTML
  (pl-string-input puts it in a popover with `data-bs-html`): the student's text escaped;
- feedback from `grade` that the student must see is rendered by question.html from
  `data["feedback"]` with mustache's escaping `{{ }}`: a wrong part's feedback is in the
  submission panel, and HTML in an answer never becomes a tag;
- a question whose `grade` replaces the elements' grading supplies `test()` (server.md, "Testing
  questions"): the test's expected scores equal what parse and grade give;
- text outside the panel elements shows in every panel: prompts belong in pl-question-panel.
"""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

from lagrade.bank.registry import get_scene
from lagrade.grading.prairielearn import export_prairielearn, vendored_folder
from lagrade.judge.key import key_answer
from tests.prairielearn_node import Node, Text, shown
from tests.prairielearn_probe import injected

ASSIGNMENT = """\
title = "PL contract"

[[problems]]
scene = "kepler"
parts = ["dof", "coordinates", "transformation", "T", "V", "lagrangian", "eom", "momenta",
         "cyclic", "conserved", { quantity = "circular_angular_velocity" }]
points = { lagrangian = 3, eom = 2 }

[[problems]]
scene = "wedge"
parts = ["transformation", "lagrangian", "eom", { quantity = "block_acceleration" }]
"""
HOSTILE = '<img src=x onerror="document.title=1">'


@pytest.fixture(scope="module")
def course(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("pl-contract")
    (root / "a.toml").write_text(ASSIGNMENT, encoding="utf-8")
    export_prairielearn(root / "a.toml", 2025, root / "course")
    return root / "course"


@pytest.fixture(scope="module")
def node(course):
    node = Node.local(course)
    yield node
    node.close()


@pytest.fixture(scope="module", params=["kepler", "wedge"])
def question(request, node, course):
    (folder,) = [p.name for p in (course / "questions").iterdir() if p.name.endswith(request.param)]
    q = node.question(folder)
    q.generate(variant_seed=4242)
    return q


def variant(question):
    scene = question.directory.rsplit("-", 1)[1]
    return get_scene(scene).variant(question.variant["params"]["seed"])


PARTS = {"dof", "coordinates", "transformation", "T", "V", "lagrangian", "eom", "momenta"}
PARTS |= {"cyclic", "conserved"}


def test_correct_answers_are_the_key_as_a_student_types_it(question):
    v = variant(question)
    for key, text in question.variant["true_answer"].items():
        assert isinstance(text, str) and text.strip(), key
        expected = key_answer(v, key) if key in PARTS else key_answer(v, "expression", key)
        assert text == ("\n".join(expected) if isinstance(expected, list) else expected), key


def test_the_key_gets_full_marks_and_says_so(question):
    got = question.submit(dict(question.variant["true_answer"]))
    assert got["format_errors"] == {} and got["gradable"]
    points = {"lagrangian": 3.0, "eom": 2.0} if "kepler" in question.directory else {}
    for key, score in got["partial_scores"].items():
        assert score == {"score": 1.0, "weight": points.get(key, 1.0)}, key
    assert got["score"] == 1.0
    panel = question.render("submission", got)
    for key in got["partial_scores"]:
        assert got["feedback"]["lagrade"][key]["outcome"].startswith("Correct:"), key
    assert panel.count("Correct:") == len(got["partial_scores"])
    assert not question.issues  # nothing printed


@pytest.mark.parametrize("test_type", ["correct", "incorrect", "invalid"])
def test_the_question_test_passes(question, test_type):
    """PrairieLearn's question test: test() says what its submission must get, and parse and
    grade give exactly that (gradable, format error keys, partial scores, score)."""
    assert question.question_test(test_type) == []


def test_a_wrong_part_shows_its_feedback_in_the_submission_panel_only(question):
    answers = dict(question.variant["true_answer"])
    answers["lagrangian"] = question.test_phase("incorrect")["raw_submitted_answers"]["lagrangian"]
    got = question.submit(answers)
    mine = got["feedback"]["lagrade"]["lagrangian"]
    assert got["partial_scores"]["lagrangian"]["score"] == 0.0
    assert mine["outcome"].startswith("Incorrect: 0 of") and mine["notes"]
    submission = question.render("submission", got)
    for note in mine["notes"]:
        assert shown(note["text"], submission), note
        assert not shown(note["text"], question.render("question", got))
    assert shown(f"Read as: {mine['read']}", submission)


def test_an_unreadable_answer_and_an_unreadable_line_are_format_errors(question):
    key = "eom"  # several lines: the first right, the second unreadable
    answers = dict(question.variant["true_answer"])
    first = answers[key].split("\n")[0]
    answers[key] = f"{first}\n1/2 m (q_dot"
    answers["lagrangian"] = "1/2 m (x_dot^2"
    got = question.submit(answers)
    assert set(got["format_errors"]) == {"eom", "lagrangian"} and not got["gradable"]
    assert got["partial_scores"] is None  # never graded: no attempt used
    eom = got["format_errors"]["eom"]
    assert eom.startswith('<pre class="mb-0">') and eom.endswith("</pre>")
    assert "Line 2 could not be read" in html.unescape(eom) and "^" in eom
    assert first not in html.unescape(eom)  # only the line that could not be read
    shown_error = got["feedback"]["lagrade"]["eom"]["error"]
    panel = question.render("submission", got)
    assert shown(shown_error, panel) and "<pre>" in panel


def test_html_in_every_answer_stays_text(question):
    keys = list(question.variant["true_answer"])
    got = question.submit({key: HOSTILE for key in keys})
    assert set(got["format_errors"]) == set(keys)
    for key, error in got["format_errors"].items():
        # what Bootstrap puts in the popover: the attribute, decoded once, as HTML
        assert "<img" not in error and injected(error) == [], key
    quoted = got["format_errors"]["lagrangian"]  # the parser quotes the answer under its caret
    assert "&lt;img src=x onerror=&quot;" in quoted and shown(HOSTILE, quoted)
    panel = question.render("submission", got)
    assert injected(panel) == [] and shown("<img src=x", panel)
    attribute = f'data-bs-content="{html.escape(got["format_errors"][keys[0]])}"'
    assert injected(f"<a {attribute}>More info</a>") == []


def test_prompts_and_the_statement_are_in_the_question_panel_only(question):
    template = question.template
    for key in question.variant["true_answer"]:
        prompt = f"{{{{{{params.prompts.{key}}}}}}}"
        assert re.search(
            rf"<pl-question-panel>\s*<p>{re.escape(prompt)}</p>\s*</pl-question-panel>", template
        ), key
    assert "<pl-question-panel>\n{{{params.statement_html}}}\n</pl-question-panel>" in template
    assert "{{{feedback" not in template and "{{{submitted" not in template  # escaped only
    answer = question.render("answer")
    for key, prompt in question.variant["params"]["prompts"].items():
        assert not shown(Text(prompt).text[:40], answer), key
        assert shown(Text(prompt).text[:40], question.render("question")), key


def test_server_py_runs_the_lagrade_copied_into_server_files_course(course, tmp_path):
    """Hosted PrairieLearn installs nothing: server.py imports the lagrade vendored under
    serverFilesCourse/, which PrairieLearn puts on sys.path. Checked in a fresh interpreter
    where no other lagrade can be imported."""
    import subprocess
    import sys

    vendored = vendored_folder(course)
    assert (vendored / "lagrade" / "__init__.py").is_file()
    assert list(vendored.glob("lagrade-*.dist-info/RECORD"))
    folder = next((course / "questions").iterdir())
    script = f"""
import importlib.abc, importlib.machinery, sys
class OnlyCourseFiles(importlib.abc.MetaPathFinder):
    # no lagrade but one found through serverFilesCourse/ (as on hosted PrairieLearn)
    def find_spec(self, name, path=None, target=None):
        if name != "lagrade":
            return None
        places = [p for p in sys.path if "serverFilesCourse" in p]
        spec = importlib.machinery.PathFinder.find_spec(name, places)
        if spec is None:
            raise ImportError("no lagrade in serverFilesCourse")
        return spec
sys.meta_path.insert(0, OnlyCourseFiles())
sys.path.insert(0, {str(course / "serverFilesCourse")!r})
module = {{"__file__": {str(folder / "server.py")!r}}}
exec(compile(open(module["__file__"]).read(), module["__file__"], "exec"), module)
import lagrade
data = {{"params": {{}}, "correct_answers": {{}}, "variant_seed": 3, "options": {{}}}}
module["generate"](data)
print(lagrade.__file__)
print(sorted(data["correct_answers"]))
"""
    run = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=tmp_path, timeout=120
    )
    assert run.returncode == 0, run.stderr
    where, keys = run.stdout.splitlines()
    assert Path(where).resolve().is_relative_to(vendored.resolve())
    assert "lagrangian" in keys


def test_html_in_a_scene_file_or_a_title_stays_text(tmp_path):
    """Scene files may come from anyone: HTML in a title, statement, parameter or quantity
    description reaches the statement and prompts as text (they go out unescaped, `{{{ }}}`)."""
    source = (Path(__file__).parents[1] / "scenes/files/parabola.toml").read_text()
    source = source.replace("A bead of mass", f"{HOSTILE} A bead of mass")
    source = source.replace('"mass of the bead"', f"'mass {HOSTILE} of the bead'")
    source = source.replace('"angular frequency of small', f"'{HOSTILE} angular frequency of small")
    source = source.replace('bottom of the wire"', "bottom of the wire'")
    (tmp_path / "scenes").mkdir()
    (tmp_path / "scenes/parabola.toml").write_text(source)
    (tmp_path / "a.toml").write_text(
        f"title = '{HOSTILE}'\n[[problems]]\nscene = 'scenes/parabola.toml'\ntitle = '{HOSTILE}'\n"
        "parts = ['lagrangian', { quantity = 'oscillation_frequency' }]\n"
    )
    export_prairielearn(tmp_path / "a.toml", 1, tmp_path / "course", tmp_path / "scenes")
    node = Node.local(tmp_path / "course")
    (folder,) = (tmp_path / "course/questions").iterdir()
    question = node.question(folder.name)
    question.generate(variant_seed=5)
    params = question.variant["params"]
    assert params["statement_html"].count("&lt;img src=x") == 2  # statement, parameter table
    assert "&lt;img src=x" in params["prompts"]["oscillation_frequency"]
    page = question.render("question")
    assert injected(page) == [] and shown(HOSTILE, page)
