"""The jinja2 side of generation: the strict template environment (an instructor's folder first,
then the shipped templates) and the filters that make text safe for LaTeX, Markdown and TOML."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path
from typing import Any

import jinja2

from lagrade.errors import AssignmentError
from lagrade.untrusted import visible

_TEX_SPECIALS = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
    "\u00a0": "~",  # a no-break space, as TeX writes one (both engines)
    "\u2212": r"\ensuremath{-}",  # a minus sign (pdflatex's utf8 has no text minus of its own)
}
_MD_SPECIALS = re.compile(r"([\\`*_{}\[\]#!|<>&~$])")
_MD_LINE_START = re.compile(r"^(\s*)([-+=]|\d+(?=[.)]))")


#: TeX's text ligatures: `''` and ``` `` ``` print as curly double quotes, `--` as a dash.
_LIGATURES = re.compile(r"(?<=')(?=')|(?<=`)(?=`)|(?<=-)(?=-)")


def tex_escape(value: Any) -> str:
    """Text made safe for LaTeX: every special character written as a command or escaped, and
    TeX's ligatures broken (`r''` stays two primes, not a closing double quote)."""
    escaped = "".join(_TEX_SPECIALS.get(ch, ch) for ch in str(value))
    return _LIGATURES.sub("{}", escaped)


#: ASCII characters a typewriter font (OT1 cmtt) sets as commands or ligatures in LaTeX, and the
#: slot of its own glyph for each: copied from the PDF, `'` is a straight quote (slot 13, not
#: the curly 39), `_` an underscore (not a drawn rule), `"` a straight double quote. Under
#: LuaLaTeX the font is Unicode and each character is its own code point: where the two differ,
#: the template's `\ttglyph{OT1}{Unicode}` picks by engine (slot 13 there is a carriage return).
_TT_SLOTS = {ch: ord(ch) for ch in '\\{}_^~#$%&"<>|`'} | {"'": 13, "`": 18}


def tt_copy(value: Any) -> str:
    """Text for a typewriter line that a reader copies out of the PDF as it was written: each
    character that LaTeX would turn into another (a curly quote, a rule for `_`) set as the
    font's own glyph, and every space kept (runs of spaces do not collapse)."""
    out = []
    for ch in str(value):
        if ch in _TT_SLOTS and _TT_SLOTS[ch] != ord(ch):
            out.append(f"\\ttglyph{{{_TT_SLOTS[ch]}}}{{{ord(ch)}}}")
        elif ch in _TT_SLOTS:
            out.append(f"{{\\char{_TT_SLOTS[ch]}}}")
        elif ch == " ":
            out.append("\\ ")
        else:
            out.append(tex_escape(ch))
    return "".join(out)


def toml_wrapped(text: str, width: int = 88) -> str:
    """A TOML document (an answer sheet) rewritten so that no line is wider than `width` where
    that can be helped, for a page that must not break a line: a long string becomes a
    multi-line basic string whose lines end in a backslash, which TOML reads as no break at all
    (it drops the newline and the indentation after it). Read back, every value is the same."""
    document = tomllib.loads(text)
    out: list[str] = []
    for table in document:
        out.append(f"[{table}]")
        for key, value in document[table].items():
            out += _toml_entry(key, value, width)
    return "\n".join(out)


def _toml_entry(key: str, value: Any, width: int) -> list[str]:
    if not isinstance(value, str):
        return [f"{key} = {json.dumps(value)}"]
    single = f"{key} = {toml_literal(value)}"
    if "\n" not in value and len(single) <= width:
        return [single]
    lines = [f'{key} = """']
    for item in value.split("\n")[:-1] if value.endswith("\n") else value.split("\n"):
        lines += _continued(_basic(item), width)
    last = lines.pop()
    lines += [last, '"""'] if value.endswith("\n") else [last + '"""']
    return lines


def _basic(text: str) -> str:
    """Text as it stands inside a multi-line basic string: backslashes and quotes escaped."""
    return text.replace("\\", "\\\\").replace('"', '\\"')


def _continued(line: str, width: int) -> list[str]:
    """`line` cut after spaces into pieces of at most `width`, each ending in a backslash
    (TOML's line continuation) but the last; the pieces after the first indented by 2."""
    pieces: list[str] = []
    while len(line) > width:
        cut = _cut(line, width - 1)  # the space stays before the backslash
        if cut <= (1 if pieces else 0):  # no space but the indentation's: cutting there loops
            break
        pieces.append(line[: cut + 1] + "\\")
        line = "  " + line[cut + 1 :]
    return [*pieces, line]


def _cut(line: str, limit: int) -> int:
    """The last space before `limit` outside brackets (between terms), else the last space
    inside them; never one of the line's leading spaces (a continuation's indentation: cutting
    there would leave the line as long as it was)."""
    start = len(line) - len(line.lstrip(" "))
    depth, best, any_space = 0, -1, -1
    for at, ch in enumerate(line[:limit]):
        depth += (ch == "(") - (ch == ")")
        if ch == " " and at > start:
            any_space = at
            best = at if depth == 0 else best
    return best if best > 0 else any_space


def md_escape(value: Any) -> str:
    """Text made inert in Markdown: punctuation backslash-escaped, so `<script>` is shown, not
    run, by any CommonMark renderer; control characters shown as escapes (`visible`)."""
    text = _MD_SPECIALS.sub(r"\\\1", visible(str(value).replace("\n", " ")))
    # a leading "- ", "+ " or "1." would start a list: escape its marker
    return _MD_LINE_START.sub(
        lambda m: (
            m.group(1) + (m.group(2) + "\\" if m.group(2)[0].isdigit() else "\\" + m.group(2))
        ),
        text,
    )


def md_code(value: Any) -> str:
    """A Markdown code span holding `value` verbatim: its fence is one backtick longer than the
    longest run of backticks inside, so no text can close it early (CommonMark's rule), and it
    is padded with a space when the text starts or ends with a backtick. Control characters
    are shown as escapes (`visible`): a code span shows them to a viewer, and `cat` runs them."""
    text = visible(" ".join(str(value).split()))
    runs = re.findall(r"`+", text)
    fence = "`" * (max((len(r) for r in runs), default=0) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


#: What TOML forbids raw in strings and comments: control characters but tab (a line break
#: only ends a comment or a one-line string), and DEL (TOML 1.0, "Comment" and "String").
TOML_FORBIDDEN = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


def toml_string(value: Any) -> str:
    """A TOML basic string (quoted) holding `value`: quotes and backslashes escaped, and every
    character TOML forbids raw written as its `\\uXXXX` escape (a line break `\\u000a`). Never a
    letter escape such as `\\n` or `\\t`: the sheet reader takes a line break or tab from one,
    followed by letters, for LaTeX that the escape ate (`\\nu`, `\\theta`) and restores it."""
    out = []
    for ch in str(value):
        if ch in ('"', "\\"):
            out.append("\\" + ch)
        elif TOML_FORBIDDEN.match(ch):
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def toml_literal(value: str | list[str], multiline: bool = False) -> str:
    """A TOML literal string: `'…'`, or `'''` with one item per line. Literal strings keep
    backslashes as typed, so LaTeX (`\\theta`, `\\frac`) means what it says; in a "…" string
    TOML would read `\\t` as a tab and `\\f` as a form feed. Falls back to a basic string
    (`toml_string`) when the text holds what a literal string cannot: its own quote, or a
    character TOML forbids raw (a control character, DEL; a line break in a one-line string)."""
    items = value if isinstance(value, list) else [value]
    text = "\n".join(str(item) for item in items)
    control = any(TOML_FORBIDDEN.match(ch) and ch != "\n" for ch in text)
    if multiline or len(items) > 1:
        if "'''" not in text and not control and not text.endswith("'"):
            return "'''\n" + text + ("\n" if text else "") + "'''"
        return toml_string(text)
    if "'" in text or "\n" in text or control:
        return toml_string(text)
    return f"'{text}'"


_LEFT = re.compile(r"\\left(\(|\[)")
_RIGHT = re.compile(r"\\right(\)|\])")


def tex_breakable(latex: str) -> str:
    """A formula TeX may break across lines at every sum's `+` and `-`, for the `\\formula` of
    the LaTeX templates (a display too wide for the page is set as a paragraph of math, which
    TeX breaks only at binary operators of its outer list). sympy writes brackets as
    `\\left(` … `\\right)`, which make their content one unbreakable box: a bracket outside
    any `{…}` whose content is a sum becomes `\\bigl(` … `\\bigr)` (`\\biggl` round a
    fraction), which leaves the sum in the outer list. Everything else is kept as it is."""
    out: list[str] = []
    at, depth = 0, 0
    while at < len(latex):
        opened = _LEFT.match(latex, at) if depth == 0 else None
        if opened:
            end = _matching_right(latex, opened.end())
            if end is not None:
                inner = latex[opened.end() : end.start()]
                if _is_sum(inner):
                    size = r"\biggl" if r"\frac" in inner else r"\bigl"
                    out.append(f"{size}{opened.group(1)}{tex_breakable(inner)}")
                    out.append(f"{size[:-1]}r{end.group(1)}")
                else:  # a box anyway: nothing inside could break
                    out.append(latex[at : end.end()])
                at = end.end()
                continue
        ch = latex[at]
        depth += (ch == "{") - (ch == "}") if at == 0 or latex[at - 1] != "\\" else 0
        out.append(ch)
        at += 1
    return "".join(out)


def _matching_right(latex: str, start: int) -> re.Match[str] | None:
    """The `\\right)` that closes the `\\left(` whose content starts at `start`."""
    level, at = 1, start
    while at < len(latex):
        if latex.startswith(r"\left", at):
            level += 1
            at += 5
        elif (closing := _RIGHT.match(latex, at)) or latex.startswith(r"\right", at):
            level -= 1
            if level == 0:
                return closing
            at += 6
        else:
            at += 1
    return None


def _is_sum(inner: str) -> bool:
    """Whether LaTeX from sympy is a sum at its own outer level (a binary ` + ` or ` - `
    outside braces and inner brackets; a leading `- ` is a sign)."""
    depth = 0
    for at, ch in enumerate(inner):
        if inner.startswith(r"\left", at):
            depth += 1
        elif inner.startswith(r"\right", at):
            depth -= 1
        elif ch in "{}" and (at == 0 or inner[at - 1] != "\\"):
            depth += 1 if ch == "{" else -1
        elif depth == 0 and at > 0 and inner[at - 1 : at + 2] in (" + ", " - "):
            return True
    return False


def format_points(value: float) -> str:
    return f"{value:g}"


def count_points(value: float) -> str:
    """`1 point`, `0.5 points`, `3 points`: the number with its noun."""
    return f"{value:g} point" + ("" if value == 1 else "s")


def one_line(value: Any) -> str:
    """Text for a TOML comment (or any one-line slot): line breaks would end the comment and
    TOML forbids control characters in it, so each becomes a space, and runs of space one."""
    return " ".join(TOML_FORBIDDEN.sub(" ", str(value)).split())


def md_block(value: Any) -> str:
    """A fenced Markdown code block holding `value` verbatim, lines and spacing kept (an
    answer line with the caret under it): the fence is longer than any backtick run inside;
    control characters are shown as escapes (`visible`)."""
    text = visible(str(value).rstrip("\n"))
    runs = re.findall(r"`+", text)
    fence = "`" * max(3, max((len(r) for r in runs), default=0) + 1)
    return f"{fence}\n{text}\n{fence}"


def environment(templates_dir: str | Path | None = None) -> jinja2.Environment:
    """The strict jinja2 environment: an instructor's folder first, then the shipped templates."""
    import lagrade.assign.templates as shipped

    loaders: list[jinja2.BaseLoader] = []
    if templates_dir is not None:
        if not Path(templates_dir).is_dir():
            raise AssignmentError(f"templates folder {str(templates_dir)!r} does not exist")
        loaders.append(jinja2.FileSystemLoader(str(templates_dir)))
    loaders.append(jinja2.FileSystemLoader(str(Path(shipped.__file__).parent)))
    env = jinja2.Environment(
        loader=jinja2.ChoiceLoader(loaders),
        undefined=jinja2.StrictUndefined,
        autoescape=jinja2.select_autoescape(
            enabled_extensions=("html.j2", "html"), default_for_string=False, default=False
        ),
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
    )
    env.filters.update(
        tex=tex_escape,
        breakable=tex_breakable,
        ttcopy=tt_copy,
        tomlwrap=toml_wrapped,
        md=md_escape,
        mdcode=md_code,
        toml=toml_string,
        literal=toml_literal,
        points=format_points,
        pointcount=count_points,
        oneline=one_line,
        mdblock=md_block,
    )
    return env
