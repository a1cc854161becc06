"""The grader's errors, under the project's single base `LagradeError` (see problem_bank.errors
for the whole tree).

    LagradeError
    └── GraderError          anything the grader reports to a user
        ├── ParseError       student text that does not parse (message, span, source, hint)
        └── RequestError     a grading request or problem definition that is malformed
"""

from __future__ import annotations

import unicodedata

from problem_bank.errors import LagradeError


class GraderError(LagradeError):
    """Base of the grader's user-facing errors."""


class RequestError(GraderError):
    """A grading request (problem definition, part name, answer shape) that cannot be used."""


class ParseError(GraderError):
    """Student text that cannot be read: a plain message, the span (start, end) of the offending
    characters in `source`, and optionally a hint; str() adds the source line and a caret.

    Built only by `grader.lexer.Source.fail`, so every parse failure carries a position.
    """

    def __init__(
        self,
        message: str,
        span: tuple[int, int] = (0, 0),
        source: str = "",
        hint: str | None = None,
    ):
        super().__init__(message)
        self.message = message
        self.span = (int(span[0]), int(span[1]))
        self.source = source
        self.hint = hint

    @property
    def position(self) -> int:
        """0-based index of the first offending character."""
        return self.span[0]

    def __reduce__(self):
        return (ParseError, (self.message, self.span, self.source, self.hint))

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
