"""The facts of a Lagrangian — which coordinates are cyclic (∂L/∂q_j ≡ 0), whether L has explicit
time (∂L/∂t ≡ 0), and so which quantities are conserved — decided by values
(`lagrade.mechanics.identically_zero`), never by whether a symbol is printed (issue 35).

The identities are sympy's own trigsimp cases (sympy/simplify/tests/test_trigsimp.py:
`test_trigsimp1`, `test_trigsimp_issues`) and Landau & Lifshitz, Mechanics, §2 (a constant
added to L changes no motion)."""

from __future__ import annotations

import sympy as sp

from lagrade.mechanics import LagrangianSystem, identically_zero, jet
from lagrade.mechanics.lagrange import cyclic_coordinates, t
from lagrade.mechanics.vanishing import without_absent

x, y = sp.symbols("x y", real=True)
m, g, l, omega, k = sp.symbols("m g l omega k", positive=True)

#: Identities from sympy's test_trigsimp.py (each side moved to one side of "= 0").
IDENTITIES = [
    sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1,
    1 - sp.sin(x) ** 2 - sp.cos(x) ** 2,
    sp.tan(x) ** 2 + 1 - 1 / sp.cos(x) ** 2,
    sp.sin(x) / sp.cos(x) - sp.tan(x),
    2 * sp.tan(x) * sp.cos(x) ** 2 - sp.sin(2 * x),
    sp.sin(x) * sp.cos(y) + sp.cos(x) * sp.sin(y) - sp.sin(x + y),
    sp.cos(x) * sp.cos(y) - sp.sin(x) * sp.sin(y) - sp.cos(x + y),
    sp.cosh(x) ** 2 - sp.sinh(x) ** 2 - 1,
    sp.sqrt(x**2 * sp.sin(y) ** 2 + x**2 * sp.cos(y) ** 2) - sp.Abs(x),
    sp.sqrt(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1),  # rounding noise under a root shrinks slower
]
#: Near misses: one factor or sign off.
NOT_IDENTITIES = [
    sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1 + sp.Rational(1, 10**12) * x,
    sp.sin(x) ** 2 - sp.cos(x) ** 2 - 1,
    sp.sin(x) * sp.cos(y) - sp.cos(x) * sp.sin(y) - sp.sin(x + y),
    sp.Float("1e-40") * sp.sin(x),
    sp.exp(-50 * x**2),
]


def test_identities_are_zero_and_near_misses_are_not():
    for e in IDENTITIES:
        assert identically_zero(e), e
        assert not e.equals(1) and e != 0  # each one is printed, not structurally 0
    for e in NOT_IDENTITIES:
        assert not identically_zero(e), e


def test_an_identity_in_a_coordinate_leaves_it_cyclic():
    """L = ½ m l² φ̇² − m g l (sin²φ + cos²φ) + k (sin 2φ − 2 sin φ cos φ): φ is printed but
    absent (Landau & Lifshitz §2: the constant m g l changes nothing), so it is cyclic and
    p_φ = m l² φ̇ is conserved, with h. The second identity's derivative is not structurally 0."""
    phi = jet("phi")
    q = phi.q
    L = (
        m * l**2 * phi.dot**2 / 2
        - m * g * l * (sp.sin(q) ** 2 + sp.cos(q) ** 2)
        + k * (sp.sin(2 * q) - 2 * sp.sin(q) * sp.cos(q))
    )
    assert L.has(q) and sp.diff(L, q) != 0
    system = LagrangianSystem(L, [phi])
    assert system.cyclic_coordinates == ("phi",)
    assert cyclic_coordinates(L, [phi]) == ("phi",)
    assert set(system.conserved_quantities) == {"p_phi", "h"}


def test_time_printed_but_absent_keeps_the_energy_function_conserved():
    """A rotating frame's sin²(ωt) + cos²(ωt) leaves L without explicit time."""
    theta = jet("theta")
    L = m * l**2 * theta.dot**2 / 2 + m * g * l * sp.cos(theta.q) * (
        sp.sin(omega * t) ** 2 + sp.cos(omega * t) ** 2
    )
    system = LagrangianSystem(L, [theta])
    assert L.has(t) and system.is_time_independent
    assert set(system.conserved_quantities) == {"h"}
    driven = LagrangianSystem(L + m * g * l * sp.cos(omega * t) * sp.sin(theta.q), [theta])
    assert not driven.is_time_independent and driven.conserved_quantities == {}


def test_a_coordinate_is_written_out_only_where_the_values_agree():
    r, theta = sp.symbols("r theta", real=True)
    V = -g * m / sp.sqrt(r**2 * sp.sin(theta) ** 2 + r**2 * sp.cos(theta) ** 2)
    assert without_absent(V, [theta, r]) == -g * m / sp.Abs(r)
    assert without_absent(m * g * l * (sp.sin(x) ** 2 + sp.cos(x) ** 2), [x]) == m * g * l
    # sign(x) has ∂/∂x = 0 wherever it has a value, but no stand-in equals it: x stays
    assert without_absent(sp.sign(x), [x]) == sp.sign(x)
    assert without_absent(m * sp.sin(x), [x]) == m * sp.sin(x)


def test_ranges_decide_where_the_values_are_taken():
    """sqrt((x − 2)²) + x − 2 vanishes for x < 2 only: inside (0, 1) it is zero, on a range
    that reaches past 2 it is not."""
    e = sp.sqrt((x - 2) ** 2) + x - 2
    assert identically_zero(e, {x: (0.1, 1.0)})
    assert not identically_zero(e, {x: (0.1, 3.0)})
