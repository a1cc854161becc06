"""Properties of the scene-file reader: whatever text it is given — junk, TOML of any shape under
the scene's own keys, a bank scene with its expressions replaced by arbitrary text — it returns
a Scene or raises one SceneFileError, quickly; never another exception."""

from __future__ import annotations

import json
import re
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.bank.registry import BANK
from lagrade.bank.scenefile import scene_from_text
from lagrade.bank.scenefile.declaration import TOP_KEYS
from lagrade.errors import SceneFileError
from lagrade.mechanics.scene import Scene

pytestmark = pytest.mark.slow
SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])

_text = st.text(st.characters(blacklist_categories=("Cs",)), max_size=40)
_names = st.sampled_from(
    ["m", "l", "g", "theta", "x", "bob", "mass", "position", "t", "pi", "gravity", "x_bob", "a"]
)
_expression = st.lists(
    st.sampled_from(
        ["m", "l", "g", "theta", "theta_dot", "x_bob", "sin(", "cos(", ")", "(", "^", "/", "*",
         "+", "-", " ", "2", "0.5", "pi", "t", "sqrt(", "gravity", "b", "__import__", "'", "{"]
    ),
    max_size=14,
).map("".join)  # fmt: skip
_value = st.recursive(
    st.one_of(
        _expression, _text, st.integers(-10, 10), st.floats(width=32), st.booleans()
    ),
    lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(_names, inner, max_size=4)
    ),
    max_leaves=12,
)  # fmt: skip


def _toml(value) -> str:
    """A TOML inline value (strings as JSON strings, which TOML's basic strings read alike)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value) if value == value and abs(value) != float("inf") else "0"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return "{" + ", ".join(f"{json.dumps(k)} = {_toml(v)}" for k, v in value.items()) + "}"


def _read(text: str):
    start = time.perf_counter()
    try:
        found = scene_from_text(text, "generated")
        assert isinstance(found, Scene)
    except SceneFileError as error:
        assert error.problems and str(error).startswith("scene 'generated' is not a valid")
    assert time.perf_counter() - start < 20


@SETTINGS
@given(_text)
def test_any_text(text):
    _read(text)


@SETTINGS
@given(st.dictionaries(st.sampled_from([*TOP_KEYS, "extra"]), _value, max_size=9))
def test_any_table_under_the_scene_keys(table):
    _read("\n".join(f"{json.dumps(k)} = {_toml(v)}" for k, v in table.items()))


_STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
_BANK = {p.stem: p.read_text() for p in sorted(BANK.glob("*.toml"))}


@SETTINGS
@given(st.sampled_from(sorted(_BANK)), st.data())
def test_a_bank_scene_with_strings_replaced(scene_id, data):
    """Every string of a real scene file is a place an expression may sit: replace a few."""
    text = _BANK[scene_id]
    strings = list(_STRING.finditer(text))
    chosen = data.draw(st.sets(st.integers(0, len(strings) - 1), max_size=3))
    for i in sorted(chosen, reverse=True):
        match = strings[i]
        text = text[: match.start()] + json.dumps(data.draw(_expression)) + text[match.end() :]
    _read(text)
