"""Hostile roster names are shown, never run or interpreted, in every format."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.assign.templating import (
    md_escape,
    tex_escape,
    toml_literal,
    toml_string,
    toml_wrapped,
)
from lagrade.assign.units import Number

from .conftest import write_roster

HOSTILE = [
    ("h1", "<script>alert(1)</script>"),
    ("h2", '"; rm -rf /'),
    ("h3", "{{7*7}}"),
    ("h4", r"\input{/etc/passwd} & 100% $x$ #1 _a {b} ~c ^d"),
    ("h5", "Robert'); DROP TABLE students;--\nsecond line"),
]


def test_hostile_names(small_assignment: Path, tmp_path: Path) -> None:
    from lagrade.assign import generate

    roster = write_roster(tmp_path / "r.csv", HOSTILE)
    out = tmp_path / "out"
    generate(small_assignment, roster, 5, out, "md,html,tex")
    html = (out / "handouts" / "h1.html").read_text()
    assert "<script>" not in html and "&lt;script&gt;alert(1)&lt;/script&gt;" in html
    assert "&#34;; rm -rf /" in (out / "handouts" / "h2.html").read_text()
    for fmt in ("md", "html", "tex"):
        text = (out / "handouts" / f"h3.{fmt}").read_text()
        assert "49" not in text.split("Problem 1")[0]
    tex = (out / "handouts" / "h4.tex").read_text()
    assert (
        r"\textbackslash{}input\{/etc/passwd\} \& 100\% \$x\$ \#1 \_a \{b\} "
        r"\textasciitilde{}c \textasciicircum{}d" in tex
    )
    md = (out / "handouts" / "h1.md").read_text()
    assert "<script>" not in md
    for sid, name in HOSTILE:
        sheet = tomllib.loads((out / "answer_sheets" / f"{sid}.toml").read_text())
        assert sheet["name"] == name.strip()


def test_filters() -> None:
    assert tex_escape("a_b & c") == r"a\_b \& c"
    assert md_escape("<b>*x*</b>") == r"\<b\>\*x\*\</b\>"
    assert tomllib.loads("v = " + toml_string('a"b\\c\nd\x01'))["v"] == 'a"b\\c\nd\x01'


def test_tex_ligatures_are_broken():
    """Issue 15: `r''` in prose printed as r” (TeX's closing-quote ligature) in the PDF; `--`
    as a dash. Every statement goes through tex_escape, so no scene can bring one back."""
    assert tex_escape("m r'' = -grad V") == "m r'{}' = -grad V"
    assert tex_escape("a--b") == "a-{}-b"
    assert tex_escape("``x") == "`{}`x"
    assert tex_escape("Newton's law") == "Newton's law"  # a lone apostrophe is left alone


def test_handout_values_are_typeset_not_e_notation():
    """Issue 15: SI values printed as 6.42e+23 in every format; now 6.42×10²³ (Markdown),
    6.42×10<sup>23</sup> (HTML), 6.42\\times10^{23} (LaTeX), and the plain text stays what the
    grader reads back."""
    n = Number(6.42e23)
    assert str(n) == "6.42e+23"
    assert n.text == "6.42×10²³"
    assert str(n.html) == "6.42×10<sup>23</sup>"
    assert n.tex == "6.42\\times10^{23}"
    small = Number(6.674e-11)
    assert small.text == "6.674×10⁻¹¹" and "<sup>−11</sup>" in str(small.html)
    assert Number(9.81).tex == Number(9.81).text == "9.81"


@settings(max_examples=300, deadline=None)
@given(
    st.lists(
        st.text(st.characters(codec="utf-8", exclude_categories=("Cs", "Cc")), max_size=300),
        min_size=1,
        max_size=4,
    ),
    st.integers(min_value=20, max_value=100),
)
def test_a_wrapped_sheet_reads_back_the_same(values, width):
    """The PDF key's sheet (`tomlwrap`): long strings written with TOML's line continuations
    read back exactly, whatever they hold (quotes, backslashes, spaces at a cut)."""
    sheet = "[problem1]\n" + "\n".join(
        f"{key} = {toml_literal(value, multiline=True)}"
        for key, value in zip(("a", "b", "c", "d"), values, strict=False)
    )
    wrapped = toml_wrapped(sheet, width)
    assert tomllib.loads(wrapped) == tomllib.loads(sheet)


def test_a_formula_s_outer_brackets_round_a_sum_let_tex_break_inside() -> None:
    """sympy's `\\left( … \\right)` is one box TeX cannot break; round a sum outside any braces
    it becomes `\\bigl( … \\bigr)` (`\\biggl` round a fraction) so the key's long L can wrap. A
    function's argument (inside braces) and a bracket round a product are kept."""
    from lagrade.assign.templating import tex_breakable

    assert tex_breakable(
        r"- g \left(l_{1} \cos{\left(\theta_{1} - \theta_{2} \right)} + l_{2}\right)"
        r" + \left(\frac{a}{b} - c\right)^{2} + \left(x y\right)^{2}"
    ) == (
        r"- g \bigl(l_{1} \cos{\left(\theta_{1} - \theta_{2} \right)} + l_{2}\bigr)"
        r" + \biggl(\frac{a}{b} - c\biggr)^{2} + \left(x y\right)^{2}"
    )
    assert tex_breakable(r"\left(- x\right) + \left(a \left(b + c\right)\right)") == (
        r"\left(- x\right) + \left(a \left(b + c\right)\right)"
    )


#: A scene file an instructor pasted HTML into: a unit, a parameter's description, a title and
#: a quantity's unit and description (text that passes `scene check`: no control characters).
HOSTILE_SCENE = """\
title = "Pendulum <img src=x onerror=alert(1)>"
statement = "A bob of mass m on a rod of length l. Use {theta}."
coordinates = ["theta"]
potential = "gravity"
constraints = ["x_bob^2 + y_bob^2 - l^2"]

[parameters]
m = { domain = "positive", unit = "<img src=x onerror=alert(2)>", values = [1.0] }
l = { domain = "positive", unit = "m", values = [1.0], description = "<b>|length|</b> *of* it" }
g = { domain = "positive", unit = "m/s^2", values = [9.81] }

[bodies.bob]
mass = "m"
position = ["l sin(theta)", "-l cos(theta)"]

[quantities.w]
description = "frequency <script>alert(3)</script>"
value = "sqrt(g/l)"
unit = "<img src=y onerror=alert(4)>"
"""


def test_a_scene_file_s_texts_are_escaped_in_every_format(tmp_path: Path) -> None:
    """Every text of an instructor's scene file is shown, never run, in each output: the
    Markdown handout (pasted into an LMS page, where raw HTML would run) and key, the HTML, the
    LaTeX and the answer sheet's comments."""
    from lagrade.assign import generate

    (tmp_path / "pendulum.toml").write_text(HOSTILE_SCENE)
    (tmp_path / "a.toml").write_text(
        'title = "PS"\n\n[[problems]]\nscene = "pendulum.toml"\n'
        'parts = ["lagrangian", { quantity = "w" }]\n'
    )
    roster = write_roster(tmp_path / "r.csv", [("s1", "Ada")])
    out = tmp_path / "out"
    generate(tmp_path / "a.toml", roster, 3, out, "md,html,tex", verify=None)
    texts = {
        path.relative_to(out): path.read_text(encoding="utf-8")
        for folder in ("handouts", "keys", "answer_sheets")
        for path in (out / folder).iterdir()
    }
    for name, text in texts.items():
        if name.suffix == ".toml":  # a comment of a plain-text file: shown as it is, inert
            continue
        # Markdown shows `\<` as a character; anything else would start a tag
        assert not re.search(r"(?<!\\)<(img|script|b)\b", text), name
    md = texts[Path("handouts/s1.md")]
    assert r"\<img src=x onerror=alert(2)\>" in md and r"\<img src=y onerror=alert(4)\>" in md
    assert "&lt;img src=x onerror=alert(2)&gt;" in texts[Path("handouts/s1.html")]
    assert r"\textless{}img src=x onerror=alert(2)\textgreater{}" in texts[Path("handouts/s1.tex")]
    sheet = tomllib.loads(texts[Path("answer_sheets/s1.toml")])
    assert set(sheet) >= {"problem1"}
