"""Property: for a random valid reparametrisation of a scene's coordinates (q → ±q + c, an angle
→ π/2 − angle, …), the reference Lagrangian lagrade builds in the student's coordinates — from
the transformation equations typed as a student would, through the transformation checker —
has Euler–Lagrange equations equivalent to the original ones mapped through the
reparametrisation: with q = s q' + c, E'_k(q') = s_k E_k(q(q')) (a point transformation carries
the Euler–Lagrange expressions as a covector). Checked in exact arithmetic at random points
(rationals put into the sympy expressions; no float tolerance to hide a wrong term)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.bank import get_scene
from lagrade.judge.driver import cached_problem
from lagrade.judge.parts.own_coordinates import chosen_coordinates
from lagrade.judge.sampling import coordinate_range
from lagrade.mechanics import lagrange as mech
from lagrade.notation.printer import plain

#: Scenes with angles, lengths, a rigid body, and potentials in positions and in coordinates.
SCENES = (
    "simple_pendulum",
    "incline_pendulum",
    "wedge",
    "spring_pendulum",
    "coupled_oscillators",
    "kepler",
    "harmonic_oscillator",
    "sliding_ladder",
    "double_pendulum",
)
PROFILE = settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
OFFSETS = (sp.S.Zero, sp.Rational(1, 2), -sp.Integer(1), sp.pi / 2, sp.pi, -sp.pi / 3)


@st.composite
def reparametrisations(draw):
    """A scene and, per coordinate, q = s q' + c (a radius only shifted outwards: its sign is
    its branch, r and −r with θ + π being the same bodies)."""
    sid = draw(st.sampled_from(SCENES))
    variant = get_scene(sid).default
    relation = {}
    for j in variant.jets:
        radial = coordinate_range(j.name)[0] > 0
        s = sp.Integer(1) if radial else draw(st.sampled_from([sp.Integer(1), -sp.Integer(1)]))
        c = draw(st.sampled_from((sp.S.Zero, sp.Rational(1, 2)) if radial else OFFSETS))
        relation[j] = (s, c)
    return sid, relation


def _random_point(jets, parameters, rng: random.Random) -> dict:
    point = {p: sp.Rational(rng.randint(60, 140), 100) for p in parameters}
    for j in jets:
        lo, hi = coordinate_range(j.name)
        lo = max(lo, 0.3) if lo > 0 else 0.3
        point[j.q] = sp.Rational(rng.randint(int(lo * 100), int(min(hi, 1.3) * 100)), 100)
        point[j.dot] = sp.Rational(rng.randint(-100, 100), 100)
        point[j.ddot] = sp.Rational(rng.randint(-100, 100), 100)
    point[mech.t] = sp.Rational(7, 10)
    return point


@pytest.mark.slow
@PROFILE
@given(reparametrisations())
def test_the_reference_in_the_students_coordinates_has_the_mapped_equations(case):
    sid, relation = case
    problem = cached_problem({"scene": sid})
    variant = problem.variant
    forward = {}
    for j, (s, c) in relation.items():
        forward[j.q] = s * j.q + c
    lines = [f"{name} = {plain(e.xreplace(forward))}" for name, e in variant.transformation.items()]
    choice = chosen_coordinates(problem, lines)
    identity = all(s == 1 and c == 0 for s, c in relation.values())
    assert choice.kind == ("statement" if identity else "own"), (lines, choice)
    own = choice.problem.lagrangian
    mapped = {}
    for j, (s, c) in relation.items():
        mapped |= {j.q: s * j.q + c, j.dot: s * j.dot, j.ddot: s * j.ddot}
    original = mech.euler_lagrange(variant.lagrangian, variant.jets)
    mine = mech.euler_lagrange(own, variant.jets)
    rng = random.Random(repr(sorted((j.name, str(v)) for j, v in relation.items())))
    for _ in range(3):
        point = _random_point(variant.jets, variant.parameter_symbols.values(), rng)
        for k, j in enumerate(variant.jets):
            s = relation[j][0]
            expected = s * original[k].xreplace(mapped).xreplace(point)
            got = mine[k].xreplace(point)
            assert sp.simplify(got - expected) == 0, (sid, j.name, relation, got, expected)
