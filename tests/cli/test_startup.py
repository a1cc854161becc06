"""Start-up stays light: `lagrade --help` (and building the command line for any command) loads
neither sympy nor numpy, scipy or matplotlib; a command imports the layers it needs when it runs.
The part names the command line offers without the judge are the judge's own."""

import subprocess
import sys

HEAVY = ("sympy", "numpy", "scipy", "matplotlib", "mpmath", "jinja2")

_PROBE = """
import sys
from lagrade.cli.main import main
try:
    main({argv!r})
except SystemExit:
    pass
print("LOADED:" + ",".join(sorted({{m.split(".")[0] for m in sys.modules}} & set({heavy!r}))))
"""


def _loaded_by(argv: list[str]) -> list[str]:
    code = _PROBE.format(argv=argv, heavy=HEAVY)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    line = out.stdout.strip().splitlines()[-1]
    assert line.startswith("LOADED:"), out.stdout
    return [m for m in line.removeprefix("LOADED:").split(",") if m]


def test_help_loads_nothing_heavy():
    assert _loaded_by(["--help"]) == []


def test_every_command_help_loads_nothing_heavy():
    for command in ("bank", "parse", "check", "generate", "grade", "demo"):
        assert _loaded_by([command, "--help"]) == [], command


def test_parse_loads_sympy_but_not_numpy_or_the_judge():
    code = (
        "import sys\nfrom lagrade.cli.main import main\n"
        "main(['parse', 'm g l cos(theta)', '--coordinates', 'theta', '--parameters', 'm,g,l'])\n"
        "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'lagrade.judge') "
        "if m in sys.modules), 'sympy' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "[] True"


def test_the_command_lines_part_names_are_the_judges():
    from lagrade.cli.check import DEFAULT_TIME_LIMIT, IMAGINARY_UNITS, PART_NAMES
    from lagrade.judge.check import DEFAULT_TIME_LIMIT as JUDGE_TIME_LIMIT
    from lagrade.judge.parts import PARTS
    from lagrade.judge.problem import IMAGINARY_UNITS as JUDGE_IMAGINARY_UNITS

    assert PART_NAMES == tuple(PARTS)
    assert DEFAULT_TIME_LIMIT == JUDGE_TIME_LIMIT
    assert IMAGINARY_UNITS == JUDGE_IMAGINARY_UNITS


def test_check_batch_loads_the_judge_but_not_the_reports(tmp_path):
    """`check --batch` writes its results through `lagrade.grading.atomic`; that leaf must not
    bring in the reports, templates and charts of `grade` (jinja2, matplotlib, lagrade.assign)."""
    requests = tmp_path / "requests.jsonl"
    requests.write_text(
        '{"problem": {"expression": "m*g", "parameters": {"m": "positive", "g": "positive"}}, '
        '"part": "expression", "answer": "g*m"}\n'
    )
    code = (
        "import sys\nfrom lagrade.cli.main import main\n"
        f"main(['check', '--batch', {str(requests)!r}, '--out', {str(tmp_path / 'out.jsonl')!r}])\n"
    )
    probe = code.replace("main([", "try:\n    main([").replace(
        "])\n", "])\nexcept SystemExit:\n    pass\n"
    )
    probe += (
        "print(sorted(m for m in ('jinja2', 'matplotlib', 'lagrade.assign', "
        "'lagrade.grading.report') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "[]", out.stdout + out.stderr
    assert '"verdict": "correct"' in (tmp_path / "out.jsonl").read_text()


def test_check_batch_on_an_empty_file_loads_nothing_heavy(tmp_path):
    """`check --batch` loads the judging modules (sympy, numpy) only when it has a request to
    judge, and then once, before its workers fork (issue 35's start-up target: an empty batch
    at the cost of a small Python program)."""
    empty = tmp_path / "empty.jsonl"
    empty.write_text("")
    out = tmp_path / "out.jsonl"
    assert _loaded_by(["check", "--batch", str(empty), "--out", str(out)]) == []
    assert out.read_text() == ""


def test_check_batch_with_a_request_loads_the_judge_before_its_workers_fork(tmp_path):
    requests = tmp_path / "one.jsonl"
    requests.write_text('{"problem": {"scene": "hoop"}, "part": "dof", "answer": "1"}\n')
    out = tmp_path / "out.jsonl"
    assert "sympy" in _loaded_by(["check", "--batch", str(requests), "--out", str(out)])
    assert '"verdict": "correct"' in out.read_text()


def test_prairielearn_parse_and_grade_load_no_templates():
    """The worker of a PrairieLearn `parse` or `grade` reads and judges: the templates that
    render a variant (jinja2, the handout's views and figures) are `generate`'s alone: every
    parse and grade call paid for importing them."""
    code = (
        "import sys, lagrade.grading.prairielearn_runtime, lagrade.grading.prairielearn_work\n"
        "print(sorted(m for m in ('jinja2', 'lagrade.assign.views', 'lagrade.assign.templating', "
        "'lagrade.assign.generation', 'lagrade.grading.prairielearn_variant') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "[]", out.stdout + out.stderr


def test_generate_is_the_function_whichever_import_came_first():
    """`lagrade.assign.generate` is a function, loaded on first use; its module has another name,
    so importing the module first cannot shadow it."""
    code = (
        "import lagrade.assign.generation\nfrom lagrade.assign import generate\n"
        "print(callable(generate) and generate.__module__)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "lagrade.assign.generation"
