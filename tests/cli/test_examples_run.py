"""Every example command we print — in each `--help` epilog and in the README's command table
and round trip — is accepted by the tool itself: exit status 0 or 1, never 2 (usage or bad
input). An example the tool refuses teaches the wrong thing on the first try."""

from __future__ import annotations

import re
import shlex
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from lagrade.cli.main import EXIT_BAD_INPUT, build_parser, main

ROOT = Path(__file__).resolve().parents[2]

#: The README table's placeholders, as an instructor would fill them in.
PLACEHOLDERS = {
    "SCENE": "wedge",
    '"TEXT"': '"1/2 m R^2 theta_dot^2"',
    '"…"': '"x_M_ddot = 0"',
    "ASSIGNMENT.toml": "examples/assignment.toml",
    "roster.csv": "examples/roster.csv",
    "S": "2025",
    "DIR/manifest.json": "ps3/manifest.json",
    "DIR": "ps3",
    "SUBMISSIONS": "submissions/",
    "REQUESTS.jsonl": "requests.jsonl",
    "RESULTS.jsonl": "results.jsonl",
    "QUESTIONS": "pl-questions",
    "SHEETS": "sheets",
    "NAME": "my_scene",
    "FILE": "examples/scenes/parabola.toml",
}
#: Runs until stopped: started as a process, stopped with SIGTERM once it listens.
SERVER = {"serve"}
#: Runs a whole synthetic class (minutes); `lagrade demo` has its own end-to-end test.
SLOW = {"demo"}
#: Generating PDF needs TeX Live, which a test machine may lack (exit 3, environment).
NEEDS_TEX = "pdf"


def _epilog_examples() -> list[str]:
    parser = build_parser()
    texts = [parser.epilog or ""]
    for action in parser._subparsers._group_actions:  # the registered commands
        texts += [sub.epilog or "" for sub in action.choices.values()]
        for sub in action.choices.values():  # `bank list`, `bank show`
            for inner in getattr(sub, "_subparsers", None) and sub._subparsers._group_actions or []:
                texts += [s.epilog or "" for s in inner.choices.values()]
    found = []
    for text in texts:
        for line in text.splitlines():
            line = line.strip().removeprefix("example:").removeprefix("examples:").strip()
            if line.startswith("lagrade "):
                found.append(line)
    return found


def _readme_examples() -> list[str]:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    found = []
    for template in re.findall(r"^\| `(lagrade [^`]*)` \|", readme, flags=re.M):
        command = re.sub(r"\s*\[[^\]]*\]", "", template.replace("\\|", "|"))
        words = [PLACEHOLDERS.get(w, w) for w in shlex.split(command, posix=False)]
        found.append(" ".join(words))
    for block in re.findall(r"```sh\n(.*?)```", readme, flags=re.S):  # quick start, round trip
        found += [ln for ln in block.splitlines() if ln.startswith("lagrade ")]
    return found


EXAMPLES = sorted(set(_epilog_examples()) | set(_readme_examples()))


def test_every_source_of_examples_is_read():
    assert any(e.startswith("lagrade check --scene hoop") for e in EXAMPLES)  # check --help
    assert any(e.startswith("lagrade grade ps3/manifest.json") for e in EXAMPLES)  # README
    assert any(e.startswith("lagrade parse ") for e in EXAMPLES)  # the main --help


@pytest.fixture(scope="module")
def workdir(tmp_path_factory) -> Path:
    """A folder holding what the examples name: examples/, a request file, an (empty)
    submissions folder, and ps3/ once the generate example has run."""
    root = tmp_path_factory.mktemp("examples")
    shutil.copytree(ROOT / "examples", root / "examples")
    (root / "submissions").mkdir()
    (root / "requests.jsonl").write_text(
        '{"id": 1, "problem": {"scene": "wedge"}, "part": "cyclic", "answer": ["x_M"]}\n'
    )
    return root


def _ordered() -> list[str]:
    """`generate` before `grade` and `export` (they need its manifest)."""
    after = (" grade ", " export ", " serve ")
    return sorted(EXAMPLES, key=lambda e: (any(a in f"{e} " for a in after), e))


@pytest.mark.parametrize("example", _ordered())
def test_example_is_accepted(example, workdir, monkeypatch, capfd):
    argv = shlex.split(example)[1:]
    if argv[0] in SLOW:
        pytest.skip(f"`lagrade {argv[0]}` runs for minutes")
    if argv[0] == "generate":
        formats = [a for a in argv if NEEDS_TEX in a.split(",")]
        if formats and shutil.which("pdflatex") is None and shutil.which("lualatex") is None:
            argv = [a if a not in formats else "md,html" for a in argv]
        out = workdir / argv[argv.index("--out") + 1]
        shutil.rmtree(out, ignore_errors=True)
    monkeypatch.chdir(workdir)
    if argv[0] in ("grade", "export", "serve") and not (workdir / "ps3" / "manifest.json").exists():
        assert main(shlex.split(_generate_example())[1:] + ["--formats", "md"]) == 0
    if argv[0] in SERVER:
        _serve_until_listening(argv, workdir)
        return
    try:
        status = main(argv)
    except SystemExit as stop:  # argparse refusing the command line
        status = stop.code
    out, err = capfd.readouterr()
    assert status in (0, 1), f"{example!r} exited {status}: {err}"
    assert status != EXIT_BAD_INPUT and "Traceback" not in err, err
    if argv[0] == "check" and "--answer" in argv:  # an example answer the parser refuses
        assert ": invalid" not in out, out


def _serve_until_listening(argv: list[str], workdir: Path) -> None:
    """Start the server as an instructor would (a free port instead of the example's), wait
    until it says where it listens, stop it with SIGTERM: a clean stop, no traceback."""
    if "--port" in argv:
        argv[argv.index("--port") + 1] = "0"
    else:
        argv += ["--port", "0"]
    process = subprocess.Popen(
        [sys.executable, "-c", "from lagrade.cli.main import entry; entry()", *argv],
        cwd=workdir,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    try:
        lines = []
        for line in process.stdout:
            lines.append(line)
            if "listening on http://" in line:
                break
        assert any("listening on http://" in ln for ln in lines), "".join(lines)
    finally:
        process.send_signal(signal.SIGTERM)
        rest = process.communicate(timeout=30)[0]
    assert process.returncode == 0, rest  # stopping is a server's normal end
    assert "Traceback" not in rest and "interrupted" not in rest, rest


def _generate_example() -> str:
    return next(e for e in EXAMPLES if e.startswith("lagrade generate") and "pdf" not in e)
