"""The class reports read right: a success rate over the answers given, a mean rounded for a
person, a chart without half students; feedback pages that keep a caret under its character."""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from lagrade.grading import report
from lagrade.judge.check import check


def _part(key, verdict, mistakes=(), feedback=()):
    return {
        "key": key,
        "part": key,
        "verdict": verdict,
        "points": 1.0 if verdict == "correct" else 0.0,
        "max_points": 1.0,
        "feedback": list(feedback),
        "interpreted": "",
        "method": "numeric",
        "mistakes": list(mistakes),
        "follows_from_own_answer": False,
    }


def _result(sid, score, parts, status="graded"):
    problems = [{"index": 1, "scene": "hoop", "title": "Hoop", "score": score, "max_score": 30.0,
                 "parts": parts}] if parts else []  # fmt: skip
    return {"student": {"id": sid, "name": sid}, "status": status, "reason": "",
            "warnings": [], "score": score, "max_score": 30.0, "problems": problems}  # fmt: skip


MANIFEST = {
    "assignment": {"title": "PS", "total_points": 30},
    "problems": [{"index": 1, "scene": "hoop", "title": "Hoop", "parts": [{"key": "dof"}]}],
    "students": [],
}


def test_success_rate_divides_by_answers_given():
    results = [
        _result("a", 24.5, [_part("dof", "correct")]),
        _result("b", 24.6, [_part("dof", "incorrect", ("blank",), ("Not answered.",))]),
        _result("c", 24.6, [_part("dof", "incorrect", ("blank",), ("Not answered.",))]),
    ]
    summary = report.class_summary(MANIFEST, results)
    dof = summary["problems"][0]["parts"][0]
    assert dof["answered"] == 1 and dof["correct"] == 1
    assert dof["success_rate"] == 1.0  # 1 of the 1 answer given, not 1 of 3 students


def test_mean_is_rounded_for_a_person():
    results = [
        _result(s, x, [_part("dof", "correct")])
        for s, x in zip("abc", (24.5, 24.6, 24.6), strict=True)
    ]
    summary = report.class_summary(MANIFEST, results)
    assert summary["mean_score"] == 24.6
    assert "mean score 24.6 of 30" in report.summary_markdown(MANIFEST, summary)


def test_chart_has_whole_students_only():
    pytest.importorskip("matplotlib")
    results = [
        _result(s, x, [_part("dof", "correct")]) for s, x in zip("abc", (3, 17, 25), strict=True)
    ]
    _png, svg = report.score_chart(results, 30.0)
    groups = re.findall(r'<g id="ytick_\d+">.*?<text [^>]*>([^<]*)</text>', svg.decode(), re.S)
    assert len(groups) >= 2, "the y axis has labelled ticks"
    assert all(re.fullmatch(r"\d+", t) for t in groups), groups  # 0, 1 — never 0.5


def test_html_feedback_keeps_the_caret_under_its_character(tmp_path):
    verdict = check({"scene": "hoop"}, "lagrangian", "1/2 m R^2 theta_dot^2 + m g R cos(theta")
    assert "\n" in verdict.feedback[0]  # message, the answer line, the caret line
    part = _part("lagrangian", verdict.status, (), verdict.feedback)
    result = _result("s001", 0.0, [part])
    report.write_student_outputs(tmp_path, MANIFEST, result)
    html = (tmp_path / "feedback" / "s001.html").read_text()
    block = re.search(r'<pre class="source"[^>]*>(.*?)</pre>', html, flags=re.S)
    assert block, html
    source, caret = block.group(1).split("\n")
    assert caret.strip() == "^"
    assert source[len(caret) - 1] == "("  # the bracket never closed, in monospace


def test_markdown_feedback_keeps_the_caret_in_a_code_block(tmp_path):
    verdict = check({"scene": "hoop"}, "lagrangian", "1/2 m R^2 theta_dot^2 + m g R cos(theta")
    result = _result("s001", 0.0, [_part("lagrangian", verdict.status, (), verdict.feedback)])
    report.write_student_outputs(tmp_path, MANIFEST, result)
    md = (tmp_path / "feedback" / "s001.md").read_text()
    block = re.search(r"```\n(.*?)\n```", md, flags=re.S)
    assert block, md
    source, caret = block.group(1).split("\n")
    assert caret.strip() == "^" and source[len(caret) - 1] == "("
    assert "| Missing ')'" in md  # the table keeps the message, not the collapsed caret


LONG_UNREADABLE = (
    "1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta) + m g R cos(theta)"
    " + 1/2 m R^2 )theta_dot^2 + omega^2 sin(theta)^2 + m g R cos(theta) + m g R cos(theta)"
)


def _chromium_measure(page: Path, width: int) -> dict:
    """Open `page` in headless Chromium at `width` pixels and return what a script measured
    there: the page column's right edge and each table's."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        pytest.skip("chromium is not installed (.ci/run installs it)")
    probe = page.with_name("probe.html")
    script = (
        "<script>window.addEventListener('load', () => { const column = document.body"
        ".getBoundingClientRect().right - parseFloat(getComputedStyle(document.body)"
        ".paddingRight); const tables = [...document.querySelectorAll('table')].map(t => "
        "t.getBoundingClientRect().right); document.body.setAttribute('data-measured', "
        "JSON.stringify({column, tables})); });</script>"
    )
    probe.write_text(page.read_text().replace("</body>", script + "</body>"))
    dom = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
         f"--window-size={width},900", probe.as_uri()],
        capture_output=True, text=True, timeout=120,
    ).stdout  # fmt: skip
    found = re.search(r"data-measured=\"([^\"]*)\"", dom)
    assert found, dom[-2000:]
    return json.loads(html.unescape(found.group(1)))


@pytest.mark.parametrize("width", [1000, 700])
def test_a_caret_block_stays_inside_the_page_column(tmp_path, width):
    verdict = check({"scene": "hoop"}, "lagrangian", LONG_UNREADABLE)
    assert len(verdict.feedback[0].split("\n")[1]) > 70  # a whole window of the answer line
    parts = [_part("lagrangian", verdict.status, (), verdict.feedback), _part("T", "correct")]
    report.write_student_outputs(tmp_path, MANIFEST, _result("s001", 0.0, parts))
    measured = _chromium_measure(tmp_path / "feedback" / "s001.html", width)
    assert measured["tables"] and all(
        right <= measured["column"] + 1 for right in measured["tables"]
    ), measured


def test_summary_keeps_a_caret_block_as_lines():
    from markdown_it import MarkdownIt

    verdict = check({"scene": "hoop"}, "lagrangian", "1/2 m R^2 theta_dot^2 + m g R cos(theta")
    feedback = verdict.feedback
    results = [
        _result(s, 0.0, [_part("lagrangian", "invalid", ("unreadable",), feedback)]) for s in "ab"
    ]
    manifest = {
        **MANIFEST,
        "problems": [{**MANIFEST["problems"][0], "parts": [{"key": "lagrangian"}]}],
    }
    text = report.summary_markdown(manifest, report.class_summary(manifest, results))
    tokens = MarkdownIt("commonmark").parse(text)
    blocks = [t.content for t in tokens if t.type in ("fence", "code_block")]
    source, caret = feedback[0].split("\n")[1:]
    assert blocks == [f"{source}\n{caret}\n"], text  # both lines, as written, under each other
    item = next(i for i, t in enumerate(tokens) if t.type == "list_item_open")
    closing = next(i for i, t in enumerate(tokens) if t.type == "list_item_close" and i > item)
    fence = next(i for i, t in enumerate(tokens) if t.type in ("fence", "code_block"))
    assert item < fence < closing  # inside the list item it illustrates


def test_common_mistakes_count_real_mistakes_with_their_own_sentence():
    """Issue 38: a valid choice of own coordinates was listed among the class's common mistakes,
    and a conserved-quantity answer with one unreadable line gave the parse message as the
    example of a missing conserved quantity."""
    parse = "Line 2 could not be read: Unknown symbol 'x'.\n  x\n  ^"
    count = "The system has 2 independent conserved quantities; your list gives 1."
    own = "Your coordinates are not the statement's: u = r cos(θ). That is a valid choice."
    results = [
        _result(s, 20.0, [_part("transformation", "correct", ("own_coordinates",), (own,)),
                          _part("conserved", "incorrect", ("missing_conserved",), (parse, count))])
        for s in "abc"
    ]  # fmt: skip
    manifest = {
        **MANIFEST,
        "problems": [{**MANIFEST["problems"][0],
                      "parts": [{"key": "transformation"}, {"key": "conserved"}]}],
    }  # fmt: skip
    summary = report.class_summary(manifest, results)
    (mistake,) = summary["problems"][0]["common_mistakes"]
    assert mistake == {"part": "conserved", "mistake": "missing_conserved", "feedback": count,
                       "count": 3}  # fmt: skip
    text = report.summary_markdown(manifest, summary)
    assert "own_coordinates" not in text and "could not be read" not in text
