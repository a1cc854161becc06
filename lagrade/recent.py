"""A memo of bounded size, the least recently used entry dropped first: what the derivation,
reading and verdict caches of a long-lived process (a worker, the answer page, a Dask worker)
keep, so that a class's worth of questions and answers fits and a stream of new ones never
grows memory without end. Under every layer: it imports nothing of lagrade's."""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any


class Recent(OrderedDict):
    """At most `size` entries, most recently used last. A dict to read (`in`, `len`, `clear`,
    iteration); `recalled`, `made` and `keep` are how an entry is found, made or kept."""

    def __init__(self, size: int) -> None:
        super().__init__()
        self.size = size

    def recalled(self, key: Hashable) -> Any:
        """The value kept for `key` (now the most recently used), or None."""
        if key not in self:
            return None
        self.move_to_end(key)
        return self[key]

    def made(self, key: Hashable, make: Callable[[], Any]) -> Any:
        """The value kept for `key`, or `make()` kept for it now (dropping the least recently
        used entry past `size`)."""
        if key in self:
            return self.recalled(key)
        value = make()
        self.keep(key, value)
        return value

    def keep(self, key: Hashable, value: Any) -> tuple[Hashable, Any] | None:
        """Keep `value` for `key`, now the most recently used; the (key, value) this dropped
        past `size` (the least recently used), or None."""
        self[key] = value
        self.move_to_end(key)
        return self.popitem(last=False) if len(self) > self.size else None
