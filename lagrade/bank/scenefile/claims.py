"""What a quantity claims about the motion, and the check of that claim against the derived
equations of motion, as the bank's tests check the bank's quantities.

A quantity's `check` table says what its value is:

    check = { accelerations = { q = "block_acceleration" } }            # q̈ in any state
    check = { at = { theta = "equilibrium_angle", theta_dot = "0" },    # an equilibrium
              accelerations = { theta = "0" } }
    check = { at = { theta = "0", theta_dot = "0" },                    # normal modes at rest
              frequencies = ["small_oscillation_frequency"] }

`at` fixes coordinates and velocities (what it leaves out takes arbitrary values), in the
parameters, the options' names and the scene's quantities; `accelerations` are the values q̈ takes
there (they may use the state: `growth_rate^2 r`); `frequencies` are all the normal-mode angular
frequencies of the linearized motion about the state `at`, which must fix every coordinate.
The check is numeric, at the scene's own parameter draws, in 50-digit arithmetic.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from lagrade.bank.scenefile.declaration import Declaration, QuantityDecl
from lagrade.bank.scenefile.fields import Problems, expression
from lagrade.mechanics import exact_number
from lagrade.mechanics import lagrange as mech

_DIGITS = 50


@dataclass(frozen=True)
class Claim:
    """A quantity's claim: the state `at` (coordinate and velocity symbols → values), the
    accelerations there (coordinate symbol → q̈), the normal-mode angular frequencies."""

    at: Mapping[sp.Symbol, sp.Expr]
    accelerations: Mapping[sp.Symbol, sp.Expr]
    frequencies: tuple[sp.Expr, ...] = ()

    def resolved(
        self, put: Callable[[sp.Expr], sp.Expr], subs: Mapping[sp.Symbol, sp.Expr]
    ) -> Claim:
        """The claim in a variant's symbols: keys renamed, values resolved by `put`."""
        return Claim(
            {subs.get(k, k): put(v) for k, v in self.at.items()},
            {subs.get(k, k): put(v) for k, v in self.accelerations.items()},
            tuple(put(f) for f in self.frequencies),
        )


def read_claim(q: QuantityDecl, d: Declaration, reader: Any, problems: Problems) -> Claim | None:
    """The claim of quantity `q`'s `check` table, its expressions read in the state vocabulary."""
    check = q.check or {}
    key = f"{q.key}.check"
    jets = reader.jets
    names = {j.name: j.q for j in jets.values()} | {j.dot.name: j.dot for j in jets.values()}
    at, ok_at = _read_table(
        check,
        "at",
        key,
        names,
        "coordinates and velocities",
        "coordinate or a coordinate's velocity",
        reader,
        problems,
    )
    by_q = {name: j.q for name, j in jets.items()}
    accelerations, ok_acc = _read_table(
        check, "accelerations", key, by_q, "coordinates", "coordinate", reader, problems
    )
    ok = ok_at and ok_acc
    raw_acc = check.get("accelerations", {})
    raw_acc = raw_acc if isinstance(raw_acc, dict) else {}
    frequencies = []
    raw_freq = check.get("frequencies", [])
    if not isinstance(raw_freq, list) or len(raw_freq) > len(jets):
        problems.add(f"{key}.frequencies", f"is not a list of at most {len(jets)} expressions")
        raw_freq, ok = [], False
    for i, value in enumerate(raw_freq, 1):
        read = reader.read(expression(value, f"{key}.frequencies[{i}]", problems), "state")
        ok &= read is not None
        if read is not None:
            frequencies.append(read)
    if raw_freq and not all(jets[c].q in at for c in jets):
        problems.add(f"{key}.at", "normal modes need the state: give every coordinate")
        ok = False
    if not raw_acc and not raw_freq:
        problems.add(key, "says nothing to check: give accelerations or frequencies")
        ok = False
    mentioned = set().union(
        *(e.free_symbols for e in [*at.values(), *accelerations.values(), *frequencies])
    )
    if ok and sp.Symbol(q.name, real=True) not in mentioned:
        problems.add(key, f"does not mention {q.name}, so it would not check its value")
        ok = False
    return Claim(at, accelerations, tuple(frequencies)) if ok else None


# --- checking a claim -----------------------------------------------------------------------------


def parameter_points(variant: Any, count: int = 3) -> list[dict[sp.Symbol, sp.Expr]]:
    """The scene's own numeric draws as exact rationals; a parameter without a pool is drawn
    from its domain."""
    points = []
    for seed in range(count):
        drawn = variant.scene.variant(seed).values
        rng = random.Random(seed)
        point = {}
        for name, symbol in variant.parameter_symbols.items():
            value = drawn.get(name)
            if value is None:
                value = rng.uniform(*variant.domains[name].sample_range())
            point[symbol] = exact_number(value)
        points.append(point)
    return points


def _read_table(
    check: Mapping,
    field: str,
    key: str,
    allowed: Mapping[str, sp.Symbol],
    plural: str,
    singular: str,
    reader: Any,
    problems: Problems,
) -> tuple[dict[sp.Symbol, sp.Expr], bool]:
    """One table of a `check` (`at` or `accelerations`): each name one of `allowed`, each value
    an expression read in the state vocabulary; the problems noted, and whether it all read."""
    found: dict[sp.Symbol, sp.Expr] = {}
    ok = True
    raw = check.get(field, {})
    if not isinstance(raw, dict):
        problems.add(f"{key}.{field}", f"is not a table of {plural}")
        return found, False
    for name, value in raw.items():
        if name not in allowed:
            problems.add(f"{key}.{field}.{name}", f"is not a {singular}")
            ok = False
            continue
        read = reader.read(expression(value, f"{key}.{field}.{name}", problems), "state")
        ok &= read is not None
        if read is not None:
            found[allowed[name]] = read
    return found, ok


def _number(expr: sp.Expr, point: Mapping) -> sp.Expr:
    """expr at `point`, kept exact (cos(pi/2) is 0, not 1e-51), after checking that it is a
    finite real number there."""
    exact = expr.xreplace(point)
    value = sp.N(exact, _DIGITS)
    if not value.is_number or value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise ArithmeticError(f"{expr} has no finite value there")
    if abs(sp.im(value)) > 10 ** (-_DIGITS // 2) * (1 + abs(sp.re(value))):
        raise ArithmeticError(f"{expr} is not real there")
    return exact


def check_claim(variant: Any, claim: Claim) -> list[str]:
    """Where the derived motion contradicts the claim (empty: it holds at every point tried)."""
    failures: list[str] = []
    system = variant.system
    A, b = system.mass_matrix, system.forcing
    for n, params in enumerate(parameter_points(variant)):
        rng = random.Random(1000 + n)
        point = dict(params)
        for j in variant.jets:
            domain = variant.coordinate_domains.get(j.name)  # where the coordinate lives
            span = domain.sample_range() if domain is not None else (0.2, 1.2)
            point[j.q] = claim.at.get(j.q, sp.Float(rng.uniform(*span), _DIGITS))
            point[j.dot] = claim.at.get(j.dot, sp.Float(rng.uniform(-1.0, 1.0), _DIGITS))
        point[mech.t] = sp.Float(rng.uniform(0, 1), _DIGITS)
        try:
            state = {k: _number(v, params) for k, v in point.items()}
            if claim.accelerations:
                failures += _check_accelerations(variant, claim, A, b, state)
            if claim.frequencies:
                failures += _check_frequencies(variant, claim, A, b, state)
        except (ArithmeticError, ValueError, TypeError, np.linalg.LinAlgError) as error:
            failures.append(f"cannot evaluate at the scene's values: {error}")
        if failures:
            return failures
    return failures


def _matrices(A: sp.Matrix, b: sp.Matrix, state: Mapping) -> tuple[sp.Matrix, sp.Matrix, list]:
    An = A.xreplace(state).evalf(_DIGITS)
    bn = b.xreplace(state).evalf(_DIGITS)
    # how large b's terms are: a claim is off when it misses by more than rounding of those
    sizes = [
        sum(abs(_number(term, state).evalf(_DIGITS)) for term in sp.Add.make_args(bi)) for bi in b
    ]
    return An, bn, sizes


def _check_accelerations(variant: Any, claim: Claim, A, b, state) -> list[str]:
    An, bn, sizes = _matrices(A, b, state)
    got = An.LUsolve(bn)
    inverse = An.inv()
    failures = []
    for k, j in enumerate(variant.jets):
        if j.q not in claim.accelerations:
            continue
        want = sp.N(_number(claim.accelerations[j.q], state), _DIGITS)
        scale = max([abs(want)] + [abs(inverse[k, i]) * sizes[i] for i in range(len(sizes))])
        if abs(got[k] - want) > 1e-20 * scale or (scale == 0 and got[k] != 0):
            failures.append(
                f"{j.ddot.name} is {sp.N(got[k], 8)} there, not {sp.N(want, 8)} "
                f"(at {_shown_state(variant, state)})"
            )
    return failures


def _check_frequencies(variant: Any, claim: Claim, A, b, state) -> list[str]:
    rest = dict(state) | {j.dot: sp.S.Zero for j in variant.jets}
    An, bn, sizes = _matrices(A, b, rest)
    for value, size in zip(bn, sizes, strict=True):
        if abs(value) > 1e-20 * max(size, 1e-300):
            return [f"the state {_shown_state(variant, rest)} is not an equilibrium at rest"]
    K = sp.Matrix([[-sp.diff(bi, j.q) for j in variant.jets] for bi in b])
    Kn = np.array(K.xreplace(rest).evalf(30).tolist(), dtype=float)
    Af = np.array(An.evalf(30).tolist(), dtype=float)
    got = sorted(np.linalg.eigvals(np.linalg.solve(Af, Kn)).real)
    want = sorted(float(sp.N(_number(f, rest), _DIGITS)) ** 2 for f in claim.frequencies)
    if len(want) < len(got):  # the frequencies not listed are the zero modes
        want = sorted([0.0] * (len(got) - len(want)) + want)
    top = max([abs(x) for x in got + want] + [1e-300])
    if not np.allclose(got, want, rtol=1e-7, atol=1e-9 * top):
        shown = ", ".join(f"{np.sqrt(abs(x)):.6g}" for x in got)
        return [f"the normal-mode angular frequencies are {shown} there"]
    return []


def _shown_state(variant: Any, state: Mapping) -> str:
    parts = [
        f"{s.name} = {float(state[s]):.4g}"
        for j in variant.jets
        for s in (j.q, j.dot)
        if s in state
    ]
    return ", ".join(parts)
