"""Bad scene declarations fail with one SceneError whose message names each problem.

Each test plants one fault in an otherwise valid simple pendulum and checks the problem line.
"""

from __future__ import annotations

import dataclasses
import pickle

import pytest
import sympy as sp
from sympy import cos, sin

from lagrade.errors import SceneError
from lagrade.mechanics.bodies import PointMass, gravity
from lagrade.mechanics.domains import param
from lagrade.mechanics.scene import Scene, SceneVariant

PENDULUM = Scene(
    id="test_pendulum",
    title="Pendulum",
    statement="A pendulum; use {theta}.",
    coordinates=("theta",),
    parameters=(param("m"), param("l"), param("g")),
    bodies=lambda s: (PointMass("bob", s.m, (s.l * sin(s.theta), -s.l * cos(s.theta))),),
    potential=lambda s, bodies: gravity(s.g, bodies),
    constraints=lambda s, c: (c.bob.x**2 + c.bob.y**2 - s.l**2,),
    renames={"theta": ("theta", "phi")},
)


def problems_of(scene: Scene, **variant_args) -> list[str]:
    """The problems validate() reports (it must report some)."""
    with pytest.raises(SceneError) as caught:
        SceneVariant(scene, **variant_args).validate()
    assert caught.value.scene_id == scene.id
    return caught.value.problems


def test_the_unbroken_pendulum_is_valid():
    PENDULUM.default.validate()


def test_constraint_the_transformation_does_not_satisfy():
    bad = dataclasses.replace(
        PENDULUM, constraints=lambda s, c: (c.bob.x**2 + c.bob.y**2 - 2 * s.l**2,)
    )
    (problem,) = problems_of(bad)
    assert problem == (
        "constraints: constraint 1 (-2*l**2 + x_bob**2 + y_bob**2 = 0) is not satisfied by the "
        "transformation equations; it leaves -l**2"
    )


def test_coordinate_that_appears_nowhere():
    bad = dataclasses.replace(PENDULUM, coordinates=("theta", "psi"))
    problems = problems_of(bad)
    assert "coordinates: 'psi' appears in no position and not in the potential" in problems
    # Two coordinates for one degree of freedom: the count is named too.
    assert any(p.startswith("constraints: 3N - k gives 1 degrees of freedom") for p in problems)


def test_parameter_used_through_the_namespace_but_not_declared():
    bad = dataclasses.replace(
        PENDULUM, potential=lambda s, bodies: gravity(s.g, bodies) + s.k * s.theta**2
    )
    (problem,) = problems_of(bad)
    assert problem.startswith("declarations: s.k is not declared (s offers: m, l, g, theta, ")


def test_parameter_used_as_a_bare_symbol_but_not_declared():
    k = sp.Symbol("k", positive=True)
    bad = dataclasses.replace(
        PENDULUM, potential=lambda s, bodies: gravity(s.g, bodies) + k * s.theta**2
    )
    (problem,) = problems_of(bad)
    assert problem == "potential: uses k, which is not a declared parameter"


def test_body_that_a_constraint_names_but_the_scene_lacks():
    bad = dataclasses.replace(PENDULUM, constraints=lambda s, c: (c.rod.x,))
    (problem,) = problems_of(bad)
    assert problem == "declarations: c.rod is not declared (c offers: bob)"


def test_duplicated_coordinate():
    with pytest.raises(SceneError) as caught:
        dataclasses.replace(PENDULUM, coordinates=("theta", "theta"), renames={})
    assert caught.value.problems == ["coordinates: 'theta' is declared twice"]


def test_dof_mismatch():
    """A bob in space with one constraint has two degrees of freedom, not one."""
    bad = dataclasses.replace(
        PENDULUM,
        bodies=lambda s: (PointMass("bob", s.m, (s.l * sin(s.theta), 0, -s.l * cos(s.theta))),),
        potential=lambda s, bodies: gravity(s.g, bodies, axis="z"),
        constraints=lambda s, c: (c.bob.x**2 + c.bob.y**2 + c.bob.z**2 - s.l**2,),
    )
    (problem,) = problems_of(bad)
    assert problem == (
        "constraints: 3N - k gives 2 degrees of freedom but the scene declares 1 coordinates "
        "['theta']"
    )


def test_parameter_without_a_domain():
    with pytest.raises(SceneError) as caught:
        param("l", None)
    assert caught.value.problems == [
        "parameter 'l': no domain (declare positive, real or an interval)"
    ]


def test_rename_that_clashes_with_a_parameter():
    bad = dataclasses.replace(PENDULUM, renames={"theta": ("theta", "l")})
    with pytest.raises(SceneError) as caught:
        SceneVariant(bad, names={"theta": "l"})
    assert caught.value.problems == ["renames: coordinate names ['l'] clash"]


def test_rename_whose_first_name_is_not_the_coordinate():
    with pytest.raises(SceneError) as caught:
        dataclasses.replace(PENDULUM, renames={"theta": ("phi", "theta")})
    assert caught.value.problems == ["renames: the first name for 'theta' must be 'theta' itself"]


def test_option_that_is_not_offered():
    scene = dataclasses.replace(PENDULUM, options={"angle_from": ("vertical",)})
    with pytest.raises(SceneError) as caught:
        SceneVariant(scene, options={"angle_from": "horizontal"})
    assert caught.value.problems == [
        "options: angle_from='horizontal' is not offered (offered: ('vertical',))"
    ]


def test_every_problem_is_reported_at_once():
    k = sp.Symbol("k", positive=True)
    bad = dataclasses.replace(
        PENDULUM,
        coordinates=("theta", "psi"),
        potential=lambda s, bodies: gravity(s.g, bodies) + k,
        constraints=lambda s, c: (c.bob.x - s.l,),
    )
    problems = problems_of(bad)
    fields = [p.split(":")[0] for p in problems]
    assert fields.count("potential") == 1
    assert fields.count("coordinates") == 1
    assert fields.count("constraints") == 2  # the broken constraint and the DOF count
    assert fields.count("bodies") == 1  # psi moves nothing: rank 1 < 2


def test_scene_error_pickles_and_lists_problems():
    bad = dataclasses.replace(PENDULUM, coordinates=("theta", "psi"))
    with pytest.raises(SceneError) as caught:
        bad.default.validate()
    error = pickle.loads(pickle.dumps(caught.value))
    assert error.problems == caught.value.problems
    assert str(error).startswith("scene 'test_pendulum' is not valid:\n  - ")
