"""The score table `grade` and `demo` print lines up for every roster: columns are measured in
the columns a terminal gives each character (a CJK character takes two, a combining mark none:
Unicode's East Asian Width, UAX #11), not in Python characters."""

from __future__ import annotations

import unicodedata
from pathlib import Path

from lagrade.cli.grade import summary_table
from lagrade.grading.batch import BatchSummary

#: Names as rosters hold them: Chinese and Japanese (wide), Vietnamese typed decomposed (NFD:
#: a letter and its combining marks), fullwidth Latin, and a plain Latin name.
ROSTER = [
    ("s01", "王小明"),
    ("s02", "佐藤 美咲"),
    ("s03", unicodedata.normalize("NFD", "Đặng Thị Ngọc Hà")),
    ("s04", "ＡＢＣ"),
    ("s05", "Ada Lovelace"),
    ("s06", "欧阳娜娜欧阳娜娜欧阳娜娜欧阳娜娜欧阳娜娜"),  # 40 columns: cut to 28
]


def summary() -> BatchSummary:
    results = [
        {"student": {"id": sid, "name": name}, "status": "graded", "score": 3.5,
         "max_score": 7, "reason": ""}
        for sid, name in ROSTER
    ]  # fmt: skip
    return BatchSummary(Path("."), {"graded": len(results)}, 0, results)


def test_every_row_s_columns_start_at_the_same_terminal_column() -> None:
    rows = summary_table(summary()).splitlines()[1 : 1 + len(ROSTER)]
    wide = {"W", "F"}
    starts = {
        sum(2 if unicodedata.east_asian_width(c) in wide else 0 if unicodedata.combining(c) else 1
            for c in row[: row.index("graded")])
        for row in rows
    }  # fmt: skip
    assert starts == {8 + 1 + 28 + 1}, rows
    assert rows[0] == "s01      王小明" + " " * 22 + " graded        3.5 / 7  "
    # 13 wide characters, …, a space: 28 columns
    assert rows[5].startswith("s06      欧阳娜娜欧阳娜娜欧阳娜娜欧…  graded")


def test_width_counts_wide_as_two_and_combining_marks_as_none() -> None:
    from lagrade.cli.terminal import cell, display_width

    assert display_width("王小明") == 6
    assert display_width(unicodedata.normalize("NFD", "Hà")) == 2
    assert display_width("ＡＢＣ") == 6
    assert cell("王小明", 5) == "王小…"  # never half a wide character
    assert cell("line\nbreak\x1b[2J", 20) == "line break\\x1b[2J   "
