"""How work is cut for a Dask cluster (`lagrade.grading.cluster.chunks`), without one: every item
in exactly one chunk, a group's items together and in their order, chunks of the size asked."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from lagrade.grading.cluster.chunks import MAX_CHUNK, MIN_CHUNK, chunk_size, cut


@given(
    st.lists(st.integers(0, 5), max_size=60).map(lambda gs: list(enumerate(gs))),
    st.integers(1, 10),
)
def test_cut_keeps_every_item_once_and_each_group_together_in_order(items, size):
    chunks = cut(items, lambda item: item[1], size)
    flat = [item for chunk in chunks for item in chunk]
    first_seen = {}
    for position, group in items:
        first_seen.setdefault(group, position)
    assert flat == sorted(items, key=lambda item: (first_seen[item[1]], item[0]))
    assert all(len(chunk) == size for chunk in chunks[:-1])
    assert all(0 < len(chunk) <= size for chunk in chunks)


def test_a_scattered_question_comes_together():
    lines = ["hoop", "wedge", "hoop", "kepler", "wedge", "hoop"]
    chunks = cut(list(enumerate(lines)), lambda item: item[1], 3)
    assert [[position for position, _ in chunk] for chunk in chunks] == [[0, 2, 5], [1, 4, 3]]


@given(st.integers(1, 10**6), st.integers(1, 1000))
def test_chunk_size_stays_in_bounds_and_gives_every_thread_work(items, threads):
    size = chunk_size(items, threads)
    assert MIN_CHUNK <= size <= MAX_CHUNK
    if size > MIN_CHUNK and size < MAX_CHUNK:  # neither bound binds: several chunks a thread
        assert -(-items // size) >= threads
