"""What a grading run writes: per-student JSON, feedback pages and Gradescope results, and for
the class a gradebook, a summary (success rate per part, most common named mistakes) and the
score distribution as a chart. Every file is written atomically; the same results give the
same bytes."""

from __future__ import annotations

import csv
import functools
import io
import json
import re
from collections import Counter
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import lagrade.grading.atomic as atomic
from lagrade.assign import environment, md_block, md_code, md_escape
from lagrade.judge import OWN_COORDINATES, is_unreadable_line
from lagrade.untrusted import visible

STUDENTS = "students"


@functools.lru_cache(maxsize=1)
def _templates():
    """The shipped templates' environment, built once per process (compiling is the slow part)."""
    return environment()


def _student_json(out: Path, student_id: str) -> Path:
    return out / STUDENTS / f"{student_id}.json"


def read_student_result(out: Path, student_id: str) -> dict[str, Any] | None:
    """A previous run's result for this student, or None when absent or unreadable."""
    path = _student_json(out, student_id)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) and "fingerprint" in data else None


def log_error(out: Path, student_id: str, details: str) -> None:
    """Keep the traceback of a grader failure for the instructor (one file per student)."""
    atomic.write_text(out / "errors" / f"{student_id}.log", visible(details) + "\n")


def gradescope_results(result: Mapping[str, Any]) -> dict[str, Any]:
    """Gradescope's results.json: total score and one test per part. Every text is marked
    plain ("text"): Gradescope renders a top-level output as HTML by default ("simple_format"),
    and the reason of an unreadable sheet can quote the student's file."""
    tests = []
    for problem in result["problems"]:
        for part in problem["parts"]:
            tests.append(
                {
                    "name": f"Problem {problem['index']} ({problem['title']}): {part['key']}",
                    "score": part["points"],
                    "max_score": part["max_points"],
                    "output": " ".join(part["feedback"]) or part["verdict"],
                }
            )
    payload: dict[str, Any] = {
        "score": result["score"],
        "output_format": "text",
        "test_output_format": "text",
        "test_name_format": "text",
        "tests": tests,
    }
    if result["status"] != "graded":
        payload["output"] = f"{result['status']}: {result['reason']}"
    return payload


def write_student_outputs(out: Path, manifest: Mapping[str, Any], result: dict[str, Any]) -> None:
    """Feedback pages, results.json, then the JSON result (last: its presence marks the student
    as done for a rerun)."""
    sid = result["student"]["id"]
    env = _templates()
    context = {"assignment": manifest["assignment"], "result": result}
    atomic.write_text(
        out / "feedback" / f"{sid}.md", env.get_template("feedback.md.j2").render(context)
    )
    atomic.write_text(
        out / "feedback" / f"{sid}.html", env.get_template("feedback.html.j2").render(context)
    )
    atomic.write_json(out / "gradescope" / sid / "results.json", gradescope_results(result))
    atomic.write_json(_student_json(out, sid), result)


def gradebook_csv(manifest: Mapping[str, Any], results: Sequence[Mapping[str, Any]]) -> str:
    """One row per roster student: id, name, the roster's other columns (email, section, …) as
    the instructor's LMS exported them, status, score, max, percent, per problem, reason."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    problems = manifest["problems"]
    extra = roster_columns(manifest)
    writer.writerow(
        ["id", "name", *(csv_cell(c) for c in extra), "status", "score", "max_score", "percent"]
        + [f"problem{p['index']}" for p in problems]
        + ["reason"]
    )
    roster = {s["id"]: s.get("extra") or {} for s in manifest["students"]}
    for r in results:
        kept = roster.get(r["student"]["id"], {})
        per_problem = {p["index"]: p["score"] for p in r["problems"]}
        percent = 100 * r["score"] / r["max_score"] if r["max_score"] else 0.0
        writer.writerow(
            [
                csv_cell(r["student"]["id"]),
                csv_cell(r["student"]["name"]),
                *(csv_cell(kept.get(c, "")) for c in extra),
                r["status"],
                format_number(r["score"]),
                format_number(r["max_score"]),
                f"{percent:.1f}",
            ]
            + [format_number(per_problem.get(p["index"], 0.0)) for p in problems]
            + [csv_cell(result_reason(r))]
        )
    return buffer.getvalue()


def result_reason(result: Mapping[str, Any]) -> str:
    """The reason a result's row gives: why it was not graded, and a sheet that names another
    student than its file's (graded as the file's student, but the instructor's to look at)."""
    reason = result["reason"]
    other = result.get("sheet_student_id")
    if not other:
        return reason
    said = f"the sheet says student_id {other!r}; graded as the file's student"
    return f"{said}; {reason}" if reason else said


def roster_columns(manifest: Mapping[str, Any]) -> list[str]:
    """The roster's extra columns, in the order they first appear."""
    columns: dict[str, None] = {}
    for student in manifest["students"]:
        for name in student.get("extra") or {}:
            if name not in ("status", "score", "max_score", "percent", "reason"):
                columns.setdefault(str(name), None)
    return list(columns)


#: What a spreadsheet reads as the start of a formula (OWASP's CSV injection list).
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r", "\n")
_LINE_BREAKS = re.compile(r"[\r\n\v\f\x1c-\x1e\x85\u2028\u2029]+")


def csv_cell(text: Any) -> str:
    """Text for a CSV cell that a spreadsheet shows and never runs: a cell that would start a
    formula (`=HYPERLINK(…)`, `+cmd|…`, `@SUM(…)`) gets a leading apostrophe, OWASP's rule;
    line breaks of any kind become spaces."""
    text = str(text)
    if text.startswith(_FORMULA_START):
        text = "'" + text
    # One cell, one line: a lone CR is not quoted by csv.writer and would split the row.
    return _LINE_BREAKS.sub(" ", text)


def format_number(x: float) -> str:
    """A score as gradebooks print it: 3, 2.5, 0.333333."""
    return f"{x:g}"


def class_summary(
    manifest: Mapping[str, Any],
    results: Sequence[Mapping[str, Any]],
    stray: Mapping[str, str] | None = None,
) -> dict[str, Any]:
    """Success rate per part (correct over answers given: a blank part is no attempt), the most
    common named mistakes per problem, and the statuses."""
    graded = [r for r in results if r["problems"]]
    problems = []
    for problem in manifest["problems"]:
        parts, mistakes = [], Counter()
        examples: dict[tuple[str, str], str] = {}
        for part in problem["parts"]:
            verdicts = [
                p
                for r in graded
                for pr in r["problems"]
                if pr["index"] == problem["index"]
                for p in pr["parts"]
                if p["key"] == part["key"]
            ]
            correct = sum(1 for v in verdicts if v["verdict"] == "correct")
            blank = sum(1 for v in verdicts if "blank" in v["mistakes"])
            parts.append(
                {
                    "key": part["key"],
                    "answered": len(verdicts) - blank,
                    "correct": correct,
                    "success_rate": round(correct / (len(verdicts) - blank), 4)
                    if len(verdicts) > blank
                    else None,
                }
            )
            for v in verdicts:
                # The first named mistake is the diagnosis; its sentence leads the feedback,
                # after any line that could not be read (a parse message is no example of it).
                kind = next((k for k in v["mistakes"] if k not in NOT_MISTAKES), None)
                if kind:
                    mistakes[(part["key"], kind)] += 1
                    said = [f for f in v["feedback"] if not is_unreadable_line(f)]
                    examples.setdefault((part["key"], kind), said[0] if said else kind)
        top = [
            {"part": k[0], "mistake": k[1], "feedback": examples[k], "count": n}
            for k, n in sorted(mistakes.items(), key=lambda kv: (-kv[1], kv[0]))[:8]
        ]
        problems.append(
            {
                "index": problem["index"],
                "scene": problem["scene"],
                "title": problem["title"],
                "parts": parts,
                "common_mistakes": top,
            }
        )
    scores = [r["score"] for r in results]
    return {
        "students": len(results),
        "statuses": dict(sorted(Counter(r["status"] for r in results).items())),
        "mean_score": round(sum(scores) / len(scores), 1) if scores else 0.0,
        "max_score": results[0]["max_score"] if results else 0.0,
        "problems": problems,
        "stray_files": dict(sorted((stray or {}).items())),
        "mismatched_ids": mismatched_ids(results),
    }


#: Tags a verdict carries that are no mistake: a part left blank, and a valid choice of other
#: coordinates (the rubric may deduct for it, but it is nothing to teach against).
NOT_MISTAKES = frozenset({"blank", OWN_COORDINATES})


def mismatched_ids(results: Sequence[Mapping[str, Any]]) -> dict[str, str]:
    """Each student whose sheet gives another `student_id` (graded as the file's student): the
    file's student → the id the sheet says. A copied sheet, or one handed in under another
    name, is the instructor's to look at."""
    return {r["student"]["id"]: r["sheet_student_id"] for r in results if r.get("sheet_student_id")}


def summary_markdown(manifest: Mapping[str, Any], summary: Mapping[str, Any]) -> str:
    lines = [f"# {md_escape(manifest['assignment']['title'])}: grading summary", ""]
    lines.append(
        f"{summary['students']} students; statuses: "
        + ", ".join(f"{k} {v}" for k, v in summary["statuses"].items())
        + f"; mean score {summary['mean_score']:g} of {summary['max_score']:g}."
    )
    if summary.get("stray_files"):
        lines += ["", "Files in the submissions folder that were not graded:", ""]
        lines += [f"- {md_code(n)}: {md_escape(why)}" for n, why in summary["stray_files"].items()]
    if summary.get("mismatched_ids"):
        lines += ["", "Sheets whose `student_id` is not their file's (graded as the file's):", ""]
        lines += [
            f"- {md_code(sid)}: the sheet says student_id = {md_code(other)}"
            for sid, other in summary["mismatched_ids"].items()
        ]
    lines += ["", "![score distribution](scores.svg)", ""]
    for problem in summary["problems"]:
        lines += [
            f"## Problem {problem['index']}: {md_escape(problem['title'])} "
            f"({md_escape(problem['scene'])})",
            "",
            "| part | answered | correct | success rate (of answers) |",
            "| --- | --- | --- | --- |",
        ]
        for p in problem["parts"]:
            rate = "–" if p["success_rate"] is None else f"{100 * p['success_rate']:.0f} %"
            lines.append(f"| {md_escape(p['key'])} | {p['answered']} | {p['correct']} | {rate} |")
        if problem["common_mistakes"]:
            lines += ["", "Most common named mistakes:", ""]
            for m in problem["common_mistakes"]:
                first, _, source = str(m["feedback"]).partition("\n")
                lines.append(
                    f"- {m['count']} × {md_escape(m['part'])}, {md_code(m['mistake'])}, "
                    f'e.g. "{md_escape(first)}"'
                )
                if source.strip():  # the answer line and its caret, kept as lines in the item
                    lines += ["", *("  " + ln for ln in md_block(source).splitlines()), ""]
        lines.append("")
    return "\n".join(lines)


def score_chart(
    results: Sequence[Mapping[str, Any]], max_score: float
) -> tuple[bytes, bytes] | None:
    """The score distribution as (PNG, SVG) bytes, deterministic; None without matplotlib."""
    try:
        import matplotlib

        matplotlib.use("Agg", force=False)
        from matplotlib.figure import Figure
        from matplotlib.ticker import MaxNLocator
    except ImportError:
        return None
    scores = [r["score"] for r in results if r["status"] != "missing"]
    with matplotlib.rc_context({"svg.hashsalt": "lagrade", "svg.fonttype": "none"}):
        fig = Figure(figsize=(6, 3.2))
        ax = fig.add_subplot()
        bins = max(5, min(20, int(max_score) or 5))
        ax.hist(scores, bins=bins, range=(0, max_score or 1), color="#4c72b0", edgecolor="white")
        ax.set_xlabel("score")
        ax.set_ylabel("students")
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))  # no half students
        ax.set_title(f"Score distribution ({len(scores)} submissions)")
        fig.tight_layout()
        png, svg = io.BytesIO(), io.BytesIO()
        fig.savefig(png, format="png", dpi=100, metadata={"Software": None})
        fig.savefig(svg, format="svg", metadata={"Date": None})
    return png.getvalue(), svg.getvalue()


def write_class_reports(
    out: Path,
    manifest: Mapping[str, Any],
    results: Sequence[Mapping[str, Any]],
    stray: Mapping[str, str] | None = None,
) -> None:
    """gradebook.csv, summary.json, summary.md and the score chart; `stray` lists the files
    of the submissions folder that are no student's sheet (name → why)."""
    atomic.write_text(out / "gradebook.csv", gradebook_csv(manifest, results))
    summary = class_summary(manifest, results, stray)
    atomic.write_json(out / "summary.json", summary)
    atomic.write_text(out / "summary.md", summary_markdown(manifest, summary))
    chart = score_chart(results, summary["max_score"])
    if chart is not None:
        atomic.write_bytes(out / "scores.png", chart[0])
        atomic.write_bytes(out / "scores.svg", chart[1])
