"""Per-student variants, seeded so that the same (assignment seed, problem, roster) always gives
the same variants, and spread so that no two students share one while the pool allows.

A problem's pool is a list of distinct variants (coordinate names, options, parameter values),
each reproducible as `scene.variant(seed)` from its own seed; seeds come from SHA-256 of
(assignment seed, problem index, k), never from Python's salted `hash()`. Students are then
taken in the order of SHA-256(assignment seed, problem index, student id); each takes its
preferred slot of the pool (also from that hash) or, when that slot is already as used as the
least used one, the next slot that is least used. A student's variant thus depends on the seed,
the problem, their id and, when slots collide, on the students hashed before them: the
manifest, not a recomputation, is what fixes a variant for grading.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from lagrade.assign.assignment import AssignedProblem
from lagrade.mechanics import Scene, SceneVariant

#: Candidate seeds tried per wanted variant before the pool is taken as exhausted.
_TRIES_PER_VARIANT = 40
_MIN_TRIES = 400


@dataclass(frozen=True)
class VariantChoice:
    """One member of a pool: `scene.variant(seed)` reproduces names, options and values."""

    seed: int
    names: Mapping[str, str]
    options: Mapping[str, str]
    values: Mapping[str, float]

    @property
    def key(self) -> tuple:
        """What makes two variants the same for a student."""
        return (
            tuple(sorted(self.names.items())),
            tuple(sorted(self.options.items())),
            tuple(sorted(self.values.items())),
        )

    def variant(self, scene: Scene) -> SceneVariant:
        return scene.variant(self.seed)


def digest(*parts: object) -> int:
    """A stable 64-bit integer from the parts (SHA-256 of their joined text)."""
    text = "\x1f".join(str(p) for p in parts).encode("utf-8")
    return int.from_bytes(hashlib.sha256(text).digest()[:8], "big")


def variant_seed(assignment_seed: int, problem_index: int, k: int) -> int:
    """The k-th candidate seed of a problem's pool (31 bits, so it reads well in a manifest)."""
    return digest("lagrade-pool", assignment_seed, problem_index, k) >> 33


def build_pool(
    problem: AssignedProblem, assignment_seed: int, wanted: int
) -> tuple[VariantChoice, ...]:
    """Up to `wanted` distinct variants allowed by the problem's `names` and `options`; fewer
    when the scene offers fewer combinations."""
    scene = problem.scene
    pool: list[VariantChoice] = []
    seen: set[tuple] = set()
    tries = max(_MIN_TRIES, _TRIES_PER_VARIANT * wanted)
    for k in range(tries):
        seed = variant_seed(assignment_seed, problem.index, k)
        v = scene.variant(seed)
        if any(v.names[c] not in allowed for c, allowed in problem.names.items()):
            continue
        if any(v.options[o] not in allowed for o, allowed in problem.options.items()):
            continue
        choice = VariantChoice(seed, dict(v.names), dict(v.options), dict(v.values))
        if choice.key in seen:
            continue
        seen.add(choice.key)
        pool.append(choice)
        if len(pool) >= wanted:
            break
    return tuple(pool)


def assign(
    problem: AssignedProblem,
    assignment_seed: int,
    student_ids: Sequence[str],
    pool: Sequence[VariantChoice],
) -> dict[str, VariantChoice]:
    """Each student's variant from the pool, spread evenly (see the module docstring)."""
    if not pool:
        raise AssertionError(f"empty variant pool for problem {problem.index}")
    order = sorted(
        student_ids,
        key=lambda sid: (digest("lagrade-student", assignment_seed, problem.index, sid), sid),
    )
    used = [0] * len(pool)
    chosen: dict[str, VariantChoice] = {}
    for sid in order:
        least = min(used)
        slot = digest("lagrade-slot", assignment_seed, problem.index, sid) % len(pool)
        while used[slot] != least:
            slot = (slot + 1) % len(pool)
        used[slot] += 1
        chosen[sid] = pool[slot]
    return chosen


def student_variants(
    problem: AssignedProblem, assignment_seed: int, student_ids: Sequence[str]
) -> dict[str, VariantChoice]:
    """The pool (as large as `problem.variants`, or one per student) and each student's draw."""
    wanted = problem.variants or max(1, len(student_ids))
    pool = build_pool(problem, assignment_seed, wanted)
    return assign(problem, assignment_seed, student_ids, pool)
