"""Names in an answer: looking a name up in the question's lexicon, dots and primes as time
derivatives, `theta(t)`, and the messages for names the question does not know (with a guess at
what was meant) or for Leibniz notation."""

from __future__ import annotations

import re
from typing import NoReturn

import sympy as sp

from lagrade.mechanics import lagrange as mechanics
from lagrade.notation.build import FUNCTIONS
from lagrade.notation.lexer import Token
from lagrade.notation.nodes import Node
from lagrade.notation.stream import TokenStream
from lagrade.notation.vocabulary import Entry

_I = sp.I
_VELOCITY_SUFFIX = re.compile(r"(.+?)_?(d?dot)\Z")
#: A run of single letters, the last one perhaps subscripted (`GMm`, `mv_0`), as LaTeX sets a
#: product of single-letter symbols.
_LETTER_RUN = re.compile(r"([A-Za-z]{2,})(_[A-Za-z0-9]+)?\Z")


class NameRules(TokenStream):
    """The rules for names, shared by the grammar's atoms, calls and diff(...)."""

    def split_letter_runs(self, tokens: list[Token], latex: bool) -> list[Token]:
        """A name the question does not know that is a run of single letters, each a declared
        name (the last one may carry the subscript, `mv_0`), becomes those names, and the
        reading is noted (in the preview and in the feedback of a wrong answer). In LaTeX
        adjacent letters are a product by convention (`\\frac{GMm}{r}` is G·M·m/r); in plain
        text `GM` for G·M is a slip the student's own message would have to guess at, so it is
        read the same way, unless a longer declared name lies inside the run (with k, m and km
        declared, `kmm` stays an error that asks)."""
        table = self.lexicon.table
        splits: dict[int, list[Token]] = {}
        for k, tok in enumerate(tokens):
            if tok.kind != "name" or tok.text in table or tok.marks or tok.primes:
                continue
            run = _LETTER_RUN.match(tok.text)
            if (
                run is None
                or self.lexicon.is_function(tok.text)
                or (tok.text == "dt" and k and tokens[k - 1].text == "/")  # d/dt, dx/dt
            ):
                continue
            letters, subscript = run.group(1), run.group(2) or ""
            names = [*letters[:-1], letters[-1] + subscript]
            if not all(name in table for name in names):
                continue
            if not latex and self.longer_name_inside(letters):
                continue
            starts = [tok.start + i for i in range(len(letters))]
            ends = [*starts[1:], tok.end]
            splits[k] = [
                Token("name", name, start, end, tok.spaced if i == 0 else False)
                for i, (name, start, end) in enumerate(zip(names, starts, ends, strict=True))
            ]
            product = "*".join(names)
            self.warn(
                f"{tok.text} is read as {product}: in LaTeX adjacent letters multiply."
                if latex
                else f"{tok.text} is read as {product}: separate names with * or a space."
            )
        if not splits:
            return tokens
        return [piece for k, tok in enumerate(tokens) for piece in splits.get(k, [tok])]

    def longer_name_inside(self, letters: str) -> bool:
        """Whether a declared name of two or more letters is spelled inside `letters`."""
        table = self.lexicon.table
        return len(letters) > 64 or any(
            letters[i:j] in table
            for i in range(len(letters))
            for j in range(i + 2, min(len(letters), i + self.lexicon.longest) + 1)
        )

    def lookup(self, tok: Token) -> Entry:
        """The lexicon's entry for a name token; unknown names and stray primes fail."""
        entry = self.lexicon.table.get(tok.text)
        if entry is None:
            self.unknown(tok)
        if tok.primes and entry.jet is None:
            self.not_a_coordinate(tok.text, tok)
        if tok.primes and not self.lexicon.allow_primes:
            if self.lexicon.table["t"].value == mechanics.t:
                # t is the only independent variable: a prime can only be d/dt (issue 38)
                jets = (entry.jet.q, entry.jet.dot, entry.jet.ddot)
                typed = jets[min(2, entry.order + tok.marks)].name + "'" * tok.primes
                read = jets[min(2, entry.order + tok.marks + tok.primes)].name
                self.warn(f"{typed} is read as {read} (a prime as d/dt).")
                return entry
            base = entry.jet.name
            if entry.order + tok.marks + tok.primes == 1:
                fix = f"write {base}dot for d{base}/dt"
            else:
                fix = f"write {base}ddot for the second derivative"
            self.fail(f"Primes are ambiguous in mechanics; {fix}.", tok.start, tok.end)
        return entry

    def parse_name(self, tok: Token) -> Node:
        """A name already taken from the stream, with its dots or primes and an optional (t)."""
        entry = self.lexicon.table.get(tok.text)
        if entry is None or tok.primes:  # else `lookup` would only return the entry
            entry = self.lookup(tok)
        extra = tok.marks + tok.primes
        if extra and entry.jet is None:
            self.not_a_coordinate(tok.text, tok)
        if entry.kind == "pi":
            return self.node("pi", tok.start, tok.end)
        if extra:
            return self.derivative(entry, entry.order + extra, tok.start, tok.end)
        end = tok.end
        if self.tokens[self.pos].text == "(" and self.followed_by_of_t():
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
        if entry.value is not _I:  # the declared imaginary unit is a number, not a symbol
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

    def time_operator(self, i: int) -> tuple[int, int] | None:
        """(order, index of the token after it) when tokens i… are the operator d/dt or
        d^2/dt^2 (written with or without spaces, d²/dt² too), else None. `dt` must be no name
        of the question; `d` may be one (a distance d): `d/dt` has no other reading."""
        tokens = self.tokens
        if i >= len(tokens) or tokens[i].text != "d" or tokens[i].marks or tokens[i].primes:
            return None
        texts = [tok.text for tok in tokens[i : i + 7]]
        if "dt" in self.lexicon.table:
            return None
        if texts[1:3] == ["/", "dt"] and tokens[i + 2].kind == "name":
            return 1, i + 3
        if texts[1:7] == ["^", "2", "/", "dt", "^", "2"]:
            return 2, i + 7
        return None

    def read_time_operator(self, i: int) -> int:
        """For a token `d` (or the `dt` of `d/dt` after a declared d) at i: the index after the
        operator d/dt or d^2/dt^2 that starts there, when a bracket follows it; -1 when none
        starts there. Without a bracket it fails (unless d is a declared name, when `d/dt x`
        is left to read, or fail, as a division)."""
        start = (
            i
            if self.tokens[i].text == "d"
            else next((k for k in (i - 2, i - 4) if k >= 0 and self.time_operator(k)), -1)
        )
        found = self.time_operator(start) if start >= 0 else None
        if found is None or found[1] <= i:
            return -1
        after = found[1]
        if self.tokens[after].text != "(":
            if "d" in self.lexicon.table:
                return -1
            self.fail(
                "Write what d/dt differentiates in brackets, as in d/dt(m*r^2*theta_dot).",
                self.tokens[start].start,
                self.tokens[after - 1].end,
            )
        return after

    def check_leibniz(self) -> None:
        """dx/dt, dtheta/dt, d^2x/dt^2: rejected before names are looked up. The operator d/dt
        (d^2/dt^2) applied to a bracket is the time derivative of what it holds; without a
        bracket it is refused (`d/dt theta^2` could mean either square)."""
        table = self.lexicon.table
        tokens = self.tokens
        operator_end = -1  # tokens before this index belong to a d/dt operator already read
        for i, tok in enumerate(tokens):
            if tok.kind != "name" or tok.text in table or i < operator_end:
                continue
            if tok.text in ("d", "dt"):  # d/dt(…); or …/dt after a declared d (a distance)
                operator_end = self.read_time_operator(i)
                if i < operator_end:
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
                f"Leibniz notation is not supported; write {what}dot, diff({what}, t) or "
                f"d/dt({what}).",
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
