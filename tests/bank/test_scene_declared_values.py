"""Scene declarations are sympy expressions or numbers, never text to be parsed."""

import pytest
import sympy as sp

from lagrade.mechanics.bodies import PointMass, as_expr
from lagrade.mechanics.domains import param
from lagrade.mechanics.scene import Scene


def test_numbers_and_expressions_pass_through():
    x = sp.Symbol("x")
    assert as_expr(x + 1) == x + 1
    assert as_expr(0) == sp.Integer(0) and as_expr(0.5) == sp.Float(0.5)


def test_text_in_a_declaration_is_refused_not_evaluated():
    with pytest.raises(TypeError, match="not .__import__"):
        as_expr("__import__('os')")
    scene = Scene(
        id="texty",
        title="t",
        statement="s",
        coordinates=("x",),
        parameters=(param("m"),),
        bodies=lambda s: (PointMass("p", s.m, ("x + 1", 0)),),
        potential=lambda s, b: 0,
    )
    with pytest.raises(TypeError, match="sympy expressions or numbers"):
        _ = scene.default.bodies
