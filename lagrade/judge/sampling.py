"""The sample space of a question and the points drawn from it: q, q̇, q̈ and t as independent
variables, parameters inside their declared domains in groups of points that share parameter
values; and a memo for inputs derived from the points alone."""

from __future__ import annotations

import math
import re
import zlib
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import sympy as sp

from lagrade.errors import ReferenceUndefined
from lagrade.judge.evaluate import COMPLEX, FLOAT, MP, MP_COMPLEX
from lagrade.mechanics import Domain, Jet, t

#: Parameter draws per set of sample points, and points (q, q̇, q̈, t) per parameter draw.
GROUPS = 4
PER_GROUP = 6

_RADIAL = re.compile(r"^(r|rho|ρ|ell|l)(_?\w*)?$")


def seed_for(*parts: object) -> int:
    """A stable seed from a request's identity (same points for every student of a problem)."""
    return zlib.crc32("|".join(map(str, parts)).encode())


def coordinate_range(name: str) -> tuple[float, float]:
    """Where a coordinate is drawn when the problem says nothing: a radius-like name in
    (0.3, 2.5), any other coordinate in ±(0.2, 2.5) — both signs of sin and cos of an angle,
    away from 0 where many expressions are special."""
    return (0.3, 2.5) if _RADIAL.match(name) else (-2.5, 2.5)


@dataclass(frozen=True)
class Space:
    """The independent variables of a problem: coordinates with their jets, t, and parameters
    with domains (and, for a numeric variant, the values on its handout)."""

    jets: tuple[Jet, ...]
    parameters: Mapping[sp.Symbol, Domain]
    values: Mapping[sp.Symbol, float] = field(default_factory=dict)
    coordinate_domains: Mapping[str, tuple[float, float]] = field(default_factory=dict)

    @cached_property
    def jet_symbols(self) -> frozenset[sp.Symbol]:
        return frozenset(s for j in self.jets for s in (j.q, j.dot, j.ddot))

    def draw(
        self,
        seed: int,
        free: Iterable[sp.Symbol] | None = None,
        valid: Callable[[dict], np.ndarray] | None = None,
        groups: int = GROUPS,
        per_group: int = PER_GROUP,
    ) -> Points:
        """Sample points: `groups` parameter draws, each with `per_group` draws of (q, q̇, q̈, t).

        Parameters in `free` (default: all) are drawn from their domains; the others keep the
        variant's values when it has them. Points where `valid` (the reference is finite) says
        no are redrawn; a group whose parameters leave the reference undefined is redrawn whole.
        Groups still missing then are searched for where the reference is defined on a small
        part of the box only (`_search`).

        Most draws keep every point of their first blocks: those are drawn at once and `valid`
        asked once (`_first_blocks`); only a draw where some point fails goes group by group.
        """
        free_set = set(self.parameters) if free is None else set(free)
        first = self._first_blocks(seed, free_set, valid, groups, per_group)
        if first is not None:
            return first
        return self._draw_by_groups(seed, free_set, valid, groups, per_group)

    def _first_blocks(
        self, seed: int, free: set, valid: Callable | None, groups: int, per_group: int
    ) -> Points | None:
        """The draw when `valid` keeps every point of the first block of every group: then the
        group-by-group loop would ask for nothing more, and these are its points exactly (the
        same random numbers in the same order, `_blocks`). None otherwise, the stream untouched
        for the loop (it starts again from `seed`).

        One call of `valid` on all the points stands for one per group because every validity
        test of a draw is pointwise — a point's verdict is its own, whatever else is asked with
        it (elementwise arithmetic, per-point determinants, per-point high precision) — or at
        least keeps every point of a group whenever it keeps every point of a union of groups
        (`lagrangian_mask` asks `finite_mask` about all the points when float64 fails at one).
        A test that raises here (a point where a matrix has no factorisation) is left to the
        loop too: it may never reach that point, or raise there as it always has."""
        if groups < 1:
            return None
        env = self._blocks(np.random.default_rng(seed), free, per_group, groups)
        if env is None:
            return None
        if valid is not None:
            try:
                ok = valid(env)
            except Exception:  # noqa: BLE001 - the loop raises it, or not, as before
                return None
            if not ok.all():
                return None
        return Points(env, np.repeat(np.arange(groups), per_group))

    def _draw_by_groups(
        self, seed: int, free_set: set, valid: Callable | None, groups: int, per_group: int
    ) -> Points:
        """The draw group by group, each redrawn where `valid` says no (`draw`)."""
        rng = np.random.default_rng(seed)
        chosen: list[dict[sp.Symbol, np.ndarray]] = []
        for _ in range(groups):
            for attempt in range(len(WIDEN) * 2):
                block = self._group(rng, free_set, per_group, widen=WIDEN[attempt // 2])
                if valid is None:
                    chosen.append(block)
                    break
                ok = valid(block)
                for _redraw in range(4):
                    if ok.all():
                        break
                    fresh = self._group(
                        rng, free_set, per_group, params_from=block, widen=WIDEN[attempt // 2]
                    )
                    ok_fresh = valid(fresh)
                    for s in block:
                        block[s] = np.where(ok, block[s], fresh[s])
                    ok = ok | ok_fresh
                if ok.all():
                    chosen.append(block)
                    break
        if valid is not None and len(chosen) < groups:
            chosen += self._search(rng, free_set, valid, groups - len(chosen), per_group)
        if len(chosen) < max(1, groups // 2):
            raise ReferenceUndefined(
                "the reference answer is undefined at every point drawn from the declared domains"
            )
        env = {s: np.concatenate([b[s] for b in chosen]) for s in chosen[0]}
        group = np.repeat(np.arange(len(chosen)), per_group)
        return Points(env, group)

    def _search(self, rng, free: set, valid: Callable, missing: int, per_group: int) -> list:
        """Up to `missing` groups where the reference is defined, by rejection sampling over
        sub-boxes: where it is defined on a small part of the box only (the pendulum's
        sqrt(l² − x²) with |x| < l = 0.1, a product of square roots of signed parameters: a
        sixteenth of the box), a pilot of points spread over the whole box (each with its own
        parameters, near 0 included) finds that part; each group takes the parameters of one
        pilot point that lands in it, and its other points are drawn in ever smaller boxes
        around that point, keeping those where the reference is defined."""
        for widen in WIDEN:
            box = self._box(free, widen)
            for n in PILOT:
                pilot = self._uniform(rng, box, n)
                inside = np.flatnonzero(valid(pilot))
                if inside.size:
                    rng.shuffle(inside)
                    return [
                        self._around(rng, pilot, int(i), box, valid, per_group)
                        for i in inside[:missing]
                    ]
        return []

    def _box(self, free: set, widen: float) -> dict:
        """The range of every variable drawn per point: free parameters, q, q̇, q̈ and t; a
        parameter that is not free keeps its value (a range of one point)."""
        box = {}
        for s, dom in self.parameters.items():
            fixed = s not in free and s in self.values
            box[s] = (float(self.values[s]),) * 2 if fixed else dom.sample_range(widen)
        for j in self.jets:
            box[j.q] = self.coordinate_domains.get(j.name) or coordinate_range(j.name)
            box[j.dot] = box[j.ddot] = (-2.0, 2.0)
        box[t] = (0.1, 3.0)
        return box

    @staticmethod
    def _uniform(rng, box: Mapping, n: int) -> dict:
        return {s: rng.uniform(lo, hi, n) for s, (lo, hi) in box.items()}

    def _around(self, rng, pilot: dict, i: int, box: Mapping, valid: Callable, k: int) -> dict:
        """A group with pilot point i's parameters: that point, and k − 1 points where the
        reference is defined drawn in boxes around it, 1/8, 1/32, then 1/128 of each range wide
        (the point itself again when none is found: a repeated point, never a wrong one)."""
        block = {s: np.full(k, v[i]) for s, v in pilot.items()}
        have = 1
        motion = [s for s in box if s not in self.parameters]
        for share in (1 / 8, 1 / 32, 1 / 128):
            if have == k or not motion:
                break
            near = {s: np.full(SUB_BOX_DRAWS, v[i]) for s, v in pilot.items()}
            for s in motion:
                lo, hi = box[s]
                half = share * (hi - lo) / 2
                centre = pilot[s][i]
                near[s] = rng.uniform(max(lo, centre - half), min(hi, centre + half), SUB_BOX_DRAWS)
            good = np.flatnonzero(valid(near))[: k - have]
            for s in motion:
                block[s][have : have + good.size] = near[s][good]
            have += good.size
        return block

    def _group(
        self, rng, free: set, k: int, params_from: dict | None = None, widen: float = 1.0
    ) -> dict:
        block: dict[sp.Symbol, np.ndarray] = {}
        for s, dom in self.parameters.items():
            if params_from is not None:
                block[s] = params_from[s]
            elif s not in free and s in self.values:
                block[s] = np.full(k, float(self.values[s]))
            else:
                block[s] = np.full(k, rng.uniform(*dom.sample_range(widen)))
        for j in self.jets:
            lo, hi = self.coordinate_domains.get(j.name) or coordinate_range(j.name)
            block[j.q] = _away_from_zero(rng, lo, hi, k)
            block[j.dot] = _away_from_zero(rng, -2.0, 2.0, k)
            block[j.ddot] = _away_from_zero(rng, -2.0, 2.0, k)
        block[t] = rng.uniform(0.1, 3.0, k)
        return block

    def _blocks(self, rng, free: set, k: int, count: int) -> dict | None:
        """`count` first blocks of k points, as `count` successive `_group` calls (widen 1)
        draw them, concatenated, from one call of the generator: each `rng.uniform(lo, hi, n)`
        there is lo + (hi − lo)·u of the next n doubles of the stream, and the calls' counts
        do not depend on the values drawn, so the stream can be cut up in advance. None when a
        range is one `rng.uniform` refuses (the group-by-group draw raises its error)."""
        plan = self._stream_plan(free)
        if any(not _drawable(lo, hi) for _, _, lo, hi in plan):
            return None
        width = sum(_stream_width(kind, k) for _, kind, _, _ in plan)
        u = rng.random(count * width).reshape(count, width)
        block: dict[sp.Symbol, np.ndarray] = {}
        col = 0
        for s, kind, lo, hi in plan:
            n = _stream_width(kind, k)
            block[s] = _from_uniform(kind, lo, hi, u[:, col : col + n], k).reshape(-1)
            col += n
        return block

    def _stream_plan(self, free: set) -> list[tuple[sp.Symbol, str, float, float]]:
        """What `_group` draws, in order: (symbol, kind, lo, hi) with kind "fixed" (a handout
        value, lo, drawing nothing), "group" (one value per group), "point" (one per point) or
        "away" (one per point, then one more per point for `_away_from_zero`)."""
        plan = []
        for s, dom in self.parameters.items():
            if s not in free and s in self.values:
                value = float(self.values[s])
                plan.append((s, "fixed", value, value))
            else:
                plan.append((s, "group", *dom.sample_range(1.0)))
        for j in self.jets:
            lo, hi = self.coordinate_domains.get(j.name) or coordinate_range(j.name)
            for s, (a, b) in ((j.q, (lo, hi)), (j.dot, (-2.0, 2.0)), (j.ddot, (-2.0, 2.0))):
                plan.append((s, "away" if a < 0 < b else "point", a, b))
        plan.append((t, "point", 0.1, 3.0))
        return plan


#: How far the unbounded sides of the domains are stretched on successive attempts to find
#: points where the reference is defined (two attempts each): the physical scale first.
WIDEN = (1.0, 10.0, 100.0)
#: Points of the pilots that look for the part of the box where a reference is defined, and
#: candidates drawn per sub-box around a point found there.
PILOT = (512, 8192)
SUB_BOX_DRAWS = 64


def _drawable(lo: float, hi: float) -> bool:
    """Whether rng.uniform(lo, hi) draws (it refuses a range that is negative or not finite)."""
    span = float(hi) - float(lo)
    return math.isfinite(span) and span >= 0


def _stream_width(kind: str, k: int) -> int:
    """Doubles of the stream a symbol of `_stream_plan` takes per group of k points."""
    return {"fixed": 0, "group": 1, "point": k, "away": 2 * k}[kind]


def _from_uniform(kind: str, lo: float, hi: float, u: np.ndarray, k: int) -> np.ndarray:
    """A symbol's values (groups, k) from its doubles u (groups, width): the arithmetic of
    `rng.uniform` (lo + (hi − lo)·u) and of `_away_from_zero`, elementwise, so every value is
    the one the group-by-group draw makes."""
    lo, hi = float(lo), float(hi)
    if kind == "fixed":
        return np.full((u.shape[0], k), lo)
    x = lo + (hi - lo) * u[:, :k]
    if kind == "group":
        return np.repeat(x, k, axis=1)
    if kind == "away":
        near = np.abs(x) < 0.2
        x = np.where(near, np.sign(x + 1e-300) * (0.2 + (0.0 + 0.3 * u[:, k:])), x)
    return x


def _away_from_zero(rng, lo: float, hi: float, k: int) -> np.ndarray:
    """Uniform in (lo, hi) but with |x| ≥ 0.2 when the range straddles 0."""
    x = rng.uniform(lo, hi, k)
    if lo < 0 < hi:
        near = np.abs(x) < 0.2
        x = np.where(near, np.sign(x + 1e-300) * (0.2 + rng.uniform(0, 0.3, k)), x)
    return x


@dataclass
class Points:
    """Sample points as arrays, one entry per point, and the parameter group of each point.
    `complex_values`: the reference is complex at some of them (a logarithm or root of a
    negative number, the declared imaginary unit), so values there are compared in complex
    arithmetic on principal branches (`backends`)."""

    env: dict[sp.Symbol, np.ndarray]
    group: np.ndarray
    _mp_env: dict | None = None
    complex_values: bool = False

    @property
    def n(self) -> int:
        return len(self.group)

    @property
    def backends(self) -> tuple:
        """(float, high precision) backends the values at these points are computed in."""
        return (COMPLEX, MP_COMPLEX) if self.complex_values else (FLOAT, MP)

    def arrays(self, backend=FLOAT) -> dict:
        if backend is FLOAT or backend is COMPLEX:
            return self.env
        if self._mp_env is None:
            self._mp_env = {s: MP.array(v) for s, v in self.env.items()}
        return self._mp_env

    def point(self, i: int, symbols: Iterable[sp.Symbol] | None = None) -> dict[str, float]:
        """Point i as {name: value} (the witness of a difference), for the named symbols."""
        keep = self.env if symbols is None else [s for s in symbols if s in self.env]
        names = {s: s.name for s in keep}  # not str(s): sympy's printer is slow
        return {
            names[s]: float(f"{float(self.env[s][i]):.6g}") for s in sorted(keep, key=names.get)
        }


_MEMO: dict = {}
_MEMO_SIZE = 256


def memo_inputs(kind: str, env: Mapping, jets: Sequence[Jet], make: Callable[[], dict]) -> dict:
    """Inputs derived from the sample points alone (tiled copies, hyper-dual seeds), built once
    per points instead of once per answer. float64 only; the entry holds `env` itself, so an
    id is never mistaken for another's. Sample points never change once drawn; an env that
    did would be served stale inputs. Callers must not modify what they get."""
    key = (kind, id(env), tuple(jets))
    hit = _MEMO.get(key)
    if hit is not None and hit[0] is env:
        return hit[1]
    value = make()
    if len(_MEMO) >= _MEMO_SIZE:
        _MEMO.clear()
    _MEMO[key] = (env, value)
    return value
