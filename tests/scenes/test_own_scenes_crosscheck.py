"""The two hand-written scene files derive what independent references give: the parabolic wire
against sympy.physics.mechanics (T from a Particle's velocity in an inertial frame, Lagrange's
equations by LagrangesMethod) and the closed forms of a bead on a spinning wire; the
relativistic particle against the closed forms of special relativity (p = γ m v,
d/dt(γ m v) = −m g ŷ, h = γ m c² + m g y), all written here without lagrade."""

from __future__ import annotations

from pathlib import Path

import sympy as sp

from lagrade.bank.scenefile import read_scene_file
from lagrade.mechanics import lagrange as mech
from tests.bank.crosscheck import lagranges_method_equations

FILES = Path(__file__).parent / "files"


def _zero(expr: sp.Expr) -> bool:
    return sp.simplify(expr) == 0


def test_parabolic_wire_against_lagranges_method():
    variant = read_scene_file(FILES / "parabola.toml").default
    (reference,) = lagranges_method_equations(variant)
    (ours,) = variant.euler_lagrange
    assert _zero(ours - reference)
    assert variant.dof == 1 and variant.cyclic_coordinates == ()


def test_parabolic_wire_closed_forms():
    """T = ½ m (ṙ² (1 + 4a²r²) + ω² r²), V = m g a r²; h = T₂ − T₀ + V is conserved
    (L has no t); small oscillations about r = 0 at ω₀² = 2 g a − ω²."""
    variant = read_scene_file(FILES / "parabola.toml").default
    m, a, g, omega = (variant.parameter_symbols[n] for n in ("m", "a", "g", "omega"))
    (r,) = variant.jets
    T = m * (r.dot**2 * (1 + 4 * a**2 * r.q**2) + omega**2 * r.q**2) / 2
    V = m * g * a * r.q**2
    assert _zero(variant.kinetic_energy - T) and _zero(variant.potential_energy - V)
    h = variant.conserved_quantities["h"]
    expected_h = m * r.dot**2 * (1 + 4 * a**2 * r.q**2) / 2 - m * omega**2 * r.q**2 / 2 + V
    assert _zero(h - expected_h)
    (E,) = variant.euler_lagrange
    linear = sp.diff(E, r.q).subs({r.q: 0, r.dot: 0, r.ddot: 0})
    mass = sp.diff(E, r.ddot).subs({r.q: 0})
    assert _zero(linear / mass - (2 * g * a - omega**2))
    assert _zero(variant.quantities["oscillation_frequency"] ** 2 - (2 * g * a - omega**2))


def test_relativistic_particle_closed_forms():
    variant = read_scene_file(FILES / "relativistic.toml").default
    m, c, g = (variant.parameter_symbols[n] for n in ("m", "c", "g"))
    x, y = variant.jets
    gamma = 1 / sp.sqrt(1 - (x.dot**2 + y.dot**2) / c**2)
    p_x, p_y = variant.generalized_momenta
    assert _zero(p_x - gamma * m * x.dot) and _zero(p_y - gamma * m * y.dot)
    E_x, E_y = variant.euler_lagrange
    assert _zero(E_x - mech.total_derivative(gamma * m * x.dot, variant.jets))
    assert _zero(E_y - (mech.total_derivative(gamma * m * y.dot, variant.jets) + m * g))
    assert variant.cyclic_coordinates == ("x",)
    assert _zero(variant.conserved_quantities["h"] - (gamma * m * c**2 + m * g * y.q))
    # released from rest it falls at g, as in Newton's mechanics
    rest = {x.dot: 0, y.dot: 0}
    accelerations = variant.system.mass_matrix.xreplace(rest).LUsolve(
        variant.system.forcing.xreplace(rest)
    )
    assert list(accelerations) == [0, -g]


def test_relativistic_particle_against_lagranges_method():
    """LagrangesMethod on the same L (an independent Euler-Lagrange derivation)."""
    from sympy.physics import mechanics as me

    variant = read_scene_file(FILES / "relativistic.toml").default
    m, c, g = (variant.parameter_symbols[n] for n in ("m", "c", "g"))
    X, Y = me.dynamicsymbols("x y")
    T_ = me.dynamicsymbols._t
    L = -m * c**2 * sp.sqrt(1 - (X.diff(T_) ** 2 + Y.diff(T_) ** 2) / c**2) - m * g * Y
    equations = me.LagrangesMethod(L, [X, Y]).form_lagranges_equations()
    x, y = variant.jets
    back = [(X.diff(T_, 2), x.ddot), (Y.diff(T_, 2), y.ddot), (X.diff(T_), x.dot)]
    back += [(Y.diff(T_), y.dot), (X, x.q), (Y, y.q)]
    for ours, reference in zip(variant.euler_lagrange, equations, strict=True):
        assert _zero(ours - reference.subs(back))
