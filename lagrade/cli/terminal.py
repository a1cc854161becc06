"""What the `lagrade` command prints goes through one guard: while a command runs, standard
output and standard error write control characters as escapes (`untrusted.visible`), so a stray
file named with an escape sequence, a title or a student's answer can neither clear the screen
nor print a fake line. Binary output (`check --batch` results, JSON) goes to `.buffer` as it is.
The progress bar's own carriage return is the one control character written raw (`raw`)."""

from __future__ import annotations

import contextlib
import io
import sys
from collections.abc import Iterator
from typing import Any, TextIO


class VisibleText(io.TextIOBase):
    """A text stream that writes `visible(text)` to the stream it wraps."""

    def __init__(self, stream: TextIO):
        # Imported here, not at the top: the command's start-up (before its Ctrl-C handling is
        # in place) stays as short as it was.
        from lagrade.untrusted import visible

        self.raw = stream
        self._visible = visible

    def write(self, text: str) -> int:
        self.raw.write(self._visible(text))
        return len(text)

    def flush(self) -> None:
        self.raw.flush()

    def isatty(self) -> bool:
        return self.raw.isatty()

    def fileno(self) -> int:
        return self.raw.fileno()

    @property
    def encoding(self) -> str:  # type: ignore[override]
        return getattr(self.raw, "encoding", "utf-8")

    @property
    def errors(self) -> str | None:  # type: ignore[override]
        return getattr(self.raw, "errors", None)

    @property
    def buffer(self) -> Any:
        return self.raw.buffer


@contextlib.contextmanager
def guarded() -> Iterator[None]:
    """Standard output and error as VisibleText for the length of the block."""
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = VisibleText(out), VisibleText(err)
    try:
        yield
    finally:
        sys.stdout, sys.stderr = out, err


def raw_stream(stream: TextIO) -> TextIO:
    """The stream under a VisibleText (for the progress bar's carriage return), or `stream`."""
    return stream.raw if isinstance(stream, VisibleText) else stream


def display_width(text: str) -> int:
    """The columns a terminal gives `text`: an East Asian wide or fullwidth character (王, Ｂ)
    two, a combining mark or other zero-width character (the dot of a decomposed ạ, U+200B)
    none, any other one (Unicode's East Asian Width, UAX #11, as wcwidth counts)."""
    import unicodedata

    width = 0
    for ch in text:
        if unicodedata.combining(ch) or unicodedata.category(ch) in ("Mn", "Me", "Cf"):
            continue
        width += 2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1
    return width


def shown(value: object) -> str:
    """`value` as a table shows it: on one line, control characters as escapes."""
    from lagrade.untrusted import visible

    return visible(" ".join(str(value).split()))


def cell(value: object, width: int, align: str = "<") -> str:
    """`value` as one cell of a table of `width` columns: on one line, control characters shown
    as escapes, cut with "…" where it is wider, and padded to `width` by display width (so a
    row of Chinese names lines up with a row of Latin ones)."""
    text = shown(value)
    if display_width(text) > width:
        kept, used = [], 0
        for ch in text:
            w = display_width(ch)
            if used + w > width - 1:
                break
            kept.append(ch)
            used += w
        text = "".join(kept) + "…"
    pad = " " * (width - display_width(text))
    return pad + text if align == ">" else text + pad
