"""Bytes nobody vetted, read one way everywhere: request lines, answer sheets, rosters,
manifests, assignment files. Sits under every layer, like `errors`.

The rules, each in one place:
- records are split on b"\\n" only (U+2028, U+0085 or a form feed inside a JSON string are
  text, not line ends, so one request line is always one result line);
- text must be UTF-8 and hold no lone surrogate (an escaped "\\ud800" in JSON is one), because
  every string read may reach an output file, which must stay valid UTF-8;
- nesting and integers are bounded before or while parsing, so a hostile record costs
  microseconds and yields a clear reason instead of a RecursionError or Python's 4,300-digit
  ValueError; nesting however it is spelled (brackets, inline tables, TOML's table headers and
  dotted keys), on the text before parsing and on the parsed structure after;
- names that become file names (student ids) use one documented safe alphabet;
- text echoed back (a parser's reading, feedback) is clipped to a bounded size;
- text for a terminal, a log or a Markdown report shows its control characters as escapes.
Each failure raises UnreadableInput with a sentence a person can act on; callers turn it into
the record's `invalid` verdict or their own error.
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from collections.abc import Iterable, Iterator
from typing import Any

from lagrade.errors import UnreadableInput

#: Deepest nesting of arrays and objects (tables) in a record; real ones use three or four.
MAX_NESTING = 64
#: Longest integer in a record, in digits (seeds and ids use a handful).
MAX_INT_DIGITS = 100
#: Longest echo of a reader's text kept in a result (characters per string).
MAX_ECHO = 2_000
#: Most items of a list kept in a result (feedback sentences, echoed equations).
MAX_ITEMS = 100

#: A student id or other name that becomes part of a file name: letters, digits and . _ @ + -,
#: starting with a letter or digit, at most 128 characters (so never '..', '/', or a dotfile).
SAFE_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9._@+-]{0,127}")
SAFE_NAME_RULE = (
    "letters, digits and . _ @ + - (starting with a letter or digit, at most 128 characters)"
)

_SURROGATE = re.compile("[\ud800-\udfff]")


def split_records(stream: Iterable[bytes]) -> Iterator[tuple[int, bytes]]:
    """(line number, record) for every line of a binary stream (an open file, or a list of
    bytes lines), split on b"\n" only; a trailing b"\r" is dropped (files saved on Windows)."""
    for number, line in enumerate(stream, 1):
        yield number, line.removesuffix(b"\n").removesuffix(b"\r")


def decode(data: bytes, what: str = "the text") -> str:
    """UTF-8 text (a byte-order mark tolerated), or UnreadableInput naming the first bad byte."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise UnreadableInput(
            f"{what} is not UTF-8 text (byte 0x{data[error.start]:02x} at position "
            f"{error.start}); save it as UTF-8"
        ) from None


def is_safe_name(name: object) -> bool:
    """True when `name` may become (part of) a file name: see SAFE_NAME."""
    return isinstance(name, str) and SAFE_NAME.fullmatch(name) is not None


def unsafe_name_reason(name: object, what: str = "the id") -> str | None:
    """Why `name` cannot name a file, or None when it can."""
    if is_safe_name(name):
        return None
    return f"{what} {clip(str(name), 80)!r} cannot name a file; use {SAFE_NAME_RULE}"


def load_json(text: str, what: str = "the record") -> Any:
    """json.loads with bounds: nesting at most MAX_NESTING, integers at most MAX_INT_DIGITS
    digits, no NaN or Infinity (not JSON), no lone surrogate in any string or key."""
    _check_nesting(text, what, toml=False)
    try:
        value = json.loads(
            text,
            parse_int=_bounded_int(what),
            parse_float=_bounded_float(what),
            parse_constant=_no_constant(what),
        )
    except json.JSONDecodeError as error:
        raise UnreadableInput(
            f"{what} is not valid JSON: {error.msg} (line {error.lineno}, column {error.colno})"
        ) from None
    except RecursionError:  # the scan above is loose about quotes; this is its backstop
        raise UnreadableInput(f"{what} nests brackets too deep") from None
    _check_depth(value, what)
    _check_strings(value, what)
    return value


def load_toml(text: str, what: str = "the file") -> dict[str, Any]:
    """tomllib.loads with the same bounds as load_json, however the nesting is spelled: brackets,
    inline tables, table headers or dotted keys (`a.a.a = 1` nests without a bracket, and
    tomllib's time and memory grow with the square of a dotted key's length). TOML itself has
    no lone surrogates: tomllib refuses the escape."""
    _check_nesting(text, what, toml=True)
    try:
        value = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise UnreadableInput(f"{what} is not valid TOML: {error}") from None
    except RecursionError:
        raise UnreadableInput(f"{what} nests brackets too deep") from None
    except ValueError:  # an integer past Python's 4,300-digit limit
        raise UnreadableInput(
            f"{what} holds a number with more than {MAX_INT_DIGITS} digits"
        ) from None
    _check_depth(value, what)
    _check_numbers(value, what)
    return value


#: What a terminal or a viewer acts on instead of showing: C0 controls but tab and line break
#: (a carriage return overwrites a line), DEL, C1 controls (ESC and CSI start the escape
#: sequences that clear a screen or move the cursor), and the bidirectional overrides and
#: isolates that show text in another order than it is stored (`exe.pdf` for `fdp.exe`).
_INVISIBLE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def visible(text: str) -> str:
    """`text` for a terminal, a log or a Markdown report: every character in _INVISIBLE written
    as its Python escape (`\\x1b`, `\\r`, `\\u202e`), so it is shown, never acted on; tabs
    and line breaks stay."""
    return _INVISIBLE.sub(_escape, text) if _INVISIBLE.search(text) else text


def _escape(match: re.Match) -> str:
    return repr(match.group())[1:-1]


def encodable(text: str) -> str:
    """`text` with any lone surrogate replaced by U+FFFD, so that it encodes as UTF-8."""
    return _SURROGATE.sub("\ufffd", text) if _SURROGATE.search(text) else text


def clip(text: str, limit: int = MAX_ECHO) -> str:
    """`text` cut to about `limit` characters, saying how much was left out."""
    if len(text) <= limit:
        return text
    return f"{text[:limit]}… ({len(text) - limit} more characters)"


def bounded(text: str, limit: int = MAX_ECHO) -> str:
    """Text that is safe to put in an output: encodable and clipped."""
    return clip(encodable(text), limit)


# --- the bounds -----------------------------------------------------------------------------------


#: The tokens that matter for nesting, in JSON and TOML: strings and comments (skipped whole,
#: so a bracket or dot inside one counts for nothing), brackets, dots between key parts.
_JSON_TOKENS = re.compile(r'"(?:\\.|[^"\\\n])*"?|[\[{]|[\]}]|[^"\[\]{}]+', re.DOTALL)
_TOML_TOKENS = re.compile(
    r"""\#[^\n]*"""
    r"""|'''.*?(?:'''|\Z)|'[^'\n]*'?"""
    r'|"""(?:\\.|[^\\])*?(?:"""|\Z)|"(?:\\.|[^"\\\n])*"?'
    r"""|[\[{]|[\]}]|\.|[A-Za-z0-9_-]+|[ \t]+|[^\#'"\[\]{}.A-Za-z0-9_ \t-]+""",
    re.DOTALL,
)


def _check_nesting(text: str, what: str, toml: bool) -> None:
    """Bound nesting before parsing: 100,000 nested brackets, or a TOML dotted key of 100,000
    parts, must cost a scan, not a RecursionError deep inside a parser or a parse whose cost
    grows with the square of the key. Strings and comments are skipped whole; in TOML a chain
    of key parts joined by dots (`a.b."c"`) counts its parts (a float such as 1.5 is two)."""
    brackets = text.count("[") + text.count("{")
    if brackets <= MAX_NESTING and (not toml or text.count(".") < MAX_NESTING):
        return
    depth, parts, after_dot = 0, 0, False
    for token in (_TOML_TOKENS if toml else _JSON_TOKENS).finditer(text):
        first = token.group()[0]
        if first in "[{":
            depth += 1
            if depth > MAX_NESTING:
                raise _too_deep(what)
        elif first in "]}":
            depth = max(0, depth - 1)
        if not toml or first in " \t#":
            continue
        if first == ".":
            after_dot = True
            continue
        if first.isalnum() or first in "_-'\"":  # a key part: bare or quoted
            parts = parts + 1 if after_dot else 1
            if parts > MAX_NESTING:
                raise _too_deep(what)
        else:
            parts = 0
        after_dot = False


def _check_depth(value: Any, what: str) -> None:
    """The parsed structure nests at most MAX_NESTING deep, checked without recursion (before
    anything recursive walks it): TOML nests by table headers and dotted keys together too."""
    stack = [(value, 1)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, dict):
            children: Iterable[Any] = item.values()
        elif isinstance(item, list):
            children = item
        else:
            continue
        if depth > MAX_NESTING:
            raise _too_deep(what)
        stack.extend((child, depth + 1) for child in children)


def _too_deep(what: str) -> UnreadableInput:
    return UnreadableInput(
        f"{what} nests more than {MAX_NESTING} deep (brackets, tables or dotted keys); no "
        "request or answer sheet needs that"
    )


def _bounded_int(what: str):
    def parse(digits: str) -> int:
        if len(digits.lstrip("-")) > MAX_INT_DIGITS:
            raise UnreadableInput(f"{what} holds a number with more than {MAX_INT_DIGITS} digits")
        return int(digits)

    return parse


def _bounded_float(what: str):
    """A float as JSON writes it, refused when it is past float range (1e400 would come back as
    Infinity, which is not JSON) or longer than any number a record holds."""

    def parse(digits: str) -> float:
        value = float(digits)
        if len(digits) > MAX_INT_DIGITS or not math.isfinite(value):
            raise UnreadableInput(
                f"{what} holds a number past the range of a float ({digits[:20]}…)"
            )
        return value

    return parse


def _no_constant(what: str):
    def parse(name: str) -> Any:
        raise UnreadableInput(f"{what} holds {name}, which is not a JSON number")

    return parse


def _walk(value: Any) -> Iterator[Any]:
    """Every scalar and key of a parsed record (nesting is bounded, so plain recursion is safe)."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield key
            yield from _walk(item)
    elif isinstance(value, list):
        for item in value:
            yield from _walk(item)
    else:
        yield value


def _check_strings(value: Any, what: str) -> None:
    for item in _walk(value):
        if isinstance(item, str) and _SURROGATE.search(item):
            found = _SURROGATE.search(item).group()
            raise UnreadableInput(
                f"{what} holds a lone surrogate (\\u{ord(found):04x}), which is not a character; "
                "it cannot be text in any file"
            )


def _check_numbers(value: Any, what: str) -> None:
    for item in _walk(value):
        if isinstance(item, int) and not isinstance(item, bool) and item.bit_length() > 333:
            raise UnreadableInput(f"{what} holds a number with more than {MAX_INT_DIGITS} digits")
