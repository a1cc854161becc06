"""Write benchmarks/corpus/systems.jsonl from the systems written out in systems_data/: every
case's label is recomputed first by verify_systems.py (sympy and mpmath, never lagrade's judge),
and only the cases whose recomputed label agrees go in; the others are listed as dropped, with
the verifier's reason, in systems_dropped.txt (written only when some are).

Run: python benchmarks/corpus/build_systems.py [--no-proofs] [--jobs N]
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from multiprocessing import get_context
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus.systems_data import (  # noqa: E402
    extra_forms,
    fields_sources,
    landau_sources,
    lecture_sources,
    sympy_sources,
    textbook_sources,
)
from benchmarks.corpus.systems_dsl import System  # noqa: E402
from benchmarks.corpus.verify_systems import SYSTEMS as OUT  # noqa: E402
from benchmarks.corpus.verify_systems import verify_case  # noqa: E402

DROPPED = OUT.with_name("systems_dropped.txt")
MODULES = (sympy_sources, landau_sources, lecture_sources, textbook_sources, fields_sources)


def systems() -> list[System]:
    """Every system, in module order, with the extra forms added across them."""
    made = [make() for module in MODULES for make in module.SYSTEMS]
    extra_forms.augment({s.key: s for s in made})
    return made


def records() -> list[dict]:
    out = [case.record() for s in systems() for case in s.all_cases()]
    ids = Counter(r["id"] for r in out)
    twice = [i for i, n in ids.items() if n > 1]
    if twice:
        raise SystemExit(f"duplicate case ids: {twice}")
    return out


def _verify(job: tuple[dict, bool]):
    record, proofs = job
    return verify_case(record, proofs=proofs)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-proofs", action="store_true")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", help="only systems whose key contains this")
    args = parser.parse_args()
    everything = records()
    if args.only:
        everything = [r for r in everything if args.only in r["id"]]
    jobs = [(r, not args.no_proofs) for r in everything]
    with get_context("fork").Pool(args.jobs) as pool:
        findings = pool.map(_verify, jobs, chunksize=4)
    kept, dropped = [], []
    for record, finding in zip(everything, findings, strict=True):
        if finding.agrees:
            record["verified"] = finding.detail + (f"; {finding.proof}" if finding.proof else "")
            kept.append(record)
        else:
            dropped.append((record, finding))
    if not args.only:
        with open(OUT, "w", encoding="utf-8") as f:
            for record in kept:
                f.write(json.dumps(record, ensure_ascii=False) + "\n")
        DROPPED.unlink(missing_ok=True)
        if dropped:
            with open(DROPPED, "w", encoding="utf-8") as f:
                for record, finding in dropped:
                    f.write(
                        f"{record['id']}: labelled {record['label']}, verifier says "
                        f"{finding.computed} ({finding.detail})\n"
                    )
    systems_kept = len({r["system"] for r in kept})
    print(f"{len(kept)} cases kept over {systems_kept} systems; {len(dropped)} dropped")
    for record, finding in dropped:
        print(f"  dropped {record['id']}: {finding.computed} ({finding.detail})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
