"""A lexicon is built once per what a vocabulary declares, and shared by every vocabulary that
declares the same: the same object, read the same; never across a difference that a reading
could see (an order of names, a label) or across equal symbols that are other objects."""

from __future__ import annotations

import sympy as sp

from lagrade.notation.parse import parse_expression
from lagrade.notation.vocabulary import Lexicon, Vocabulary


def _vocabulary(*names: str, labels: tuple[str, ...] = ()) -> Vocabulary:
    return Vocabulary(("theta",), {n: sp.Symbol(n, positive=True) for n in names}, labels)


def test_equal_vocabularies_share_one_lexicon():
    one, two = _vocabulary("m", "l", "g"), _vocabulary("m", "l", "g")
    assert one is not two
    assert one._lexicon is two._lexicon
    assert (
        parse_expression("m l^2 theta_dot^2/2", one).expr
        == parse_expression("m l^2 theta_dot^2/2", two).expr
    )


def test_what_a_reading_can_see_is_not_shared():
    base = _vocabulary("m", "l", "g")
    assert _vocabulary("g", "l", "m")._lexicon is not base._lexicon  # the order an error lists
    assert _vocabulary("m", "l", "g", labels=("L",))._lexicon is not base._lexicon
    assert _vocabulary("m", "l", "g")._lexicon.allowed == Lexicon(base).allowed


def test_equal_symbols_that_are_other_objects_get_their_own_lexicon():
    shared = _vocabulary("m", "k")._lexicon
    other_m = sp.Symbol.__xnew__(sp.Symbol, "m", positive=True)  # sympy's cache bypassed
    assert other_m == shared.table["m"].value and other_m is not shared.table["m"].value
    fresh = Vocabulary(("theta",), {"m": other_m, "k": sp.Symbol("k", positive=True)})
    assert fresh._lexicon is not shared
    assert fresh._lexicon.table["m"].value is other_m
