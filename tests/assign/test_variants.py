"""Per-student variants: reproducible, distinct while the pool allows, evenly spread after."""

from __future__ import annotations

from collections import Counter

from lagrade.assign.assignment import AssignedProblem, Part
from lagrade.assign.variants import build_pool, digest, student_variants

WEDGE = AssignedProblem(1, "wedge", (Part("lagrangian", 1),))
HOOP = AssignedProblem(2, "hoop", (Part("lagrangian", 1),))


def test_digest_is_stable_across_processes() -> None:
    # SHA-256, not the salted hash(): this number must never change
    assert digest("a", 1) == 0x839E11A421D370BE


def test_distinct_variants_while_the_pool_allows() -> None:
    ids = [f"s{i}" for i in range(40)]
    chosen = student_variants(WEDGE, 9, ids)
    assert len({c.key for c in chosen.values()}) == len(ids)


def test_pool_is_reproducible_by_scene_variant() -> None:
    from lagrade.bank import get_scene

    for choice in build_pool(WEDGE, 3, 10):
        v = get_scene("wedge").variant(choice.seed)
        assert (v.names, v.options, v.values) == (choice.names, choice.options, choice.values)


def test_small_pool_is_spread_evenly() -> None:
    problem = AssignedProblem(1, "wedge", (Part("lagrangian", 1),), variants=4)
    chosen = student_variants(problem, 5, [f"s{i}" for i in range(13)])
    counts = Counter(c.key for c in chosen.values())
    assert len(counts) == 4 and max(counts.values()) - min(counts.values()) <= 1


def test_exhausted_scene_spreads_over_every_combination() -> None:
    ids = [f"s{i}" for i in range(200)]
    chosen = student_variants(HOOP, 5, ids)
    counts = Counter(c.key for c in chosen.values())
    # the hoop offers 2 names x 3 masses x 3 radii x 3 speeds = 54 distinct variants
    assert len(counts) == 54 and max(counts.values()) - min(counts.values()) <= 1


def test_restricted_names_are_respected() -> None:
    problem = AssignedProblem(1, "wedge", (Part("lagrangian", 1),), names={"x_M": ("X",)})
    chosen = student_variants(problem, 5, [f"s{i}" for i in range(10)])
    assert {c.names["x_M"] for c in chosen.values()} == {"X"}


def test_a_students_variant_does_not_depend_on_roster_order() -> None:
    ids = [f"s{i}" for i in range(20)]
    forward = student_variants(WEDGE, 8, ids)
    backward = student_variants(WEDGE, 8, ids[::-1])
    assert {k: v.seed for k, v in forward.items()} == {k: v.seed for k, v in backward.items()}
