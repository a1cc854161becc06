"""For every scene of the bank the grader accepts the key's answers to every part and rejects
every mistake of the catalogue: what `lagrade generate` checks before it writes a handout."""

import pytest

from lagrade.assign.assignment import PARTS, Part
from lagrade.assign.phase_solution import PHASE_PARTS, can_ask_scene
from lagrade.bank import get_scene, scene_ids
from lagrade.judge.parts import run_checker
from lagrade.judge.problem import build_problem
from lagrade.judge.verify import verify_variant


@pytest.mark.parametrize("scene_id", scene_ids())
def test_key_is_accepted_and_catalogue_mistakes_rejected(scene_id):
    scene = get_scene(scene_id)
    variant = scene.variant(1)
    # the next lecture's parts only where the scene can be asked them (a stable equilibrium,
    # an L quadratic in the velocities): `generate` refuses the others, saying why
    askable = [p for p in PARTS if p not in PHASE_PARTS or can_ask_scene(scene, p) is None]
    parts = [Part(p, 1) for p in askable] + [
        Part("expression", 1, q.name) for q in variant.scene.quantities
    ]
    assert verify_variant(variant, parts) == []


@pytest.mark.parametrize("seed", range(4))
def test_dropping_the_magnetic_term_is_wrong_in_every_gauge(seed):
    """With SI values (e = 1.6e-19 C) the term e v·A is tiny next to ½ m v² at the handout's
    numbers; the check samples every parameter, so the missing term is seen."""
    variant = get_scene("charged_particle").variant(seed)
    problem = build_problem({"scene": "charged_particle", "seed": seed})
    x, y, z = (j.dot for j in variant.jets)
    verdict = run_checker(
        problem,
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2 + z_dot^2)".replace("x_dot", str(x))
        .replace("y_dot", str(y))
        .replace("z_dot", str(z)),
    )
    assert verdict.status == "incorrect"
