"""The Markdown handouts and keys read in a Markdown viewer as the HTML ones do in a browser:
rendered by a CommonMark reader (markdown-it-py), every list has the HTML's items, and every
item its lines (a part's prompt, then each list of names on a line of its own); a formula in
prose is one math span, not a name per span with escaped operators between them."""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from lagrade.assign import generate
from lagrade.bank import scene_ids

from .conftest import all_parts, write_assignment, write_roster

markdown_it = pytest.importorskip("markdown_it")


@pytest.fixture(scope="module")
def out(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("markdown")
    assignment = write_assignment(
        folder / "bank.toml", [{"scene": s, "parts": all_parts(s)} for s in scene_ids()]
    )
    roster = write_roster(folder / "roster.csv", [("s001", "Ada Lovelace")])
    generate(assignment, roster, 5, folder / "out", formats=("md", "html"))
    return folder / "out"


def _md_lists(text: str) -> list[tuple[str, list[int]]]:
    """Each list of the rendered Markdown: its kind ("ol", "ul") and each item's line count."""
    tokens = markdown_it.MarkdownIt("commonmark").enable("table").parse(text)
    lists: list[tuple[str, list[int]]] = []
    stack: list[tuple[str, list[int]]] = []
    for token in tokens:
        if token.type in ("ordered_list_open", "bullet_list_open"):
            stack.append(("ol" if token.type.startswith("ordered") else "ul", []))
        elif token.type in ("ordered_list_close", "bullet_list_close"):
            lists.append(stack.pop())
        elif token.type == "list_item_open":
            stack[-1][1].append(0)
        elif token.type == "inline" and stack:
            breaks = sum(1 for c in token.children or [] if c.type == "hardbreak")
            stack[-1][1][-1] += 1 + breaks
    return lists


class _HtmlLists(HTMLParser):
    """The same from the HTML: each <ol>/<ul>, each <li>'s lines (<br> starts one)."""

    def __init__(self) -> None:
        super().__init__()
        self.lists: list[tuple[str, list[int]]] = []
        self.stack: list[tuple[str, list[int]]] = []
        self.in_math = 0

    def handle_starttag(self, tag, attrs):
        if tag == "math":
            self.in_math += 1
        elif tag in ("ol", "ul"):
            self.stack.append((tag, []))
        elif tag == "li":
            self.stack[-1][1].append(1)
        elif tag == "br" and self.stack:
            self.stack[-1][1][-1] += 1

    def handle_endtag(self, tag):
        if tag == "math":
            self.in_math -= 1
        elif tag in ("ol", "ul"):
            self.lists.append(self.stack.pop())


def _html_lists(text: str) -> list[tuple[str, list[int]]]:
    parser = _HtmlLists()
    parser.feed(text)
    return parser.lists


def test_handout_lists_match_the_html(out: Path):
    md = _md_lists((out / "handouts" / "s001.md").read_text(encoding="utf-8"))
    html = _html_lists((out / "handouts" / "s001.html").read_text(encoding="utf-8"))
    assert len(md) == len(scene_ids())  # one list of parts per problem
    assert md == html


def test_key_lists_match_the_html(out: Path):
    """The key's constraint bullets: one item each (the Markdown key lists no parts)."""
    md = _md_lists((out / "keys" / "s001.md").read_text(encoding="utf-8"))
    html = [k for k in _html_lists((out / "keys" / "s001.html").read_text(encoding="utf-8"))]
    assert md == [k for k in html if k[0] == "ul"]
    assert sum(len(items) for _, items in md) > len(scene_ids())  # most scenes have several


def test_no_part_runs_into_the_next(out: Path):
    text = (out / "handouts" / "s001.md").read_text(encoding="utf-8")
    html = markdown_it.MarkdownIt("commonmark").enable("table").render(text)
    for item in re.findall(r"<li>(.*?)</li>", html, flags=re.S):
        assert item.count("pt") >= 1 and len(re.findall(r"\(\d+(?:\.\d+)? pts?,", item)) == 1
        assert item.count("May use:") <= 1 and not re.search(r"[^>\n]\s*May use:", item), item


#: Two math spans with only spaces and an operator between them (or nothing but spaces): one
#: formula in pieces (`$\omega^{2}$ $R$ \> $g$`). A bracket alone is prose: `$z$ ($z$ up)`.
_PIECES = re.compile(r"\$[^$\n]+\$(?: *\\?[+\-*/=<>^] *\(?| +)\$[^$\n]+\$")


@pytest.mark.parametrize("kind", ["handouts", "keys"])
def test_a_formula_in_prose_is_one_math_span(out: Path, kind: str):
    text = (out / kind / "s001.md").read_text(encoding="utf-8")
    prose = [ln for ln in text.splitlines() if not ln.startswith(("$$", "|", "```"))]
    pieces = [m.group() for ln in prose for m in _PIECES.finditer(ln)]
    # a list of names ($x$, $y$) is prose, not a formula; what is left must be none
    pieces = [p for p in pieces if not re.fullmatch(r"(\$[^$]+\$,? ?)+", p)]
    assert pieces == [], pieces[:5]
    assert "\\+" not in text and "\\>" not in text  # escaped operators between math spans


def test_tex_name_lists_start_their_own_line(tmp_path):
    """In the PDF too, each list of names after a prompt is a paragraph of its own (a single
    newline in TeX would run it into the prompt, as "…L = T − V. May use: …")."""
    assignment = write_assignment(
        tmp_path / "a.toml", [{"scene": "wedge", "parts": all_parts("wedge")}]
    )
    roster = write_roster(tmp_path / "r.csv", [("s001", "Ada Lovelace")])
    generate(assignment, roster, 5, tmp_path / "out", formats=("tex",))
    tex = (tmp_path / "out" / "handouts" / "s001.tex").read_text(encoding="utf-8")
    groups = re.findall(r"(.*)\n?(\{\\small (?:May use|Left-hand sides|Coordinate names):)", tex)
    assert groups and all(before.endswith("\\par") or before == "" for before, _ in groups), groups
