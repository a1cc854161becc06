"""The external corpus (benchmarks/corpus/external.jsonl): issue 12's classes — instructors'
vocabulary, principal branches, SI scale — in cases from public sources nobody here wrote, each
with its source. Every label is checked independently (sympy's own complex evaluation at 50
digits, `verify_external`), and lagrade must reach it: zero false accepts, zero false rejects."""

from __future__ import annotations

import pytest

from benchmarks.corpus.corpus import EXTERNAL, load, read_pairs
from benchmarks.corpus.verify_external import label_holds
from lagrade.judge.check import check

PAIRS = load(EXTERNAL)


def test_every_case_names_its_source_and_both_labels_occur():
    raw = read_pairs(EXTERNAL)
    assert len(raw) >= 30
    assert all(p.source for p in raw)
    assert {p.label for p in raw} == {True, False}
    assert len({p.id for p in raw}) == len(raw)


@pytest.mark.parametrize("pp", PAIRS, ids=[p.id for p in PAIRS])
def test_label_verifies_independently(pp):
    assert label_holds(pp)


@pytest.mark.parametrize("pp", PAIRS, ids=[p.id for p in PAIRS])
def test_lagrade_reaches_the_label(pp):
    pair = pp.pair
    verdict = check(pair.problem, "expression", pair.answer, time_limit=None)
    assert verdict.status == ("correct" if pair.label else "incorrect"), verdict.feedback
