"""Every scene against what the lecture derives by hand: closed-form EOM, momenta, cyclic
coordinates, and each `quantities` entry checked against the derived equations of motion.

Symbolic checks (`simplify(a - b) == 0`) where the algebra is small; normal-mode frequencies are
checked numerically, as eigenvalues of the linearized motion at the scene's own parameter values.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import sympy as sp

from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.scene import SceneVariant


# --- helpers --------------------------------------------------------------------------------
def variant(scene_id: str, **options: str) -> SceneVariant:
    """The symbolic variant with the canonical names and the given options."""
    return SceneVariant(get_scene(scene_id), options=options)


def option_variants(scene_id: str) -> list[SceneVariant]:
    """One symbolic variant per combination of the scene's options."""
    scene = get_scene(scene_id)
    combos = itertools.product(*scene.options.values())
    return [SceneVariant(scene, options=dict(zip(scene.options, c, strict=True))) for c in combos]


def jets(v: SceneVariant) -> dict[str, mech.Jet]:
    return {j.name: j for j in v.jets}


def state(v: SceneVariant, **values) -> dict[sp.Symbol, sp.Expr]:
    """A state: the named coordinates (`theta=0`) and velocities (`theta_dot=1`) as given, every
    other velocity zero."""
    point: dict[sp.Symbol, sp.Expr] = {j.dot: sp.S.Zero for j in v.jets}
    for j in v.jets:
        if j.name in values:
            point[j.q] = sp.sympify(values[j.name])
        if j.name + mech.DOT in values:
            point[j.dot] = sp.sympify(values[j.name + mech.DOT])
    return point


def accelerations_at(v: SceneVariant, point: dict) -> list[sp.Expr]:
    """q̈ = A⁻¹ b at a (symbolic) state, simplified."""
    A = v.system.mass_matrix.xreplace(point)
    b = v.system.forcing.xreplace(point)
    return [sp.simplify(x) for x in A.LUsolve(b)]


def is_zero(expr: sp.Expr) -> bool:
    return sp.simplify(expr) == 0


def parameter_points(v: SceneVariant, count: int = 3) -> list[dict[sp.Symbol, sp.Expr]]:
    """The scene's own numeric draws (exact rationals), for checks that are numeric."""
    points = []
    for seed in range(count):
        drawn = v.scene.variant(seed).values
        points.append(
            {v.parameter_symbols[n]: sp.nsimplify(x, rational=True) for n, x in drawn.items()}
        )
    return points


def squared_frequencies(v: SceneVariant, equilibrium: dict, params: dict) -> list[float]:
    """ω² of the normal modes about an equilibrium at rest: eigenvalues of A⁻¹K with
    K = −∂b/∂q (at rest, b has no terms linear in q̇ in these scenes), sorted."""
    point = {q: value.xreplace(params) for q, value in equilibrium.items()} | params
    A = np.array(v.system.mass_matrix.xreplace(point).evalf(30).tolist(), dtype=float)
    b = v.system.forcing
    K = sp.Matrix([[-sp.diff(bi, j.q) for j in v.jets] for bi in b])
    K = np.array(K.xreplace(point).evalf(30).tolist(), dtype=float)
    return sorted(np.linalg.eigvals(np.linalg.solve(A, K)).real)


def assert_frequencies(v, equilibrium, expected, params_list=None):
    """The linearized motion at `equilibrium` has the squared frequencies `expected(params)`."""
    for params in params_list or parameter_points(v):
        # An equilibrium: b vanishes at rest there.
        at_rest = {q: value.xreplace(params) for q, value in equilibrium.items()} | params
        for bi in v.system.forcing.xreplace(at_rest):
            assert abs(float(bi)) < 1e-9 * (1 + max(abs(float(x)) for x in params.values()))
        got = squared_frequencies(v, equilibrium, params)
        want = sorted(float(sp.sympify(w).xreplace(params)) for w in expected)
        np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-9 * max(want))


# --- the lecture's eight ------------------------------------------------------------------------
@pytest.mark.parametrize("potential", get_scene("free_particle").options["potential"])
def test_free_particle_recovers_newtons_second_law(potential):
    v = variant("free_particle", potential=potential)
    s = v.namespace
    V = v.potential_energy
    for j, E in zip(v.jets, v.euler_lagrange, strict=True):
        assert is_zero(E - (s.m * j.ddot + sp.diff(V, j.q))), j.name
    assert set(v.conserved_quantities) >= {"h"}


def test_free_particle_in_gravity_conserves_horizontal_momenta():
    v = variant("free_particle", potential="gravity")
    assert v.cyclic_coordinates == ("x", "y")


def test_wedge_acceleration_along_the_incline():
    v = get_scene("wedge").default
    assert is_zero(v.system.accelerations[1] - v.quantities["block_acceleration"])
    assert v.cyclic_coordinates == ("x_M",)


def test_hoop_equilibria():
    v = get_scene("hoop").default
    s = v.namespace
    for theta in (0, sp.pi, v.quantities["equilibrium_angle"]):
        (acc,) = accelerations_at(v, state(v, theta=theta))
        assert is_zero(acc), theta
    # cos θ₀ = g / (ω² R): the closed form the lecture gives.
    assert is_zero(sp.cos(v.quantities["equilibrium_angle"]) - s.g / (s.omega**2 * s.R))


def test_projectile_in_space_has_x_and_y_cyclic():
    v = get_scene("projectile").default
    s = v.namespace
    assert v.cyclic_coordinates == ("x", "y")
    assert v.conserved_quantities["p_x"] == s.m * s.x_dot
    assert v.conserved_quantities["p_y"] == s.m * s.y_dot
    assert is_zero(v.euler_lagrange[2] - s.m * (jets(v)["z"].ddot + s.g))


def test_projectile_in_a_plane_has_x_cyclic():
    v = get_scene("projectile_plane").default
    assert v.cyclic_coordinates == ("x",)
    assert v.conserved_quantities["p_x"] == v.namespace.m * v.namespace.x_dot


def test_kepler_theta_is_cyclic_with_angular_momentum():
    v = get_scene("kepler").default
    s = v.namespace
    assert v.cyclic_coordinates == ("theta",)
    assert is_zero(v.conserved_quantities["p_theta"] - s.m * s.r**2 * s.theta_dot)
    # The radial equation: m r̈ − m r θ̇² + G M m / r² = 0.
    r = jets(v)["r"]
    expected = s.m * r.ddot - s.m * s.r * s.theta_dot**2 + s.G * s.M * s.m / s.r**2
    assert is_zero(v.euler_lagrange[0] - expected)


def test_kepler_cyclic_coordinate_follows_the_rename():
    v = SceneVariant(get_scene("kepler"), names={"r": "rho", "theta": "phi"})
    assert v.cyclic_coordinates == ("phi",)
    assert "p_phi" in v.conserved_quantities


def test_kepler_circular_orbit_angular_velocity():
    v = get_scene("kepler").default
    s = v.namespace
    omega = v.quantities["circular_angular_velocity"]
    acc = accelerations_at(v, state(v, r=s.a, theta=0, theta_dot=omega))
    assert is_zero(acc[0]) and is_zero(acc[1])


def test_wheel_lagrangian_is_half_i_theta_dot_squared():
    v = get_scene("wheel").default
    s = v.namespace
    assert v.lagrangian == s.I * s.theta_dot**2 / 2
    assert v.cyclic_coordinates == ("theta",)
    assert v.conserved_quantities["p_theta"] == s.I * s.theta_dot
    # 6 freedoms of a rigid body − 2 for the axle − 3 for staying in its plane.
    assert v.dof == 1


EXPECTED_GAUGE_CYCLIC = {"landau_y": ("y", "z"), "landau_x": ("x", "z"), "symmetric": ("z",)}


@pytest.mark.parametrize("gauge", sorted(EXPECTED_GAUGE_CYCLIC))
def test_charged_particle_cyclic_coordinates_depend_on_the_gauge(gauge):
    v = variant("charged_particle", gauge=gauge)
    assert v.cyclic_coordinates == EXPECTED_GAUGE_CYCLIC[gauge]


@pytest.mark.parametrize("gauge", sorted(EXPECTED_GAUGE_CYCLIC))
def test_charged_particle_canonical_momentum_is_m_v_plus_e_a(gauge):
    v = variant("charged_particle", gauge=gauge)
    s = v.namespace
    B = s.B
    A = {
        "landau_y": (0, B * s.x, 0),
        "landau_x": (-B * s.y, 0, 0),
        "symmetric": (-B * s.y / 2, B * s.x / 2, 0),
    }[gauge]
    velocity = (s.x_dot, s.y_dot, s.z_dot)
    for p, vel, a in zip(v.generalized_momenta, velocity, A, strict=True):
        assert is_zero(p - (s.m * vel + s.e * a))


def test_charged_particle_landau_gauge_p_y():
    v = variant("charged_particle", gauge="landau_y")
    s = v.namespace
    assert v.conserved_quantities["p_y"] == s.m * s.y_dot + s.e * s.B * s.x


def test_charged_particle_motion_is_gauge_invariant_and_cyclotron():
    """ẍ = ω_c ẏ, ÿ = −ω_c ẋ, z̈ = 0 with ω_c = e B / m, in every gauge."""
    for v in option_variants("charged_particle"):
        s = v.namespace
        omega_c = v.quantities["cyclotron_frequency"]
        acc = v.system.accelerations
        assert is_zero(acc[0] - omega_c * s.y_dot)
        assert is_zero(acc[1] + omega_c * s.x_dot)
        assert acc[2] == 0


@pytest.mark.parametrize("angle_from", ("vertical", "horizontal"))
def test_incline_pendulum_hangs_steadily_while_sliding(angle_from):
    v = variant("incline_pendulum", angle_from=angle_from)
    q = v.quantities
    # Any speed down the incline, the pendulum at its steady angle and at rest relative to it.
    point = state(v, s=sp.Symbol("s0"), phi=q["steady_angle"], s_dot=sp.Symbol("u"))
    s_acc, phi_acc = accelerations_at(v, point)
    assert is_zero(s_acc - q["steady_acceleration"])
    assert is_zero(phi_acc)


def test_incline_pendulum_has_no_cyclic_coordinate():
    assert get_scene("incline_pendulum").default.cyclic_coordinates == ()


# --- pendulums ----------------------------------------------------------------------------------
def test_simple_pendulum_equation_of_motion():
    v = variant("simple_pendulum", angle_from="vertical")
    assert is_zero(v.euler_lagrange[0] - simple_pendulum_eom(v))


def test_simple_pendulum_from_the_horizontal():
    v = variant("simple_pendulum", angle_from="horizontal")
    s, th = v.namespace, jets(v)["theta"]
    expected = s.m * s.l**2 * th.ddot - s.m * s.g * s.l * sp.cos(s.theta)
    assert is_zero(v.euler_lagrange[0] - expected)


@pytest.mark.parametrize("angle_from, bottom", [("vertical", 0), ("horizontal", sp.pi / 2)])
def test_simple_pendulum_small_oscillation_frequency(angle_from, bottom):
    v = variant("simple_pendulum", angle_from=angle_from)
    omega = v.quantities["small_oscillation_frequency"]
    assert_frequencies(v, state(v, theta=bottom), [omega**2])


def test_double_pendulum_normal_modes():
    v = get_scene("double_pendulum").default
    q = v.quantities
    expected = [q["slow_mode_frequency"] ** 2, q["fast_mode_frequency"] ** 2]
    assert_frequencies(v, state(v, theta_1=0, theta_2=0), expected)


def test_double_pendulum_equal_masses_and_lengths_modes():
    """m₁ = m₂, l₁ = l₂: ω² = (2 ∓ √2) g / l, the textbook result."""
    v = get_scene("double_pendulum").default
    s = v.namespace
    equal = {s.m_2: s.m_1, s.l_2: s.l_1}
    for name, sign in (("slow_mode_frequency", -1), ("fast_mode_frequency", 1)):
        got = v.quantities[name].xreplace(equal) ** 2
        assert is_zero(got - (2 + sign * sp.sqrt(2)) * s.g / s.l_1), name


def test_spherical_pendulum_azimuth_is_cyclic_and_conical_motion():
    v = get_scene("spherical_pendulum").default
    s = v.namespace
    assert v.cyclic_coordinates == ("phi",)
    assert is_zero(
        v.conserved_quantities["p_phi"] - s.m * s.l**2 * sp.sin(s.theta) ** 2 * s.phi_dot
    )
    Omega = v.quantities["conical_angular_velocity"]
    acc = accelerations_at(v, state(v, theta=s.beta, phi=0, phi_dot=Omega))
    assert is_zero(acc[0]) and is_zero(acc[1])


@pytest.mark.parametrize("angle_from, bottom", [("vertical", 0), ("horizontal", sp.pi / 2)])
def test_spring_pendulum_equilibrium_and_frequencies(angle_from, bottom):
    v = variant("spring_pendulum", angle_from=angle_from)
    q = v.quantities
    equilibrium = state(v, r=q["equilibrium_length"], theta=bottom)
    assert_frequencies(v, equilibrium, [q["radial_frequency"] ** 2, q["swing_frequency"] ** 2])


@pytest.mark.parametrize("angle_from, bottom", [("vertical", 0), ("horizontal", sp.pi / 2)])
def test_pendulum_on_cart_frequency_and_horizontal_momentum(angle_from, bottom):
    v = variant("pendulum_on_cart", angle_from=angle_from)
    s = v.namespace
    assert v.cyclic_coordinates == ("x",)
    # Total horizontal momentum: (M + m) ẋ + m × (bob's horizontal velocity relative to the cart).
    bob_x = v.bodies[1].position[0] - s.x
    relative = mech.total_derivative(bob_x, v.jets)
    assert is_zero(v.conserved_quantities["p_x"] - ((s.M + s.m) * s.x_dot + s.m * relative))
    omega = v.quantities["small_oscillation_frequency"]
    # The cart's free translation is a zero-frequency mode.
    assert_frequencies(v, state(v, x=0, theta=bottom), [0, omega**2])


def test_driven_pendulum_lagrangian_depends_on_time():
    for v in option_variants("driven_pendulum"):
        assert v.lagrangian.has(mech.t)
        assert not v.system.is_time_independent
        assert "h" not in v.conserved_quantities
        assert v.cyclic_coordinates == ()


def test_driven_pendulum_without_drive_is_the_simple_pendulum():
    v = get_scene("driven_pendulum").default
    s = v.namespace
    undriven = v.euler_lagrange[0].xreplace({s.a: 0})
    assert is_zero(undriven - simple_pendulum_eom(v))


def simple_pendulum_eom(v: SceneVariant) -> sp.Expr:
    s, th = v.namespace, jets(v)["theta"]
    return s.m * s.l**2 * th.ddot + s.m * s.g * s.l * sp.sin(s.theta)


# --- machines and oscillators -------------------------------------------------------------------
@pytest.mark.parametrize("pulley", ("massless", "massive"))
def test_atwood_acceleration(pulley):
    v = variant("atwood", pulley=pulley)
    s = v.namespace
    (acc,) = v.system.accelerations
    assert is_zero(acc - v.quantities["acceleration"])
    inertia_term = 0 if pulley == "massless" else s.M / 2
    assert is_zero(acc - (s.m_1 - s.m_2) * s.g / (s.m_1 + s.m_2 + inertia_term))


@pytest.mark.parametrize("orientation", ("horizontal", "vertical"))
def test_harmonic_oscillator_frequency_is_independent_of_gravity(orientation):
    v = variant("harmonic_oscillator", orientation=orientation)
    s = v.namespace
    rest = 0 if orientation == "horizontal" else s.m * s.g / s.k
    assert_frequencies(v, state(v, x=rest), [v.quantities["angular_frequency"] ** 2])


def test_coupled_oscillators_normal_modes():
    v = get_scene("coupled_oscillators").default
    q = v.quantities
    expected = [q["in_phase_frequency"] ** 2, q["out_of_phase_frequency"] ** 2]
    assert_frequencies(v, state(v, x_1=0, x_2=0), expected)


def test_two_body_spring_centre_of_mass_and_reduced_mass():
    v = get_scene("two_body_spring").default
    s = v.namespace
    assert v.cyclic_coordinates == ("X", "Y", "theta")
    total, mu = s.m_1 + s.m_2, s.m_1 * s.m_2 / (s.m_1 + s.m_2)
    p = v.conserved_quantities
    assert is_zero(p["p_X"] - total * s.X_dot)
    assert is_zero(p["p_theta"] - mu * s.r**2 * s.theta_dot)
    equilibrium = state(v, X=0, Y=0, r=s.l_0, theta=0)
    assert_frequencies(v, equilibrium, [0, 0, 0, v.quantities["radial_frequency"] ** 2])


# --- moving constraints and frames --------------------------------------------------------------
def test_rotating_rod_bead_conserves_h_but_not_energy():
    v = get_scene("rotating_rod_bead").default
    s = v.namespace
    (acc,) = v.system.accelerations
    assert is_zero(acc - v.quantities["growth_rate"] ** 2 * s.r)
    h = v.conserved_quantities["h"]
    assert is_zero(h - (s.m * s.r_dot**2 / 2 - s.m * s.omega**2 * s.r**2 / 2))
    # T + V = T here, and it is not conserved: D_t T ≠ 0 on shell.
    energy = v.kinetic_energy + v.potential_energy
    assert not is_zero(v.system.on_shell(mech.total_derivative(energy, v.jets)))


def test_rotating_frame_has_coriolis_and_centrifugal_terms():
    v = get_scene("rotating_frame").default
    s = v.namespace
    L = v.lagrangian
    assert not L.has(mech.t)
    # Coriolis: m ω (x ẏ − y ẋ); centrifugal: ½ m ω² (x² + y²).
    assert sp.diff(L, s.x, s.y_dot) == s.m * s.omega
    assert sp.diff(L, s.y, s.x_dot) == -s.m * s.omega
    free = s.m * (s.x_dot**2 + s.y_dot**2) / 2
    assert is_zero(
        L
        - free
        - s.m * s.omega * (s.x * s.y_dot - s.y * s.x_dot)
        - s.m * s.omega**2 * (s.x**2 + s.y**2) / 2
    )
    # Coriolis force in the EOM: m ẍ − 2 m ω ẏ − m ω² x = 0.
    x = jets(v)["x"]
    assert is_zero(
        v.euler_lagrange[0] - (s.m * x.ddot - 2 * s.m * s.omega * s.y_dot - s.m * s.omega**2 * s.x)
    )


def test_rotating_frame_conserves_jacobi_h_not_kinetic_energy():
    v = get_scene("rotating_frame").default
    s = v.namespace
    h = v.conserved_quantities["h"]
    assert is_zero(
        h - (s.m * (s.x_dot**2 + s.y_dot**2) / 2 - s.m * s.omega**2 * (s.x**2 + s.y**2) / 2)
    )
    relative_T = s.m * (s.x_dot**2 + s.y_dot**2) / 2
    assert not is_zero(v.system.on_shell(mech.total_derivative(relative_T, v.jets)))
    assert is_zero(v.system.on_shell(mech.total_derivative(h, v.jets)))


def test_cone_particle_azimuth_cyclic_and_circular_orbit():
    v = get_scene("cone_particle").default
    s = v.namespace
    assert v.cyclic_coordinates == ("phi",)
    assert is_zero(v.conserved_quantities["p_phi"] - s.m * s.r**2 * s.phi_dot)
    Omega = v.quantities["circular_angular_velocity"]
    acc = accelerations_at(v, state(v, r=s.r_0, phi=0, phi_dot=Omega))
    assert is_zero(acc[0]) and is_zero(acc[1])


# --- rigid bodies -------------------------------------------------------------------------------
@pytest.mark.parametrize("shape, ratio", [("solid", sp.Rational(1, 2)), ("hollow", 1)])
def test_rolling_cylinder_acceleration(shape, ratio):
    v = variant("rolling_cylinder", shape=shape)
    s = v.namespace
    (acc,) = v.system.accelerations
    assert is_zero(acc - v.quantities["acceleration"])
    # a = g sin α / (1 + I/(m R²))
    assert is_zero(acc - s.g * sp.sin(s.alpha) / (1 + ratio))
    # 6 − 3 (plane) − 1 (contact) − 1 (rolling)
    assert v.dof == 1


@pytest.mark.parametrize("angle_from", ("wall", "floor"))
def test_sliding_ladder_equation_of_motion(angle_from):
    """With θ from the wall: (m l²/3) θ̈ = (m g l/2) sin θ."""
    v = variant("sliding_ladder", angle_from=angle_from)
    s, th = v.namespace, jets(v)["theta"]
    gravity_torque = (
        s.m * s.g * s.l / 2 * (sp.sin(s.theta) if angle_from == "wall" else -sp.cos(s.theta))
    )
    assert is_zero(v.euler_lagrange[0] - (s.m * s.l**2 / 3 * th.ddot - gravity_torque))


# --- every quantity is verified somewhere above -------------------------------------------------
VERIFIED = {
    ("wedge", "block_acceleration"),
    ("hoop", "equilibrium_angle"),
    ("kepler", "circular_angular_velocity"),
    ("charged_particle", "cyclotron_frequency"),
    ("incline_pendulum", "steady_angle"),
    ("incline_pendulum", "steady_acceleration"),
    ("simple_pendulum", "small_oscillation_frequency"),
    ("double_pendulum", "slow_mode_frequency"),
    ("double_pendulum", "fast_mode_frequency"),
    ("spherical_pendulum", "conical_angular_velocity"),
    ("spring_pendulum", "equilibrium_length"),
    ("spring_pendulum", "radial_frequency"),
    ("spring_pendulum", "swing_frequency"),
    ("pendulum_on_cart", "small_oscillation_frequency"),
    ("atwood", "acceleration"),
    ("harmonic_oscillator", "angular_frequency"),
    ("coupled_oscillators", "in_phase_frequency"),
    ("coupled_oscillators", "out_of_phase_frequency"),
    ("two_body_spring", "radial_frequency"),
    ("rotating_rod_bead", "growth_rate"),
    ("cone_particle", "circular_angular_velocity"),
    ("rolling_cylinder", "acceleration"),
}


def test_every_quantity_in_the_bank_has_a_closed_form_check():
    declared = {(sid, q.name) for sid in scene_ids() for q in get_scene(sid).quantities}
    assert declared == VERIFIED
