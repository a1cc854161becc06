"""The sample points of a question are drawn once and shared by every student, so a faster draw
must draw the very same points. `Space.draw` takes the first blocks of every group at once and
asks the validity test once (`_first_blocks`); these tests hold it to the group-by-group draw
(`_draw_by_groups`) point for point, and hold the bank's validity tests to being pointwise,
which is what lets one call stand for one per group."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.errors import ReferenceUndefined
from lagrade.judge.compiled import tiled
from lagrade.judge.driver import cached_problem
from lagrade.judge.sampling import Space
from lagrade.mechanics import Domain, jet, t

DOMAINS = ("positive", "nonnegative", "real", "(0, 1)", "[-2, 3]", "(5, 6]")
NAMES = ("theta", "x", "r", "phi", "rho", "s")


@st.composite
def spaces(draw) -> Space:
    """A space of 0–3 parameters (some with handout values) and 1–3 coordinates (some with
    declared domains, some radial, some straddling 0)."""
    n_par = draw(st.integers(0, 3))
    doms = draw(st.lists(st.sampled_from(DOMAINS), min_size=n_par, max_size=n_par))
    symbols = [jet(f"p{i}").q for i in range(n_par)]
    parameters = {s: Domain.parse(d) for s, d in zip(symbols, doms, strict=True)}
    values = {s: draw(st.floats(0.5, 5.0)) for s in symbols if draw(st.booleans())}
    names = draw(st.lists(st.sampled_from(NAMES), min_size=1, max_size=3, unique=True))
    coordinate_domains = {
        n: draw(st.sampled_from([(-1.0, 1.0), (0.5, 2.0), (-3.0, -1.0)]))
        for n in names
        if draw(st.booleans())
    }
    return Space(tuple(jet(n) for n in names), parameters, values, coordinate_domains)


def _rejecting(share: float, raising: float = 0.0):
    """A pointwise validity test that says no at about `share` of the points, and raises at
    about `raising` of them (as a factorisation may), by a hash of the point's t (never by its
    neighbours)."""

    def valid(env: dict) -> np.ndarray:
        h = (env[t] * 7919.0) % 1.0
        if np.any((env[t] * 104729.0) % 1.0 < raising):
            raise np.linalg.LinAlgError("no factorisation at a point")
        return h >= share

    return valid


def _drawn(space: Space, seed: int, free, valid, groups: int, per_group: int, whole: bool):
    """The draw's points, or the name of what it raised."""
    try:
        if whole:
            return space.draw(seed, free, valid, groups, per_group)
        free_set = set(space.parameters) if free is None else set(free)
        return space._draw_by_groups(seed, free_set, valid, groups, per_group)
    except (ReferenceUndefined, np.linalg.LinAlgError) as error:
        return type(error).__name__


@settings(max_examples=120, deadline=None)
@given(
    space=spaces(),
    seed=st.integers(0, 2**32 - 1),
    share=st.sampled_from([None, 0.0, 0.02, 0.2, 0.7, 1.0]),
    groups=st.integers(1, 5),
    per_group=st.integers(1, 7),
    all_free=st.booleans(),
    raising=st.sampled_from([0.0, 0.0, 0.01, 0.05]),
)
def test_draw_is_the_group_by_group_draw(space, seed, share, groups, per_group, all_free, raising):
    free = None if all_free else frozenset()
    valid = None if share is None else _rejecting(share, raising)
    fast = _drawn(space, seed, free, valid, groups, per_group, whole=True)
    slow = _drawn(space, seed, free, valid, groups, per_group, whole=False)
    if isinstance(slow, str) or isinstance(fast, str):
        assert fast == slow
        return
    assert list(fast.env) == list(slow.env)
    for s in slow.env:
        assert fast.env[s].dtype == slow.env[s].dtype
        assert np.array_equal(fast.env[s], slow.env[s])
    assert np.array_equal(fast.group, slow.group)


@settings(max_examples=60, deadline=None)
@given(space=spaces(), seed=st.integers(0, 2**32 - 1), count=st.integers(1, 5), k=st.integers(1, 7))
def test_blocks_consume_the_stream_as_groups_do(space, seed, count, k):
    free = set(space.parameters)
    one, other = np.random.default_rng(seed), np.random.default_rng(seed)
    together = space._blocks(one, free, k, count)
    apart = [space._group(other, free, k) for _ in range(count)]
    assert list(together) == list(apart[0])
    for s in together:
        assert np.array_equal(together[s], np.concatenate([b[s] for b in apart]))
    assert one.bit_generator.state == other.bit_generator.state


def test_a_test_that_raises_at_a_point_the_loop_never_reaches():
    """The loop redraws a point of group 0 (not the parameter: its stream moves on by one value
    less than a group's), so it never draws group 3's first block, whose parameter value is
    then never drawn; the draw at once must not raise at a point of that block either."""
    m = jet("m").q
    space = Space((jet("x"),), {m: Domain.parse("positive")})
    first = space._blocks(np.random.default_rng(7), {m}, 6, 4)
    reject, explode = first[t][0], (first[m][20], first[t][20])

    def valid(env: dict) -> np.ndarray:
        if np.any((env[m] == explode[0]) & (env[t] == explode[1])):
            raise np.linalg.LinAlgError("no factorisation at a point")
        return env[t] != reject

    slow = space._draw_by_groups(7, {m}, valid, 4, 6)
    fast = space.draw(7, None, valid)
    assert list(fast.env) == list(slow.env)
    assert all(np.array_equal(fast.env[s], slow.env[s]) for s in slow.env)


def test_a_range_uniform_refuses_is_left_to_the_group_by_group_draw():
    space = Space((jet("x"),), {}, coordinate_domains={"x": (0.0, float("inf"))})
    assert space._blocks(np.random.default_rng(0), set(), 6, 4) is None
    with pytest.raises(OverflowError):
        space.draw(0)


# Questions whose validity tests take every path: float64, complex128 and high precision (masses
# past float range), poles, relations between parameters, a singular mass matrix (eom).
PROBLEMS = [
    ({"scene": "wedge"}, ("lagrangian", "eom", "transformation", "T")),
    ({"scene": "hoop"}, ("lagrangian", "conserved")),
    ({"scene": "double_pendulum"}, ("eom",)),
    (
        {
            "expression": "G*M^20/m^19",
            "parameters": {"G": "(6e-11, 7e-11)", "M": "(1e30, 2e30)", "m": "(5e24, 7e24)"},
        },
        ("expression",),
    ),
    ({"expression": "log(x)/(a - 1)", "parameters": {"x": "real", "a": "(0, 2)"}}, ("expression",)),
]


@pytest.mark.parametrize(("spec", "parts"), PROBLEMS)
def test_validity_tests_are_pointwise(spec, parts):
    """A point's verdict is its own: the test of 24 points at once says of each what the test of
    its block of 6 says, on drawn points and on points with a fifth of the values set to 0."""
    problem = cached_problem(spec)
    space = problem.space
    for part in parts:
        valid = problem._kept(problem._validity(part))
        for seed in range(3):
            rng = np.random.default_rng(seed)
            union = space._uniform(rng, space._box(set(space.parameters), 1.0), 24)
            if seed:
                for v in union.values():
                    v[rng.random(v.size) < 0.2] = 0.0
            blocks = [{s: v[i : i + 6].copy() for s, v in union.items()} for i in range(0, 24, 6)]
            assert np.array_equal(valid(union), np.concatenate([valid(b) for b in blocks]))


@settings(max_examples=60, deadline=None)
@given(
    n=st.integers(0, 9),
    copies=st.integers(0, 5),
    kind=st.sampled_from([float, complex, object, "2d", "0d"]),
)
def test_tiled_is_np_tile(n, copies, kind):
    """The seeds of every hyper-dual pass are tiled points: `tiled` must be np.tile's array."""
    x = np.arange(n, dtype=float) * 0.5 - 1.0
    if kind == "2d":
        x = x.reshape(1, n)
    elif kind == "0d":
        x = np.float64(2.5)
    else:
        x = x.astype(kind)
    ours, theirs = tiled(x, copies), np.tile(x, copies)
    assert ours.dtype == theirs.dtype
    assert ours.shape == theirs.shape
    assert np.array_equal(ours, theirs)
