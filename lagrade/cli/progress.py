"""Progress of long runs, on stderr, without dependencies.

On a terminal it is a bar redrawn in place; anywhere else (a pipe, a log file, a scheduler) it
is a plain line now and then — every tenth of the run or every few seconds, whichever comes
first — with no carriage returns, so a run piped to a log is never silent for long and the log
stays readable. It is a callable `(done, total, label)`, the shape of `assign.generate`'s
`progress` argument.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

from lagrade.cli.terminal import raw_stream
from lagrade.untrusted import visible


class ProgressBar:
    """`bar(done, total, label)` redraws one line (terminal) or writes one now and then (log);
    `close()` ends a drawn bar with a newline. `enabled` forces the terminal bar on or off;
    `quiet=True` silences the log lines too."""

    def __init__(
        self,
        stream: TextIO | None = None,
        enabled: bool | None = None,
        width: int = 30,
        min_interval: float = 0.1,
        log_interval: float = 5.0,
        quiet: bool = False,
    ):
        self.stream = stream if stream is not None else sys.stderr
        isatty = getattr(self.stream, "isatty", lambda: False)
        self.enabled = isatty() if enabled is None else enabled
        self.logging = not self.enabled and not quiet
        self.width = width
        self.min_interval = min_interval
        self.log_interval = log_interval
        self._last = 0.0
        self._logged = time.monotonic()
        self._drawn = False

    def __call__(self, done: int, total: int, label: str = "") -> None:
        if self.logging:
            self._log(done, total, label)
            return
        if not self.enabled:
            return
        now = time.monotonic()
        if done < total and now - self._last < self.min_interval:
            return
        self._last = now
        fraction = done / total if total else 1.0
        filled = int(round(self.width * fraction))
        bar = "#" * filled + "-" * (self.width - filled)
        line = visible(f"[{bar}] {done}/{total} {label[:40]:<40}")
        raw_stream(self.stream).write("\r" + line)  # the bar's own return, written raw
        self.stream.flush()
        self._drawn = True

    def _log(self, done: int, total: int, label: str) -> None:
        """A plain line at the first and last step, every tenth of the run and whenever
        `log_interval` seconds have passed since the last line."""
        now = time.monotonic()
        step = max(1, total // 10)
        due = done in (1, total) or done % step == 0 or now - self._logged >= self.log_interval
        if not due:
            return
        self._logged = now
        self.stream.write(f"progress: {done}/{total} {label[:60]}".rstrip() + "\n")
        self.stream.flush()

    def __enter__(self) -> ProgressBar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        if self.enabled and self._drawn:
            self.stream.write("\n")
            self.stream.flush()
            self._drawn = False
