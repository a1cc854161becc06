"""Issue 24: nesting is bounded however it is spelled. A TOML dotted key `a.a.a…` 3,000 deep nests
without a bracket: it passed the bracket count, and `grade` reported our `error` (a
RecursionError) instead of `invalid`, `generate` printed a traceback and exited 1, the answer
page answered 500. tomllib's own cost also grows with the square of a dotted key (measured:
10,000 parts took 2.2 s and 400 MB, 30,000 parts 19 s and 3.4 GB), so the bound is checked on
the text before parsing, and on the parsed structure (table headers and dotted keys add up)."""

from __future__ import annotations

import time

import pytest

import lagrade.untrusted as untrusted
from lagrade.errors import UnreadableInput
from tests.batch.hostile import run_lagrade
from tests.batch.test_hostile_inputs import assert_only_s1_invalid, grade

DEEP = 3_000


def dotted(n: int, part: str = "a", dot: str = ".") -> str:
    return dot.join([part] * n)


#: Ways TOML nests past the bound, each without a run of brackets a bracket count would see.
SPELLINGS = {
    "dotted key": f"{dotted(DEEP)} = 1\n",
    "quoted dotted key": f"{dotted(DEEP, chr(34) + 'a' + chr(34))} = 1\n",
    "spaced dotted key": f"{dotted(DEEP, 'a', ' . ')} = 1\n",
    "table header": f"[{dotted(DEEP)}]\nx = 1\n",
    "array of tables": f"[[{dotted(DEEP)}]]\nx = 1\n",
    "dotted key in an inline table": f"x = {{ {dotted(DEEP)} = 1 }}\n",
    "inline tables": "x = " + "{a=" * DEEP + "1" + "}" * DEEP + "\n",
    "header, dotted key and inline table together": f"[{dotted(40)}]\n{dotted(40, 'b')} = "
    f"{{ {dotted(40, 'c')} = 1 }}\n",
}


@pytest.mark.parametrize("text", SPELLINGS.values(), ids=SPELLINGS.keys())
def test_every_spelling_of_deep_nesting_is_unreadable_input_at_once(text):
    start = time.perf_counter()
    with pytest.raises(UnreadableInput, match="nests more than 64 deep"):
        untrusted.load_toml(text, "the answer sheet")
    assert time.perf_counter() - start < 1.0  # a scan, not a quadratic parse


def test_a_100000_part_dotted_key_is_refused_before_tomllib_sees_it():
    """tomllib would need gigabytes for this one (its cost grows with the key's square)."""
    with pytest.raises(UnreadableInput):
        untrusted.load_toml(dotted(100_000) + " = 1\n", "the sheet")


@pytest.mark.parametrize(
    "text",
    [
        "v = [" + ", ".join(["1.5"] * 500) + "]\n",  # a float is two key-like parts
        "[problem1]\neom = '''\n" + "." * 500 + "\n" + "[" * 500 + "\n'''\n",  # inside a string
        "# " + "a." * 500 + "\nx = 1\n",  # inside a comment
        f"{dotted(60)} = 1\n",  # deep, but within the bound
    ],
    ids=["floats", "dots and brackets in a string", "dots in a comment", "60 parts"],
)
def test_dots_and_brackets_that_do_not_nest_are_read(text):
    untrusted.load_toml(text, "the file")


def test_json_nesting_is_still_bounded_by_brackets():
    with pytest.raises(UnreadableInput):
        untrusted.load_json("[" * 100 + "]" * 100, "the record")
    assert untrusted.load_json('{"a.b.c": "[[[[.....]"}', "the record") == {"a.b.c": "[[[[.....]"}


@pytest.mark.parametrize("name", ["dotted key", "table header", "dotted key in an inline table"])
def test_a_sheet_nesting_by_dotted_keys_is_invalid_and_the_class_is_graded(classroom, name):
    (classroom / "subs" / "s1.toml").write_text("[problem1]\n" + SPELLINGS[name])
    assert_only_s1_invalid(classroom, grade(classroom))


def test_an_assignment_nesting_by_a_dotted_key_is_one_line_and_exit_2(tmp_path):
    (tmp_path / "a.toml").write_text('title = "x"\n' + SPELLINGS["dotted key"])
    (tmp_path / "roster.csv").write_text("id,name\ns1,A\n")
    proc = run_lagrade(
        "generate", "a.toml", "--roster", "roster.csv", "--seed", "1", "--out", "out",
        cwd=tmp_path,
    )  # fmt: skip
    stderr = proc.stderr.decode()
    assert proc.returncode == 2, stderr
    assert stderr.count("\n") == 1 and stderr.startswith("lagrade: error: "), stderr
    assert "nests more than 64 deep" in stderr
    assert not (tmp_path / "out").exists()
