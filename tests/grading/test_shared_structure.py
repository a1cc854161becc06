"""The variants of one structure (a scene and its presentation: coordinate names, options)
share what does not depend on the handout's values — the compiled reference, the sample points,
the mistake catalogue — and judge exactly as each would alone. A class of 60 variants derives
and compiles each structure once (benchmarks/bench_grade.py measures it)."""

from __future__ import annotations

from lagrade.bank import get_scene
from lagrade.judge.driver import cached_problem, forget_problems, judge

SCENE = "wedge"


def _variants_by_presentation() -> dict[tuple, list[int]]:
    """Seeds of the wedge's variants grouped by presentation (names, options)."""
    scene = get_scene(SCENE)
    groups: dict[tuple, list[int]] = {}
    for seed in range(1, 40):
        v = scene.variant(seed)
        key = (tuple(sorted(v.names.items())), tuple(sorted(v.options.items())))
        groups.setdefault(key, []).append(seed)
    return groups


def _two_of_one_and_one_of_another() -> tuple[int, int, int]:
    groups = [seeds for seeds in _variants_by_presentation().values() if len(seeds) >= 2]
    assert len(groups) >= 2, "the wedge draws at least two presentations"
    return groups[0][0], groups[0][1], groups[1][0]


def test_variants_of_one_presentation_share_points_and_catalogue_and_no_other_does():
    forget_problems()
    a, b, other = _two_of_one_and_one_of_another()
    first, second, third = (cached_problem({"scene": SCENE, "seed": s}) for s in (a, b, other))
    assert first.values != second.values  # different handouts…
    assert first.shared is second.shared  # …one structure
    assert first.points("eom") is second.points("eom")
    assert first.catalogue is second.catalogue and first.L is second.L
    assert third.shared is not first.shared
    assert third.coordinates != first.coordinates or third.points("eom") is not first.points("eom")


def test_a_shared_structure_judges_as_the_variant_would_alone():
    """Every part's verdict and feedback for the second variant, after the first warmed the
    shared structure, equal those of a process that met the second variant first."""
    a, b, _ = _two_of_one_and_one_of_another()
    names = get_scene(SCENE).variant(b).names
    x, q = names["x_M"], names["q"]
    answers = {  # wrong, so diagnosed through the shared catalogue
        "lagrangian": f"m*{q}_dot^2/2 + M*{x}_dot^2/2",
        "eom": [f"{q}_ddot = g*sin(alpha)", f"{x}_ddot = 0"],
        "momenta": [f"p_{x} = M*{x}_dot", f"p_{q} = m*{q}_dot"],
    }
    forget_problems()
    for part, answer in answers.items():
        judge({"scene": SCENE, "seed": a}, part, answer)
    warmed = {p: judge({"scene": SCENE, "seed": b}, p, x).to_dict() for p, x in answers.items()}
    forget_problems()
    alone = {p: judge({"scene": SCENE, "seed": b}, p, x).to_dict() for p, x in answers.items()}
    for part in answers:
        for timing in ("ms", "prepare_ms"):
            warmed[part].pop(timing, None)
            alone[part].pop(timing, None)
        assert warmed[part] == alone[part], part
        assert warmed[part]["verdict"] == "incorrect" and warmed[part]["feedback"], part
