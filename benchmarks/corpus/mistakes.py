"""Wrong answers with a recorded cause: each is a reference answer of a bank variant with one
mistake applied, the mistakes that students are known to make in Lagrangian mechanics. Read by
`benchmarks/claims.py`, which checks every claim the feedback makes about them.

Where the causes come from (the common-mistake remarks of textbooks and instructors; each entry
says which cause it motivates; cited from memory of the texts, not checked against a copy here):

- J. R. Taylor, *Classical Mechanics* (2005), ch. 7 (examples 7.3–7.7 and problems 7.8–7.40):
  the sign of V and L = T − V, the ½ of the kinetic energy, the cross term of a moving support
  (pendulum on a cart, bead on a rotating rod), the factor sin²θ of the spherical pendulum's
  p_φ, E = T + V not conserved when a constraint moves (§7.8's bead on a rotating hoop).
- D. Morin, *Introduction to Classical Mechanics* (2008), ch. 6 (remarks after 6.1–6.3 and the
  problems "Lagrangians"): a forgotten velocity component of a point on a moving body, the
  wrong moment of inertia, the energy function h versus E for a time-dependent constraint,
  signs in d/dt(∂L/∂q̇) − ∂L/∂q = 0.
- H. Goldstein, C. Poole, J. Safko, *Classical Mechanics* (3rd ed.), §2.7 and §8.2: h conserved
  when L has no explicit t, h ≠ E when the transformation depends on t.
- MIT OpenCourseWare 8.09 *Classical Mechanics III* (Fall 2014) and 8.223 *Classical Mechanics
  II* (IAP 2017), problem-set solutions (remarks on "p_φ = m l² φ̇ forgets sin²θ", missing
  equations, a cyclic coordinate claimed where L depends on it): the course pages at
  ocw.mit.edu, cited from memory.

Nothing here parses student text: the answers are sympy expressions made from the reference and
printed with lagrade's own printer, and a correction (in claims.py) is applied to them the same
way.
"""

from __future__ import annotations

import random
from collections.abc import Iterator
from dataclasses import dataclass, field

import sympy as sp

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.mechanics import LagrangianSystem
from lagrade.mechanics import lagrange as mech
from lagrade.notation import plain

#: Where each cause is motivated (short form of the sources above).
SOURCES = {
    "sign_of_V": "Taylor ch. 7 (L = T − V); Morin ch. 6",
    "V_minus_T": "Taylor ch. 7 (L = T − V)",
    "dropped_half_all": "Taylor ch. 7 (T = ½ m v²)",
    "dropped_term": "Morin ch. 6 (a forgotten velocity component)",
    "factor_two": "Morin ch. 6 (a wrong moment of inertia / factor on one body)",
    "term_sign": "Morin ch. 6 (signs)",
    "part_cross_term": "Taylor ch. 7 (pendulum on a cart's cross term); Morin ch. 6",
    "one_momentum_doubled": "MIT 8.09 problem-set remarks (a momentum's factor)",
    "momentum_trig_dropped": "Taylor ch. 7 (spherical pendulum p_φ); MIT 8.09",
    "momentum_term_dropped": "Taylor ch. 7 (p of a moving support)",
    "momentum_of_wrong_L": "Morin ch. 6 (momenta of a wrong L)",
    "missing_equation": "MIT 8.223 problem-set remarks (one equation per coordinate)",
    "negated_rhs": "Morin ch. 6 (signs in Lagrange's equation), a solved form",
    "el_sign": "Morin ch. 6 (d/dt ∂L/∂q̇ − ∂L/∂q)",
    "eom_of_wrong_L": "Morin ch. 6 (a wrong L derived correctly)",
    "eom_of_own_L": "Morin ch. 6 (a wrong L derived correctly), handed in with that L: the "
    "follow-through of a grader's rubric (e.g. MIT 8.09 problem-set grading; from memory)",
    "row_term_sign": "Taylor ch. 7 problems (a sign slip in one term)",
    "cyclic_extra": "MIT 8.09 (a coordinate called cyclic where L depends on it)",
    "cyclic_missed": "Taylor §7.8 (ignorable coordinates)",
    "energy_offered": "Goldstein §8.2; Taylor §7.8 (E not conserved when a constraint moves)",
    "conserved_trig_dropped": "Taylor ch. 7 (m l² φ̇ for m l² sin²θ φ̇)",
    "conserved_not_cyclic": "MIT 8.09 (p of a coordinate that is not cyclic)",
}


@dataclass(frozen=True)
class Wrong:
    """One wrong answer: its problem, part, text (what a student would type), the recorded
    cause, and the sympy form it was printed from (`exprs`: L; the momenta; the equations as
    (lhs, rhs); the conserved quantities; the cyclic names) so that a correction can be
    applied to it."""

    problem: dict
    part: str
    answer: str | list[str]
    cause: str
    exprs: tuple = field(compare=False)
    #: What the request brings besides the answer: the student's own L (follow-through).
    given: dict | None = field(default=None, compare=False)
    #: The own L of `given`, as the sympy form it was printed from.
    own_L: sp.Expr | None = field(default=None, compare=False)


def _terms(e: sp.Expr) -> tuple[sp.Expr, ...]:
    return sp.Add.make_args(sp.expand(e))


def _moving(term: sp.Expr, jets) -> bool:
    return any(term.has(j.q) or term.has(j.dot) for j in jets)


def _trig_factor(term: sp.Expr) -> sp.Expr | None:
    """A sin or cos power multiplying the term, or None."""
    for f in sp.Mul.make_args(term):
        base = f.base if isinstance(f, sp.Pow) else f
        if isinstance(base, (sp.sin, sp.cos)):
            return f
    return None


def _eq(lhs: sp.Expr, rhs: sp.Expr = sp.S.Zero) -> str:
    return f"{plain(lhs)} = {plain(rhs)}"


def wrong_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """The wrong answers of one variant, each with its cause."""
    v = get_scene(sid).variant(seed)
    spec = {"scene": sid, "seed": seed}
    jets, system = v.jets, v.system
    T, V = sp.expand(v.kinetic_energy), sp.expand(v.potential_energy)
    L = T - V

    def lag(expr, cause):
        return Wrong(spec, "lagrangian", plain(expr), cause, (expr,))

    # --- Lagrangian ---
    if V != 0:
        yield lag(T + V, "sign_of_V")
    yield lag(V - T, "V_minus_T")
    yield lag(2 * T - V, "dropped_half_all")
    moving = [x for x in _terms(L) if _moving(x, jets)]
    if len(moving) > 1:
        x = rng.choice(moving)
        yield lag(L - x, "dropped_term")
        yield lag(L + x, "factor_two")
        yield lag(L - 2 * rng.choice(moving), "term_sign")
    cross = [x for x in _terms(T) if sum(x.has(j.dot) for j in jets) >= 2]
    if cross:
        yield lag(L - cross[0] / 2, "part_cross_term")

    # --- momenta ---
    p = list(system.generalized_momenta)

    def mom(ps, cause):
        names = [f"p_{j.name} = {plain(e)}" for j, e in zip(jets, ps, strict=True)]
        return Wrong(spec, "momenta", names, cause, tuple(ps))

    if len(p) > 1:
        k = rng.randrange(len(p))
        yield mom([2 * e if i == k else e for i, e in enumerate(p)], "one_momentum_doubled")
    yield mom([2 * e for e in p], "dropped_half_all")
    for k, pk in enumerate(p):
        terms = _terms(pk)
        trig = [(x, _trig_factor(x)) for x in terms if _trig_factor(x) is not None]
        if trig:
            x, f = trig[0]
            yield mom([e - x + x / f if i == k else e for i, e in enumerate(p)],
                      "momentum_trig_dropped")  # fmt: skip
            break
    for k, pk in enumerate(p):
        if len(_terms(pk)) > 1:
            x = _terms(pk)[-1]
            yield mom([e - x if i == k else e for i, e in enumerate(p)], "momentum_term_dropped")
            break
    if cross:
        wrong_L = L - cross[0] / 2
        yield mom([sp.expand(sp.diff(wrong_L, j.dot)) for j in jets], "momentum_of_wrong_L")

    # --- equations of motion ---
    E = [sp.expand(e) for e in system.euler_lagrange]

    def eom(rows, cause):
        return Wrong(spec, "eom", [_eq(a, b) for a, b in rows], cause, tuple(rows))

    zero = sp.Integer(0)
    if len(E) > 1:
        k = rng.randrange(len(E))
        yield eom([(e, zero) for i, e in enumerate(E) if i != k], "missing_equation")
    if len(E) == 1 and system.mass_matrix[0, 0] != 0:
        acc = sp.cancel(system.forcing[0] / system.mass_matrix[0, 0])
        if acc != 0:
            yield eom([(jets[0].ddot, -acc)], "negated_rhs")
    k = rng.randrange(len(E))
    forces = system.generalized_forces
    if forces[k] != 0:
        yield eom([(e + 2 * forces[k] if i == k else e, zero) for i, e in enumerate(E)],
                  "el_sign")  # fmt: skip
    row_terms = _terms(E[k])
    if len(row_terms) > 1:
        x = rng.choice(row_terms)
        yield eom([(e - 2 * x if i == k else e, zero) for i, e in enumerate(E)], "row_term_sign")
    wrong_L = L - cross[0] / 2 if cross else L + moving[0] if len(moving) > 1 else None
    if wrong_L is not None:
        rows = [(sp.expand(e), zero) for e in LagrangianSystem(wrong_L, jets).euler_lagrange]
        yield eom(rows, "eom_of_wrong_L")
        # the same equations handed in with the L they came from (follow-through)
        own = eom(rows, "eom_of_own_L")
        given = {"lagrangian": plain(wrong_L)}
        yield Wrong(spec, "eom", own.answer, own.cause, own.exprs, given, wrong_L)

    # --- cyclic coordinates ---
    cyclic = list(system.cyclic_coordinates)
    others = [j.name for j in jets if j.name not in cyclic]
    if others:
        names = cyclic + [others[0]]
        yield Wrong(spec, "cyclic", ", ".join(names), "cyclic_extra", tuple(names))
    if cyclic:
        names = cyclic[1:]
        text = ", ".join(names) if names else "none"
        yield Wrong(spec, "cyclic", text, "cyclic_missed", tuple(names))

    # --- conserved quantities ---
    key = list(system.conserved_quantities.values())
    h = system.energy_function
    energy = sp.expand(T + V)
    if sp.expand(energy - h) != 0 or not system.is_time_independent:
        qs = [q for name, q in system.conserved_quantities.items() if name != "h"] + [energy]
        yield Wrong(spec, "conserved", [plain(q) for q in qs], "energy_offered", tuple(qs))
    for name, q in system.conserved_quantities.items():
        if name == "h":
            continue
        trig = [(x, _trig_factor(x)) for x in _terms(q) if _trig_factor(x) is not None]
        if trig:
            x, f = trig[0]
            qs = [q - x + x / f if o is q else o for o in key]
            yield Wrong(spec, "conserved", [plain(o) for o in qs], "conserved_trig_dropped",
                        tuple(qs))  # fmt: skip
            break
    not_cyclic = [k for k, j in enumerate(jets) if j.name not in cyclic and p[k] != 0]
    if not_cyclic and key:
        k = not_cyclic[0]
        qs = key[:-1] + [p[k]]
        if len(key) == 1:
            qs = [p[k]]
        yield Wrong(spec, "conserved", [plain(o) for o in qs], "conserved_not_cyclic", tuple(qs))


def build(seeds: tuple[int, ...] = (1, 2), scenes: tuple[str, ...] | None = None) -> list[Wrong]:
    """The corpus: every bank scene's variants `seeds`, every cause that applies to it."""
    out: list[Wrong] = []
    for sid in scenes or tuple(scene_ids()):
        for seed in seeds:
            rng = random.Random(f"{sid}:{seed}")
            try:
                out.extend(wrong_answers(sid, seed, rng))
            except (NotImplementedError, ValueError) as error:  # a scene we cannot mutate
                print(f"{sid}/{seed}: skipped ({error})")
    return out


__all__ = ["SOURCES", "Wrong", "build", "mech"]
