"""The textbook corpus of the next lecture's parts (`phase_corpus.py`: after Taylor chs. 7, 11, 13;
Goldstein §§6.4, 8.2; Kibble & Berkshire chs. 11, 12), each label recomputed in plain sympy, then
every case through `lagrade check --batch` in one run: the verdict is the label, and a named
mistake is named."""

from __future__ import annotations

import json

import pytest

from lagrade.cli.main import main

from .phase_corpus import CASES, request, verify


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c.system.name}-{c.part}-{c.label}")
def test_the_label_holds_in_plain_sympy(case):
    assert verify(case) == case.label, case


def test_every_case_through_check_batch(tmp_path):
    requests = tmp_path / "requests.jsonl"
    requests.write_text("\n".join(json.dumps(request(c, n)) for n, c in enumerate(CASES)) + "\n")
    out = tmp_path / "results.jsonl"
    main(["check", "--batch", str(requests), "--out", str(out)])
    results = [json.loads(line) for line in out.read_text().splitlines()]
    assert [r["id"] for r in results] == list(range(len(CASES)))
    wrong = []
    for case, result in zip(CASES, results, strict=True):
        verdict = "correct" if result["verdict"] == "correct" else "incorrect"
        named = case.mistake is None or case.mistake in result["mistakes"]
        if verdict != case.label or result["verdict"] == "error" or not named:
            wrong.append((case.system.source, case.answer, case.label, result))
    assert not wrong, wrong
