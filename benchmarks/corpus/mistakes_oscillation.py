"""Wrong answers with a recorded cause for the small-oscillation parts: `equilibrium`,
`normal_modes` and `mode_shapes`. Read through `mistakes.MAKERS`; each cause cites where it is
motivated (`SOURCES`).

Where the causes come from (cited from memory of the texts, not checked against a copy here):

- Taylor, *Classical Mechanics*, §5.1 and §11.1–11.5 (stable equilibria where U is a minimum,
  the coupled carts, the double pendulum): the unstable equilibrium (θ = π) offered, ω² given
  for ω, one of the two modes left out, the frequency of one coordinate alone √(K_ii/M_ii)
  (the coupling ignored: a pendulum on a cart given √(g/l)), the modes' shapes exchanged.
- Goldstein, Poole, Safko §6.2–6.3: K a = ω² M a, not the eigenvectors of K alone (the mass
  matrix forgotten), and the frequency in cycles (ν = ω/2π) for ω.
- Landau–Lifshitz §21–23: a factor 2 lost from the ½ of T or of V (ω² twice or half), and the
  sign of an equilibrium's displacement (x₀ = −m g/k for m g/k).
"""

from __future__ import annotations

import random
from collections.abc import Iterator

import numpy as np
import sympy as sp
from mistakes import Wrong

from lagrade.bank.registry import get_scene
from lagrade.mechanics.oscillations import variant_oscillations
from lagrade.notation import plain

SOURCES = {
    "EQ_unstable": "Taylor §5.1, §11.1 (U a maximum: θ = π)",
    "EQ_wrong_angle": "Taylor ch. 7 (the angle from the horizontal for the vertical's)",
    "EQ_term_sign": "Landau–Lifshitz §21 (the sign of the displacement)",
    "NM_squared": "Taylor §11.2 (ω² given for ω)",
    "NM_missing": "Taylor §11.2 (one frequency per coordinate)",
    "NM_uncoupled": "Taylor §11.4 (√(K_ii/M_ii) of one coordinate: the coupling ignored)",
    "NM_cycles": "Goldstein §6.2 (ν = ω/2π for ω)",
    "NM_factor_two": "Landau–Lifshitz §21 (a ½ of T or V lost: ω² twice what it is)",
    "MS_swapped": "Taylor §11.2 (the two modes' shapes exchanged)",
    "MS_K_alone": "Goldstein §6.2 (K a = λ a: the mass matrix forgotten)",
    "MS_missing": "Taylor §11.2 (one mode per oscillating coordinate)",
}


def _values(v) -> dict:
    return {v.parameter_symbols[n]: x for n, x in v.values.items()}


def _differs(a: sp.Expr, b: sp.Expr, values: dict) -> bool:
    try:
        return abs(complex(sp.N((a - b).xreplace(values)))) > 1e-9 * (
            1 + abs(complex(sp.N(b.xreplace(values))))
        )
    except (TypeError, ValueError):
        return True


def oscillation_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """The wrong equilibrium, normal_modes and mode_shapes answers of one variant."""
    v = get_scene(sid).variant(seed)
    osc = variant_oscillations(v)
    if osc.why_not is not None:
        return
    spec = {"scene": sid, "seed": seed}
    jets, values = v.jets, _values(v)
    eq = osc.stable
    at = {j.q: eq.at.get(j.q, sp.S.Zero) for j in jets}

    def equilibrium(point: dict, cause: str) -> Wrong:
        lines = [f"{j.name} = {plain(point[j.q])}" for j in jets if j.name not in eq.free]
        return Wrong(spec, "equilibrium", lines, cause, tuple(point.items()))

    for other in osc.equilibria:
        if other is not eq and not osc.is_stable(other):
            yield equilibrium({j.q: other.at.get(j.q, sp.S.Zero) for j in jets}, "EQ_unstable")
            break
    fixed = [j for j in jets if j.name not in eq.free]
    angles = [j for j in fixed if j.name in v.coordinate_domains or "th" in j.name
              or j.name in ("phi", "psi", "theta")]  # fmt: skip
    if angles:
        j = rng.choice(angles)
        moved = {**at, j.q: sp.pi / 2 - at[j.q]}
        if _differs(moved[j.q], at[j.q], values):
            yield equilibrium(moved, "EQ_wrong_angle")
    for j in fixed:
        terms = sp.Add.make_args(sp.expand(at[j.q]))
        moving = [x for x in terms if x.free_symbols]
        if moving and j not in angles:
            x = rng.choice(moving)
            yield equilibrium({**at, j.q: at[j.q] - 2 * x}, "EQ_term_sign")
            break

    # --- normal modes ---
    closed = osc.frequencies
    if closed is None:
        return
    modes = [w for w in closed if w != 0]
    if not modes:
        return

    def freq(ws: list, cause: str) -> Wrong:
        return Wrong(spec, "normal_modes", [plain(w) for w in ws], cause, tuple(ws))

    k = rng.randrange(len(modes))
    yield freq([w**2 if i == k else w for i, w in enumerate(modes)], "NM_squared")
    if len(modes) > 1:
        yield freq([w for i, w in enumerate(modes) if i != k], "NM_missing")
    yield freq([w / (2 * sp.pi) if i == k else w for i, w in enumerate(modes)], "NM_cycles")
    yield freq([sp.sqrt(2) * w if i == k else w for i, w in enumerate(modes)], "NM_factor_two")
    K, M = eq.stiffness, eq.mass
    oscillating = [i for i, j in enumerate(jets) if j.name not in eq.free]
    if len(jets) > 1 and not (K.is_diagonal() and M.is_diagonal()):
        alone = [sp.sqrt(sp.simplify(K[i, i] / M[i, i])) for i in oscillating if K[i, i] != 0]
        if alone:
            yield freq(alone, "NM_uncoupled")

    # --- mode shapes ---
    shapes = osc.mode_shapes
    if not shapes:
        return

    def shape(pairs: list, cause: str) -> Wrong:
        lines = [f"omega = {plain(w)}: ({', '.join(plain(x) for x in a)})" for w, a in pairs]
        return Wrong(spec, "mode_shapes", lines, cause, tuple(pairs))

    if len(shapes) > 1:
        (w1, a1), (w2, a2), *rest = shapes
        yield shape([(w1, a2), (w2, a1), *rest], "MS_swapped")
        k = rng.randrange(len(shapes))
        yield shape([s for i, s in enumerate(shapes) if i != k], "MS_missing")
    Mn = np.array(sp.N(M.xreplace(values)).tolist(), dtype=float)
    if not np.allclose(Mn, Mn[0, 0] * np.eye(len(Mn))):
        # K's own eigenvectors (K a = μ a, M forgotten), in closed form, each paired with a
        # frequency in ascending order of μ at the handout's values
        found = []
        for mu, _times, basis in K.eigenvects(simplify=True):
            if mu != 0:
                found += [(complex(sp.N(mu.xreplace(values))).real, b) for b in basis]
        found.sort(key=lambda pair: pair[0])
        if len(found) == len(shapes):
            pairs = []
            for (w, _a), (_mu, b) in zip(shapes, found, strict=True):
                first = next(x for x in b if x != 0)
                pairs.append((w, tuple(sp.simplify(x / first) for x in b)))
            yield shape(pairs, "MS_K_alone")
