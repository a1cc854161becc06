"""Coordinate domains and dissipation in scene files: a constraint that holds on the physical
branch is accepted once the coordinate's domain is declared (and refused without it), the shown
T and V are simplified under the domain, the judge's sample points keep to it; a Rayleigh
function and a generalized force enter the equations of motion, and what is conserved follows
the damped motion. Physics checked against closed forms (the damped oscillator's solution, a
driven oscillator's steady state) that lagrade did not derive."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.bank.scenefile import scene_from_text
from lagrade.errors import SceneFileError
from lagrade.judge.check import check
from lagrade.judge.problem import build_problem
from lagrade.mechanics.dissipation import DissipativeSystem
from lagrade.mechanics.lagrange import jet, t

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "scenes"
ATWOOD = (EXAMPLES / "swinging_atwood.toml").read_text()
DAMPED = (EXAMPLES / "damped_oscillator.toml").read_text()

# --- coordinate domains ---------------------------------------------------------------------------


def test_the_square_root_constraint_needs_the_declared_domain():
    undeclared = ATWOOD.replace('domains = { r = "positive" }', "")
    with pytest.raises(SceneFileError, match=r"leaves -r \+ Abs\(r\).*declare their domains"):
        scene_from_text(undeclared, "swinging_atwood")
    scene = scene_from_text(ATWOOD, "swinging_atwood")
    assert scene.default.dof == 2


def test_a_domain_names_a_coordinate_and_reads_as_a_domain():
    for text, message in [
        (ATWOOD.replace('{ r = "positive" }', '{ s = "positive" }'), "domains.s: 's' is not a"),
        (ATWOOD.replace('{ r = "positive" }', '{ r = "upwards" }'), "domains.r: unknown domain"),
    ]:
        with pytest.raises(SceneFileError, match=message):
            scene_from_text(text, "swinging_atwood")


def test_what_is_shown_is_simplified_under_the_domain():
    """A position written with |r| (the rope's length measured as a distance) shows as r."""
    text = ATWOOD.replace('position = ["0", "r - l"]', 'position = ["0", "sqrt(r^2) - l"]')
    variant = scene_from_text(text, "swinging_atwood").default
    r = variant.jets[0].q
    assert not variant.potential_energy.has(sp.Abs) and variant.potential_energy.has(r)
    assert "sqrt" not in str(variant.kinetic_energy)


def test_the_judges_points_stay_in_the_domain():
    problem = build_problem({"scene": "swinging_atwood", "scene_text": ATWOOD, "seed": 2})
    assert problem.coordinate_domains == {"r": (0.5, 3.0)}
    points = problem.points("lagrangian")
    r = problem.jets[0].q
    assert (points.env[r] > 0).all()


def test_a_renamed_coordinate_keeps_its_domain():
    text = ATWOOD.replace('renames = { theta = ["theta", "phi"] }', 'renames = { r = ["r", "s"] }')
    scene = scene_from_text(text, "atwood_renamed")
    names = {scene.variant(seed).names["r"] for seed in range(12)}
    assert names == {"r", "s"}
    for seed in range(12):
        variant = scene.variant(seed)
        assert set(variant.coordinate_domains) == {variant.names["r"]}


RADIAL = """\
title = "Bead on a ring of radius a r"
statement = "Use {{r}} and {{theta}}."
coordinates = ["r", "theta"]
{domain}
constraints = ["k sqrt(x_bead^2 + y_bead^2) - {scale} z_bead"]
potential = "0"

[parameters]
m = {{ domain = "positive" }}
k = {{ domain = "positive" }}

[bodies.bead]
mass = "m"
position = ["{scale} r cos(theta)", "{scale} r sin(theta)", "k r"]
"""


@settings(max_examples=12, deadline=None)
@given(
    scale=st.sampled_from(["1", "2", "3/2", "k", "k^2", "(1 + k)"]),
    domain=st.sampled_from(["positive", "(0, 5)", "[1, 2]", "(0.5, inf)"]),
)
def test_any_positive_domain_makes_a_distance_constraint_hold(scale, domain):
    """Property: a distance constraint k √(x² + y²) = c z (that is, √(c² r²) = c r) holds
    exactly when r's domain keeps it positive; declared real (or not at all), it is refused."""
    good = RADIAL.format(domain=f'domains = {{ r = "{domain}" }}', scale=scale)
    variant = scene_from_text(good, "radial", validate=True).default
    assert variant.dof == 2
    for bad in ('domains = { r = "real" }', ""):
        with pytest.raises(SceneFileError, match="is not satisfied"):
            scene_from_text(RADIAL.format(domain=bad, scale=scale), "radial")


# --- dissipation and generalized forces ---------------------------------------------------


def test_the_damped_oscillators_closed_form_solves_the_derived_equation():
    """x = e^(−γt) cos(ω_d t), γ = b/2m, ω_d² = k/m − γ² (any mechanics text) satisfies the
    equation of motion lagrade derives from L and F = ½ b ẋ²."""
    variant = scene_from_text(DAMPED, "damped_oscillator").default
    (E,) = variant.euler_lagrange
    x = variant.jets[0]
    m, k, b = (variant.parameter_symbols[n] for n in ("m", "k", "b"))
    gamma, omega = b / (2 * m), sp.sqrt(k / m - b**2 / (4 * m**2))
    solution = sp.exp(-gamma * t) * sp.cos(omega * t)
    on = {x.q: solution, x.dot: sp.diff(solution, t), x.ddot: sp.diff(solution, t, 2)}
    assert sp.simplify(E.xreplace(on)) == 0
    assert variant.conserved_quantities == {}  # D_t h = −b ẋ²
    assert variant.system.conservative.conserved_quantities  # L alone would conserve h


def test_a_force_along_one_coordinate_leaves_the_other_momentum_conserved():
    """A particle in the plane, damped along y only (F = ½ b ẏ²) and pushed along y (Q_y =
    F₀ cos ωt): p_x is still conserved, h is not; E_y = m ÿ + b ẏ − F₀ cos ωt."""
    x, y = jet("x"), jet("y")
    m, b, F0, w = sp.symbols("m b F_0 omega", positive=True)
    L = m * (x.dot**2 + y.dot**2) / 2
    system = DissipativeSystem(L, (x, y), b * y.dot**2 / 2, (0, F0 * sp.cos(w * t)))
    assert set(system.conserved_quantities) == {"p_x"}
    assert sp.expand(system.euler_lagrange[1] - (m * y.ddot + b * y.dot - F0 * sp.cos(w * t))) == 0
    assert system.cyclic_coordinates == ("x", "y")  # a property of L: both are cyclic
    # the driven, damped free particle's steady state: y = F₀ sin(ωt − δ)/(ω √(m²ω² + b²))
    delta = sp.atan2(m * w, b)
    steady = F0 * sp.sin(w * t - delta) / (w * sp.sqrt(m**2 * w**2 + b**2))
    on = {y.q: steady, y.dot: sp.diff(steady, t), y.ddot: sp.diff(steady, t, 2)}
    assert sp.simplify(sp.expand_trig(system.euler_lagrange[1].xreplace(on))) == 0


def test_forces_are_read_per_coordinate():
    text = DAMPED.replace(
        'dissipation = "b x_dot^2/2"', 'dissipation = "b x_dot^2/2"\nforces = { x = "k cos(t)" }'
    )
    variant = scene_from_text(text, "driven").default
    assert variant.generalized_forces == (variant.parameter_symbols["k"] * sp.cos(t),)
    with pytest.raises(SceneFileError, match="forces.y: 'y' is not a coordinate"):
        scene_from_text(text.replace("forces = { x", "forces = { y"), "driven")
    with pytest.raises(SceneFileError, match="dissipation: uses x_ddot"):
        scene_from_text(DAMPED.replace('"b x_dot^2/2"', '"b x_ddot^2/2"'), "driven")


def test_the_judge_holds_a_students_equation_to_the_damped_motion():
    problem = {"scene": "damped_oscillator", "scene_text": DAMPED}
    assert check(problem, "eom", "m x_ddot + b x_dot + k x = 0", time_limit=None).score == 1
    assert check(problem, "eom", "x_ddot = -(k x + b x_dot)/m", time_limit=None).score == 1
    undamped = check(problem, "eom", "m x_ddot + k x = 0", time_limit=None)
    assert undamped.status == "incorrect"
    assert check(problem, "conserved", "none", time_limit=None).score == 1
    energy = check(problem, "conserved", "m x_dot^2/2 + k x^2/2", time_limit=None)
    assert energy.status == "incorrect" and "not conserved" in " ".join(energy.feedback)
    # L is still L: the dissipation is not part of it
    assert check(problem, "lagrangian", "m x_dot^2/2 - k x^2/2", time_limit=None).score == 1


def test_other_coordinates_are_not_followed_where_dissipation_acts():
    """F is written in the statement's x: a student measuring x the other way is told that the
    later parts are judged in the statement's coordinates."""
    problem = {"scene": "damped_oscillator", "scene_text": DAMPED}
    verdict = check(problem, "transformation", ["x_mass = -x", "y_mass = 0"], time_limit=None)
    assert verdict.status == "correct"
    assert (
        "dissipation and forces are written in the statement's coordinates" in (verdict.feedback[0])
    )


# --- relations between parameters -------------------------------------------------------------

LIGHTER = ATWOOD.replace("[parameters]", 'relations = ["m < M"]\n\n[parameters]').replace(
    "values = [0.5, 1.0, 1.5]", "values = [0.5, 1.5, 2.5, 3.5]"
)


def test_every_variant_and_every_judged_point_keeps_the_relations():
    scene = scene_from_text(LIGHTER, "lighter")
    drawn = [scene.variant(seed).values for seed in range(40)]
    assert all(v["m"] < v["M"] for v in drawn)
    assert {v["m"] for v in drawn} == {0.5, 1.5, 2.5, 3.5}  # every pool value still drawn
    problem = build_problem({"scene": "lighter", "scene_text": LIGHTER, "seed": 4})
    for part in ("lagrangian", "eom"):
        env = problem.points(part).env
        assert (env[problem.parameters["m"]] < env[problem.parameters["M"]]).all()


@pytest.mark.parametrize(
    "relation, message",
    [
        ('"m > 10 M"', "no values drawn from the pools keep"),
        ('"m = M"', "is not one inequality"),
        ('"m < M < l"', "is not one inequality"),
        ('"m < r"', "uses r, a coordinate"),
        ("3", "is not an inequality"),
    ],
)
def test_a_relation_is_one_inequality_in_the_parameters_the_pools_can_keep(relation, message):
    with pytest.raises(SceneFileError, match=message):
        scene_from_text(LIGHTER.replace('"m < M"', relation), "lighter")


def test_renames_as_consistent_sets():
    """`renames` as sets: a variant takes one set whole, never r beside phi."""
    text = ATWOOD.replace(
        'renames = { theta = ["theta", "phi"] }', 'renames = [["r", "theta"], ["rho", "phi"]]'
    )
    scene = scene_from_text(text, "sets")
    drawn = {tuple(scene.variant(seed).names.values()) for seed in range(30)}
    assert drawn == {("r", "theta"), ("rho", "phi")}
    assert scene.renames == {"r": ("r", "rho"), "theta": ("theta", "phi")}
    assert {n: d.text for n, d in scene.variant(1).coordinate_domains.items()} in (
        {"r": "positive"},
        {"rho": "positive"},
    )
    for sets, message in [
        ('[["r"], ["rho"]]', "one name per coordinate"),
        ('[["rho", "phi"], ["r", "theta"]]', "the first set must be the coordinates"),
        ('[["r", "theta"], ["rho", "rho"]]', "given twice"),
    ]:
        with pytest.raises(SceneFileError, match=message):
            scene_from_text(text.replace('[["r", "theta"], ["rho", "phi"]]', sets), "sets")


# --- the examples against sources nobody here wrote ---------------------------------------------


def test_the_swinging_atwood_machine_has_tufillaros_equations():
    """Tufillaro, Abbott and Griffiths, "Swinging Atwood's Machine", Am. J. Phys. 52, 895
    (1984), eqs. (2)-(3): (M + m) r̈ − m r θ̇² + g (M − m cos θ) = 0 and
    r θ̈ + 2 ṙ θ̇ + g sin θ = 0; lagrade's rows are these times 1 and m r."""
    variant = scene_from_text(ATWOOD, "swinging_atwood").default
    r, theta = variant.jets
    M, m, g = (variant.parameter_symbols[n] for n in ("M", "m", "g"))
    radial = (M + m) * r.ddot - m * r.q * theta.dot**2 + g * (M - m * sp.cos(theta.q))
    angular = r.q * theta.ddot + 2 * r.dot * theta.dot + g * sp.sin(theta.q)
    E_r, E_theta = variant.euler_lagrange
    assert sp.expand(E_r - radial) == 0
    assert sp.expand(E_theta - m * r.q * angular) == 0


def test_the_cycloid_is_a_tautochrone():
    """Huygens: on a cycloid the period does not depend on the amplitude, 4π √(R/g). The
    derived equation of motion integrated numerically (scipy) from two amplitudes."""
    from scipy.integrate import solve_ivp

    variant = scene_from_text((EXAMPLES / "cycloid.toml").read_text(), "cycloid").default
    (s,) = variant.jets
    R, g = variant.parameter_symbols["R"], variant.parameter_symbols["g"]
    (acceleration,) = variant.system.accelerations
    values = {R: sp.Rational(1), g: sp.Rational(981, 100)}
    f = sp.lambdify((s.q, s.dot), acceleration.xreplace(values))  # our own derived expression

    def quarter_period(amplitude: float) -> float:
        """From rest at the amplitude to the bottom: a quarter of the period."""
        bottom = lambda _t, y: y[0]  # noqa: E731
        bottom.terminal, bottom.direction = True, -1
        run = solve_ivp(
            lambda _t, y: [y[1], f(y[0], y[1])], (0, 10), [amplitude, 0.0],
            events=bottom, rtol=1e-11, atol=1e-12,
        )  # fmt: skip
        return float(run.t_events[0][0])

    expected = float(4 * sp.pi * sp.sqrt(values[R] / values[g]))
    for amplitude in (0.1, 2.5):
        assert 4 * quarter_period(amplitude) == pytest.approx(expected, rel=1e-7)
