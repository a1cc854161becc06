"""How often the "read left to right" warning (`g/2l is read as (g/2)*l; …`) fires, on right
answers and on wrong ones, over every corpus the project has: the key's own answers (every
scene, seeds 1–3, every part, in the plain, implicit-product and undotted notations the demo
writes), benchmarks/corpus/*.jsonl and the generated corpus of tests/grading/corpus.py.

    python benchmarks/reading_warnings.py

A warning that fires on a right answer is noise (issue 30): the target is zero there. Each
line is parsed with the question's own vocabulary, exactly as a student's answer is read.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from lagrade.bank import get_scene, scene_ids  # noqa: E402
from lagrade.errors import LagradeError  # noqa: E402
from lagrade.judge.problem import build_problem  # noqa: E402
from lagrade.notation.keys import key_answer  # noqa: E402
from lagrade.notation.parse import Vocabulary, parse_answer  # noqa: E402

PARTS = ("transformation", "T", "V", "lagrangian", "eom", "momenta", "conserved")


def _implicit(text: str) -> str:
    return re.sub(r"(?<=[\w)])\*(?=[\w(])", " ", text)


def _undotted(text: str) -> str:
    return re.sub(r"_(d?dot)\b", r"\1", text)


def warned(text: str, vocabulary: Vocabulary) -> bool | None:
    """Whether reading `text` (each line) warns about a division; None when it does not parse."""
    found = False
    for line in [ln for ln in text.splitlines() if ln.strip()] or [text]:
        for candidate in (line, _LABEL.sub("", line)):  # `p_theta = …`: the label is no name
            try:
                found |= any(
                    "fraction bar" in w for w in parse_answer(candidate, vocabulary).warnings
                )
                break
            except LagradeError:
                continue
        else:
            return None
    return found


_LABEL = re.compile(r"^\s*[A-Za-z][A-Za-z0-9_]*\s*=")


def key_answers():
    """(vocabulary, text, True) for the key's answers in three notations."""
    for sid in scene_ids():
        for seed in (1, 2, 3):
            variant = get_scene(sid).variant(seed)
            vocabulary = build_problem({"scene": sid, "seed": seed}).vocabulary()
            for part in PARTS:
                if part == "conserved" and not variant.conserved_quantities:
                    continue
                answer = key_answer(variant, part)
                for text in answer if isinstance(answer, list) else [answer]:
                    for shown in {text, _implicit(text), _undotted(_implicit(text))}:
                        yield vocabulary, shown, True
            for q in variant.scene.quantities:
                vocabulary = build_problem({"scene": sid, "seed": seed, "quantity": q.name})
                text = key_answer(variant, "expression", q.name)
                for shown in {text, _implicit(text)}:
                    yield vocabulary.vocabulary(), shown, True


def pairs(name: str):
    for line in (ROOT / "benchmarks" / "corpus" / name).read_text().splitlines():
        row = json.loads(line)
        vocabulary = Vocabulary.from_names(
            row["coordinates"], row["parameters"], imaginary_unit=row.get("imaginary_unit")
        )
        yield vocabulary, row["answer"], bool(row["label"])


def judged():
    for line in (ROOT / "benchmarks" / "corpus" / "judged.jsonl").read_text().splitlines():
        row = json.loads(line)
        vocabulary = build_problem(row["problem"]).vocabulary()
        answers = row["answer"] if isinstance(row["answer"], list) else [row["answer"]]
        for text in answers:
            yield vocabulary, text, row["status"] == "correct"


def generated():
    from tests.grading.corpus import corpus

    for item in corpus():
        vocabulary = build_problem(item.problem).vocabulary()
        answers = item.answer if isinstance(item.answer, list) else [item.answer]
        for text in answers:
            yield vocabulary, text, item.label == "correct"


def main() -> None:
    sources = {
        "key answers (3 notations)": key_answers,
        "corpus/pairs.jsonl": lambda: pairs("pairs.jsonl"),
        "corpus/external.jsonl": lambda: pairs("external.jsonl"),
        "corpus/judged.jsonl": judged,
        "tests/grading/corpus.py": generated,
    }
    print(f"{'source':28} {'right':>7} {'warned':>7} {'wrong':>7} {'warned':>7} {'unread':>7}")
    for name, rows in sources.items():
        counts: Counter = Counter()
        for vocabulary, text, right in rows():
            w = warned(text, vocabulary)
            kind = "right" if right else "wrong"
            counts[kind] += 1
            counts[f"{kind} warned"] += bool(w)
            counts["unread"] += w is None
        print(
            f"{name:28} {counts['right']:7} {counts['right warned']:7} {counts['wrong']:7} "
            f"{counts['wrong warned']:7} {counts['unread']:7}"
        )


if __name__ == "__main__":
    main()
