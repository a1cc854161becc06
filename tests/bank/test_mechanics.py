"""The jet calculus and the Euler–Lagrange machinery, on systems small enough to check by hand."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.mechanics import lagrange as mech

m, g, l, k = sp.symbols("m g l k", positive=True)
theta = mech.jet("theta")
x = mech.jet("x")


def simple_pendulum() -> mech.LagrangianSystem:
    L = sp.Rational(1, 2) * m * l**2 * theta.dot**2 + m * g * l * sp.cos(theta.q)
    return mech.LagrangianSystem(L, [theta])


def test_jet_symbols_are_named_after_the_coordinate():
    assert (str(theta.q), str(theta.dot), str(theta.ddot)) == ("theta", "theta_dot", "theta_ddot")
    assert mech.jet("theta") == theta  # the same sympy objects every time


def test_total_derivative_is_the_chain_rule_on_jets():
    f = x.q**2 * sp.sin(theta.q) + x.dot * mech.t
    expected = (
        2 * x.q * x.dot * sp.sin(theta.q)
        + x.q**2 * sp.cos(theta.q) * theta.dot
        + x.ddot * mech.t
        + x.dot
    )
    assert sp.expand(mech.total_derivative(f, [x, theta]) - expected) == 0


def test_total_derivative_refuses_accelerations():
    with pytest.raises(ValueError, match="third derivative"):
        mech.total_derivative(x.ddot, [x])


def test_simple_pendulum_momentum_equation_and_energy():
    system = simple_pendulum()
    assert system.generalized_momenta == (m * l**2 * theta.dot,)
    assert (
        sp.expand(system.euler_lagrange[0] - (m * l**2 * theta.ddot + m * g * l * sp.sin(theta.q)))
        == 0
    )
    assert system.mass_matrix == sp.Matrix([[m * l**2]])
    assert sp.expand(system.forcing[0] + m * g * l * sp.sin(theta.q)) == 0
    assert sp.simplify(system.accelerations[0] + g / l * sp.sin(theta.q)) == 0
    h = sp.Rational(1, 2) * m * l**2 * theta.dot**2 - m * g * l * sp.cos(theta.q)
    assert sp.expand(system.energy_function - h) == 0
    assert system.cyclic_coordinates == ()
    assert set(system.conserved_quantities) == {"h"}


def test_free_particle_coordinate_is_cyclic_and_its_momentum_conserved():
    system = mech.LagrangianSystem(sp.Rational(1, 2) * m * x.dot**2, [x])
    assert system.cyclic_coordinates == ("x",)
    assert system.conserved_quantities["p_x"] == m * x.dot


def test_explicit_time_dependence_removes_the_energy_function():
    L = sp.Rational(1, 2) * m * x.dot**2 - sp.Rational(1, 2) * k * x.q**2 * sp.cos(mech.t)
    system = mech.LagrangianSystem(L, [x])
    assert not system.is_time_independent
    assert "h" not in system.conserved_quantities


def test_lazy_results_are_not_computed_until_asked():
    system = simple_pendulum()
    _ = system.generalized_momenta
    assert "accelerations" not in system.__dict__ and "mass_matrix" not in system.__dict__


coefficients = st.integers(min_value=-5, max_value=5)


@settings(max_examples=25, deadline=None)
@given(a=coefficients, b=coefficients, c=coefficients)
def test_total_derivative_added_to_L_leaves_the_equations_unchanged(a, b, c):
    """L and L + dF/dt give the same Euler–Lagrange expressions, for F(q, t) of any shape."""
    F = a * x.q**2 * sp.sin(theta.q) + b * mech.t * x.q + c * sp.cos(theta.q) * mech.t**2
    L = simple_pendulum().L + sp.Rational(1, 2) * m * x.dot**2
    plain = mech.euler_lagrange(L, [theta, x])
    gauged = mech.euler_lagrange(L + mech.total_derivative(F, [theta, x]), [theta, x])
    assert all(sp.simplify(p - q) == 0 for p, q in zip(plain, gauged, strict=True))


@settings(max_examples=25, deadline=None)
@given(a=st.integers(1, 9), b=st.integers(1, 9))
def test_euler_lagrange_is_linear_in_accelerations(a, b):
    """E = A q̈ − b exactly, for coupled quadratic kinetic energies."""
    L = (
        sp.Rational(a, 2) * x.dot**2
        + b * x.dot * theta.dot * sp.cos(theta.q)
        + theta.dot**2
        - x.q * sp.sin(theta.q)
    )
    system = mech.LagrangianSystem(L, [x, theta])
    A, f = system.mass_matrix, system.forcing
    qdd = sp.Matrix([x.ddot, theta.ddot])
    rebuilt = A * qdd - f
    assert all(sp.expand(r - e) == 0 for r, e in zip(rebuilt, system.euler_lagrange, strict=True))
