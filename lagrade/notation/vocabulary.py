"""What a question lets a student write: its `Vocabulary` (coordinates, parameters, labels) and the
`Lexicon` of every spelling that vocabulary accepts (m1 for m_1, thetadot for theta_dot)."""

from __future__ import annotations

import re
import threading
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import sympy as sp

from lagrade.errors import RequestError
from lagrade.mechanics import Domain, momentum_jet
from lagrade.mechanics import lagrange as mechanics
from lagrade.notation.build import FUNCTIONS
from lagrade.recent import Recent

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")


class Entry(NamedTuple):
    """What one spelling means: the symbol (or pi), its coordinate's jet, and its time order."""

    kind: str  # "sym" or "pi"
    value: sp.Expr
    jet: mechanics.Jet | None
    order: int  # 0 coordinate or plain symbol, 1 velocity, 2 acceleration


def _digit_variants(name: str) -> set[str]:
    """m1 ↔ m_1, theta12 ↔ theta_12: digit subscripts with or without the underscore."""
    return {name, re.sub(r"_(?=[0-9])", "", name), re.sub(r"(?<=[A-Za-z])(?=[0-9])", "_", name)}


#: Greek letters with a variant shape LaTeX and Unicode spell apart (\\vartheta, ϑ): two
#: spellings of one letter to a student, so a question that declares only one of the two reads
#: the other as it (a coordinate named vartheta is typed θ, ϑ, theta or \\vartheta alike).
GREEK_VARIANTS = ("theta", "phi", "epsilon", "rho")
_VARIANT = re.compile(rf"(var)?({'|'.join(GREEK_VARIANTS)})(?=_|[0-9]|d?dot\Z|\Z)")


def _variant_spelling(name: str) -> str | None:
    """vartheta_dot for theta_dot, theta1 for vartheta1; None for a name with no variant."""
    m = _VARIANT.match(name)
    if m is None:
        return None
    return ("" if m.group(1) else "var") + m.group(2) + name[m.end() :]


@dataclass(frozen=True)
class Vocabulary:
    """What a question lets a student write: its coordinates (each with velocity and
    acceleration), its parameters as the very sympy symbols of the reference, extra labels
    (p_theta, L, h, …), whether primes mean time derivatives, and how the imaginary unit is
    spelled when the question is about complex numbers (None: `I`, `i`, `j` are ordinary
    names, unknown unless declared, so that a real question never meets a complex number).
    `momenta`: the momentum p_<q> of every coordinate is a variable with its rate (p_theta,
    p_theta_dot, \\dot{p}_\\theta), for the parts on phase space (H, Hamilton's equations);
    elsewhere p_theta is at most a label."""

    coordinates: tuple[str, ...]
    parameters: Mapping[str, sp.Symbol]
    labels: tuple[str, ...] = ()
    allow_primes: bool = False
    imaginary_unit: str | None = None
    momenta: bool = False

    def __post_init__(self) -> None:
        object.__setattr__(self, "coordinates", tuple(self.coordinates))
        object.__setattr__(self, "parameters", dict(self.parameters))
        object.__setattr__(self, "labels", tuple(self.labels))
        problems = []
        names = list(self.coordinates) + list(self.parameters) + list(self.labels)
        for name in names:
            if not isinstance(name, str) or not _NAME.match(name):
                problems.append(
                    f"{name!r} is not a name (letters, digits and _, starting with a letter)"
                )
        for name, symbol in self.parameters.items():
            if not isinstance(symbol, sp.Symbol):
                problems.append(f"parameter {name!r} must map to a sympy Symbol, not {symbol!r}")
        named = list(self.coordinates)
        named += [momentum_jet(c).name for c in self.coordinates] if self.momenta else []
        jet_names = [f"{c}{suffix}" for c in named for suffix in ("", "_dot", "_ddot")]
        seen: set[str] = set()
        unit = [self.imaginary_unit] if self.imaginary_unit is not None else []
        for name in jet_names + list(self.parameters) + list(self.labels) + unit:
            if name in seen:
                problems.append(f"{name!r} is declared twice")
            seen.add(name)
        if problems:
            raise RequestError("vocabulary is not valid: " + "; ".join(problems))

    def __hash__(self) -> int:
        return hash(self._declared)

    @property
    def _declared(self) -> tuple:
        """Everything the vocabulary declares, in order (the order of the parameters is the
        order of the names an error lists): what its lexicon is a function of."""
        return (
            self.coordinates,
            tuple(self.parameters.items()),
            self.labels,
            self.allow_primes,
            self.imaginary_unit,
            self.momenta,
        )

    @classmethod
    def from_variant(
        cls, variant, labels: Iterable[str] = (), *, allow_primes: bool = False
    ) -> Vocabulary:
        """The vocabulary of a scene variant (`lagrade.mechanics.scene.SceneVariant`)."""
        return cls(
            tuple(variant.coordinates), dict(variant.parameter_symbols), tuple(labels), allow_primes
        )

    @classmethod
    def from_names(
        cls,
        coordinates: Iterable[str],
        parameters: Mapping[str, str | Domain] | Iterable[str],
        labels: Iterable[str] = (),
        *,
        allow_primes: bool = False,
        imaginary_unit: str | None = None,
    ) -> Vocabulary:
        """From names alone; parameter domains as strings ('positive', '(0, pi/2)'), and bare
        parameter names are positive (masses, lengths, g)."""
        if isinstance(parameters, Mapping):
            symbols = {
                name: Domain.parse(domain).symbol(name) for name, domain in parameters.items()
            }
        else:
            symbols = {name: Domain.parse("positive").symbol(name) for name in parameters}
        return cls(tuple(coordinates), symbols, tuple(labels), allow_primes, imaginary_unit)

    @cached_property
    def _lexicon(self) -> Lexicon:
        """The lexicon of what this vocabulary declares, shared with every vocabulary that
        declares the same (each question of a batch builds its own vocabulary, and a class's
        questions on one scene declare the same names). A lexicon holds no state of a request:
        the parser only reads it. It is shared only while its symbols are the very objects a
        new one would hold (sympy's cache may have let a symbol go and made an equal one since),
        so that the parser's output is what it was, object for object."""
        key = self._declared
        with _LEXICONS_LOCK:
            kept = _LEXICONS.recalled(key)
        if kept is not None and kept.holds(_symbols(self, _jets(self))):
            return kept
        made = Lexicon(self)
        with _LEXICONS_LOCK:  # this one's now (an equal one of other symbols is dropped)
            _LEXICONS.pop(key, None)
            return _LEXICONS.made(key, lambda: made)


#: Lexicons kept per process, by what their vocabulary declares (most recently used last).
LEXICONS_KEPT = 512
_LEXICONS: Recent = Recent(LEXICONS_KEPT)
#: A Recent is no thread-safe dict, and on the answer page a preview and a view's drawing may
#: read names at once.
_LEXICONS_LOCK = threading.Lock()


def _jets(vocabulary: Vocabulary) -> list[mechanics.Jet]:
    """The jets a vocabulary's names read as: its coordinates' and, with `momenta`, the
    momenta's (p_q and its rate read like a coordinate and its velocity)."""
    jets = [mechanics.jet(c) for c in vocabulary.coordinates]
    if vocabulary.momenta:
        jets += [momentum_jet(c) for c in vocabulary.coordinates]
    return jets


def _symbols(vocabulary: Vocabulary, jets: list[mechanics.Jet]) -> tuple[sp.Symbol, ...]:
    """Every symbol a vocabulary declares (the jets', the parameters', the labels'), in order."""
    labels = [sp.Symbol(name, real=True) for name in vocabulary.labels]
    return (
        *(s for j in jets for s in (j.q, j.dot, j.ddot)),
        *vocabulary.parameters.values(),
        *labels,
    )


class Lexicon:
    """Every spelling a vocabulary accepts, resolved once per what a vocabulary declares."""

    def __init__(self, vocabulary: Vocabulary):
        self.allow_primes = vocabulary.allow_primes
        self.jets = _jets(vocabulary)
        self.coordinates = vocabulary.coordinates
        #: The symbols declared, as the objects this lexicon reads names as (`holds`).
        self.symbols = _symbols(vocabulary, self.jets)
        exact: dict[str, Entry] = {}
        for j in self.jets:
            exact[j.name] = Entry("sym", j.q, j, 0)
            exact[j.dot.name] = Entry("sym", j.dot, j, 1)
            exact[j.ddot.name] = Entry("sym", j.ddot, j, 2)
        for name, symbol in vocabulary.parameters.items():
            exact[name] = Entry("sym", symbol, None, 0)
        labels = self.symbols[len(self.symbols) - len(vocabulary.labels) :]
        for name, symbol in zip(vocabulary.labels, labels, strict=True):
            exact[name] = Entry("sym", symbol, None, 0)
        self.imaginary_unit = vocabulary.imaginary_unit
        if self.imaginary_unit is not None:  # declared: a number, not a name
            exact[self.imaginary_unit] = Entry("sym", sp.I, None, 0)
        table = dict(exact)
        for j in self.jets:
            for v in _digit_variants(j.name):
                table.setdefault(v, exact[j.name])
                for suffix, order in (("dot", 1), ("_dot", 1), ("ddot", 2), ("_ddot", 2)):
                    table.setdefault(
                        v + suffix, Entry("sym", (j.q, j.dot, j.ddot)[order], j, order)
                    )
        for name in list(vocabulary.parameters) + list(vocabulary.labels):
            for v in _digit_variants(name):
                table.setdefault(v, exact[name])
        for spelling, entry in list(table.items()):  # ϑ and θ: one letter, unless both declared
            momentum = spelling.startswith("p_") and entry.jet is not None and vocabulary.momenta
            other = _variant_spelling(spelling[2:] if momentum else spelling)
            other = "p_" + other if momentum and other is not None else other
            if other is not None:
                table.setdefault(other, entry)
        table.setdefault("t", Entry("sym", mechanics.t, None, 0))
        table.setdefault("pi", Entry("pi", sp.pi, None, 0))
        self.table = table
        #: The function names this question leaves to functions (a declared name is no function),
        #: one set lookup for the parser's every name.
        self.functions = FUNCTIONS - table.keys()
        self.longest = max(len(k) for k in table)
        allowed = list(vocabulary.parameters)
        for j in self.jets:
            allowed += [j.name, j.dot.name] + ([j.ddot.name] if j.name in self.coordinates else [])
        allowed += list(vocabulary.labels) + ["t"]
        if self.imaginary_unit is not None:
            allowed.append(self.imaginary_unit)
        self.allowed = ", ".join(allowed)

    def holds(self, symbols: tuple[sp.Symbol, ...]) -> bool:
        """Whether this lexicon's declared symbols are these very objects."""
        return len(symbols) == len(self.symbols) and all(
            a is b for a, b in zip(symbols, self.symbols, strict=True)
        )

    def is_function(self, name: str) -> bool:
        return name in self.functions

    def split(self, name: str) -> list[str] | None:
        """Fewest declared names that spell `name` (mgl → m, g, l), or None."""
        if len(name) > 64:
            return None
        best: list[list[str] | None] = [None] * (len(name) + 1)
        best[0] = []
        for i in range(len(name)):
            if best[i] is None:
                continue
            for k in range(i + 1, min(len(name), i + self.longest) + 1):
                piece = name[i:k]
                if piece in self.table:
                    candidate = best[i] + [piece]  # type: ignore[operator]
                    if best[k] is None or len(candidate) < len(best[k]):  # type: ignore[arg-type]
                        best[k] = candidate
        found = best[len(name)]
        return found if found is not None and len(found) > 1 else None
