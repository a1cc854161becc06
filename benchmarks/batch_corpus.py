"""A cold batch like a grading script's, built from the bank for `bench_batch.py`: every scene given
ad hoc (`{"lagrangian", "coordinates", "parameters"}`) under renamed coordinates, three renamings
each, plus closed-form `expression` problems (T, V, momenta, h and the scenes' quantities), six
answers to each, right and wrong, in several notations (plain, Python, implicit products,
undotted, LaTeX).

Wrong answers are the slips students make (a term's sign, a dropped ½, a missing term, sin for
cos, twice a term), so that the mistake catalogue is exercised as a real batch would.
Deterministic: the same seed gives the same batch, line for line.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass, field

import sympy as sp

from lagrade.bank.registry import get_scene, scene_ids
from lagrade.mechanics import lagrange as mech
from lagrade.notation.printer import plain, symbol_names

#: Names the coordinates are renamed to (none is a parameter of any scene, nor t, e, E or I).
NAMES = ("u", "w", "s", "xi", "eta", "zeta", "chi", "psi", "q1", "q2", "y1", "z1", "rho1", "b1")
RENAMINGS = 3


@dataclass
class Request:
    """One line of the batch, and for the reference judge the sympy objects behind it."""

    body: dict
    reference: object = field(repr=False, default=None)  # what the reference judge compares
    answer_exprs: object = field(repr=False, default=None)


# --- notations ----------------------------------------------------------------------------------


def _implicit(text: str) -> str:
    return re.sub(r"(?<=[\w)])\*(?=[\w(])", " ", text)


def _undotted(text: str) -> str:
    return re.sub(r"_(d?dot)\b", r"\1", text)


def _notations(coordinates):
    names = symbol_names(coordinates)
    return {
        "plain": plain,
        "python": sp.sstr,
        "implicit": lambda e: _implicit(plain(e)),
        "undotted": lambda e: _undotted(plain(e)),
        "latex": lambda e: sp.latex(e, symbol_names=names),
    }


# --- renaming -------------------------------------------------------------------------------------


def renamed(variant, rng: random.Random):
    """(coordinate names, substitution, jets) for one renaming of the variant's coordinates."""
    taken = set(variant.parameter_symbols)
    pool = [n for n in NAMES if n not in taken]
    names = rng.sample(pool, len(variant.jets))
    swap, jets = {}, []
    for old, new in zip(variant.jets, names, strict=True):
        j = mech.jet(new)
        swap |= {old.q: j.q, old.dot: j.dot, old.ddot: j.ddot}
        jets.append(j)
    return names, swap, tuple(jets)


def _one_term(expr: sp.Expr, rng: random.Random, kind: str) -> sp.Expr:
    terms = list(sp.Add.make_args(sp.expand(expr)))
    k = rng.randrange(len(terms))
    rest = sp.Add(*(terms[:k] + terms[k + 1 :]))
    term = terms[k]
    if kind == "sign":
        return rest - term
    if kind == "double":
        return rest + 2 * term
    if kind == "drop" and len(terms) > 1:
        return rest
    if kind == "swap" and (term.has(sp.sin) or term.has(sp.cos)):
        return rest + term.replace(
            lambda e: isinstance(e, sp.sin | sp.cos),
            lambda e: (sp.cos if isinstance(e, sp.sin) else sp.sin)(e.args[0]),
        )
    return rest - term


def _wrong(expr: sp.Expr, rng: random.Random) -> sp.Expr:
    for _ in range(8):
        kind = rng.choice(("sign", "double", "drop", "swap"))
        out = _one_term(expr, rng, kind)
        if sp.expand(out - expr) != 0:
            return out
    return 2 * expr + 1


# --- Lagrangian problems --------------------------------------------------------------------------


def lagrangian_requests(sid: str, copy: int, rng: random.Random) -> list[Request]:
    v = get_scene(sid).default
    names, swap, jets = renamed(v, rng)
    L = v.lagrangian.xreplace(swap)
    T = v.kinetic_energy.xreplace(swap)
    V = v.potential_energy.xreplace(swap)
    system = mech.LagrangianSystem(L, jets)
    spec = {
        "lagrangian": plain(L),
        "coordinates": names,
        "parameters": {n: d.text for n, d in v.domains.items()},
    }
    notations = _notations(names)
    style = list(notations.values())
    out = []

    def add(part, answer, reference, exprs):
        out.append(
            Request({"problem": spec, "part": part, "answer": answer}, (part, reference), exprs)
        )

    say = rng.choice(style)
    right_L = rng.choice([L, 2 * L, L + 7, sp.expand(L)])
    add("lagrangian", say(right_L), L, right_L)
    wrong_L = rng.choice([T + V, 2 * T - V, _wrong(T, rng) - V])
    add("lagrangian", rng.choice(style)(wrong_L), L, wrong_L)
    momenta = system.generalized_momenta
    say = rng.choice(style)
    add(
        "momenta",
        [f"p_{j.name} = {say(p)}" for j, p in zip(jets, momenta, strict=True)],
        L,
        list(momenta),
    )
    E = list(system.euler_lagrange)
    say = rng.choice(style)
    rows = [-r if rng.random() < 0.5 else r for r in E]
    add("eom", [f"{say(r)} = 0" for r in rows], L, rows)
    wrong_rows = list(E)
    wrong_rows[0] = _wrong(E[0], rng)
    add("eom", [f"{say(r)} = 0" for r in wrong_rows], L, wrong_rows)
    key = list(system.conserved_quantities.values())
    if copy % 2 == 0 and key:
        qs = [3 * q if rng.random() < 0.3 else q for q in key]
        if rng.random() < 0.4:
            qs = [T + V] if not system.is_time_independent else [_wrong(key[0], rng)]
        add("conserved", [rng.choice(style)(q) for q in qs], L, qs)
    else:
        cyclic = list(system.cyclic_coordinates)
        answer = ", ".join(cyclic) or "none"
        if rng.random() < 0.3:
            answer = ", ".join(names)
        add("cyclic", answer, L, answer)
    return out


# --- expression problems --------------------------------------------------------------------------


def expression_problems(sid: str, rng: random.Random) -> list[tuple[dict, sp.Expr, list[str]]]:
    """(problem field, reference, coordinate names) for a scene's closed forms."""
    v = get_scene(sid).default
    names, swap, jets = renamed(v, rng)
    system = mech.LagrangianSystem(v.lagrangian.xreplace(swap), jets)
    exprs = [v.kinetic_energy.xreplace(swap), v.potential_energy.xreplace(swap)]
    exprs += list(system.generalized_momenta) + [system.energy_function]
    exprs += list(v.quantities.values())
    params = {n: d.text for n, d in v.domains.items()}
    out = []
    for e in exprs:
        if e == 0 or not e.free_symbols:
            continue
        text = plain(e)
        spec = {"expression": text, "parameters": params}
        used = [n for n, j in zip(names, jets, strict=True) if e.has(j.q, j.dot)]
        if used:
            spec["coordinates"] = names
        out.append((spec, e, names))
    return out


def expression_requests(spec: dict, e: sp.Expr, names, rng: random.Random) -> list[Request]:
    notations = _notations(names)
    rights = [e, sp.expand(e), sp.factor(e), e]
    out = []
    for k in range(6):
        right = k < 4
        expr = rights[k] if right else _wrong(e, rng)
        say = rng.choice(list(notations.values()))
        body = {"problem": spec, "part": "expression", "answer": say(expr)}
        out.append(Request(body, ("expression", e), expr))
    return out


def build_batch(seed: int = 13, expressions: int = 220) -> list[Request]:
    """The whole batch, problem by problem as a grading script sends them (all the answers to
    one problem, then the next)."""
    rng = random.Random(seed)
    requests: list[Request] = []
    for copy in range(RENAMINGS):
        for sid in scene_ids():
            requests += lagrangian_requests(sid, copy, rng)
    pool = []
    for _ in range(3):  # three renamings of each scene's closed forms, until the count is met
        for sid in scene_ids():
            pool += expression_problems(sid, rng)
    seen, chosen = set(), []
    for spec, e, names in pool:
        key = repr(sorted(spec.items()))
        if key not in seen:
            seen.add(key)
            chosen.append((spec, e, names))
    for spec, e, names in chosen[:expressions]:
        requests += expression_requests(spec, e, names, rng)
    return requests
