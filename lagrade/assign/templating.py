"""The jinja2 side of generation: the strict template environment (an instructor's folder first,
then the shipped templates) and the filters that make text safe for LaTeX, Markdown and TOML."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import jinja2

from lagrade.errors import AssignmentError

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
}
_MD_SPECIALS = re.compile(r"([\\`*_{}\[\]#!|<>&~$])")
_MD_LINE_START = re.compile(r"^(\s*)([-+=]|\d+(?=[.)]))")


def tex_escape(value: Any) -> str:
    """Text made safe for LaTeX: every special character written as a command or escaped."""
    return "".join(_TEX_SPECIALS.get(ch, ch) for ch in str(value))


def md_escape(value: Any) -> str:
    """Text made inert in Markdown: punctuation backslash-escaped, so `<script>` is shown, not
    run, by any CommonMark renderer."""
    text = _MD_SPECIALS.sub(r"\\\1", str(value).replace("\n", " "))
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
    is padded with a space when the text starts or ends with a backtick."""
    text = " ".join(str(value).split())
    runs = re.findall(r"`+", text)
    fence = "`" * (max((len(r) for r in runs), default=0) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def toml_string(value: Any) -> str:
    """A TOML basic string (quoted) holding `value`."""
    out = []
    for ch in str(value):
        if ch in ('"', "\\"):
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def format_points(value: float) -> str:
    return f"{value:g}"


def one_line(value: Any) -> str:
    """Text for a TOML comment: line breaks would end the comment, so they become spaces."""
    return " ".join(str(value).split())


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
        md=md_escape,
        mdcode=md_code,
        toml=toml_string,
        points=format_points,
        oneline=one_line,
    )
    return env
