"""A list that is built only as far as someone reads it: the mistake catalogue's mutants, which are
costly to derive (sympy, then a fingerprint at the sample points) and needed only for wrong
answers, and then usually only up to the first mutant that matches.

Items come from a source in order and pass a filter that may depend on the items kept before
them (the catalogue drops a mutant that duplicates an earlier one), so the kept items and their
order are exactly those of building the whole list at once. Readers take them in chunks of
growing size: a chunk, once made, is the same tuple object for every later reader, so that
values computed per chunk (the catalogue's stacks) can be cached by it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import Generic, TypeVar

_T = TypeVar("_T")

#: Size of the first chunk; each next chunk is twice the size of the one before.
FIRST_CHUNK = 4


class LazyList(Generic[_T]):
    """The items of `make()` that pass `keep`, built on demand. `make` returns a fresh source
    and a fresh filter each time it is called: an interrupted build (a time limit striking in
    the middle of an item) starts again from scratch rather than from a half-kept item."""

    def __init__(self, make: Callable[[], tuple[Iterable[_T], Callable[[_T], bool]]]) -> None:
        self._make = make
        self._start()

    def _start(self) -> None:
        source, keep = self._make()
        self._source: Iterator[_T] | None = iter(source)
        self._keep = keep
        self._items: list[_T] = []
        self._chunks: list[tuple[_T, ...]] = []
        self._taken = 0  # items already handed out in chunks

    @property
    def complete(self) -> bool:
        """Every item has been built."""
        return self._source is None

    def _pull(self, n: int) -> None:
        """Build until n more items are kept or the source ends."""
        goal = len(self._items) + n
        try:
            while self._source is not None and len(self._items) < goal:
                item = next(self._source, _END)
                if item is _END:
                    self._source = None
                elif self._keep(item):
                    self._items.append(item)
        except BaseException:
            self._start()  # the source and the filter's state are lost with the item in hand
            raise

    def built(self, k: int) -> tuple[_T, ...] | None:
        """Chunk k if it has been made already (no building), else None."""
        return self._chunks[k] if k < len(self._chunks) else None

    def chunk(self, k: int) -> tuple[_T, ...] | None:
        """Chunk k (of 4, 8, 16, … items), building the chunks before it and it as needed; None
        past the last item."""
        while k >= len(self._chunks):
            size = FIRST_CHUNK << len(self._chunks)
            if len(self._items) - self._taken < size:
                self._pull(size - (len(self._items) - self._taken))
            chunk = tuple(self._items[self._taken : self._taken + size])
            if not chunk:
                return None
            self._chunks.append(chunk)
            self._taken += len(chunk)
        return self._chunks[k]

    def chunks(self) -> Iterator[tuple[_T, ...]]:
        """The kept items in order, a chunk at a time (4, 8, 16, … items), building each chunk
        only when the reader asks for it."""
        k = 0
        while (chunk := self.chunk(k)) is not None:
            yield chunk
            k += 1

    def __iter__(self) -> Iterator[_T]:
        """The kept items in order, building one more only when the reader asks for it."""
        k = 0
        while True:
            if k == len(self._items):
                self._pull(1)
                if k == len(self._items):
                    return
            yield self._items[k]
            k += 1

    def all(self) -> list[_T]:
        """Every kept item (builds the rest)."""
        self._pull(float("inf"))  # type: ignore[arg-type]
        return list(self._items)


_END = object()
