"""Student text → tokens: Unicode normalisation, position bookkeeping and the tokenizer.

Every later stage (LaTeX translation, parsing) works on a rewritten text; `Source` remembers,
for each rewritten character, which characters of the student's original text it came from, so
that every error points at what the student actually typed. `Source.fail` is the one place that
builds a `ParseError`.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable
from typing import NamedTuple, NoReturn

from lagrade.errors import ParseError

#: Combining dot and diaeresis: the lexer reads them as "velocity of" and "acceleration of".
DOT_MARK = "\u0307"
DDOT_MARK = "\u0308"


class Source:
    """Text being read, and for each of its characters the span in the original answer."""

    __slots__ = ("original", "text", "offset", "stop", "starts", "ends", "notes")

    def __init__(
        self,
        original: str,
        text: str,
        offset: int = 0,
        stop: int | None = None,
        starts: list[int] | None = None,
        ends: list[int] | None = None,
    ):
        self.original = original
        self.text = text
        self.offset = offset  # used only while the text is an untouched slice of the original
        self.stop = offset + len(text) if stop is None else stop
        self.starts = starts
        self.ends = ends
        self.notes: tuple[str, ...] = ()  # how a rewriting read the text (2¾), for warnings

    def locate(self, start: int, end: int) -> tuple[int, int]:
        """Span (start, end) of this text → span in the original answer."""
        n = len(self.text)
        if self.starts is None:
            start, end = min(start, n), min(max(start, end), n)
            return self.offset + start, self.offset + end
        assert self.ends is not None
        if start >= n:
            return self.stop, self.stop
        s = self.starts[start]
        e = self.ends[min(end, n) - 1] if end > start else s
        return s, max(s, e)

    def fail(
        self,
        message: str,
        start: int,
        end: int,
        hint: str | None = None,
        readings: tuple[tuple[str, str], ...] = (),
    ) -> NoReturn:
        """Raise the ParseError for characters start…end of this text (`readings`: this text
        under each reading of an ambiguity)."""
        raise ParseError(message, self.locate(start, end), self.original, hint, readings)

    def fail_at_original(self, message: str, start: int, end: int) -> NoReturn:
        raise ParseError(message, (start, end), self.original)

    def derive(self, pieces: Iterable[tuple[str, int, int]]) -> Source:
        """A rewritten text made of `pieces` (text, start, end): each piece replaces characters
        start…end of this text."""
        texts: list[str] = []
        starts: list[int] = []
        ends: list[int] = []
        # An untouched slice (normalise's usual source) maps a span by its offset: no `locate`
        # per piece, of which normalise writes one per character.
        n = len(self.text) if self.starts is None else -1
        offset = self.offset
        for piece, start, end in pieces:
            if not piece:
                continue
            if start <= end <= n:
                s, e = offset + start, offset + end
            else:
                s, e = self.locate(start, end)
            texts.append(piece)
            if len(piece) == 1:
                starts.append(s)
                ends.append(e)
            else:
                starts.extend([s] * len(piece))
                ends.extend([e] * len(piece))
        derived = Source(self.original, "".join(texts), stop=self.stop, starts=starts, ends=ends)
        derived.notes = self.notes
        return derived


# --- Unicode normalisation -----------------------------------------------------------------------

_ASCII_CONTROL = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]")
_CONTROLS = frozenset(chr(c) for c in range(128) if _ASCII_CONTROL.match(chr(c)))

# Letters that look exactly like Latin ones: a student (or a paste) could hide a different symbol.
_LOOKALIKES = frozenset("οΟΑΒΕΖΗΙΚΜΝΡΤΥΧϲϳѕіјԁһ")
# Characters of other categories that render as nothing.
_BLANKS = frozenset("\u034f\u115f\u1160\u17b4\u17b5\u180e\u2800\u3164\uffa0")

_SUPERSCRIPTS = {
    "⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8",
    "⁹": "9", "⁻": "-",
}  # fmt: skip
_FRACTIONS = {
    "½": "(1/2)", "⅓": "(1/3)", "⅔": "(2/3)", "¼": "(1/4)", "¾": "(3/4)", "⅕": "(1/5)",
    "⅙": "(1/6)", "⅛": "(1/8)",
}  # fmt: skip
_OPERATORS = {
    "·": "*", "⋅": "*", "×": "*", "∙": "*", "∗": "*", "−": "-", "–": "-", "—": "-", "÷": "/",
    "′": "'", "’": "'", "≠": "!=", "≤": "<=", "≥": ">=", "√": " sqrt ", "∛": " cbrt ",
}  # fmt: skip
GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ζ": "zeta",
    "η": "eta", "θ": "theta", "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu",
    "ξ": "xi", "π": "pi", "ρ": "rho", "σ": "sigma", "ς": "sigma", "τ": "tau", "υ": "upsilon",
    "φ": "phi", "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi",
    "Σ": "Sigma", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
}  # fmt: skip
#: Letter variants read by their own name before NFKC (which would make ϑ a θ): a question may
#: name its coordinate vartheta (the handout then prints ϑ); where it names only one of theta
#: and vartheta, the lexicon reads either spelling as that one (`vocabulary.GREEK_VARIANTS`).
VARIANT_LETTERS = {"ϑ": "vartheta", "ϱ": "varrho", "ϕ": "phi", "ϵ": "epsilon"}


def _is_hidden(c: str) -> bool:
    """Invisible (format, control, unassigned) or look-alike characters."""
    if c in "\t\n\r":
        return False
    if c in _LOOKALIKES or c in _BLANKS or "\u0400" <= c <= "\u052f" or "\ufe00" <= c <= "\ufe0f":
        return True
    return unicodedata.category(c) in ("Cc", "Cf", "Co", "Cs", "Cn", "Zl", "Zp")


def _hidden_message(c: str, position: int) -> str:
    # Positions in messages count from 1, as a student counts characters.
    return f"Invisible or look-alike character U+{ord(c):04X} at position {position + 1}."


def normalise(src: Source) -> Source:
    """NFKC, then the operator, superscript, fraction and Greek mappings of notation.md; reject
    invisible and look-alike characters. Plain ASCII (the usual case) is returned untouched."""
    text = src.text
    if text.isascii():
        bad = _ASCII_CONTROL.search(text)
        if bad:
            where = src.locate(bad.start(), bad.end())[0]
            src.fail(_hidden_message(bad.group(), where), bad.start(), bad.end())
        return src
    pieces: list[tuple[str, int, int]] = []
    i, n = 0, len(text)
    after_greek = False  # ωt is omega*t: a Greek letter is one symbol, not part of a longer name
    while i < n:
        c = text[i]
        if c < "\x80":
            if c in _CONTROLS:
                src.fail(_hidden_message(c, src.locate(i, i)[0]), i, i + 1)
            if after_greek and c.isalpha():
                pieces.append((" ", i, i))
            after_greek = False
            pieces.append((c, i, i + 1))
            i += 1
            continue
        after_greek = False
        if _is_hidden(c):
            src.fail(_hidden_message(c, src.locate(i, i)[0]), i, i + 1)
        if c in _SUPERSCRIPTS:  # before NFKC, which would turn x² into x2
            j = i
            while j < n and text[j] in _SUPERSCRIPTS:
                j += 1
            pieces.append(("^" + "".join(_SUPERSCRIPTS[x] for x in text[i:j]), i, j))
            i = j
            continue
        if c in _FRACTIONS and _mixed_number(src, pieces, i):
            i += 1
            continue
        if c in _FRACTIONS or c in _OPERATORS:  # before NFKC, which decomposes ≠ and ½
            pieces.append((_FRACTIONS.get(c) or _OPERATORS[c], i, i + 1))
            i += 1
            continue
        previous = pieces[-1][0][-1:] if pieces else ""
        out, j, after_greek = _cluster(src, i, previous)
        pieces.append((out, i, j))
        i = j
    return src.derive(pieces)


def _mixed_number(src: Source, pieces: list[tuple[str, int, int]], i: int) -> bool:
    """2¾ (or 2 ¾) is the mixed number 2 + 3/4, as on paper, never 2·¾: when the fraction sign
    at i follows a whole number, rewrite the two as `(2+3/4)` and note the reading. A decimal
    before it (2.5½) has no such reading and is refused. False when no number comes before."""
    k = len(pieces)
    while k and pieces[k - 1][0] == " ":
        k -= 1
    digits = k
    while digits and pieces[digits - 1][0].isdigit() and len(pieces[digits - 1][0]) == 1:
        digits -= 1
    if digits == k:
        return False
    before = pieces[digits - 1][0][-1:] if digits else ""
    if before == ".":
        first = digits - 1
        while first and (pieces[first - 1][0].isdigit() or pieces[first - 1][0] == "."):
            first -= 1
        src.fail(
            f"A fraction sign right after a decimal number: write {src.text[i]} as a sum "
            "or a product with brackets, as in 2.5 + 1/2 or 2.5*(1/2).",
            pieces[first][1],
            i + 1,
        )
    if before.isalnum() or before == "_":  # the end of a name (m1½ is m1·½)
        return False
    whole = "".join(p[0] for p in pieces[digits:k])
    fraction = _FRACTIONS[src.text[i]][1:-1]
    start = pieces[digits][1]
    del pieces[digits:]
    pieces.append((f"({whole}+{fraction})", start, i + 1))
    typed = src.text[start : i + 1]
    src.notes = (*src.notes, f"{typed} is read as the mixed number {whole} + {fraction}.")
    return True


def _cluster(src: Source, i: int, previous: str) -> tuple[str, int, bool]:
    """The character at i with its combining marks, in plain notation: (text, end, whether it
    held a Greek letter). `previous` is the last character written before it."""
    text, n, c = src.text, len(src.text), src.text[i]
    j = i + 1
    while j < n and unicodedata.combining(text[j]):
        if _is_hidden(text[j]):
            src.fail(_hidden_message(text[j], src.locate(j, j)[0]), j, j + 1)
        j += 1
    out = []
    greek = False
    first = i
    variant = VARIANT_LETTERS.get(c)
    if variant is not None:  # ϑ̇: the variant's name, then its marks
        if previous.isascii() and previous.isalpha():
            out.append(" ")
        out.append(variant)
        greek, first = True, i + 1
    cluster = unicodedata.normalize("NFD", unicodedata.normalize("NFKC", text[first:j]))
    for ch in cluster:
        if ch < "\x80" or ch == DOT_MARK or ch == DDOT_MARK:
            out.append(ch)
        elif ch in GREEK:
            before = out[-1][-1:] if out else previous
            if before.isascii() and before.isalpha():
                out.append(" ")
            out.append(GREEK[ch])
            greek = True
        elif ch in _OPERATORS:  # reached through NFKC, e.g. fullwidth forms
            out.append(_OPERATORS[ch])
        elif unicodedata.category(ch) == "Zs":
            out.append(" ")
        else:
            where = src.locate(i, i)[0] + 1
            bad = text[i:j]
            src.fail(f"Unexpected character '{bad}' (U+{ord(c):04X}) at position {where}.", i, j)
    return "".join(out), j, greek


# --- tokens --------------------------------------------------------------------------------------


class Token(NamedTuple):
    """One token. For names, `text` has braces and derivative marks removed; `marks` counts
    time derivatives written as combining dots, `primes` the trailing primes."""

    kind: str  # "num", "name", "op", "end"
    text: str
    start: int
    end: int
    spaced: bool = False  # whitespace right before it
    marks: int = 0
    primes: int = 0


# One match per token with the whitespace before it, in groups: 1 the whitespace, then the token as
# 2 a name, 3 an operator or 4 a number (their first characters tell them apart).
_TOKEN = re.compile(
    r"""
    ([ \t\r\n]*)
    (?:
        ([A-Za-z_](?:[A-Za-z0-9\u0307\u0308]|_(?:\{[A-Za-z0-9_\u0307\u0308]*\})?)*'*)
      | (\*\*|==|<=|>=|!=|[-+*/^=(),<>;|])
      | ((?:[0-9]+(?:\.[0-9]+)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
    )
    """,
    re.VERBOSE,
)
_BLANK = re.compile(r"[ \t\r\n]*")

_EQUATION_OPS = frozenset(("==", "<", ">", "<=", ">=", "!="))

_CHAR_MESSAGES = {
    "[": "Use round brackets ( ) only.",
    "]": "Use round brackets ( ) only.",
    "{": "Use round brackets ( ) only.",
    "}": "Use round brackets ( ) only.",
    "!": "Factorials are not supported.",
    "#": "Unexpected character '#': comments are not part of an answer.",
    ".": "Unexpected '.': write decimals with digits on both sides, as in 0.5.",
    "\\": "Unexpected backslash: LaTeX is read only when the answer is marked as LaTeX.",
    DOT_MARK: "A combining dot must follow a coordinate's name, as in θ̇.",
    DDOT_MARK: "A combining diaeresis must follow a coordinate's name, as in θ̈.",
}

MAX_DIGITS = 30
MAX_DECIMAL_EXPONENT = 100


def tokenize(src: Source) -> list[Token]:
    """The tokens of `src`, ending with an `end` token; lexical errors raise at once.

    The hottest loop of reading an answer, so it reads all the tokens in one `findall` and
    makes them with `tuple.__new__` (no Python-level `Token.__new__`). `findall` passes over
    what no token matches: then the text does not end in whitespace alone after the tokens
    read, and `_refuse` finds the first error, as it does for '=='."""
    text = src.text
    tokens: list[Token] = []
    append = tokens.append
    new = tuple.__new__
    pos = 0
    refused = False
    for blank, name, op, number in _TOKEN.findall(text):
        start = pos + len(blank)
        if name:
            pos = start + len(name)
            if "'" in name or "{" in name or not name.isascii():
                append(_marked_name(name, start, pos, blank != ""))
            else:
                append(new(Token, ("name", name, start, pos, blank != "", 0, 0)))
        elif op:
            pos = start + len(op)
            refused = refused or op in _EQUATION_OPS
            append(new(Token, ("op", op, start, pos, blank != "", 0, 0)))
        else:
            pos = start + len(number)
            append(new(Token, ("num", number, start, pos, blank != "", 0, 0)))
    n = len(text)
    if refused or _BLANK.match(text, pos).end() != n:  # type: ignore[union-attr]
        _refuse(src)
    append(new(Token, ("end", "", n, n, pos < n, 0, 0)))
    return tokens


def _marked_name(word: str, start: int, end: int, spaced: bool) -> Token:
    """A name token written with primes, combining dots or a braced subscript (x_{M}):
    `text` without them, `marks` and `primes` counting the derivatives."""
    primes = len(word) - len(word.rstrip("'"))
    word = word[: len(word) - primes]
    marks = 0
    if DOT_MARK in word or DDOT_MARK in word:
        marks = word.count(DOT_MARK) + 2 * word.count(DDOT_MARK)
        word = word.replace(DOT_MARK, "").replace(DDOT_MARK, "")
    if "{" in word:
        word = word.replace("{", "").replace("}", "")
    return Token("name", word, start, end, spaced, marks, primes)


def _refuse(src: Source) -> NoReturn:
    """The first lexical error of `src`, token by token: a character no token begins with,
    or an equation sign other than '='."""
    text, pos = src.text, 0
    while True:
        pos = _BLANK.match(text, pos).end()  # type: ignore[union-attr]
        m = _TOKEN.match(text, pos)
        if m is None:
            c = text[pos]
            message = _CHAR_MESSAGES.get(c)
            if message is None:
                quote = '"' if c == "'" else "'"
                message = f"Unexpected character {quote}{c}{quote}."
            src.fail(message, pos, pos + 1)
        if m.group(3) in _EQUATION_OPS:
            src.fail("Use a single '=' for an equation.", pos, m.end())
        pos = m.end()


def read_number(token: Token, src: Source) -> tuple[int, int, bool]:
    """A number token's exact value as (numerator, denominator, written_as_integer); decimals and
    scientific notation are exact (6.674e-11 is 6674/10^14). Enforces the size limits."""
    text = token.text
    if len(text) <= MAX_DIGITS and text.isdigit():  # the usual whole number, within the limits
        return int(text), 1, True
    mantissa, _, exponent = text.replace("E", "e").partition("e")
    whole, _, fraction = mantissa.partition(".")
    digits = (whole + fraction).lstrip("0")
    if len(digits) > MAX_DIGITS:
        src.fail(f"Number too long: at most {MAX_DIGITS} digits.", token.start, token.end)
    shift = 0
    if exponent:
        if len(exponent.lstrip("+-").lstrip("0")) > 3 or abs(int(exponent)) > MAX_DECIMAL_EXPONENT:
            src.fail(
                f"Exponent of a number too large: at most e±{MAX_DECIMAL_EXPONENT}.",
                token.start,
                token.end,
            )
        shift = int(exponent)
    p = int(whole + fraction) if whole + fraction else 0
    shift -= len(fraction)
    q = 1
    if shift >= 0:
        p *= 10**shift
    else:
        q = 10**-shift
    return p, q, not fraction and not exponent and "." not in text
