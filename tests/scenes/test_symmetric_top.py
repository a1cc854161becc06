"""The heavy symmetric top (examples/scenes/symmetric_top.toml), a rigid body in space turned by
Z-X-Z Euler angles: its T and its equations of motion against sympy.physics.mechanics (a
`RigidBody` oriented with `orient_body_fixed(…, "ZXZ")`, its Lagrange equations from
`LagrangesMethod`), which shares no code with lagrade's derivation; its cyclic coordinates and
conserved momenta against Goldstein's closed forms (Classical Mechanics, 3rd ed., §5.7:
p_ψ = I₃(ψ̇ + φ̇ cos θ), p_φ = (I₁ sin²θ + I₃ cos²θ) φ̇ + I₃ ψ̇ cos θ)."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from sympy.physics import mechanics as me

from lagrade.bank.scenefile import read_scene_file, scene_from_text
from lagrade.errors import SceneFileError

FILE = Path(__file__).resolve().parents[2] / "examples" / "scenes" / "symmetric_top.toml"


@pytest.fixture(scope="module")
def top():
    return read_scene_file(FILE).default


@pytest.fixture(scope="module")
def physics(top):
    """T and the Lagrange equations of the same top, by sympy.physics.mechanics, in lagrade's
    jet symbols."""
    M, g, l, I1, I3 = (top.parameter_symbols[n] for n in ("M", "g", "l", "I_1", "I_3"))
    theta, phi, psi = me.dynamicsymbols("theta phi psi")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    tip = me.Point("tip")
    tip.set_vel(N, 0)
    centre = tip.locatenew("G", l * B.z)
    centre.v2pt_theory(tip, N, B)
    # principal moments about the centre of mass: I_1 about the tip less M l² (Steiner)
    body = me.RigidBody(
        "top", centre, B, M, (me.inertia(B, I1 - M * l**2, I1 - M * l**2, I3), centre)
    )
    body.potential_energy = M * g * centre.pos_from(tip).dot(N.z)
    method = me.LagrangesMethod(me.Lagrangian(N, body), [theta, phi, psi])
    equations = method.form_lagranges_equations()
    t = me.dynamicsymbols._t
    jets = {j.name: j for j in top.jets}
    to_jets = {}
    for q in (theta, phi, psi):
        j = jets[q.func.__name__]
        to_jets |= {q.diff(t, 2): j.ddot, q.diff(t): j.dot, q: j.q}

    def mine(expr):
        return expr.subs(to_jets)  # the derivatives first: `subs` takes them in this order

    return mine(body.kinetic_energy(N)), [mine(e) for e in equations]


def test_the_kinetic_energy_is_the_rigid_bodys(top, physics):
    T, _ = physics
    assert sp.simplify(top.kinetic_energy - T) == 0


def test_the_equations_of_motion_are_lagranges(top, physics):
    _, equations = physics
    for mine, theirs in zip(top.euler_lagrange, equations, strict=True):
        assert sp.simplify(mine - theirs) == 0


def test_phi_and_psi_are_cyclic_and_their_momenta_conserved(top):
    theta, phi, psi = top.jets
    I1, I3 = top.parameter_symbols["I_1"], top.parameter_symbols["I_3"]
    assert set(top.cyclic_coordinates) == {"phi", "psi"}
    conserved = top.conserved_quantities
    p_psi = I3 * (psi.dot + phi.dot * sp.cos(theta.q))
    p_phi = (I1 * sp.sin(theta.q) ** 2 + I3 * sp.cos(theta.q) ** 2) * phi.dot
    p_phi += I3 * psi.dot * sp.cos(theta.q)
    assert sp.simplify(conserved["p_psi"] - p_psi) == 0
    assert sp.simplify(conserved["p_phi"] - p_phi) == 0
    assert "h" in conserved


def test_the_body_brings_its_euler_angles_to_the_transformation(top):
    assert list(top.transformation)[3:] == ["phi_top", "theta_top", "psi_top"]
    assert top.dof == 3


@pytest.mark.parametrize(
    "change, message",
    [
        (('inertia = ["I_1 - M l^2", "I_1 - M l^2", "I_3"]', 'inertia = "I_3"'), "list of 3"),
        (('angles = ["phi", "theta", "psi"]', 'angles = ["phi", "theta"]'), "list of 3"),
    ],
)
def test_a_body_in_space_declares_three_moments_and_three_angles(change, message):
    text = FILE.read_text()
    assert change[0] in text
    with pytest.raises(SceneFileError, match=message):
        scene_from_text(text.replace(*change), "top_broken")


def test_a_spin_measured_the_other_way_is_followed():
    """The student's own coordinates (ψ the other way): T is the body's T on their angles."""
    from lagrade.judge.check import check

    problem = {"scene": "symmetric_top", "scene_text": FILE.read_text()}
    mine = ["x_top = l sin(theta) sin(phi)", "y_top = -l sin(theta) cos(phi)"]
    mine += ["z_top = l cos(theta)", "phi_top = phi", "theta_top = theta", "psi_top = -psi"]
    L = "I_1/2 (theta_dot^2 + phi_dot^2 sin(theta)^2) + I_3/2 (phi_dot cos(theta) - psi_dot)^2"
    L += " - M g l cos(theta)"
    verdict = check(problem, "lagrangian", L, given={"transformation": mine}, time_limit=None)
    assert verdict.status == "correct", verdict.feedback
    assert "Judged in your coordinates" in verdict.feedback[0]
