"""The grammar of an answer, one method per rule (notation.md):

    answer  := sum [ '=' sum ]
    sum     := ['+'|'-'] term (('+'|'-') term)*
    term    := unary ( ('*'|'/') unary | <juxtaposition> power )*
    unary   := '-' unary | power
    power   := atom [ ('^'|'**') unary ]            -- right-associative: 2^3^2 = 2^9
    atom    := number | '(' sum ')' | call | diff | name

The rules build a `nodes.Node` tree and never touch sympy; names are read by `names.NameRules`.
"""

from __future__ import annotations

from typing import NoReturn

from lagrade.notation.build import SEVERAL_ARGUMENTS, TWO_ARGUMENTS
from lagrade.notation.lexer import Token, read_number
from lagrade.notation.limits import (
    MAX_DEPTH,
    MAX_EXPONENT,
    MAX_EXTREMUM_ARGUMENTS,
    MAX_FUNCTION_POWER,
)
from lagrade.notation.names import NameRules
from lagrade.notation.nodes import Node

_TERM_END = frozenset(("+", "-", ")", "=", ",", ";", "|"))
_new = tuple.__new__
#: Token kinds that cannot begin a term; only before one does `operand_after` have to look.
_NOT_TERMS = ("op", "end")
_TRIG = frozenset(("sin", "cos", "tan", "sec", "csc", "cot", "sinh", "cosh", "tanh"))


class Parser(NameRules):
    """Recursive descent over the tokens of one answer; one method per grammar rule."""

    def parse_answer(self, mode: str) -> tuple[Node, Node | None]:
        """answer := sum ['=' sum]; mode 'expression' forbids the '='."""
        self.check_leibniz()
        if self.peek().kind == "end":
            self.fail("The answer is empty.", 0, len(self.text))
        lhs = self.parse_sum()
        rhs = None
        tok = self.peek()
        if tok.text == "=":
            if mode == "expression":
                self.fail(
                    "Expected an expression, not an equation; "
                    "write only the expression, without '='.",
                    tok.start,
                    tok.end,
                )
            self.next()
            if self.peek().kind == "end":
                self.fail(
                    "The answer ends with '='; write what it equals (0 if nothing).",
                    tok.start,
                    tok.end,
                )
            rhs = self.parse_sum()
            tok = self.peek()
            if tok.text == "=":
                self.fail("Use a single '=' for an equation.", tok.start, tok.end)
        if tok.kind != "end":
            self.unexpected(tok)
        return lhs, rhs

    def parse_sum(self) -> Node:
        """sum := ['+'|'-'] term (('+'|'-') term)*"""
        tokens = self.tokens
        first = tokens[self.pos]
        terms = []
        negative = False
        if first.text in ("+", "-"):
            self.next()
            self.operand_after(first)
            negative = first.text == "-"
        term = self.parse_term()
        terms.append(self.node("neg", first.start, term.end, term) if negative else term)
        while tokens[self.pos].text in ("+", "-"):
            op = tokens[self.pos]
            self.pos += 1
            if tokens[self.pos].kind in _NOT_TERMS:  # else `operand_after` finds nothing amiss
                self.operand_after(op)
            term = self.parse_term()
            terms.append(self.node("neg", op.start, term.end, term) if op.text == "-" else term)
        if len(terms) == 1:
            return terms[0]
        return self.node("add", terms[0].start, terms[-1].end, terms)

    def parse_term(self) -> Node:
        """term := unary ( ('*'|'/') unary | <juxtaposition> power )*; a juxtaposition after a
        division multiplies what came before (`k/m x` is (k/m)·x), with a warning"""
        first = self.parse_unary()
        tokens = self.tokens
        factors = [first]
        after_division = False
        while True:
            tok = tokens[self.pos]
            if tok.text in ("*", "/"):
                self.pos += 1
                if tokens[self.pos].kind in _NOT_TERMS:
                    self.operand_after(tok)
                factor = self.parse_unary()
                if tok.text == "*":
                    factors.append(factor)
                    after_division = False
                else:
                    factors.append(self.node("inv", factor.start, factor.end, factor))
                    after_division = True
            elif (
                tok.kind in ("name", "num")
                or tok.text == "("
                or (tok.text == "|" and self.opens_bars(tok))
            ):
                if tok.kind == "num" and tokens[self.pos - 1].kind == "num":
                    self.two_numbers(tok)
                factors.append(self.parse_power())
                if after_division and not self.is_integer_fraction(factors[:-1]):
                    self.note_division(first.start, factors[-2], factors[-1])
                after_division = False
            else:
                break
        if len(factors) == 1:
            return first
        return self.node("mul", first.start, factors[-1].end, factors)

    def two_numbers(self, tok: Token) -> NoReturn:
        """The message for the number `tok` right after another one (`2 3`, `2 3/4`)."""
        before = self.tokens[self.pos - 1]
        a, b = before.text, tok.text
        if not tok.spaced:
            self.fail(f"Cannot read the number '{a}{b}'.", before.start, tok.end)
        if self.peek(1).text == "/" and self.peek(2).kind == "num":
            c = self.peek(2).text  # 2 3/4: a mixed number, or a number with a space
            self.fail(
                f"Two numbers side by side: for the mixed number write {a} + {b}/{c}"
                f", for a product {a}*{b}/{c}.",
                before.start,
                self.peek(2).end,
            )
        self.fail(f"Two numbers side by side; write {a}{b} or {a}*{b}.", before.start, tok.end)

    @staticmethod
    def is_integer_fraction(factors: list[Node]) -> bool:
        """1/2 m v^2: an integer over an integer may be followed by more factors."""
        if len(factors) != 2:
            return False
        top, bottom = factors[0], factors[1].value
        return top.kind == "num" and top.extra and bottom.kind == "num" and bottom.extra  # type: ignore[union-attr]

    def note_division(self, term_start: int, divisor: Node, following: Node) -> None:
        """`k/m (x - x0)`, as textbooks print it: read left to right, as mainstream computer
        algebra reads it (the implicit product binds like '*'). A warning says so only where
        the other reading, a/(b c), is plausible: where c is written against the divisor
        (`g/2l`, `k/m(x - x0)`), as if under the bar with it — but not a bracket after a
        number (`m/2(…)` is m/2 times the bracket). A space (`m/2 (ṙ² + r²θ̇²)`, `k/m x`)
        sets the factor apart: no warning on what is read as written (the echo shows it)."""
        if following.start > divisor.end:
            return
        number = divisor.value if divisor.kind == "inv" else divisor
        if number.kind == "num" and self.text[following.start] == "(":  # type: ignore[union-attr]
            return
        left = self.text[term_start : divisor.start].rstrip().rstrip("/").rstrip()
        under = self.text[divisor.start : divisor.end]
        after = self.text[following.start : following.end]
        self.warn(
            f"{left}/{under}{after} is read as ({left}/{under})*{after}; if {after} belongs "
            f"under the fraction bar, write {left}/({under}*{after})."
        )

    def parse_unary(self) -> Node:
        """unary := '-' unary | power"""
        tok = self.tokens[self.pos]
        self.depth += 1  # self.enter(tok), inline: every factor comes through here
        if self.depth > MAX_DEPTH:
            self.depth -= 1
            self.enter(tok)
        if tok.text == "-":
            self.next()
            self.operand_after(tok)
            operand = self.parse_unary()
            result = self.node("neg", tok.start, operand.end, operand)
        else:
            result = self.parse_power()
        self.depth -= 1
        return result

    def parse_power(self) -> Node:
        """power := atom [('^'|'**') unary], right-associative."""
        base = self.parse_atom()
        tok = self.tokens[self.pos]
        if tok.text != "^" and tok.text != "**":
            return base
        self.pos += 1
        if self.tokens[self.pos].kind in _NOT_TERMS:
            self.operand_after(tok)
        exponent = self.parse_unary()
        literal = exponent.value if exponent.kind == "num" else None
        if exponent.kind == "neg" and exponent.value.kind == "num":  # type: ignore[union-attr]
            literal = exponent.value.value  # type: ignore[union-attr]
        if literal is not None and abs(literal[0]) > MAX_EXPONENT * literal[1]:  # type: ignore[index]
            self.fail(
                f"Exponent too large: at most {MAX_EXPONENT:,} in absolute value.",
                exponent.start,
                exponent.end,
            )
        return self.node("pow", base.start, exponent.end, base, exponent)

    def parse_atom(self) -> Node:
        """atom := number | '(' sum ')' | call | diff | name"""
        tok = self.tokens[self.pos]
        kind, text = tok.kind, tok.text
        if kind == "name":
            if text == "diff" and "diff" not in self.lexicon.table:
                return self.parse_diff()
            operator = self.time_operator(self.pos) if text == "d" else None
            if operator is not None and self.peek(operator[1] - self.pos).text == "(":
                return self.parse_time_derivative(*operator)
            if text in self.lexicon.functions:
                return self.parse_call()
            self.pos += 1
            return self.parse_name(tok)
        if kind == "num":
            self.pos += 1
            p, q, whole = read_number(tok, self.src)
            return self.node("num", tok.start, tok.end, (p, q), whole)
        if text == "(":
            return self.parse_group()
        if text == "|":
            return self.parse_bars()
        self.unexpected(tok)

    def opens_bars(self, tok: Token) -> bool:
        """After a factor, '|' opens an absolute value only outside bars (`m |x|`); inside
        them it closes the one that is open (`|a x|`)."""
        return tok.text == "|" and self.bars == 0

    def parse_bars(self) -> Node:
        """'|' sum '|': the absolute value, abs(sum)."""
        opening = self.next()
        self.enter(opening)
        self.bars += 1
        inner = self.parse_sum()  # a '|' right after the opening one opens another: ||x| - 1|
        closing = self.peek()
        if closing.text != "|":
            if closing.kind == "end":
                self.fail(
                    f"Missing '|': the '|' at position {self.column(opening.start)} is never "
                    "closed.",
                    opening.start,
                    opening.end,
                )
            self.unexpected(closing)
        self.next()
        self.bars -= 1
        self.depth -= 1
        return self.node("call", opening.start, closing.end, "abs", (inner, None))

    def parse_group(self) -> Node:
        """'(' sum ')'"""
        tokens = self.tokens
        opening = tokens[self.pos]
        self.pos += 1
        self.enter(opening)
        tok = tokens[self.pos]
        if tok.text == ")":
            self.fail("Empty brackets '()'.", opening.start, tok.end)
        if tok.kind == "end":
            self.fail(
                f"Missing ')': the '(' at position {self.column(opening.start)} is never closed.",
                opening.start,
                opening.end,
            )
        inner = self.parse_sum()
        closing = tokens[self.pos]
        if closing.text != ")":
            if closing.kind == "end":
                self.fail(self.missing_close(opening), opening.start, opening.end)
            self.unexpected(closing)
        self.pos += 1
        self.depth -= 1
        # inner._replace(start=…, end=…), without its Python-level detour; not a new node
        return _new(Node, (inner.kind, opening.start, closing.end, inner.value, inner.extra))

    def parse_call(self) -> Node:
        """call := FUNC ['^' INTEGER] ('(' sum ')' | simple_arg)"""
        tok = self.next()
        name = tok.text
        if tok.marks or tok.primes:
            self.fail(
                f"'{name}' is a function; it cannot carry a dot or a prime.", tok.start, tok.end
            )
        if name == "log":
            self.warn("log is read as the natural logarithm ln.")
        power = None
        if self.peek().text in ("^", "**"):
            op = self.next()
            nxt = self.peek()
            if nxt.kind == "num" and nxt.text.isdigit() and 0 < int(nxt.text) <= MAX_FUNCTION_POWER:
                power = int(nxt.text)
                self.next()
            elif nxt.text == "-" or (nxt.text == "(" and self.peek(1).text == "-"):
                fix = f"a{name}(x) or 1/{name}(x)" if name in _TRIG else f"1/{name}(x)"
                self.fail(f"{name}^-1 is ambiguous; write {fix}.", tok.start, nxt.end)
            else:
                self.fail(
                    f"After '{name}^' write a whole number, as in {name}^2(x), "
                    f"or put the power after the argument: {name}(x)^n.",
                    op.start,
                    nxt.end,
                )
        nxt = self.peek()
        if name in TWO_ARGUMENTS:
            arguments = self.parse_two_arguments(tok)
            return self.node(
                "call", tok.start, self.tokens[self.pos - 1].end, name, (arguments, power)
            )
        if name in SEVERAL_ARGUMENTS:
            arguments = self.parse_several_arguments(tok)
            return self.node(
                "call", tok.start, self.tokens[self.pos - 1].end, name, (arguments, power)
            )
        if nxt.text == "(":
            argument = self.parse_group()
        elif (
            nxt.kind in ("name", "num")
            and not self.lexicon.is_function(nxt.text)
            and nxt.text != "diff"
        ):
            argument = self.parse_simple_argument()
            self.check_bare_argument(tok, power, argument)
        elif nxt.kind == "end":
            self.fail(f"Expected '(' after '{name}' but the answer ended.", tok.start, tok.end)
        else:
            self.fail(
                f"Write the argument of '{name}' in brackets, as in {name}(x).", tok.start, nxt.end
            )
        return self.node("call", tok.start, argument.end, name, (argument, power))

    def parse_two_arguments(self, function: Token) -> tuple[Node, Node]:
        """'(' sum ',' sum ')' after a function of two arguments (atan2(y, x))."""
        name = function.text
        opening = self.peek()
        if opening.text != "(":
            self.fail(f"Write {name}(y, x) with brackets.", function.start, function.end)
        self.next()
        self.enter(opening)
        first = self.parse_sum()
        comma = self.expect_in_call(",", opening, function)
        self.operand_after(comma)
        second = self.parse_sum()
        self.expect_in_call(")", opening, function)
        self.depth -= 1
        return first, second

    def parse_several_arguments(self, function: Token) -> tuple[Node, ...]:
        """'(' sum (',' sum)+ ')' after Max or Min: two arguments or more, and no more than
        MAX_EXTREMUM_ARGUMENTS in all the answer's calls together."""
        name = function.text
        opening = self.peek()
        if opening.text != "(":
            self.fail(f"Write {name}(a, b) with brackets.", function.start, function.end)
        self.next()
        self.enter(opening)
        arguments = [self.parse_sum()]
        while self.peek().text == ",":
            self.operand_after(self.next())
            arguments.append(self.parse_sum())
        closing = self.peek()
        if closing.text != ")":
            if closing.kind == "end":
                self.fail(self.missing_close(opening), opening.start, opening.end)
            self.unexpected(closing)
        self.next()
        self.depth -= 1
        if len(arguments) < 2:
            self.fail(
                f"{name} compares two values or more: {name}(a, b).", function.start, closing.end
            )
        self.extremum_arguments += len(arguments)
        if self.extremum_arguments > MAX_EXTREMUM_ARGUMENTS:
            self.fail(
                f"Too many values to compare: at most {MAX_EXTREMUM_ARGUMENTS} in all the Max "
                "and Min of one answer.",
                function.start,
                closing.end,
            )
        return tuple(arguments)

    def expect_in_call(self, text: str, opening: Token, function: Token) -> Token:
        """The ',' or ')' of a call of two arguments, or the message for what stands there."""
        tok = self.peek()
        if tok.text != text:
            if tok.kind == "end":
                self.fail(self.missing_close(opening), opening.start, opening.end)
            name = function.text
            self.fail(f"{name} takes two arguments: {name}(y, x).", function.start, tok.end)
        return self.next()

    def parse_simple_argument(self) -> Node:
        tok = self.next()
        if tok.kind == "num":
            p, q, whole = read_number(tok, self.src)
            return self.node("num", tok.start, tok.end, (p, q), whole)
        return self.parse_name(tok)

    def check_bare_argument(self, function: Token, power: int | None, argument: Node) -> None:
        """`sin theta` must end its term or be followed by another function: `sin omega t`,
        `sin 2 theta`, `cos theta^2` are ambiguous."""
        tok = self.peek()
        if tok.kind == "end" or tok.text in _TERM_END:
            return
        if tok.kind == "name" and self.lexicon.is_function(tok.text):
            return
        if (
            tok.text == "*"
            and self.peek(1).kind == "name"
            and self.lexicon.is_function(self.peek(1).text)
        ):
            return
        name = function.text + (f"^{power}" if power else "")
        arg = self.text[argument.start : argument.end]
        if tok.text in ("^", "**"):
            self.next()
            self.operand_after(tok)
            following = self.parse_unary()
            rest = self.text[tok.start : following.end]
            readings = (f"{name}({arg}{rest})", f"{name}({arg}){rest}")
        elif tok.text in ("*", "/"):
            self.next()
            self.operand_after(tok)
            following = self.parse_power()
            rest = tok.text + self.text[following.start : following.end]
            readings = (f"{name}({arg}{rest})", f"{name}({arg}){rest}")
        else:
            following = self.parse_power()
            rest = self.text[following.start : following.end]
            readings = (f"{name}({arg}*{rest})", f"{name}({arg})*{rest}")
        before, after = self.text[: function.start], self.text[following.end :]
        self.fail(
            f"Ambiguous '{function.text}' without brackets: write {' or '.join(readings)}.",
            function.start,
            following.end,
            readings=tuple((reading, before + reading + after) for reading in readings),
        )

    def parse_time_derivative(self, order: int, after: int) -> Node:
        """ddt := 'd/dt' '(' sum ')' | 'd^2/dt^2' '(' sum ')': the total time derivative D_t
        of what the bracket holds (built on the jets, `build._time_derivative`)."""
        start = self.peek().start
        self.pos = after
        inner = self.parse_group()
        return self.time_derivative(inner, order, start, inner.end)

    def time_derivative(self, inner: Node, order: int, start: int, end: int) -> Node:
        """The node of D_t applied `order` times to `inner`. Of a name alone, only a coordinate's
        (or a velocity's, or t's) is taken: d/dt(m) or d/dt(p_theta) is 0, which a student who
        writes it does not mean, so it is refused as diff(m, t) is."""
        time = self.lexicon.table["t"].value
        if inner.kind == "sym" and inner.value is not time:
            motion = {s for j in self.lexicon.jets for s in (j.q, j.dot, j.ddot)}
            if inner.value not in motion:
                name = getattr(inner.value, "name", self.text[inner.start : inner.end])
                coordinates = ", ".join(self.lexicon.coordinates) or "none"
                self.fail(
                    f"'{name}' is not a coordinate of this problem (coordinates: {coordinates}).",
                    inner.start,
                    inner.end,
                )
        return self.node("ddt", start, end, inner, (order, time, tuple(self.lexicon.jets)))

    def parse_diff(self) -> Node:
        """diff := 'diff' '(' (name | sum) ',' 't' [',' INTEGER] ')': of a name, its velocity
        or acceleration (a name that is no coordinate is refused); of an expression, its total
        time derivative."""
        tok = self.next()
        if self.peek().text != "(":
            self.fail("Write diff(x, t) with brackets.", tok.start, tok.end)
        opening = self.next()
        target = self.peek()
        of_t = [self.peek(k).text for k in (1, 2, 3, 4)] == ["(", "t", ")", ","]
        single = (
            target.kind == "name"
            and not self.lexicon.is_function(target.text)  # diff(sin(t), t) is no theta(t)
            and (self.peek(1).text in (",", ")") or of_t)
        )
        inner = None
        if single:
            self.next()
            self.skip_of_t()
        else:
            self.enter(opening)
            inner = self.parse_sum()
            self.depth -= 1
        comma = self.peek()
        if comma.text != ",":
            if comma.kind == "end":
                self.fail(self.missing_close(opening), opening.start, opening.end)
            if comma.text == ")":
                what = target.text if single else "x"
                self.fail(
                    f"diff(...) needs the variable t: write diff({what}, t).",
                    tok.start,
                    comma.end,
                )
            self.unexpected(comma)
        self.next()
        var = self.peek()
        if not (var.kind == "name" and var.text == "t" and not var.marks and not var.primes):
            self.fail("diff(...) is only allowed with respect to t.", var.start, var.end)
        self.next()
        order = 1
        if self.peek().text == ",":
            self.next()
            n = self.peek()
            if not (n.kind == "num" and n.text in ("1", "2")):
                self.fail("The order in diff(x, t, n) must be 1 or 2.", n.start, n.end)
            order = int(n.text)
            self.next()
        closing = self.peek()
        if closing.text != ")":
            if closing.kind == "end":
                self.fail(
                    self.missing_close(opening),
                    opening.start,
                    opening.end,
                )
            self.fail("Expected ')' to close diff(...).", closing.start, closing.end)
        self.next()
        if inner is not None:
            return self.time_derivative(inner, order, tok.start, closing.end)
        entry = self.lookup(target)
        if entry.jet is None:
            self.not_a_coordinate(target.text, target)
        return self.derivative(entry, entry.order + target.marks + order, tok.start, closing.end)
