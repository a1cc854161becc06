"""The workers `tests.prairielearn_node` drives: PrairieLearn's own `zygote.py` (spoken to as
its `code-caller-native.ts` does: JSON lines on stdin, answers on fd 3, exits confirmed on fd 4, a
restart after each request, a 10 s limit per call, anything printed reported), mustache (Node's
`mustache`, PrairieLearn's, or chevron), and `InProcess`, a stand-in that runs server.py in this
process with the documented behaviour of the elements lagrade's questions use."""

from __future__ import annotations

import json
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class CourseIssue(Exception):
    """What PrairieLearn records as a course issue (a fatal one breaks the variant)."""


#: PrairieLearn's default `questionTimeoutMilliseconds`: a call past it kills the worker.
CALL_LIMIT = 10.0
#: Its `workerPingTimeoutMilliseconds`: how long a new zygote may take to answer its first ping.
PING_LIMIT = 60.0


class Mustache:
    """PrairieLearn's mustache render of question.html: Node's `mustache` (what PrairieLearn
    runs) in one long-lived process, or chevron in PrairieLearn's Python."""

    _JS = (
        "const m=require(process.argv[1]);const rl=require('readline').createInterface("
        "{input:process.stdin});rl.on('line',l=>{const r=JSON.parse(l);"
        "process.stdout.write(JSON.stringify(m.render(r.t,r.v))+'\\n')});"
    )

    def __init__(self, pl: Path, python: str) -> None:
        found = os.environ.get("LAGRADE_MUSTACHE_JS") or next(
            (
                str(p)
                for p in (
                    pl / "node_modules/mustache",
                    pl / "apps/prairielearn/node_modules/mustache",
                )
                if p.is_dir()
            ),
            None,
        )
        self.engine = "mustache.js" if found and shutil.which("node") else "chevron"
        if self.engine == "mustache.js":
            command = ["node", "-e", self._JS, found]
        else:
            command = [python, "-c", _CHEVRON]
        self.process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, encoding="utf-8"
        )

    def render(self, template: str, view: dict) -> str:
        self.process.stdin.write(json.dumps({"t": template, "v": view}) + "\n")
        self.process.stdin.flush()
        return json.loads(self.process.stdout.readline())

    def close(self) -> None:
        self.process.stdin.close()
        self.process.wait(timeout=10)


_CHEVRON = """
import chevron, json, sys
for line in sys.stdin:
    r = json.loads(line)
    sys.stdout.write(json.dumps(chevron.render(r["t"], r["v"])) + "\\n"); sys.stdout.flush()
"""

_LAUNCH = """
import os, sys
os.dup2(int(sys.argv[1]), 3); os.dup2(int(sys.argv[2]), 4)
os.execv(sys.executable, [sys.executable, "-B", sys.argv[3]])
"""


@dataclass
class Call:
    """One call's answer, its time and what the worker printed meanwhile."""

    value: Any
    seconds: float
    output: str


@dataclass
class Zygote:
    """PrairieLearn's zygote.py, spoken to as code-caller-native.ts does."""

    pl: Path
    python: str
    course: Path
    calls: list[tuple[str, str, float]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self._start()

    def _start(self) -> None:
        out_r, out_w = os.pipe()
        exit_r, exit_w = os.pipe()
        zygote = self.pl / "apps/prairielearn/python/zygote.py"
        env = {**os.environ, "PYTHONIOENCODING": "utf-8"}
        self.process = subprocess.Popen(
            [self.python, "-c", _LAUNCH, str(out_w), str(exit_w), str(zygote)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            pass_fds=(out_w, exit_w),
            cwd=zygote.parent,
            env=env,
        )
        os.close(out_w)
        os.close(exit_w)
        self.answers = os.fdopen(out_r, "r", encoding="utf-8")
        self.exits = os.fdopen(exit_r, "r", encoding="utf-8")
        for stream in (self.process.stdout, self.process.stderr):
            os.set_blocking(stream.fileno(), False)
        self.fresh = True
        assert self.call(None, None, "ping", []).value == "pong"

    def _replace(self) -> str:
        """A call ran out of time or its worker died: PrairieLearn kills the zygote and starts
        another; what it printed is returned."""
        output = self._output()
        self.close()
        self._start()
        return output

    def call(self, directory: str | None, file: str | None, fcn: str, args: list) -> Call:
        paths = [str(self.pl / "apps/prairielearn/python"), str(self.course / "serverFilesCourse")]
        cwd = str(self.course / "questions" / directory) if directory else None
        line = {"file": file, "fcn": fcn, "args": args, "cwd": cwd, "paths": paths}
        line["forbidden_modules"] = []
        start = time.monotonic()
        self.process.stdin.write(json.dumps(line).encode() + b"\n")
        self.process.stdin.flush()
        limit = PING_LIMIT if fcn == "ping" else CALL_LIMIT
        self.fresh = False
        ready, _, _ = select.select([self.answers], [], [], limit)
        text = self.answers.readline() if ready else ""
        seconds = time.monotonic() - start
        self.calls.append((str(file), fcn, seconds))
        if not ready:
            self._replace()
            raise CourseIssue(f"{file} {fcn}(): timeout exceeded ({limit:g} s)")
        if not text:
            raise CourseIssue(f"{file} {fcn}(): the worker died\n{self._replace()[-2000:]}")
        output = self._output()
        answer = json.loads(text)
        if not answer.get("present", False):
            return Call(None, seconds, output)
        return Call(answer["val"], seconds, output)

    def restart(self) -> None:
        """The end of a request: the worker exits, the zygote forks a fresh one."""
        if self.fresh:  # a new zygote after a failed call
            return
        assert self.call(None, None, "restart", []).value == "success"
        assert json.loads(self.exits.readline()) == {"exited": True}

    def _output(self) -> str:
        chunks = []
        for stream in (self.process.stdout, self.process.stderr):
            while (chunk := stream.read()) is not None and chunk:
                chunks.append(chunk.decode("utf-8", "replace"))
        return "".join(chunks)

    def close(self) -> None:
        self.process.terminate()
        self.process.wait(timeout=10)
        for stream in (self.answers, self.exits, self.process.stdin):
            stream.close()


def core_elements(pl: Path) -> dict[str, dict[str, str]]:
    """What freeform.ts's `loadElements` finds: each core element's name and controller."""
    elements = {}
    for info in sorted((pl / "apps/prairielearn/elements").glob("*/info.json")):
        controller = json.loads(info.read_text(encoding="utf-8"))["controller"]
        name = info.parent.name
        elements[name] = {"name": name, "controller": controller, "type": "core"}
    return elements


class Chevron:
    """Mustache in this process (chevron, which PrairieLearn's elements use too)."""

    engine = "chevron"

    def render(self, template: str, view: dict) -> str:
        import chevron

        return chevron.render(template, view)

    def close(self) -> None:
        pass


_PANELS = {"question": "pl-question-panel", "submission": "pl-submission-panel"}
_PANELS["answer"] = "pl-answer-panel"
_INPUT = re.compile(r'<pl-string-input answers-name="(\w+)"[^>]*?(multiline="true")?[^>]*>')


@dataclass
class InProcess:
    """A stand-in for PrairieLearn's worker where it is not installed: server.py executed in
    this process as zygote.py executes it (a module from the file, `serverFilesCourse/` on
    sys.path), each call's output to fd 1 and 2 captured, and for question.html the documented
    behaviour of the elements lagrade uses: the panels keep their content in their own panel
    only; pl-string-input's parse strips a multi-line answer and makes a missing one a format
    error, and it renders as a tag that names its answer."""

    course: Path
    calls: list[tuple[str, str, float]] = field(default_factory=list)
    modules: dict[str, dict] = field(default_factory=dict)

    def call(self, directory: str | None, file: str | None, fcn: str, args: list) -> Call:
        start = time.monotonic()
        with _captured() as output:
            if file == "question.html":
                value = self._elements(fcn, *args)
            else:
                value = self._server(directory, fcn, args)
        seconds = time.monotonic() - start
        self.calls.append((str(file), fcn, seconds))
        return Call(json.loads(json.dumps(value, allow_nan=False)), seconds, output[0])

    def _server(self, directory: str, fcn: str, args: list) -> Any:
        path = self.course / "questions" / directory / "server.py"
        module = self.modules.get(str(path))
        if module is None:
            module = {"__file__": str(path)}
            saved = list(sys.path)
            sys.path.insert(0, str(self.course / "serverFilesCourse"))
            try:
                exec(compile(path.read_text(encoding="utf-8"), str(path), "exec"), module)
            finally:
                sys.path[:] = saved
            self.modules[str(path)] = module
        method = module.get(fcn)
        if method is None:
            return None
        value = method(*args)
        return value if fcn == "render" else args[-1]

    def _elements(self, phase: str, context: dict, data: dict) -> dict:
        html = context["html"]
        if phase == "render":
            for panel, tag in _PANELS.items():
                keep = r"\1" if data["panel"] == panel else ""
                html = re.sub(rf"<{tag}>(.*?)</{tag}>", keep, html, flags=re.S)
        for match in _INPUT.finditer(context["html"]):
            name, multiline = match.group(1), bool(match.group(2))
            if phase == "parse":
                value = data["submitted_answers"].get(name)
                if value is None:
                    data["format_errors"][name] = "No submitted answer."
                    continue
                value = value.strip() if multiline else value
                data["submitted_answers"][name] = value.replace("\r\n", "\n")
        return {"html": html if phase == "render" else None, "data": data}

    def restart(self) -> None:
        pass

    def close(self) -> None:
        pass


@contextmanager
def _captured():
    """What the call writes to fd 1 and 2 (PrairieLearn makes a course issue of any)."""
    found = [""]
    with tempfile.TemporaryFile() as sink:
        sys.stdout.flush()
        sys.stderr.flush()
        saved = os.dup(1), os.dup(2)
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            yield found
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
            sink.seek(0)
            found[0] = sink.read().decode("utf-8", "replace")
