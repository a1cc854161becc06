"""Wrong answers with a recorded cause for the set-up parts: `dof`, `coordinates` and
`transformation` (the bodies' Cartesian coordinates in the generalized ones). Read through
`mistakes.MAKERS`; each cause cites where it is motivated (`SOURCES`).

Where the causes come from (cited from memory of the texts, not checked against a copy here):

- Taylor, *Classical Mechanics*, §7.2–7.3 and problems 7.1–7.8 (the pendulum on a moving
  support, the double pendulum): a position written relative to the support without the
  support's own motion (x = l sin φ where x = s + l sin φ), a sign of one term, sin and cos of
  the angle from the vertical exchanged in one line, the wrong rod's length in the lower bob's
  position.
- Morin, *Introduction to Classical Mechanics*, ch. 6 and ch. 8 (the sliding ladder,
  problem 8.x): the centre of a rod placed at its end (l where l/2 belongs).
- Goldstein, Poole, Safko §1.3 and Taylor §7.2: degrees of freedom as 3N − k, where a student
  counts the bodies' freedoms and subtracts no constraint, or forgets that motion in a plane is
  k constraints too; a velocity listed as a coordinate (MIT 8.09 problem-set remarks).
"""

from __future__ import annotations

import random
from collections.abc import Iterator

import sympy as sp
from mistakes import Wrong

from lagrade.bank.registry import get_scene
from lagrade.judge.mutations import swap_sin_cos
from lagrade.notation import plain

SOURCES = {
    "DOF_no_constraints": "Goldstein §1.3; Taylor §7.2 (3N − k: k forgotten)",
    "DOF_planarity": "Taylor §7.2 (motion in a plane is a constraint per body)",
    "COORD_velocity": "MIT 8.09 problem-set remarks (a velocity is no coordinate; from memory)",
    "COORD_missing": "Taylor §7.2 (one coordinate per degree of freedom)",
    "TR_term_sign": "Taylor §7.2–7.3 problems (a sign slip in one term)",
    "TR_sin_cos": "Taylor ch. 7 problems (sin and cos of the angle from the vertical)",
    "TR_dropped_term": "Taylor §7.3 (the support's motion left out of the bob's position)",
    "TR_wrong_length": "Taylor problem 7.29-style double pendulum (l_1 for l_2); Morin ch. 8 "
    "(a rod's centre at l for l/2)",
}


def _lines(tr: dict[str, sp.Expr]) -> list[str]:
    return [f"{name} = {plain(e)}" for name, e in tr.items()]


def _moving(e: sp.Expr, jets) -> bool:
    return any(e.has(j.q) for j in jets)


def _lengths(v) -> list[sp.Symbol]:
    """The parameters measured in metres."""
    return [v.parameter_symbols[p.name] for p in v.scene.parameters if p.unit == "m"
            and p.name in v.parameter_symbols]  # fmt: skip


def setup_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """The wrong dof, coordinates and transformation answers of one variant."""
    v = get_scene(sid).variant(seed)
    spec = {"scene": sid, "seed": seed}
    jets = v.jets
    if v.bodies:
        freedoms = sum(b.freedoms for b in v.bodies)
        if freedoms != v.dof:
            yield Wrong(spec, "dof", str(freedoms), "DOF_no_constraints", (freedoms,))
        implied = sum(1 for label, _ in v.constraints if label != "declared")
        if implied and v.dof + implied != freedoms:
            yield Wrong(spec, "dof", str(v.dof + implied), "DOF_planarity", (v.dof + implied,))
    names = [j.name for j in jets]
    k = rng.randrange(len(names))
    velocity = [n if i != k else f"{n}_dot" for i, n in enumerate(names)]
    yield Wrong(spec, "coordinates", ", ".join(velocity), "COORD_velocity", tuple(velocity))
    if len(names) > 1:
        fewer = [n for i, n in enumerate(names) if i != k]
        yield Wrong(spec, "coordinates", ", ".join(fewer), "COORD_missing", tuple(fewer))
    if not v.bodies:
        return
    tr = {name: sp.expand(e) for name, e in v.transformation.items()}
    moving = [name for name, e in tr.items() if _moving(e, jets)]
    if not moving:
        return

    def one(changed: dict, cause: str) -> Wrong:
        d = {**tr, **changed}
        return Wrong(spec, "transformation", _lines(d), cause, tuple(d.items()))

    name = rng.choice(moving)
    terms = sp.Add.make_args(tr[name])
    t = rng.choice([x for x in terms if _moving(x, jets)])
    yield one({name: tr[name] - 2 * t}, "TR_term_sign")
    swappable = [n for n in moving if swap_sin_cos(tr[n]) != tr[n]]
    if swappable:
        n = rng.choice(swappable)
        yield one({n: sp.expand(swap_sin_cos(tr[n]))}, "TR_sin_cos")
    several = [n for n in moving if len(sp.Add.make_args(tr[n])) > 1]
    if several:
        n = rng.choice(several)
        terms = sp.Add.make_args(tr[n])
        # the support's term: one without this body's own angle, else any
        support = [x for x in terms if not _moving(x, jets) or len(terms) > 1]
        yield one({n: tr[n] - rng.choice(support)}, "TR_dropped_term")
    lengths = _lengths(v)
    with_length = [n for n in moving if any(tr[n].has(s) for s in lengths)]
    if with_length:
        n = rng.choice(with_length)
        s = rng.choice([x for x in lengths if tr[n].has(x)])
        others = [x for x in lengths if x != s]
        wrong = others[0] if others else 2 * s
        terms = [x for x in sp.Add.make_args(tr[n]) if x.has(s)]
        x = rng.choice(terms)
        yield one({n: sp.expand(tr[n] - x + x.xreplace({s: wrong}))}, "TR_wrong_length")
