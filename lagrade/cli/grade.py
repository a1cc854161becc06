"""`lagrade grade`: a folder of answer sheets graded against a manifest."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from lagrade.cli.arguments import count, seconds

if TYPE_CHECKING:
    from lagrade.grading import BatchSummary

#: Stray files named one by one in the printed summary; summary.md lists them all.
SHOWN_STRAY = 20


def summary_table(summary: BatchSummary) -> str:
    """A plain-text table of every student's status and score, the files of the submissions
    folder that were not graded, and the totals (printed by `grade` and by `demo`)."""
    from lagrade.cli.terminal import cell, display_width, shown

    # ids are never cut (they name the file to look at); names are, to 28 columns
    ids = max([8, *(display_width(shown(r["student"]["id"])) for r in summary.results)])
    lines = [f"{cell('student', ids)} {'name':28} {'status':8} {'score':>12}  reason"]
    others = {}
    for r in summary.results:
        score = f"{r['score']:g} / {r['max_score']:g}"
        reason = r["reason"]
        if r.get("sheet_student_id"):
            others[r["student"]["id"]] = r["sheet_student_id"]
            reason = f"sheet says student_id {r['sheet_student_id']!r}" + (
                f"; {reason}" if reason else ""
            )
        lines.append(
            f"{cell(r['student']['id'], ids)} {cell(r['student']['name'], 28)} "
            f"{cell(r['status'], 8)} {cell(score, 12, '>')}  {reason[:60]}"
        )
    if summary.stray:
        lines.append("\nnot graded (no roster student's sheet):")
        shown = list(summary.stray.items())[:SHOWN_STRAY]
        lines += [f"  {name!r}: {why}" for name, why in shown]
        if len(summary.stray) > SHOWN_STRAY:
            lines.append(f"  … and {len(summary.stray) - SHOWN_STRAY} more (see summary.md)")
    if others:
        lines.append("\nsheets naming another student_id (graded as the file's student):")
        lines += [
            f"  {sid}: the sheet says student_id = {other!r}" for sid, other in others.items()
        ]
    counts = ", ".join(f"{k} {v}" for k, v in summary.counts.items() if v)
    mismatched = f"; {len(others)} sheet(s) naming another student_id" if others else ""
    lines.append(f"\n{len(summary.results)} students: {counts}{mismatched}")
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    from lagrade.cli.progress import ProgressBar
    from lagrade.grading import ExportOptions, export_file_name, grade, readme_file_name

    kinds = tuple(dict.fromkeys(k for k in args.export if k != "csv"))
    options = ExportOptions(args.canvas_assignment_id, args.missing_as_zero)
    as_of = None
    if args.as_of is not None:
        from lagrade.grading import as_of_instant, shown

        as_of = as_of_instant(args.as_of, args.manifest)
        print(f"grading as of {shown(as_of)}: each student's last save at or before it")
    with ProgressBar() as bar:
        summary = grade(
            args.manifest,
            args.submissions,
            args.out,
            jobs=args.jobs,
            part_time_limit=args.part_time_limit,
            progress=bar,
            exports=kinds,
            export_options=options,
            as_of=as_of,
            dask=args.dask,
        )
    print(summary_table(summary) + f" ({summary.reused} unchanged, reused)")
    print(f"gradebook: {summary.out_dir / 'gradebook.csv'}")
    for book in summary.exports:
        readme = summary.out_dir / readme_file_name(book.kind)
        print(f"{book.kind + ':':10} {summary.out_dir / export_file_name(book.kind)}")
        print(f"{'':10} how to import it: {readme}")
        if book.warnings:
            print(f"{'':10} {len(book.warnings)} thing(s) to check first, listed there")
    print(f"summary:   {summary.out_dir / 'summary.md'}")
    return 0 if summary.all_graded else 1


def add_parser(commands: argparse._SubParsersAction) -> None:
    """Register this command with the `lagrade` parser."""
    grade = commands.add_parser(
        "grade",
        help="grade a folder of answer sheets: gradebook, feedback, results.json, summary",
        description="Grade every roster student's answer sheet (SUBMISSIONS/<id>.toml or .json) "
        "against the manifest. Every student gets a row; a rerun reuses unchanged results. "
        "Exit 0 when every student was graded, 1 when some are missing, invalid, timed out or "
        "failed (their rows say why).",
        epilog="example: lagrade grade ps3/manifest.json submissions/ --out grades --jobs 2",
    )
    grade.add_argument("manifest", type=Path, metavar="DIR/manifest.json")
    grade.add_argument("submissions", type=Path, metavar="SUBMISSIONS")
    grade.add_argument("--out", type=Path, default=None, help="output folder (default DIR/grades)")
    grade.add_argument("--jobs", type=count, default=1, help="submissions graded in parallel")
    grade.add_argument(
        "--dask",
        metavar="SCHEDULER",
        default=None,
        help="grade on a Dask cluster: 'local' starts one here (--jobs workers), tcp://host:port "
        "joins a running one; needs pip install 'lagrade[dask]'",
    )
    grade.add_argument(
        "--part-time-limit",
        type=seconds,
        default=2.0,
        help="seconds allowed per answer part (default 2)",
    )
    grade.add_argument(
        "--export",
        action="append",
        default=[],
        choices=("canvas", "moodle", "csv"),
        help="also write the gradebook as Canvas or Moodle import it (gradebook-canvas.csv, "
        "gradebook-moodle.csv, each with a README.txt saying how to import it); repeat for "
        "both; csv is gradebook.csv, always written",
    )
    grade.add_argument(
        "--canvas-assignment-id",
        default=None,
        metavar="ID",
        help="the Canvas assignment to fill (the number in its address, …/assignments/ID); "
        "default: canvas_assignment_id in the assignment file's [lms] table",
    )
    grade.add_argument(
        "--missing-as-zero",
        action="store_true",
        help="give 0 in the Canvas and Moodle gradebooks to students who handed in nothing "
        "readable (default: no grade, so an import does not overwrite a grade with 0)",
    )
    grade.add_argument(
        "--as-of",
        metavar="TIME",
        default=None,
        help="grade each student's last save at or before TIME (2025-03-14T23:59:00, with an "
        "offset or in the assignment's [answer_page] timezone; a date alone is the end of that "
        "day; `due` is the assignment's due date), from the answer page's log of saves in "
        "SUBMISSIONS",
    )
    grade.set_defaults(run=run)
