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
- L. D. Landau, E. M. Lifshitz, *Mechanics* (3rd ed.), §40 and Goldstein §8.1–8.2: H = Σ p q̇ − L
  written in the momenta (not in the velocities, not L itself), q̇ = ∂H/∂p = p/m (the 1/m a
  student drops), ṗ = −∂H/∂q (its sign), two first-order equations per coordinate; the charge
  in a magnetic field, H = (p − eA)²/2m (Goldstein §8.1; Taylor §7.9 and problem 7.49).
- Taylor ch. 4 (§4.4, potential energy: the zero level and the sign of m g h when the height
  is measured downwards) and ch. 10 (§10.1–10.4: the moment of inertia of a disc ½ M R², not
  M R², and of a rod about its end, 1/3 M L², not 1/12 M L²) for T and V.
- The closed-form slips of the `expression` part (a sign, sin for cos, a result upside down, a
  dropped factor such as the (M + m) of the wedge's acceleration, Morin problem 6.10's answer):
  the common-error lists of physics problem-solving guides (e.g. the "check the dimensions and
  the limiting cases" advice of Morin ch. 1 and of Taylor §1.5); cited from memory.
- MIT OpenCourseWare 8.09 *Classical Mechanics III* (Fall 2014) and 8.223 *Classical Mechanics
  II* (IAP 2017), problem-set solutions (remarks on "p_φ = m l² φ̇ forgets sin²θ", missing
  equations, a cyclic coordinate claimed where L depends on it): the course pages at
  ocw.mit.edu, cited from memory.

The set-up parts (`dof`, `coordinates`, `transformation`) and the small-oscillation parts
(`equilibrium`, `normal_modes`, `mode_shapes`) are made in `mistakes_setup.py` and
`mistakes_oscillation.py`, which cite their own sources.

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
from lagrade.judge.mutations import swap_sin_cos
from lagrade.mechanics import LagrangianSystem, phase_space
from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.hamilton import NotQuadratic
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
    # T and V
    "T_dropped_half": "Taylor ch. 7 (T = ½ m v²)",
    "T_dropped_term": "Morin ch. 6 (a forgotten velocity component)",
    "T_factor_two": "Morin ch. 6 (a factor 2 on one term)",
    "T_wrong_inertia": "Taylor §10.1–10.4; Morin ch. 8 (½ M R² vs M R², a rod's 1/12 vs 1/3)",
    "T_sin_cos": "Taylor ch. 7 problems (sin and cos of the angle from the vertical)",
    "V_sign": "Taylor §4.4 (height measured downwards: V = −m g h)",
    "V_dropped_term": "Morin ch. 6 (a term of V forgotten: the spring, the other body)",
    "V_sin_cos": "Taylor ch. 7 problems (V = m g l sin θ for m g l cos θ)",
    "V_term_sign": "Taylor ch. 7 problems (a sign slip in one term)",
    # the Hamiltonian
    "H_velocities": "Goldstein §8.1; Landau–Lifshitz §40 (H in p, not q̇)",
    "H_is_L": "Goldstein §8.1 (H = Σ p q̇ − L, not L)",
    "H_sign_of_V": "Taylor §7.9 / Goldstein §8.1 (H = T + V, not T − V)",
    "H_dropped_half": "Taylor §13.2 (H = p²/2m)",
    "H_vector_potential": "Goldstein §8.1; Taylor problem 7.49 (H = (p − eA)²/2m)",
    # Hamilton's equations
    "Heq_p_dot_sign": "Goldstein §8.1; Taylor §13.2 (ṗ = −∂H/∂q)",
    "Heq_missing": "Taylor §13.2 (2n first-order equations)",
    "Heq_no_mass": "Taylor §13.2 (q̇ = ∂H/∂p = p/m, the 1/m dropped)",
    # a closed-form quantity
    "X_sign": "Morin ch. 1 (check limiting cases: the sign)",
    "X_sin_cos": "Morin ch. 1 (limiting cases: sin for cos)",
    "X_upside_down": "Morin ch. 1; Taylor §1.5 (check the dimensions: a result upside down)",
    "X_dropped_factor": "Morin ch. 1 (check the dimensions: a dropped factor)",
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


def _changed(mutated: sp.Expr, right: sp.Expr) -> bool:
    return sp.expand(mutated - right) != 0


def energy_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """Wrong T and V of one variant (the parts `T`, `V`), each with its cause."""
    v = get_scene(sid).variant(seed)
    spec = {"scene": sid, "seed": seed}
    jets = v.jets
    T, V = sp.expand(v.kinetic_energy), sp.expand(v.potential_energy)

    def one(part, expr, cause):
        return Wrong(spec, part, plain(expr), cause, (expr,))

    if T != 0:
        yield one("T", 2 * T, "T_dropped_half")
        terms = [x for x in _terms(T) if any(x.has(j.dot) for j in jets)]
        if len(terms) > 1:
            yield one("T", T - rng.choice(terms), "T_dropped_term")
            yield one("T", T + rng.choice(terms), "T_factor_two")
        for b in v.bodies:
            rotation = (
                sp.expand(b.rotational_energy(jets)) if hasattr(b, "rotational_energy") else 0
            )
            if rotation != 0:  # I = M R² for ½ M R²: the rotational term doubled
                yield one("T", sp.expand(T + rotation), "T_wrong_inertia")
                break
        if _changed(swap_sin_cos(T), T):
            yield one("T", sp.expand(swap_sin_cos(T)), "T_sin_cos")
    if V != 0 and not any(V.has(j.dot) for j in jets):
        yield one("V", -V, "V_sign")
        moving = [x for x in _terms(V) if _moving(x, jets)]
        if len(moving) > 1:
            yield one("V", V - rng.choice(moving), "V_dropped_term")
            yield one("V", V - 2 * rng.choice(moving), "V_term_sign")
        if _changed(swap_sin_cos(V), V):
            yield one("V", sp.expand(swap_sin_cos(V)), "V_sin_cos")


def phase_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """Wrong H and Hamilton's equations of one variant, each with its cause."""
    v = get_scene(sid).variant(seed)
    spec = {"scene": sid, "seed": seed}
    jets, system = v.jets, v.system
    try:
        hs = phase_space(system)
        H = hs.hamiltonian
        U = hs.effective_potential
    except NotQuadratic:
        return
    V = sp.expand(v.potential_energy)
    to_p = dict(zip([j.dot for j in jets], hs.velocities, strict=True))

    def ham(expr, cause):
        return Wrong(spec, "hamiltonian", plain(expr), cause, (expr,))

    yield ham(system.energy_function, "H_velocities")
    yield ham(sp.expand(system.L.xreplace(to_p)), "H_is_L")
    if V != 0 and not any(V.has(j.dot) for j in jets):
        yield ham(H - 2 * V, "H_sign_of_V")
    yield ham(2 * H - U, "H_dropped_half")
    if any(c != 0 for c in hs.momentum_offset):
        A_inv, p = hs.inverse_matrix, sp.Matrix(hs.momenta)
        yield ham(sp.expand((p.T * A_inv * p)[0, 0] / 2 + U), "H_vector_potential")

    equations = [(e.lhs, e.rhs) for e in hs.hamilton_equations]
    n = len(jets)

    def heq(rows, cause):
        return Wrong(spec, "hamilton_equations", [_eq(a, b) for a, b in rows], cause, tuple(rows))

    forced = [k for k in range(n) if equations[n + k][1] != 0]
    if forced:
        k = n + rng.choice(forced)
        yield heq([(a, -b) if i == k else (a, b) for i, (a, b) in enumerate(equations)],
                  "Heq_p_dot_sign")  # fmt: skip
    k = rng.randrange(2 * n)
    yield heq([e for i, e in enumerate(equations) if i != k], "Heq_missing")
    k = rng.randrange(n)
    mass = hs.velocity_matrix[k, k]
    if mass != 1:
        rows = [
            (a, sp.expand(mass * b)) if i == k else (a, b) for i, (a, b) in enumerate(equations)
        ]
        yield heq(rows, "Heq_no_mass")


def expression_answers(sid: str, seed: int, rng: random.Random) -> Iterator[Wrong]:
    """Wrong closed forms of each of a scene's quantities (the `expression` part)."""
    v = get_scene(sid).variant(seed)
    for name, ref in v.quantities.items():
        spec = {"scene": sid, "seed": seed, "quantity": name}

        def one(expr, cause, spec=spec):
            return Wrong(spec, "expression", plain(expr), cause, (expr,))

        yield one(-ref, "X_sign")
        if _changed(swap_sin_cos(ref), ref):
            yield one(swap_sin_cos(ref), "X_sin_cos")
        yield one(1 / ref, "X_upside_down")
        factors = [f for f in sp.Mul.make_args(ref) if not f.is_number]
        if len(factors) > 1:
            yield one(ref / rng.choice(factors), "X_dropped_factor")


#: The parts of the corpus, each with the function that makes its wrong answers.
MAKERS = {
    "lagrangian,momenta,eom,cyclic,conserved": wrong_answers,
    "T,V": energy_answers,
    "hamiltonian,hamilton_equations": phase_answers,
    "expression": expression_answers,
}

# the set-up and small-oscillation parts, in modules of their own (each imports `Wrong` above)
from mistakes_oscillation import SOURCES as _OSCILLATION_SOURCES  # noqa: E402
from mistakes_oscillation import oscillation_answers  # noqa: E402
from mistakes_setup import SOURCES as _SETUP_SOURCES  # noqa: E402
from mistakes_setup import setup_answers  # noqa: E402

MAKERS["dof,coordinates,transformation"] = setup_answers
MAKERS["equilibrium,normal_modes,mode_shapes"] = oscillation_answers
SOURCES |= _SETUP_SOURCES | _OSCILLATION_SOURCES


def build(
    seeds: tuple[int, ...] = (1, 2),
    scenes: tuple[str, ...] | None = None,
    part_filter: tuple[str, ...] | None = None,
) -> list[Wrong]:
    """The corpus: every bank scene's variants `seeds`, every cause that applies to it (of the
    parts `part_filter`, or all)."""
    out: list[Wrong] = []
    for sid in scenes or tuple(scene_ids()):
        for seed in seeds:
            for parts, make in MAKERS.items():
                if part_filter and not set(parts.split(",")) & set(part_filter):
                    continue
                # the first maker's draws as before; the others each from their own stream
                key = f"{sid}:{seed}" if make is wrong_answers else f"{sid}:{seed}:{parts}"
                rng = random.Random(key)
                try:
                    out.extend(w for w in make(sid, seed, rng)
                               if not part_filter or w.part in part_filter)  # fmt: skip
                except (NotImplementedError, ValueError) as error:  # a scene we cannot mutate
                    print(f"{sid}/{seed} {parts}: skipped ({error})")
    return out


__all__ = ["MAKERS", "SOURCES", "Wrong", "build", "mech"]
