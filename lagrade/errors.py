"""The one error tree of lagrade: every error a user can act on, and nothing else.

    LagradeError                    anything a user can fix; str() says what to do next
    ├── DomainError                 a parameter domain that cannot be read ('(0, pi/2)' is fine)
    ├── SceneError                  an inconsistent scene declaration (lists every problem)
    │   └── SceneFileError          a scene file that cannot be used (every problem, by key)
    ├── UnknownSceneError           a scene id the bank does not have (lists the ids)
    ├── DerivationLimit             a scene whose derivation ran out of time or memory (names it)
    ├── AssignmentError             an assignment file, roster, manifest or folder unusable as given
    ├── UnreadableInput             bytes that are not the text they claim to be (not UTF-8, a lone
    │                               surrogate, nesting or a number past the bounds, not JSON/TOML)
    ├── OutputError                 an output folder that cannot be written (disk full, read-only)
    │   └── OutputBusy              an output folder another run is writing to now (locked)
    ├── ClusterError                a Dask cluster that cannot be used (not installed, unreachable,
    │                               workers running another lagrade)
    └── GraderError                 reading and judging answers
        ├── ParseError              student text that does not parse (message, span, source, hint)
        ├── RequestError            a grading request or problem definition that is malformed
        ├── UnsupportedExpression   something the numeric evaluator cannot compute (names it)
        └── ReferenceUndefined      a reference with no finite value anywhere on its domains

A broken invariant in our own code is an assertion, never one of these. Every class pickles, so
an error crosses from a worker process to the parent with its type.
"""

from __future__ import annotations

import unicodedata


class LagradeError(Exception):
    """Base of every error a user of lagrade can act on."""


class DomainError(LagradeError, ValueError):
    """A parameter domain that cannot be read."""


class SceneError(LagradeError):
    """A scene whose declaration is inconsistent; `problems` lists each one, naming its field."""

    def __init__(self, scene_id: str, problems: list[str]):
        self.scene_id = scene_id
        self.problems = list(problems)
        lines = "\n".join(f"  - {p}" for p in self.problems)
        super().__init__(f"scene {scene_id!r} is not valid:\n{lines}")

    def __reduce__(self):
        return (SceneError, (self.scene_id, self.problems))


class DerivationLimit(LagradeError):
    """A scene whose derivation ran out of time or memory: one sentence naming the scene and
    what ran out (`lagrade.judge.deriving.deriving`)."""


class SceneFileError(SceneError):
    """A scene file that cannot be used: `problems` lists each one as `key: message` (an
    expression's with the parser's caret), all found in one reading."""

    def __init__(self, origin: str, problems: list[str]):
        self.origin = origin
        self.scene_id = origin
        self.problems = list(problems)
        lines = "\n".join(f"  - {p}" for p in self.problems)
        LagradeError.__init__(self, f"{origin} is not a valid scene file:\n{lines}")

    def __reduce__(self):
        return (SceneFileError, (self.origin, self.problems))


class UnknownSceneError(LagradeError, KeyError):
    """A scene id that the bank does not have."""

    def __init__(self, scene_id: str, known: list[str]):
        self.scene_id = scene_id
        self.known = list(known)
        super().__init__(scene_id)

    def __str__(self) -> str:
        import difflib  # only when the message is shown: keeps start-up short

        close = difflib.get_close_matches(str(self.scene_id), self.known, n=1)
        guess = f"did you mean {close[0]!r}? " if close else ""
        return f"unknown scene {self.scene_id!r}; {guess}the bank has: {', '.join(self.known)}"

    def __reduce__(self):
        return (UnknownSceneError, (self.scene_id, self.known))


class AssignmentError(LagradeError):
    """An assignment file, roster or output location that cannot be used as given."""


class UnreadableInput(LagradeError, ValueError):
    """Bytes that are not the text or structure they claim to be; see `lagrade.untrusted`."""


class OutputError(LagradeError):
    """Results that cannot be written where asked: a full disk, a read-only folder, a folder
    another run holds. Distinct from bad input, so a script can tell the two apart."""


class OutputBusy(OutputError):
    """The output folder is locked by another run that is writing there now."""


class ClusterError(LagradeError):
    """A Dask cluster that cannot be used as asked (`--dask`): the optional extra is not
    installed, the scheduler cannot be reached or has no workers, a worker runs another version
    of lagrade, or the scheduler was lost mid-run. The message says what to do."""


class GraderError(LagradeError):
    """Base of the errors of reading and judging answers."""


class RequestError(GraderError):
    """A grading request (problem definition, part name, answer shape) that cannot be used."""


class UnsupportedExpression(GraderError):
    """An expression that contains something the numeric evaluator does not know (an undefined
    function, an unknown symbol, a complex constant); the message names it."""


class ReferenceUndefined(GraderError):
    """The reference has no finite value at any point that could be drawn from the domains."""


class ParseError(GraderError):
    """Student text that cannot be read: a plain message, the span (start, end) of the offending
    characters in `source`, and optionally a hint; str() adds the source line and a caret.

    Built only by `lagrade.notation.lexer.Source.fail`, so every parse failure carries a position.
    """

    def __init__(
        self,
        message: str,
        span: tuple[int, int] = (0, 0),
        source: str = "",
        hint: str | None = None,
        readings: tuple[tuple[str, str], ...] = (),
    ):
        super().__init__(message)
        self.message = message
        self.span = (int(span[0]), int(span[1]))
        self.source = source
        self.hint = hint
        #: For an ambiguity, each reading as (the ambiguous part, the whole text so read):
        #: `sin omega t` gives sin(omega*t) and sin(omega)*t; so that a grader can judge them.
        self.readings = tuple((str(a), str(b)) for a, b in readings)

    @property
    def position(self) -> int:
        """0-based index of the first offending character."""
        return self.span[0]

    def __reduce__(self):
        return (ParseError, (self.message, self.span, self.source, self.hint, self.readings))

    def __str__(self) -> str:
        lines = [self.message]
        if self.source:
            line, column, width = _caret_window(self.source, *self.span)
            lines += ["  " + line, "  " + " " * column + "^" * width]
        if self.hint:
            lines.append(f"Hint: {self.hint}")
        return "\n".join(lines)


def _caret_window(source: str, start: int, end: int, room: int = 72) -> tuple[str, int, int]:
    """The source line holding `start`, cut to about `room` characters around the span, with
    unprintable characters shown as '?', and the caret's column and width on it."""
    start = max(0, min(start, len(source)))
    end = max(start, min(end, len(source)))
    line_start = source.rfind("\n", 0, start) + 1
    line_end = source.find("\n", start)
    line_end = len(source) if line_end < 0 else line_end
    end = min(end, line_end)
    lo = max(line_start, start - room // 2)
    hi = min(line_end, lo + room)
    prefix = "…" if lo > line_start else ""
    suffix = "…" if hi < line_end else ""
    shown, column, width = [], len(prefix), 0
    for i in range(lo, hi):
        c = source[i]
        if unicodedata.combining(c):
            shown.append(c)  # draws on the previous character: takes no column
            continue
        if c == "\t":
            c = " "
        elif unicodedata.category(c)[0] in "CZ" and c != " ":
            c = "?"  # invisible, bidirectional or control: never echo it raw to a terminal
        shown.append(c)
        if i < start:
            column += 1
        elif i < end:
            width += 1
    return prefix + "".join(shown) + suffix, column, max(1, width)
