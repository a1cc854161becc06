"""The next lecture's parts through `lagrade check --batch`: the textbook corpus of
tests/grading/phase_corpus.py (43 answers on 10 systems), judge time per answer and the
question's preparation (H, the equilibria by sympy's solver, the draws) per part.

    python benchmarks/bench_phase_parts.py
"""

from __future__ import annotations

import collections
import json
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from lagrade.cli.main import main  # noqa: E402
from tests.grading.phase_corpus import CASES, request  # noqa: E402


def run() -> None:
    folder = Path(tempfile.mkdtemp())
    lines = [json.dumps(request(case, n)) for n, case in enumerate(CASES)]
    (folder / "requests.jsonl").write_text("\n".join(lines) + "\n")
    main(["check", "--batch", str(folder / "requests.jsonl"), "--out", str(folder / "out.jsonl")])
    parts: dict[str, list[float]] = collections.defaultdict(lambda: [0, 0.0, 0.0])
    for line in (folder / "out.jsonl").read_text().splitlines():
        result = json.loads(line)
        row = parts[result["part"]]
        row[0] += 1
        row[1] += result["ms"]
        row[2] += result["prepare_ms"]
    for part, (n, ms, prepare) in parts.items():
        print(f"{part:20} {n:3} answers  judge {ms / n:7.1f} ms/answer  prepare {prepare:7.0f} ms")


if __name__ == "__main__":
    run()
