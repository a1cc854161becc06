"""The claims of the set-up and small-oscillation parts (`dof`, `coordinates`, `transformation`,
`equilibrium`, `normal_modes`, `mode_shapes`), each with the correction it implies or a check by
values with the handout's parameters; read by `claims.py`, whose `Claim` and `one` they use.
A localisation that names no mistake ("your positions violate the constraint …", "(K − ω² M)
a ≠ 0") is no claim here; its numbers are checked by `quoted_frequencies`."""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from lagrade.judge.mutations import swap_sin_cos
from lagrade.mechanics import phase_space
from lagrade.mechanics.oscillations import variant_oscillations
from lagrade.notation import plain

_NUMBER = r"(−?[\d.]+)"


def setup_claims(body: str, w, ref, one) -> list | None:
    """dof, coordinates and transformation sentences; None for another part."""
    if w.part == "dof":
        if body.startswith("You counted") and "subtracted no constraints" in body:
            n = int(body.split()[2])
            return one("no_constraints", None, also=lambda: n == sum(
                b.freedoms for b in ref.variant.bodies))  # fmt: skip
        if body.startswith("Motion in a plane is a constraint too"):
            implied = sum(1 for label, _ in ref.variant.constraints if label != "declared")
            return one("forgot_planarity", None, also=lambda: w.exprs[0] == ref.variant.dof
                       + implied)  # fmt: skip
        return []
    if w.part == "coordinates":
        m = re.match(
            r"^A coordinate's velocity or acceleration is not a coordinate \((.+)\)$", body
        )
        if m:
            names = m.group(1).split(", ")
            fixed = tuple(x.removesuffix("_dot") if x in names else x for x in w.exprs)
            return one("velocity_named", fixed)
        m = re.match(r"^Your list lacks (.+)$", body)
        if m:
            return one("coordinate_missing", tuple(w.exprs) + tuple(m.group(1).split(", ")))
        return []
    if w.part != "transformation":
        return None
    lines = dict(w.exprs)

    def fixed(name: str, new: sp.Expr):
        if name not in lines:
            return one("?", None)
        return tuple((n, new if n == name else e) for n, e in w.exprs)

    def student_term(name: str, shown: str):
        return next((x for x in sp.Add.make_args(sp.expand(lines.get(name, 0)))
                     if plain(x) == shown), None)  # fmt: skip

    m = re.match(r"^(\w+) has the wrong sign$", body)
    if m and m.group(1) in lines:
        return one("line_sign", fixed(m.group(1), -lines[m.group(1)]))
    m = re.match(r"^Sin and cos are swapped in (\w+)$", body)
    if m and m.group(1) in lines:
        return one("line_swap", fixed(m.group(1), swap_sin_cos(lines[m.group(1)])))
    m = re.match(r"^(\w+) lacks the term (.+?)(, the .*)?$", body)
    if m and m.group(1) in lines:
        statement = ref.variant.transformation.get(m.group(1), sp.S.Zero)
        t = next((x for x in sp.Add.make_args(sp.expand(statement)) if plain(x) == m.group(2)),
                 None)  # fmt: skip
        if t is None:
            return one("missing_term", None)
        return one("missing_term", fixed(m.group(1), lines[m.group(1)] + t))
    m = re.match(r"^The term (.+) in (\w+) (has the wrong sign|is twice what it should be|is "
                 r"half what it should be|has the length (\w+) where (\w+) belongs)$",
                 body)  # fmt: skip
    if m is None:
        m2 = re.match(r"^Sin and cos are swapped in the term (.+) of (\w+)$", body)
        if m2 is None:
            return []
        s = student_term(m2.group(2), m2.group(1))
        if s is None:
            return one("term_swap", None)
        return one("term_swap", fixed(m2.group(2), lines[m2.group(2)] - s + swap_sin_cos(s)))
    name, s = m.group(2), student_term(m.group(2), m.group(1))
    if s is None:
        return one("term", None)
    X = lines[name]
    if m.group(3) == "has the wrong sign":
        return one("term_sign", fixed(name, X - 2 * s))
    if m.group(4):
        symbols = {str(x): x for x in ref.variant.parameter_symbols.values()}
        a, b = symbols.get(m.group(4)), symbols.get(m.group(5))
        if a is None or b is None:
            return one("wrong_length", None)
        return one("wrong_length", fixed(name, X - s + s.xreplace({a: b})))
    c = 2 if "twice" in m.group(3) else sp.Rational(1, 2)
    return one("term_factor", fixed(name, X - s + s / c))


def _handout(ref) -> dict:
    return {s: float(ref.variant.values[n]) for n, s in ref.variant.parameter_symbols.items()}


def _gradient_hessian(ref, point: dict, values: dict):
    """∂U/∂q and ∂²U/∂q∂q and A at `point` (coordinate → value) with `values`."""
    hs = phase_space(ref.system)
    U = hs.effective_potential
    qs = [j.q for j in ref.jets]
    at = {**values, **{q: point.get(q, 0) for q in qs}}
    g = np.array([complex(sp.N(sp.diff(U, q).xreplace(at))) for q in qs])
    H = np.array(sp.N(sp.hessian(U, qs).xreplace(at)).tolist(), dtype=complex).real
    A = np.array(sp.N(hs.velocity_matrix.xreplace(at)).tolist(), dtype=complex).real
    return g, H, A, float(np.abs(sp.N(U.xreplace(at))) + 1)


def oscillation_claims(body: str, w, ref, one) -> list | None:
    """equilibrium, normal_modes and mode_shapes sentences; None for another part."""
    if w.part == "equilibrium":
        point = dict(w.exprs)
        values = _handout(ref)
        if "is an equilibrium, but not a stable one" in body:

            def unstable():
                at = {q: float(sp.N(v.xreplace(values))) for q, v in point.items()}
                g, H, A, size = _gradient_hessian(ref, at, values)
                from scipy.linalg import eigh

                lam = eigh(H, A, eigvals_only=True)
                return bool(np.all(np.abs(g) < 1e-9 * size) and lam.min() < -1e-9 * abs(lam).max())

            return one("unstable", None, also=unstable)
        if body.startswith("The system does not stay at rest at"):

            def moves():
                at = {q: float(sp.N(v.xreplace(values))) for q, v in point.items()}
                g, *_, size = _gradient_hessian(ref, at, values)
                return bool(np.any(np.abs(g) > 1e-6 * size))

            return one("not_equilibrium", None, also=moves)
        return []
    if w.part not in ("normal_modes", "mode_shapes"):
        return None
    osc = variant_oscillations(ref.variant)
    # a generic point near the handout's values (where two frequencies may coincide: k = k_z
    # makes k_z/m equal to √(k_z/m) at m = 1)
    values = {
        ref.variant.parameter_symbols[n]: x * (1 + 0.03 * (i + 1))
        for i, (n, x) in enumerate(sorted(ref.variant.values.items()))
    }
    modes = [float(x) for x in osc.numeric_frequencies(values) if x > 0]
    freq = [x if w.part == "normal_modes" else x[0] for x in w.exprs]
    given = [float(sp.N(f.xreplace(values))) for f in freq]

    def one_is(f) -> bool:  # some item is f(ω) of a mode, and no mode's frequency
        for x in given:
            if not any(abs(x - m) <= 1e-6 * m for m in modes) and any(
                abs(x - f(m)) <= 1e-6 * abs(f(m)) for m in modes
            ):
                return True
        return False

    slips = {
        "this is ω², not the angular frequency ω": ("squared", lambda m: m**2),
        "this is the frequency ω/2π in cycles": ("cycles", lambda m: m / (2 * np.pi)),
        "this is the period 2π/ω": ("period", lambda m: 2 * np.pi / m),
        "this is √2 times a normal-mode frequency": ("factor_two", lambda m: np.sqrt(2) * m),
        "this is a normal-mode frequency divided by √2": ("factor_half", lambda m: m / np.sqrt(2)),
    }
    for said, (kind, f) in slips.items():
        if said in body:
            return one(kind, None, also=lambda f=f: one_is(f))
    m = re.search(r"this is √\(K/M\) of (\S+) alone", body)
    if m:
        K, M = osc.numeric(osc.stable, values)
        alone = [float(np.sqrt(K[k, k] / M[k, k])) for k in range(len(K)) if K[k, k] > 0]
        return one(
            "uncoupled",
            None,
            also=lambda: (
                any(abs(x - a) <= 1e-6 * a for x in given for a in alone)
                and not one_is(lambda m: m)
            ),
        )
    m = re.match(r"^(\d+) normal(?:-mode)? (?:frequency is|frequencies are|mode is|modes are) "
                 r"missing \((\d+) in all\)$", body)  # fmt: skip
    if m:
        n, total = int(m.group(1)), int(m.group(2))
        return one("missing_mode", None, also=lambda: total == len(modes) and n == total - len(
            [x for x in given if any(abs(x - q) <= 1e-6 * q for q in modes)]))  # fmt: skip
    if w.part == "mode_shapes" and "this is the shape of the mode at ω =" in body:
        return one("swapped", None, also=lambda: _some_vector(w, ref, osc, values, "swapped"))
    if w.part == "mode_shapes" and "this is an eigenvector of K alone" in body:
        return one("mass_ignored", None, also=lambda: _some_vector(w, ref, osc, values, "K"))
    return []


def _some_vector(w, ref, osc, values, kind: str) -> bool:
    """Some line's vector is another mode's shape (`swapped`) or an eigenvector of K alone and
    no mode's shape (`K`), at the handout's values."""
    K, M = osc.numeric(osc.stable, values)
    lam = [m**2 for m in osc.numeric_frequencies(values) if m > 0]
    for omega, vector in w.exprs:
        a = np.array([float(sp.N(sp.S(x).xreplace(values))) for x in vector])
        own = float(sp.N(omega.xreplace(values))) ** 2
        fits = [abs(np.linalg.norm((K - x * M) @ a)) <= 1e-7 * np.linalg.norm(K) * np.linalg.norm(a)
                for x in lam]  # fmt: skip
        mine = [abs(x - own) <= 1e-6 * x for x in lam]
        if kind == "swapped" and any(f and not me for f, me in zip(fits, mine, strict=True)):
            return True
        if kind == "K" and not any(fits):
            Ka = K @ a
            mu = Ka @ a / (a @ a)
            if np.linalg.norm(Ka - mu * a) <= 1e-7 * np.linalg.norm(K) * np.linalg.norm(a):
                return True
    return False


def quoted_frequencies(sentence: str, witness: dict | None, ref) -> list[str]:
    """ "(with your handout's values, the frequencies are 0.576, 1.21 rad/s)" and "the mode at
    ω = 1.15 rad/s, not of ω = 2.3 (at the first point drawn)": the frequencies at the
    witness's parameters, which must be the student's own handout values where it says so."""
    handout = "with your handout's values" in sentence
    if not handout and "at the first point drawn" not in sentence:
        return []
    if handout and witness != {n: float(v) for n, v in ref.variant.values.items()}:
        return [f"{sentence[:60]}… (the witness is not the handout's values)"]
    if not witness:
        return [f"{sentence[:60]}… (no witness)"]
    symbols = ref.variant.parameter_symbols
    at = {symbols[n]: v for n, v in witness.items() if n in symbols}
    osc = variant_oscillations(ref.variant)
    got = [x for x in osc.numeric_frequencies(at) if x > 0]
    m = re.search(r"the frequencies are ([\d., ]+) rad/s", sentence)
    quoted = [float(x) for x in m.group(1).split(", ")] if m else []
    quoted += [float(x) for x in re.findall(r"ω = (\d+(?:\.\d+)?)", sentence)]
    out = []
    for q in quoted:
        if not any(abs(float(f"{g:.3g}") - q) <= 1e-9 + 1e-3 * q for g in got):
            out.append(f"{q} (the witness's parameters give {[round(g, 4) for g in got]})")
    return out
