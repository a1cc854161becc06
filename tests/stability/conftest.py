"""Shared fixtures of the stability tests: the labelled corpus, parsed once per session."""

from __future__ import annotations

import pytest

from benchmarks.corpus.corpus import ParsedPair, load


@pytest.fixture(scope="session")
def corpus() -> dict[str, ParsedPair]:
    """Every corpus pair by id."""
    return {p.id: p for p in load()}
