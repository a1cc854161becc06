"""A potential written in the scene's own generalized coordinates, and how it follows a student
into theirs. Every such potential of the bank (a spring in r, x_1 and x_2, a charge's e v·A with
A in x) is carried over through the positions: the coordinate's closed form in the bodies'
Cartesian coordinates (r = √(x² + y²), x_2 = x_block2 − a), checked at the sample points. A
potential in a coordinate no position holds simply (a torsion spring's κ θ²/2 on a pendulum's
angle) is carried over by the closed-form relation between the two sets of coordinates
(θ = π/2 − θ' for an angle from the horizontal); when there is none (another choice altogether)
the student is not followed: the later parts are judged in the statement's coordinates, and
the feedback says so. Labels are written here by hand from the physics."""

from __future__ import annotations

import pytest

from lagrade.bank import get_scene, scene_ids
from lagrade.bank.scenefile import presentations
from lagrade.judge.check import check
from lagrade.judge.driver import cached_problem
from lagrade.judge.parts.own_coordinates import _verified_inverses
from lagrade.mechanics.reparametrize import coordinates_to_carry
from lagrade.mechanics.scene import SceneVariant

TORSION_PENDULUM = """\
title = "Pendulum on a torsion spring"
statement = "A bob of mass m hangs on a rod of length l from a torsion spring kappa. Use {theta}."
coordinates = ["theta"]
potential = "gravity + kappa theta^2/2"
constraints = ["x_bob^2 + y_bob^2 - l^2"]

[parameters]
m = { domain = "positive" }
l = { domain = "positive" }
g = { domain = "positive" }
kappa = { domain = "positive" }

[bodies.bob]
mass = "m"
position = ["l sin(theta)", "-l cos(theta)"]
"""

#: Two pucks on a spring whose line is held towards the x axis by a torsion term in its angle.
ALIGNED_PAIR = """\
title = "Two pucks on a spring, aligned"
statement = "Two pucks joined by a spring, turned back to the x axis. Use {X}, {Y}, {r}, {theta}."
coordinates = ["X", "Y", "r", "theta"]
potential = "k (r - l_0)^2/2 + kappa theta^2/2"

[parameters]
m_1 = { domain = "positive" }
m_2 = { domain = "positive" }
k = { domain = "positive" }
l_0 = { domain = "positive" }
kappa = { domain = "positive" }

[bodies.mass1]
mass = "m_1"
position = ["X - m_2 r cos(theta)/(m_1 + m_2)", "Y - m_2 r sin(theta)/(m_1 + m_2)"]

[bodies.mass2]
mass = "m_2"
position = ["X + m_1 r cos(theta)/(m_1 + m_2)", "Y + m_1 r sin(theta)/(m_1 + m_2)"]
"""

PENDULUM = {"scene": "torsion_pendulum", "scene_text": TORSION_PENDULUM}
PAIR = {"scene": "aligned_pair", "scene_text": ALIGNED_PAIR}
NOTE = "Judged in your coordinates"


def judge(problem, part, answer, given=None):
    return check(problem, part, answer, time_limit=None, given=given)


def test_every_potential_of_the_bank_in_its_coordinates_is_carried_through_the_positions():
    """Scenes whose V names a coordinate (besides gravity): each such coordinate has a closed
    form in the positions that reproduces it at the sample points."""
    carried = {}
    for sid in scene_ids():
        scene = get_scene(sid)
        if scene.given_by_lagrangian:
            continue
        for options in presentations(scene):
            variant = SceneVariant(scene, options=options)
            names = [j.name for j in coordinates_to_carry(variant)]
            if not names:
                continue
            carried[(sid, tuple(options.values()))] = names
            if not options:
                problem = cached_problem({"scene": sid})
                found = _verified_inverses(problem, coordinates_to_carry(problem.variant))
                assert {str(q) for q in found} >= set(names), sid
    # the bank's potentials in coordinates, so that a new one is looked at here
    assert {sid for sid, _ in carried} == {
        "free_particle", "projectile", "projectile_plane", "kepler", "charged_particle",
        "harmonic_oscillator", "spring_pendulum", "coupled_oscillators", "two_body_spring",
    }  # fmt: skip


# --- a torsion spring on the angle: carried by the relation ------------------------------------

FROM_HORIZONTAL = ["x_bob = l cos(theta)", "y_bob = -l sin(theta)"]


def test_a_potential_in_an_angle_follows_the_relation():
    """θ from the horizontal: the spring's twist, the angle from the downward vertical, is
    π/2 − θ, so V = −m g l sin θ + κ (π/2 − θ)²/2 (written by hand)."""
    remark = judge(PENDULUM, "transformation", FROM_HORIZONTAL).feedback[-1]
    assert "from the other axis" in remark and "judged in your coordinates" in remark
    given = {"transformation": FROM_HORIZONTAL}
    L = "m l^2 theta_dot^2/2 + m g l sin(theta) - kappa (pi/2 - theta)^2/2"
    verdict = judge(PENDULUM, "lagrangian", L, given)
    assert verdict.status == "correct" and verdict.feedback[0].startswith(NOTE)
    eom = "m l^2 theta_ddot - m g l cos(theta) - kappa (pi/2 - theta) = 0"
    assert judge(PENDULUM, "eom", [eom], given).status == "correct"
    assert judge(PENDULUM, "V", "-m g l sin(theta) + kappa (pi/2 - theta)^2/2", given).status == (
        "correct"
    )
    # the spring's twist taken as the student's own θ: wrong in their coordinates
    forgot = "m l^2 theta_dot^2/2 + m g l sin(theta) - kappa theta^2/2"
    assert judge(PENDULUM, "lagrangian", forgot, given).status == "incorrect"


def test_the_spring_in_r_follows_a_radius_on_another_branch():
    """The spring pendulum with the bob at (−r sin θ, r cos θ) is θ turned by half a turn;
    its spring still stretches by r − l_0 (r the distance, carried through the positions)."""
    lines = ["x_bob = -r sin(theta)", "y_bob = r cos(theta)"]
    problem = {"scene": "spring_pendulum"}
    assert "own_coordinates" in judge(problem, "transformation", lines).mistakes
    V = "m g r cos(theta) + k (r - l_0)^2/2"
    verdict = judge(problem, "V", V, {"transformation": lines})
    assert verdict.status == "correct" and verdict.feedback[0].startswith(NOTE)


# --- no way to carry it over: the statement's coordinates, said -------------------------------

FIRST_PUCK = [
    "x_mass1 = X",
    "y_mass1 = Y",
    "x_mass2 = X + r cos(theta)",
    "y_mass2 = Y + r sin(theta)",
]
M = "(m_1 + m_2)"
L_STATEMENT = (
    f"{M} (X_dot^2 + Y_dot^2)/2 + m_1 m_2 (r_dot^2 + r^2 theta_dot^2)/(2 {M})"
    " - k (r - l_0)^2/2 - kappa theta^2/2"
)
L_FIRST_PUCK = (
    "m_1 (X_dot^2 + Y_dot^2)/2 + m_2 ((X_dot + r_dot cos(theta) - r sin(theta) theta_dot)^2"
    " + (Y_dot + r_dot sin(theta) + r cos(theta) theta_dot)^2)/2"
    " - k (r - l_0)^2/2 - kappa theta^2/2"
)


def test_a_potential_that_cannot_be_carried_over_keeps_the_statements_coordinates():
    verdict = judge(PAIR, "transformation", FIRST_PUCK)
    assert verdict.status == "correct" and "own_coordinates" in verdict.mistakes
    (remark,) = verdict.feedback
    assert "cannot be carried over" in remark and "θ" in remark
    assert "judged in the statement's coordinates" in remark
    given = {"transformation": FIRST_PUCK}
    right = judge(PAIR, "lagrangian", L_STATEMENT, given)
    assert right.status == "correct" and right.feedback == ()
    mine = judge(PAIR, "lagrangian", L_FIRST_PUCK, given)
    assert mine.status == "incorrect"
    assert "judged in the statement's coordinates" in mine.feedback[0]


def test_the_first_puck_is_followed_where_the_potential_is_the_springs_alone():
    """The same choice on the bank's pair (V = k (r − l_0)²/2, r a distance) is followed."""
    given = {"transformation": FIRST_PUCK}
    L = L_FIRST_PUCK.replace(" - kappa theta^2/2", "")
    verdict = judge({"scene": "two_body_spring"}, "lagrangian", L, given)
    assert verdict.status == "correct" and verdict.feedback[0].startswith(NOTE)


@pytest.mark.parametrize("part", ["eom", "momenta", "cyclic"])
def test_the_statements_answers_need_no_note_when_not_followed(part):
    expected = {
        "eom": [
            f"{M} X_ddot = 0",
            f"{M} Y_ddot = 0",
            f"m_1 m_2 (r_ddot - r theta_dot^2)/{M} + k (r - l_0) = 0",
            f"m_1 m_2 (r^2 theta_ddot + 2 r r_dot theta_dot)/{M} + kappa theta = 0",
        ],
        "momenta": [
            f"p_X = {M} X_dot",
            f"p_Y = {M} Y_dot",
            f"p_r = m_1 m_2 r_dot/{M}",
            f"p_theta = m_1 m_2 r^2 theta_dot/{M}",
        ],
        "cyclic": ["X", "Y"],
    }[part]
    given = {"transformation": FIRST_PUCK, "lagrangian": L_STATEMENT}
    verdict = judge(PAIR, part, expected, given)
    assert verdict.status == "correct" and verdict.feedback == ()


def test_the_carried_coordinate_in_a_velocity_dependent_potential():
    """The charge under A = (0, B x, 0) with the student's x axis mirrored: U = −e ẏ B x_p with
    x_p = −x, so L holds −e B x ẏ (by hand), and p_y = m ẏ − e B x."""
    lines = ["x_particle = -x", "y_particle = y", "z_particle = z"]
    given = {"transformation": lines}
    problem = {"scene": "charged_particle"}
    L = "m (x_dot^2 + y_dot^2 + z_dot^2)/2 - e B x y_dot"
    assert judge(problem, "lagrangian", L, given).status == "correct"
    momenta = ["p_x = m x_dot", "p_y = m y_dot - e B x", "p_z = m z_dot"]
    assert judge(problem, "momenta", momenta, given).status == "correct"


def test_a_map_whose_reference_takes_too_long_keeps_the_statements_coordinates(monkeypatch):
    """Deriving in the student's coordinates has its own budget (10 s per map in a process);
    a map that exhausts it is judged in the statement's coordinates, saying why, never a
    timeout of the part."""
    from lagrade.judge.clocks import time_limit
    from lagrade.judge.parts import own_coordinates, run_checker
    from lagrade.judge.problem import build_problem

    monkeypatch.setattr(own_coordinates, "OWN_PREPARE_LIMIT", 1e-6)
    fresh = build_problem({"scene": "spring_pendulum"})  # nothing of it cached yet
    given = {"transformation": ["x_bob = r cos(theta)", "y_bob = -r sin(theta)"]}
    statement = "m (r_dot^2 + r^2 theta_dot^2)/2 + m g r cos(theta) - k (r - l_0)^2/2"
    with time_limit(30.0):  # a part clock, as in a worker: the budget is then enforced
        verdict = run_checker(fresh, "lagrangian", statement, given)
        remark = run_checker(fresh, "transformation", given["transformation"]).feedback[-1]
    assert verdict.status == "correct" and verdict.feedback == ()
    assert "took longer than" in remark and "judged in the statement's coordinates" in remark
    assert ": ." not in remark  # the relation was not found in time: said in general words
