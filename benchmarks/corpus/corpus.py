"""The labelled corpus of expression pairs: its record type, and reading it back through the
project's parser (`lagrade.notation`), never through sympify, exactly as a student's answer is read.

Each line of pairs.jsonl is one pair: `answer` and `reference` in the plain notation students
type, the question's `coordinates` and `parameters` (name → domain) as a Vocabulary takes them,
the sampling `domains` of every variable (parameters, q, q̇, q̈, t), the `label` (true: the answer
equals the reference on the declared domains), a `category`, a `kind` and a `note`.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from dataclasses import asdict, dataclass, field
from pathlib import Path

import sympy as sp

from lagrade.mechanics.domains import REAL, Domain
from lagrade.notation.parse import Vocabulary, parse_expression

PAIRS = Path(__file__).with_name("pairs.jsonl")
#: Cases from public sources nobody here wrote (sympy's tests, textbooks), each with its source;
#: labels by principal branches in complex arithmetic where the reference is finite
#: (tests/stability/test_external_corpus.py checks them with sympy's own evaluation).
EXTERNAL = Path(__file__).with_name("external.jsonl")

#: Categories of the hand-written hard cases (the bank's pairs are `bank_rewrite`/`bank_mutation`).
HARD_CATEGORIES = (
    "trig_identity",
    "near_miss",
    "cancellation",
    "scale",
    "domain",
    "time",
    "undefined",
)


@dataclass(frozen=True)
class Pair:
    """One labelled pair, as stored."""

    id: str
    category: str
    kind: str
    label: bool
    answer: str
    reference: str
    coordinates: tuple[str, ...] = ()
    parameters: Mapping[str, str] = field(default_factory=dict)
    domains: Mapping[str, str] = field(default_factory=dict)
    note: str = ""
    source: str = ""  # where a case nobody here wrote comes from (external.jsonl)
    #: How the question spells the imaginary unit, where it declares one ("I"): then both
    #: sides are read with it as a number, as `check` reads an expression question that does.
    imaginary_unit: str | None = None

    def to_json(self) -> str:
        record = asdict(self)
        record["coordinates"] = list(self.coordinates)
        record["parameters"] = dict(self.parameters)
        record["domains"] = dict(self.domains)
        if not record["source"]:  # only the external cases carry one
            del record["source"]
        if record["imaginary_unit"] is None:
            del record["imaginary_unit"]
        return json.dumps(record, ensure_ascii=False, sort_keys=False)

    @classmethod
    def from_json(cls, line: str) -> Pair:
        record = json.loads(line)
        record["coordinates"] = tuple(record.get("coordinates", ()))
        return cls(**record)

    @property
    def vocabulary(self) -> Vocabulary:
        return Vocabulary.from_names(
            self.coordinates, dict(self.parameters), imaginary_unit=self.imaginary_unit
        )

    @property
    def problem(self) -> dict:
        """The question as a `check` request's problem field."""
        spec = {"expression": self.reference, "parameters": dict(self.parameters)}
        return spec | ({"imaginary_unit": self.imaginary_unit} if self.imaginary_unit else {})


@dataclass(frozen=True)
class ParsedPair:
    """A pair read back: the parsed expressions and each free symbol's sampling domain."""

    pair: Pair
    answer: sp.Expr
    reference: sp.Expr
    domains: Mapping[sp.Symbol, Domain]

    @property
    def id(self) -> str:
        return self.pair.id

    @property
    def label(self) -> bool:
        return self.pair.label


def read_pairs(path: Path = PAIRS) -> list[Pair]:
    """Every pair of the corpus file, in file order."""
    with open(path, encoding="utf-8") as f:
        return [Pair.from_json(line) for line in f if line.strip()]


def parse_pair(pair: Pair) -> ParsedPair:
    """Read both sides with the project's parser; domains keyed by the parsed symbols."""
    vocabulary = pair.vocabulary
    answer = parse_expression(pair.answer, vocabulary).expr
    reference = parse_expression(pair.reference, vocabulary).expr
    domains: dict[sp.Symbol, Domain] = {}
    # In name order: a method that draws points in the mapping's order then draws the same points
    # in every process (a set of symbols iterates in an order that changes with PYTHONHASHSEED).
    for s in sorted(answer.free_symbols | reference.free_symbols, key=lambda s: s.name):
        text = pair.domains.get(s.name) or pair.parameters.get(s.name)
        domains[s] = Domain.parse(text) if text else REAL
    return ParsedPair(pair, answer, reference, domains)


def load(path: Path = PAIRS, ids: Iterable[str] | None = None) -> list[ParsedPair]:
    """The corpus parsed; only the pairs named in `ids` (in corpus order) when given."""
    pairs = read_pairs(path)
    if ids is not None:
        wanted = set(ids)
        missing = wanted - {p.id for p in pairs}
        if missing:
            raise KeyError(f"not in the corpus: {sorted(missing)}")
        pairs = [p for p in pairs if p.id in wanted]
    return [parse_pair(p) for p in pairs]
