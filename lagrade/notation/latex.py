"""LaTeX → the plain answer grammar, by a small translator of our own.

sympy's LaTeX parsers read `\\dot{x}` as dot·x and drop primes; this translator knows only the
subset students use for mechanics (`\\frac`, `\\dot`, `\\ddot`, `^{}`, `_{}`, `\\left( \\right)`,
`\\cdot`, spacing, functions and Greek letters) and rejects every other command with a message.
Its output is plain text for the ordinary parser, with each character mapped back to the LaTeX
the student wrote, so errors point into the original.
"""

from __future__ import annotations

import re
from collections.abc import Container

from lagrade.notation.lexer import DDOT_MARK, DOT_MARK, Source

_GREEK = (
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau "
    "upsilon phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega"
).split()
_WORDS = {name: name for name in _GREEK} | {
    "varphi": "varphi", "vartheta": "vartheta", "varepsilon": "varepsilon", "varrho": "varrho",
    "varsigma": "sigma", "varpi": "pi",
    "sin": "sin", "cos": "cos", "tan": "tan", "sec": "sec", "csc": "csc", "cot": "cot",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "arcsin": "asin", "arccos": "acos",
    "arctan": "atan", "exp": "exp", "ln": "ln", "log": "log", "max": "Max", "min": "Min",
}  # fmt: skip
#: The commands that are letters (a function's bare argument may be one).
_LETTERS = frozenset(name for name in _WORDS if _WORDS[name] in _GREEK or name.startswith("var"))
_TIMES = {"cdot": "*", "times": "*", "ast": "*"}
_SPACES = frozenset((",", ";", ":", "!", " ", "quad", "qquad", "(", ")", "[", "]", "displaystyle"))
_FRACS = frozenset(("frac", "dfrac", "tfrac"))
_FUNCTIONS = frozenset(
    "sin cos tan sec csc cot sinh cosh tanh arcsin arccos arctan exp ln log".split()
)
#: Spacing commands that end a bracket-less function's argument (\! is a negative space, kept
#: inside the argument's reach only by the grammar's own rule).
_ENDING_SPACES = frozenset((",", ";", ":", " ", "quad", "qquad"))
_DOTS = {"dot": DOT_MARK, "ddot": DDOT_MARK}
#: Every command (by name, without its backslash) the translator reads.
COMMANDS = frozenset(
    {*_WORDS, *_TIMES, *_FRACS, *_DOTS, "sqrt", "left", "right", "quad", "qquad", "displaystyle"}
)

_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\\$|\s+|.", re.DOTALL)
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_SUBSCRIPT = re.compile(r"[A-Za-z0-9_]+\Z")
#: What a fraction's numerator or denominator may be without brackets: a whole number, or one
#: letter with its subscript. Anything longer is bracketed, whatever it looks like: `2l` is a
#: product (the grammar would read `mg/2l` as (mg/2)*l), and a run of letters may be one too.
_ATOM = re.compile(r"([0-9]+|[A-Za-z](_[A-Za-z0-9]+)?)\Z")
_INTEGER = re.compile(r"[0-9]+\Z")
_LEIBNIZ_DENOMINATOR = re.compile(r"d\s*t(\s*\^\s*\(?\s*2\s*\)?)?\Z")
#: Numerators of \frac{d}{dt} and \frac{d^2}{dt^2} (as translated), by the order they give.
_TIME_OPERATOR = {"d": 1, "d^2": 2, "d^(2)": 2}


class _Translator:
    """Recursive descent over LaTeX tokens; `out` collects (text, start, end) pieces."""

    def __init__(self, src: Source, keep_e: bool, names: Container[str] = ()):
        self.src = src
        self.keep_e = keep_e
        self.names = names
        self.tokens = [(m.group(), m.start(), m.end()) for m in _TOKEN.finditer(src.text)]
        self.i = 0
        self.out: list[tuple[str, int, int]] = []
        self.separate = False  # the last piece was a word that must not fuse with the next one

    # --- output ---------------------------------------------------------------------------------
    def emit(self, text: str, start: int, end: int) -> None:
        if not text:
            return
        if self.separate and text[0].isalnum():
            self.out.append((" ", start, start))
        self.separate = False
        self.out.append((text, start, end))

    def word(self, text: str, start: int, end: int) -> None:
        """A command that becomes a name (\\theta → theta): keep it apart from its neighbours."""
        last = self.out[-1][0][-1:] if self.out else ""
        if last.isalnum() or last in (DOT_MARK, DDOT_MARK, "'"):
            self.out.append((" ", start, start))
        self.separate = False
        self.out.append((text, start, end))
        self.separate = True

    def fail(self, message: str, start: int, end: int) -> None:
        self.src.fail(message, start, end)

    # --- reading ---------------------------------------------------------------------------------
    def peek(self) -> tuple[str, int, int] | None:
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def skip_space(self) -> None:
        while self.i < len(self.tokens) and self.tokens[self.i][0].isspace():
            self.i += 1

    def argument(self, command: str, start: int) -> tuple[int, int]:
        """The token range of one argument: a {group} (braces excluded) or a single token."""
        self.skip_space()
        tok = self.peek()
        if tok is None:
            self.fail(
                f"'\\{command}' needs an argument, as in \\{command}{{x}}.", start, self.end()
            )
        assert tok is not None
        if tok[0] == "{":
            close = self.matching(self.i)
            first, self.i = self.i + 1, close + 1
            return first, close
        if tok[0] == "}":
            self.fail(f"'\\{command}' needs an argument, as in \\{command}{{x}}.", tok[1], tok[2])
        self.i += 1
        return self.i - 1, self.i

    def matching(self, index: int) -> int:
        depth = 0
        for k in range(index, len(self.tokens)):
            text = self.tokens[k][0]
            if text == "{":
                depth += 1
            elif text == "}":
                depth -= 1
                if depth == 0:
                    return k
        tok = self.tokens[index]
        self.fail("Missing '}': this '{' is never closed.", tok[1], tok[2])
        raise AssertionError  # unreachable: fail raises

    def end(self) -> int:
        return len(self.src.text)

    def sub(self, first: int, last: int) -> list[tuple[str, int, int]]:
        """Translate tokens first…last on their own and return the pieces."""
        saved = self.tokens, self.i, self.out, self.separate
        self.tokens, self.i, self.out, self.separate = saved[0][:last], first, [], False
        try:
            self.sequence()
            return self.out
        finally:
            self.tokens, self.i, _, self.separate = saved[0], saved[1], None, saved[3]
            self.out = saved[2]

    @staticmethod
    def flat(pieces: list[tuple[str, int, int]]) -> str:
        return "".join(p[0] for p in pieces)

    def span_of(self, first: int, last: int) -> tuple[int, int]:
        if first >= last:
            at = self.tokens[first][1] if first < len(self.tokens) else self.end()
            return at, at
        return self.tokens[first][1], self.tokens[last - 1][2]

    def group(self, pieces: list[tuple[str, int, int]], start: int, end: int) -> None:
        """Emit pieces in round brackets, unless they are one number or one letter (with its
        subscript): `\\frac{mg}{2l}` is (mg)/(2l), never mg/2l."""
        text = self.flat(pieces).strip()
        if _ATOM.match(text):
            for p in pieces:
                self.emit(*p)
            return
        self.emit("(", start, start + 1)
        for p in pieces:
            self.out.append(p)
        self.emit(")", end - 1, end)

    # --- translation -----------------------------------------------------------------------------
    def sequence(self) -> None:
        while self.i < len(self.tokens):
            self.item()

    def item(self) -> None:
        text, start, end = self.tokens[self.i]
        self.i += 1
        if text.startswith("\\"):
            self.command(text[1:], start, end)
        elif text == "{":
            close = self.matching(self.i - 1)
            pieces = self.sub(self.i, close)
            self.i = close + 1
            if pieces:
                self.emit("(", start, end)
                self.out.extend(pieces)
                self.emit(")", self.tokens[close][1], self.tokens[close][2])
        elif text == "}":
            self.fail("Unmatched '}'.", start, end)
        elif text == "^":
            self.superscript(start, end)
        elif text == "_":
            self.subscript(start, end)
        elif text == "$":
            self.emit(" ", start, end)
        elif text == "e" and not self.keep_e and self.is_exp(start):
            self.exponential(start, end)
        else:
            self.emit(" " if text.isspace() else text, start, end)

    def is_exp(self, start: int) -> bool:
        """A lone e before ^: the exponential (e^{-\\gamma t})."""
        before = self.src.text[start - 1 : start]
        after = self.peek()
        return not (before.isalnum() or before == "_") and after is not None and after[0] == "^"

    def exponential(self, start: int, end: int) -> None:
        self.i += 1  # the '^'
        first, last = self.argument("exp", start)
        pieces = self.sub(first, last)
        self.word("exp", start, end)
        self.separate = False
        a, b = self.span_of(first, last)
        self.emit("(", a, a)
        self.out.extend(pieces)
        self.emit(")", b, b)

    def superscript(self, start: int, end: int) -> None:
        self.emit("^", start, end)
        first, last = self.argument("^", start)
        pieces = self.sub(first, last)
        text = self.flat(pieces).strip()
        a, b = self.span_of(first, last)
        if _INTEGER.match(text) or _NAME.match(text):
            self.out.extend(pieces)
        else:
            self.out.append(("(", a, a))
            self.out.extend(pieces)
            self.out.append((")", b, b))
        self.separate = True

    def subscript(self, start: int, end: int) -> None:
        if self.declared_subscript(start):
            return
        first, last = self.argument("_", start)
        pieces = self.sub(first, last)
        text = self.flat(pieces).replace(" ", "")
        a, b = self.span_of(first, last)
        if not _SUBSCRIPT.match(text):
            self.fail("A subscript may hold only letters and digits, as in x_{M}.", start, b)
        self.out.append(("_" + text, start, b))
        self.separate = True

    def argument_to_spacing(self, name: str, start: int, end: int) -> bool:
        """`\\cos\\theta \\, \\dot{\\theta}`: a function without brackets whose argument a
        spacing command ends is read as that function of what stands before the spacing, by
        LaTeX's own convention (the thin space is how a typesetter ends the argument). Only names,
        Greek letters, dots, subscripts and digits may form that argument; anything else (a
        power, an operator, a bracket) leaves the function to the grammar's rule. Returns whether
        the function was read here."""
        k = self.i
        while k < len(self.tokens) and self.tokens[k][0].isspace():
            k += 1
        power = None
        if k < len(self.tokens) and self.tokens[k][0] == "^":  # \cos^2\theta \, x
            saved = self.i
            self.i = k + 1
            power = self.argument("^", start)
            k, self.i = self.i, saved
            if not _INTEGER.match(self.flat(self.sub(*power)).strip()):
                return False  # the grammar says what sin^-1 or sin^x would mean
        first, depth, letters = k, 0, False
        while k < len(self.tokens):
            text = self.tokens[k][0]
            if depth == 0 and text[1:] in _ENDING_SPACES and text.startswith("\\"):
                break
            if text == "{":
                depth += 1
            elif text == "}":
                depth -= 1
                if depth < 0:
                    return False
            elif depth == 0 and not (
                text.isspace()
                or (len(text) == 1 and text.isascii() and (text.isalnum() or text == "_"))
                or (text.startswith("\\") and (text[1:] in _LETTERS or text[1:] in _DOTS))
            ):
                return False
            letters = letters or not text.isspace()
            k += 1
        if k == len(self.tokens) or depth or not letters:
            return False
        self.word(_WORDS[name], start, end)
        self.separate = False
        if power is not None:
            a, b = self.span_of(*power)
            self.emit("^", a, a)
            self.out.extend(self.sub(*power))
        a, b = self.span_of(first, k)
        pieces = self.sub(first, k)
        self.emit("(", a, a)
        self.out.extend(pieces)
        self.emit(")", b, b)
        self.i = k
        return True

    def declared_subscript(self, start: int) -> bool:
        """An unbraced subscript that spells one of the question's own names with the letters
        before it (`x_dot`, `theta_ddot`, `x_Mdot` where the question declares them): the
        student wrote the name the sheet gives, not x_{d}·o·t, so it is read whole. The longest
        declared name wins; a letter or digit run must follow `_` without a space."""
        before = _NAME.search(self.flat(self.out))  # the name the output ends with
        if before is None or not self.names:
            return False
        run = []
        for text, _a, _b in self.tokens[self.i :]:
            if len(text) != 1 or not (text.isalnum() or text == "_") or not text.isascii():
                break
            run.append(text)
        stem = before.group()
        for k in range(len(run), 1, -1):
            suffix = "".join(run[:k])
            # in LaTeX `mx_dot` is m·x_dot: the name may start at any letter of the stem
            if any(stem[s:] + "_" + suffix in self.names for s in range(len(stem))):
                end = self.tokens[self.i + k - 1][2]
                self.i += k
                self.out.append(("_" + suffix, start, end))
                self.separate = True
                return True
        return False

    def command(self, name: str, start: int, end: int) -> None:
        if name in _FUNCTIONS and self.argument_to_spacing(name, start, end):
            return
        if name in _WORDS:
            self.word(_WORDS[name], start, end)
        elif name in _TIMES:
            self.emit("*", start, end)
        elif name in _SPACES:
            self.emit(" ", start, end)
        elif name in _FRACS:
            self.fraction(name, start, end)
        elif name in _DOTS:
            self.dot(name, start, end)
        elif name == "sqrt":
            self.root(start, end)
        elif name in ("left", "right"):
            self.delimiter(name, start, end)
        elif name == "partial":
            self.fail(
                "Partial derivatives are not supported; write the expression itself, "
                "with \\dot{x} for a velocity.",
                start,
                end,
            )
        elif name in ("{", "}"):
            self.fail("Use round brackets ( ) only.", start, end)
        elif name == "\\":
            self.fail("Write one equation per line.", start, end)
        else:
            self.fail(f"Unknown LaTeX command '\\{name}'.", start, end)

    def fraction(self, name: str, start: int, end: int) -> None:
        n_first, n_last = self.argument(name, start)
        d_first, d_last = self.argument(name, start)
        numerator = self.sub(n_first, n_last)
        denominator = self.sub(d_first, d_last)
        top, bottom = self.flat(numerator).strip(), self.flat(denominator).strip()
        leibniz = _LEIBNIZ_DENOMINATOR.match(bottom)
        operator = _TIME_OPERATOR.get(top.replace(" ", ""))
        if leibniz and operator and (operator == 2) == bool(leibniz.group(1)):
            # \frac{d}{dt}(…): the operator d/dt, applied by the grammar to the bracket after it
            operator_text = "d/dt" if operator == 1 else "d^2/dt^2"
            end = self.span_of(d_first, d_last)[1] + 1
            self.skip_space()
            after = self.peek()
            if after is None or after[0] not in ("(", "\\left"):
                # \frac{d}{dt}\frac{1}{2} m v^2: how far does it reach? Only a bracket says.
                self.fail(
                    "Write what \\frac{d}{dt} differentiates in round brackets, as in "
                    "\\frac{d}{dt}\\left(m r^2 \\dot{\\theta}\\right).",
                    start,
                    end,
                )
            self.word(operator_text, start, end)
            return
        if top.startswith("d") and leibniz:
            what = top[1:].lstrip("^2 ").strip() or "x"
            what = what if _NAME.match(what) else "x"
            what = "\\" + what if what in _GREEK else what
            self.fail(
                f"Leibniz notation is not supported; write \\dot{{{what}}}, diff({what}, t) or "
                f"\\frac{{d}}{{dt}}({what}).",
                start,
                self.span_of(d_first, d_last)[1] + 1,
            )
        a, b = start, self.span_of(d_first, d_last)[1] + 1
        self.emit("(", a, end)
        self.group(numerator, *self.span_of(n_first, n_last))
        self.emit("/", a, end)
        self.group(denominator, *self.span_of(d_first, d_last))
        self.emit(")", b - 1, b)

    def root(self, start: int, end: int) -> None:
        self.skip_space()
        tok = self.peek()
        index = None
        if tok is not None and tok[0] == "[":
            close = next(
                (k for k in range(self.i, len(self.tokens)) if self.tokens[k][0] == "]"), None
            )
            if close is None:
                self.fail("Missing ']' after \\sqrt[.", tok[1], tok[2])
            assert close is not None
            index = self.sub(self.i + 1, close)
            self.i = close + 1
        first, last = self.argument("sqrt", start)
        radicand = self.sub(first, last)
        a, b = self.span_of(first, last)
        if index is None:
            self.word("sqrt", start, end)
            self.separate = False
            self.emit("(", a, a)
            self.out.extend(radicand)
            self.emit(")", b, b)
        else:
            self.emit("((", start, end)
            self.out.extend(radicand)
            self.emit(")^(1/(", start, end)
            self.out.extend(index)
            self.emit(")))", b, b)

    def dot(self, name: str, start: int, end: int) -> None:
        """\\dot{x}, \\dot x, \\dot{x_M} and \\dot{x}_M: a name followed by the derivative mark.
        \\dot{(…)} over a bracket is the time derivative of what the bracket holds (d/dt(…))."""
        first, last = self.argument(name, start)
        pieces = self.sub(first, last)
        target = self.flat(pieces).replace(" ", "")
        b = self.span_of(first, last)[1]
        if _is_bracketed(target):
            self.word("d/dt" if name == "dot" else "d^2/dt^2", start, end)
            self.out.extend(pieces)
            return
        if not _NAME.match(target):
            self.fail(
                f"\\{name}{{...}} must hold a single coordinate, as in \\{name}{{x}}.", start, b
            )
        self.skip_space()
        tok = self.peek()
        if tok is not None and tok[0] == "_" and "_" not in target:
            self.i += 1
            s_first, s_last = self.argument("_", tok[1])
            subscript = self.flat(self.sub(s_first, s_last)).replace(" ", "")
            if not _SUBSCRIPT.match(subscript):
                self.fail(
                    "A subscript may hold only letters and digits, as in x_{M}.", tok[1], tok[2]
                )
            target += "_" + subscript
            b = self.span_of(s_first, s_last)[1]
        self.word(target + _DOTS[name], start, b)

    def delimiter(self, name: str, start: int, end: int) -> None:
        tok = self.peek()
        if tok is None:
            self.fail(f"'\\{name}' must be followed by a bracket.", start, end)
        assert tok is not None
        self.i += 1
        bracket = tok[0]
        if bracket == ".":
            return
        if bracket in ("\\{", "\\}"):
            bracket = bracket[1]
        elif bracket.startswith("\\"):
            self.fail(f"Unknown LaTeX delimiter '{bracket}'.", tok[1], tok[2])
        self.emit(bracket, start, tok[2])


def _is_bracketed(text: str) -> bool:
    """Whether text is one bracket from its first character to its last: `(a+b)`, not
    `(a)+(b)`."""
    if not (text.startswith("(") and text.endswith(")")):
        return False
    depth = 0
    for k, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth == 0 and k < len(text) - 1:
            return False
    return depth == 0


def translate(src: Source, keep_e: bool = False, names: Container[str] = ()) -> Source:
    """The plain-grammar text of a LaTeX answer. `keep_e`: the question declares a symbol `e`, so
    e^{x} is that symbol to a power rather than the exponential. `names`: every spelling the
    question accepts, so that its own plain names (`x_dot`) read whole in a LaTeX line."""
    translator = _Translator(src, keep_e, names)
    translator.sequence()
    return src.derive(translator.out)
