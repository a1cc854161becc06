"""Names in an answer: looking a name up in the question's lexicon, dots and primes as time
derivatives, `theta(t)`, and the messages for names the question does not know (with a guess at
what was meant) or for Leibniz notation."""

from __future__ import annotations

import re
from typing import NoReturn

import sympy as sp

from lagrade.notation.build import FUNCTIONS
from lagrade.notation.lexer import Token
from lagrade.notation.nodes import Node
from lagrade.notation.stream import TokenStream
from lagrade.notation.vocabulary import Entry

_VELOCITY_SUFFIX = re.compile(r"(.+?)_?(d?dot)\Z")


class NameRules(TokenStream):
    """The rules for names, shared by the grammar's atoms, calls and diff(...)."""

    def lookup(self, tok: Token) -> Entry:
        """The lexicon's entry for a name token; unknown names and stray primes fail."""
        entry = self.lexicon.table.get(tok.text)
        if entry is None:
            self.unknown(tok)
        if tok.primes and not self.lexicon.allow_primes:
            base = entry.jet.name if entry.jet is not None else tok.text
            if entry.order + tok.marks + tok.primes == 1:
                fix = f"write {base}dot for d{base}/dt"
            else:
                fix = f"write {base}ddot for the second derivative"
            self.fail(f"Primes are ambiguous in mechanics; {fix}.", tok.start, tok.end)
        return entry

    def parse_name(self, tok: Token) -> Node:
        """A name already taken from the stream, with its dots or primes and an optional (t)."""
        entry = self.lookup(tok)
        extra = tok.marks + tok.primes
        if extra and entry.jet is None:
            self.not_a_coordinate(tok.text, tok)
        if entry.kind == "pi":
            return self.node("pi", tok.start, tok.end)
        if extra:
            return self.derivative(entry, entry.order + extra, tok.start, tok.end)
        end = tok.end
        if self.followed_by_of_t():
            if entry.jet is None:
                self.fail(
                    f"'{tok.text}(t)' reads as a function of time, but {tok.text} is not a "
                    f"coordinate; write {tok.text}*t for a product.",
                    tok.start,
                    self.peek(2).end,
                )
            end = self.peek(2).end
            self.skip_of_t()
            self.warn(f"{tok.text}(t) is read as {tok.text}.")
        if entry.value is not sp.I:  # the declared imaginary unit is a number, not a symbol
            self.found.add(entry.value.name)  # type: ignore[attr-defined]
        return self.node("sym", tok.start, end, entry.value)

    def derivative(self, entry: Entry, order: int, start: int, end: int) -> Node:
        """The node of a coordinate's time derivative of `order`; only orders up to 2 exist."""
        jet = entry.jet
        assert jet is not None
        if order > 2:
            self.fail(
                "Only velocities and accelerations exist here: "
                f"that is a derivative of order {order} of {jet.name}.",
                start,
                end,
            )
        symbol = (jet.q, jet.dot, jet.ddot)[order]
        self.found.add(symbol.name)
        return self.node("sym", start, end, symbol)

    def not_a_coordinate(self, name: str, tok: Token) -> NoReturn:
        coordinates = ", ".join(self.lexicon.coordinates) or "none"
        self.fail(
            f"'{name}' is not a coordinate of this problem (coordinates: {coordinates}).",
            tok.start,
            tok.end,
        )

    def unknown(self, tok: Token) -> NoReturn:
        name = tok.text
        velocity = _VELOCITY_SUFFIX.match(name)
        if velocity and name not in ("ddot", "_dot", "_ddot"):
            stem = velocity.group(1).rstrip("_")
            entry = self.lexicon.table.get(stem)
            if stem and (entry is None or entry.jet is None) and not self.lexicon.split(name):
                self.not_a_coordinate(stem, tok)
        parts = self.lexicon.split(name)
        if parts:
            self.fail(
                f"Unknown symbol '{name}'. Did you mean {'*'.join(parts)}? "
                "Separate variables with * or a space.",
                tok.start,
                tok.end,
            )
        for function in sorted(FUNCTIONS, key=len, reverse=True):
            rest = name[len(function) :]
            if name.startswith(function) and rest:
                inner = (
                    rest if rest in self.lexicon.table else "*".join(self.lexicon.split(rest) or ())
                )
                if inner:
                    self.fail(
                        f"Unknown symbol '{name}'. Did you mean {function}({inner})?",
                        tok.start,
                        tok.end,
                    )
        hint = None
        if name == "e":
            hint = "e is not Euler's number here; write exp(x) for the exponential."
        elif name == "E":
            hint = (
                "E is not one of this question's names: write the energy out in the names "
                "above (and e^x as exp(x))."
            )
        elif name == "I":
            hint = (
                "I is not one of this question's names: write a moment of inertia out in the "
                "names above (no imaginary unit is used here)."
            )
        self.fail(
            f"Unknown symbol '{name}'. Allowed: {self.lexicon.allowed}.", tok.start, tok.end, hint
        )

    def check_leibniz(self) -> None:
        """dx/dt, d/dt(...), dtheta/dt, d^2x/dt^2: rejected before names are looked up."""
        table = self.lexicon.table
        tokens = self.tokens
        for i, tok in enumerate(tokens):
            if tok.kind != "name" or tok.text in table:
                continue
            leibniz = (
                (tok.text == "dt" and i > 0 and tokens[i - 1].text == "/")
                or (tok.text == "d" and tokens[i + 1].text == "/")
                or (
                    tok.text == "d"
                    and i > 0
                    and tokens[i - 1].text == "/"
                    and tokens[i + 1].text == "t"
                )
            )
            if not leibniz:
                continue
            what = "x"
            for k in [*range(i - 1, max(-1, i - 6), -1), *range(i + 1, min(len(tokens), i + 6))]:
                candidate = tokens[k].text
                entry = table.get(candidate[1:]) if candidate.startswith("d") else None
                if entry is None:
                    entry = table.get(candidate)
                if entry is not None and entry.jet is not None:
                    what = entry.jet.name
                    break
            start = tokens[i - 2].start if i >= 2 and tokens[i - 1].text == "/" else tok.start
            end = tok.end
            if tok.text == "d" and tokens[i + 1].text == "/":
                end = tokens[i + 2].end
            self.fail(
                f"Leibniz notation is not supported; write {what}dot or diff({what}, t).",
                start,
                end,
            )

    def followed_by_of_t(self) -> bool:
        """'(t)' right after a name, without a space: theta(t)."""
        opening = self.peek()
        return (
            opening.text == "("
            and not opening.spaced
            and self.peek(1).text == "t"
            and self.peek(2).text == ")"
        )

    def skip_of_t(self) -> bool:
        """Consume '(t)' after a coordinate (theta(t) is theta)."""
        if self.followed_by_of_t():
            self.pos += 3
            return True
        return False
