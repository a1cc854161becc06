"""H, Hamilton's equations, equilibria and normal modes of every bank scene, each against an
independent derivation: H against a Legendre transform done in plain sympy (`solve` for the
velocities, H = Σ p q̇ − L), Hamilton's equations against the Euler–Lagrange equations carried to
phase space, and the normal-mode frequencies against the eigenvalues of a numerical (finite
difference) linearisation of the equations of motion and against the frequencies of the motion
itself (scipy's solve_ivp, then an FFT) — for every bank scene that has a stable equilibrium."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from lagrade.bank import get_scene, scene_ids
from lagrade.mechanics import (
    HamiltonianSystem,
    frequencies_from,
    momentum_name,
    small_oscillations,
)

SEEDS = (1, 2)
#: Scenes with a stable equilibrium at rest (the others say why not: `WHY_NOT`).
STABLE = (
    "wheel",
    "hoop",
    "harmonic_oscillator",
    "simple_pendulum",
    "double_pendulum",
    "spring_pendulum",
    "pendulum_on_cart",
    "coupled_oscillators",
    "two_body_spring",
    "sliding_ladder",
)
WHY_NOT = {
    "free_particle": "no stationary point",
    "projectile": "no stationary point",
    "kepler": "no stationary point",
    "charged_particle": "velocity-dependent force",
    "rotating_frame": "velocity-dependent force",
    "driven_pendulum": "depends explicitly on time",
    "spherical_pendulum": "singular",
    "rotating_rod_bead": "no equilibrium at rest is stable",
    "atwood": "no stationary point",
    "incline_pendulum": "no stationary point",
    "wedge": "no stationary point",
    "projectile_plane": "no stationary point",
    "cone_particle": "no stationary point",
    "rolling_cylinder": "no stationary point",
}


def _variant(scene_id: str, seed: int):
    return get_scene(scene_id).variant(seed)


def _values(variant) -> dict:
    return {variant.parameter_symbols[n]: sp.Float(v, 30) for n, v in variant.values.items()}


def _plain_legendre(variant) -> tuple[sp.Expr, list[sp.Symbol]]:
    """H by the textbook recipe, in plain sympy: solve p_j = ∂L/∂q̇_j for the q̇, H = Σ p q̇ − L."""
    L, jets = variant.lagrangian, variant.jets
    p = [sp.Symbol(momentum_name(j.name), real=True) for j in jets]
    equations = [sp.Eq(pj, sp.diff(L, j.dot)) for pj, j in zip(p, jets, strict=True)]
    (solution,) = sp.solve(equations, [j.dot for j in jets], dict=True)
    H = sum(pj * solution[j.dot] for pj, j in zip(p, jets, strict=True)) - L.xreplace(solution)
    return H, p


def _random_point(variant, rng: random.Random, symbols) -> dict:
    point = {s: sp.Float(rng.uniform(0.3, 1.2), 30) for s in symbols}
    point[sp.Symbol("t", real=True)] = sp.Float(rng.uniform(0.1, 1.0), 30)
    return point | _values(variant)


def _close(a, b, scale=1.0) -> bool:
    return abs(complex(a) - complex(b)) <= 1e-15 * max(abs(complex(a)), abs(complex(b)), scale)


@pytest.mark.parametrize("scene_id", scene_ids())
def test_hamiltonian_is_the_plain_legendre_transform(scene_id):
    variant = _variant(scene_id, 1)
    ours = HamiltonianSystem(variant.system)
    H, p = _plain_legendre(variant)
    rng = random.Random(scene_id)
    for _ in range(3):
        point = _random_point(variant, rng, [j.q for j in variant.jets] + p)
        assert _close(sp.N(ours.hamiltonian.xreplace(point), 30), sp.N(H.xreplace(point), 30))


@pytest.mark.parametrize("scene_id", scene_ids())
def test_hamilton_equations_are_the_euler_lagrange_motion_in_phase_space(scene_id):
    """At a point (q, q̇) of velocity space carried to phase space by p = ∂L/∂q̇: Hamilton's
    q̇-equations give back q̇, and their ṗ-equations give D_t(∂L/∂q̇) along the motion that the
    Euler–Lagrange equations give (q̈ = A⁻¹ b, solved numerically here)."""
    variant = _variant(scene_id, 1)
    system = variant.system
    ours = HamiltonianSystem(system)
    rng = random.Random(scene_id)
    jets = variant.jets
    for _ in range(2):
        point = _random_point(variant, rng, [j.q for j in jets] + [j.dot for j in jets])
        A = system.mass_matrix.xreplace(point).evalf(30)
        b = system.forcing.xreplace(point).evalf(30)
        accelerations = dict(zip([j.ddot for j in jets], A.LUsolve(b), strict=True))
        momenta = {
            m: sp.N(p.xreplace(point), 30)
            for m, p in zip(ours.momenta, system.generalized_momenta, strict=True)
        }
        phase = {s: v for s, v in point.items() if s not in {j.dot for j in jets}} | momenta
        rates = {}
        for j, p in zip(jets, system.generalized_momenta, strict=True):
            dp = sum(sp.diff(p, s.q) * s.dot + sp.diff(p, s.dot) * s.ddot for s in jets)
            dp += sp.diff(p, sp.Symbol("t", real=True))
            rates[momentum_name(j.name)] = dp.xreplace(point).xreplace(accelerations)
        for equation in ours.hamilton_equations:
            got = sp.N(equation.rhs.xreplace(phase), 30)
            name = equation.lhs.name
            want = (
                point[equation.lhs]
                if name.endswith("_dot") and name[:-4] in variant.coordinates
                else rates[name[:-4]]
            )
            assert _close(got, sp.N(want, 30), 1e-10), (equation, got, want)


def _accelerations(variant):
    """q̈(q, q̇) at the variant's values from the Euler–Lagrange equations, as a float function."""
    system, jets = variant.system, variant.jets
    values = _values(variant)
    A = system.mass_matrix.xreplace(values)
    b = system.forcing.xreplace(values)
    args = [j.q for j in jets] + [j.dot for j in jets]
    fA, fb = sp.lambdify(args, A, "numpy"), sp.lambdify(args, b, "numpy")

    def rhs(_t, y):
        n = len(jets)
        acc = np.linalg.solve(np.array(fA(*y), float), np.array(fb(*y), float).ravel())
        return np.concatenate([y[n:], acc])

    return rhs


def _linearised_frequencies(rhs, y0: np.ndarray) -> np.ndarray:
    """|Im λ| of the Jacobian of the first-order system at the equilibrium, by central finite
    differences: the small-oscillation frequencies, each once."""
    n2 = len(y0)
    J = np.empty((n2, n2))
    for k in range(n2):
        h = 1e-6 * max(1.0, abs(y0[k]))
        up, down = y0.copy(), y0.copy()
        up[k] += h
        down[k] -= h
        J[:, k] = (rhs(0, up) - rhs(0, down)) / (2 * h)
    lam = np.linalg.eigvals(J)
    return np.sort(np.abs(lam.imag))[::2]  # the pairs ±iω


def _simulated_frequencies(rhs, y0: np.ndarray, n: int, slowest: float) -> list[float]:
    """The peaks of the power spectrum of a small motion about the equilibrium."""
    rng = np.random.default_rng(7)
    start = y0.copy()
    start[:n] += 1e-4 * rng.uniform(0.5, 1.0, n)
    period = 2 * np.pi / slowest
    T, samples = 60 * period, 2**14
    times = np.linspace(0, T, samples, endpoint=False)
    motion = solve_ivp(rhs, (0, T), start, t_eval=times, rtol=1e-10, atol=1e-14, method="LSODA")
    assert motion.success
    power = sum(
        np.abs(np.fft.rfft((x - x.mean()) * np.hanning(samples))) ** 2 for x in motion.y[:n]
    )
    omega = 2 * np.pi * np.fft.rfftfreq(samples, T / samples)
    peaks = [
        k
        for k in range(2, len(power) - 1)
        if power[k] > power[k - 1] and power[k] >= power[k + 1] and power[k] > 1e-4 * power.max()
    ]
    out = []
    for k in peaks:  # parabolic interpolation of the peak
        a, b, c = np.log(power[k - 1 : k + 2])
        out.append(omega[k] + 0.5 * (a - c) / (a - 2 * b + c) * (omega[1] - omega[0]))
    return out


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("scene_id", STABLE)
def test_normal_modes_against_linearisation_and_simulated_motion(scene_id, seed):
    variant = _variant(scene_id, seed)
    values = {s: float(v) for s, v in _values(variant).items()}
    osc = small_oscillations(variant.system, values)
    assert osc.why_not is None
    ours = np.sort(osc.numeric_frequencies())
    if osc.frequencies is not None:  # the closed form agrees with the numeric eigenproblem
        closed = sorted(float(sp.N(w.xreplace(_values(variant)))) for w in osc.frequencies)
        assert np.allclose(closed, ours, rtol=1e-9, atol=1e-12)
    jets = variant.jets
    n = len(jets)
    at = [float(sp.N(sp.S(osc.stable.at.get(j.q, 0)).xreplace(_values(variant)))) for j in jets]
    y0 = np.array(at + [0.0] * n)
    rhs = _accelerations(variant)
    assert np.allclose(rhs(0, y0), 0, atol=1e-9)  # at rest, it stays at rest
    linear = np.sort(_linearised_frequencies(rhs, y0))
    assert np.allclose(linear, ours, rtol=1e-4, atol=1e-4 * ours.max() + 1e-9), (linear, ours)
    nonzero = [w for w in ours if w > 1e-6 * max(ours.max(), 1e-300)]
    if not nonzero:
        return  # a free wheel: nothing oscillates
    seen = _simulated_frequencies(rhs, y0, n, min(nonzero))
    for w in seen:  # every frequency in the motion is a normal mode's
        assert min(abs(w - x) for x in nonzero) <= 0.01 * w, (seen, nonzero)
    assert seen


@pytest.mark.parametrize("scene_id", sorted(WHY_NOT))
def test_why_there_are_no_normal_modes(scene_id):
    variant = _variant(scene_id, 1)
    values = {s: float(v) for s, v in _values(variant).items()}
    osc = small_oscillations(variant.system, values)
    assert osc.why_not is not None and WHY_NOT[scene_id] in osc.why_not
    assert osc.numeric_frequencies() is None


def test_every_bank_scene_is_classified():
    assert set(STABLE) | set(WHY_NOT) == set(scene_ids())


def test_zero_modes_are_the_free_directions():
    """A pendulum on a cart: the cart's position is free (ω = 0); the swing has
    ω² = (M + m) g / (M l) (Goldstein §6.4's method; Taylor ch. 11)."""
    variant = _variant("pendulum_on_cart", 1)
    values = {s: float(v) for s, v in _values(variant).items()}
    osc = small_oscillations(variant.system, values)
    assert len(osc.stable.free) == 1
    w = osc.numeric_frequencies()
    assert w[0] == 0.0 and w[1] > 0
    p = {n: float(v) for n, v in variant.values.items()}
    assert np.isclose(w[1] ** 2, (p["M"] + p["m"]) * p["g"] / (p["M"] * p["l"]))


def test_frequencies_from_is_the_generalized_eigenproblem():
    """Two equal masses m and three equal springs k (Taylor Example 11.1): ω² = k/m and 3k/m."""
    k, m = 2.0, 0.5
    K = np.array([[2 * k, -k], [-k, 2 * k]])
    M = np.diag([m, m])
    assert np.allclose(frequencies_from(K, M), np.sqrt([k / m, 3 * k / m]))
