"""Write benchmarks/corpus/pairs.jsonl: the labelled pairs the speed-against-accuracy study runs
every equivalence method over.

Run: python benchmarks/corpus/build_corpus.py   (deterministic; rewrites pairs.jsonl)

Two sources:
- the bank: for every scene's L, momenta p_j and Euler–Lagrange expressions E_j, correct
  algebraic rewrites (factored, collected, Pythagoras sin² = 1 − cos², product-to-sum and angle
  sums, common denominators) and single-term mutations (sign, factor 2, half, dropped term,
  sin/cos swap, wrong coordinate, the whole expression scaled — a scale is a wrong answer for
  plain expression equivalence, whatever it means for a Lagrangian);
- hand-written hard cases, each in a category where some method fails (see HARD below).

Expressions are written in the plain notation students type and read back with lagrade.notation;
a pair whose text does not read back to the expression it was written from stops the build.
Labels are the generator's intent; benchmarks/corpus/verify_labels.py checks every one
independently.
"""

from __future__ import annotations

import random
import re
import sys
from pathlib import Path

import sympy as sp
from sympy.simplify.fu import TR8, TR10

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from benchmarks.corpus.corpus import PAIRS, Pair, parse_pair  # noqa: E402
from lagrade.bank.registry import get_scene, scene_ids  # noqa: E402
from lagrade.mechanics import lagrange as mech  # noqa: E402

#: How many rewrites and mutations to keep per bank expression (chosen by a seeded draw).
REWRITES_PER_EXPRESSION = 4
MUTATIONS_PER_EXPRESSION = 3
TIME_DOMAIN = "(0, 10)"
_USES_TIME = re.compile(r"\bt\b")


# --- the bank ---------------------------------------------------------------------------------


def _trig_args(expr: sp.Expr) -> set[sp.Expr]:
    return {f.args[0] for f in expr.atoms(sp.sin, sp.cos)}


def rewrites(expr: sp.Expr, jets) -> list[tuple[str, sp.Expr]]:
    """Correct algebraic rewrites of expr that a student might hand in."""
    out: list[tuple[str, sp.Expr]] = [
        ("factored", sp.factor(expr)),
        ("factor_terms", sp.factor_terms(expr)),
    ]
    velocities = [j.dot for j in jets] + [j.ddot for j in jets]
    out.append(("collected", sp.collect(sp.expand(expr), velocities)))
    parameters = sorted(
        expr.free_symbols - set(velocities) - {j.q for j in jets} - {mech.t}, key=str
    )
    if parameters:
        out.append(("collected_parameters", sp.collect(sp.expand(expr), parameters)))
    out.append(
        (
            "horner",
            sp.horner(sp.expand(expr), *velocities) if expr.has(*velocities) else sp.expand(expr),
        )
    )
    args = _trig_args(expr)
    if args:
        u = min(args, key=str)
        out.append(("times_pythagoras_one", expr * (sp.sin(u) ** 2 + sp.cos(u) ** 2)))
        out.append(
            (
                "collected_trig",
                sp.collect(sp.expand(expr), [sp.sin(a) for a in args] + [sp.cos(a) for a in args]),
            )
        )
        out.append(
            (
                "pythagoras_cos",
                sp.expand(expr).xreplace({sp.sin(u) ** 2: 1 - sp.cos(u) ** 2 for u in args}),
            )
        )
        out.append(
            (
                "pythagoras_sin",
                sp.expand(expr).xreplace({sp.cos(u) ** 2: 1 - sp.sin(u) ** 2 for u in args}),
            )
        )
        out.append(("product_to_sum", TR8(expr)))
        out.append(("angle_sum", TR10(expr)))
    if any(p.exp.is_negative for p in expr.atoms(sp.Pow)):
        out.append(("together", sp.together(expr)))
    if expr.has(sp.tan):
        out.append(
            (
                "tan_as_ratio",
                expr.xreplace(
                    {f: sp.sin(f.args[0]) / sp.cos(f.args[0]) for f in expr.atoms(sp.tan)}
                ),
            )
        )
    seen = {str(expr)}
    unique = []
    for kind, e in out:
        if str(e) not in seen and e != 0:
            seen.add(str(e))
            unique.append((kind, e))
    return unique


def mutations(expr: sp.Expr, jets, rng: random.Random) -> list[tuple[str, sp.Expr]]:
    """Single-term mistakes: each changes one term of the expanded expression (or scales all)."""
    terms = list(sp.Add.make_args(sp.expand(expr)))
    motion = {s for j in jets for s in (j.q, j.dot, j.ddot)}
    varying = [k for k, term in enumerate(terms) if term.free_symbols & motion] or list(
        range(len(terms))
    )
    k = rng.choice(varying)
    term = terms[k]

    def with_term(new: sp.Expr) -> sp.Expr:
        return sp.Add(*(terms[:k] + [new] + terms[k + 1 :]))

    out = [
        ("sign", with_term(-term)),
        ("factor_2", with_term(2 * term)),
        ("half", with_term(term / 2)),
        ("scaled", 2 * expr),
    ]
    if len(terms) > 1:
        out.append(("dropped_term", with_term(sp.S.Zero)))
    trig = [t for t in range(len(terms)) if terms[t].has(sp.sin, sp.cos)]
    if trig:
        kt = rng.choice(trig)
        swap = {}
        for f in terms[kt].atoms(sp.sin, sp.cos):
            swap[f] = (sp.cos if isinstance(f, sp.sin) else sp.sin)(f.args[0])
        out.append(
            ("sin_cos_swap", sp.Add(*(terms[:kt] + [terms[kt].xreplace(swap)] + terms[kt + 1 :])))
        )
    present = [j for j in jets if term.has(j.q) or term.has(j.dot)]
    if present:
        j = rng.choice(present)
        others = [o for o in jets if o is not j]
        if others:
            o = rng.choice(others)
            wrong = {j.q: o.q, j.dot: o.dot}
        else:
            wrong = {j.dot: j.q} if term.has(j.dot) else {j.q: j.dot}
        out.append(("wrong_coordinate", with_term(term.xreplace(wrong))))
    return [(kind, e) for kind, e in out if sp.expand(e - expr) != 0]


def bank_pairs() -> list[Pair]:
    pairs: list[Pair] = []
    for sid in scene_ids():
        variant = get_scene(sid).default
        system = variant.system
        jets = variant.jets
        parts = [("L", variant.lagrangian)]
        parts += [(f"p_{j.name}", p) for j, p in zip(jets, system.generalized_momenta, strict=True)]
        parts += [(f"E_{j.name}", e) for j, e in zip(jets, system.euler_lagrange, strict=True)]
        domains = {name: d.text for name, d in variant.domains.items()}
        for j in jets:
            domains |= {j.q.name: "real", j.dot.name: "real", j.ddot.name: "real"}
        domains["t"] = TIME_DOMAIN
        for part, expr in parts:
            rng = random.Random(f"{sid}:{part}")
            good = rewrites(expr, jets)
            bad = mutations(expr, jets, rng)
            good = rng.sample(good, min(REWRITES_PER_EXPRESSION, len(good)))
            bad = rng.sample(bad, min(MUTATIONS_PER_EXPRESSION, len(bad)))
            for label, chosen, category in (
                (True, good, "bank_rewrite"),
                (False, bad, "bank_mutation"),
            ):
                for kind, e in chosen:
                    used = {s.name for s in (e.free_symbols | expr.free_symbols)}
                    pairs.append(
                        Pair(
                            id=f"bank/{sid}/{part}/{kind}",
                            category=category,
                            kind=kind,
                            label=label,
                            answer=str(e),
                            reference=str(expr),
                            coordinates=variant.coordinates,
                            parameters={n: d.text for n, d in variant.domains.items()},
                            domains={n: d for n, d in domains.items() if n in used},
                            note=f"{sid}: {part}, {kind.replace('_', ' ')}",
                        )
                    )
    return pairs


# --- hand-written hard cases -------------------------------------------------------------------


def _decimal(text: str) -> str:
    """'1e-28' → '0.0000000000000000000000000001': domain bounds must be plain decimals."""
    value = sp.Rational(text)
    if value.q == 1:
        return str(value.p)
    digits = len(str(value.q)) - 1
    assert value.q == 10**digits, text
    return f"{'-' if value < 0 else ''}0.{str(abs(value.p)).zfill(digits)}"


def _interval(lo: str, hi: str) -> str:
    return f"({_decimal(lo)}, {_decimal(hi)})"


SMALL = "(0.001, 0.01)"
TINY = _interval("1e-9", "1e-8")


def _expanded(polynomial: sp.Expr) -> str:
    """The expanded form of a polynomial built here, in trusted generator code."""
    return str(sp.expand(polynomial))


_X, _Y = sp.symbols("x y", real=True)


def _hard() -> list[tuple]:
    """(category, kind, answer, reference, parameters, label, note); coordinates none unless the
    parameters dict carries the key '_coordinates'."""
    R = "real"
    P = "positive"
    H: list[tuple] = []

    def add(category, kind, answer, reference, params, label, note):
        H.append((category, kind, answer, reference, params, label, note))

    # Trig identities that sympy.simplify leaves unproved (Expr.equals answers None).
    x = {"x": R}
    xy = {"x": R, "y": R}
    add("trig_identity", "half_angle", "tan(x/2)", "sin(x)/(1 + cos(x))", x, True, "tan half-angle")
    add(
        "trig_identity",
        "half_angle_wrong",
        "tan(x/2)",
        "sin(x)/(1 - cos(x))",
        x,
        False,
        "that is cot(x/2)",
    )
    add("trig_identity", "cot_half", "sin(x)/(1 - cos(x))", "cot(x/2)", x, True, "cot half-angle")
    add(
        "trig_identity",
        "csc_minus_cot",
        "1/sin(x) - cos(x)/sin(x)",
        "tan(x/2)",
        x,
        True,
        "csc − cot = tan(x/2)",
    )
    add(
        "trig_identity",
        "sixth_powers",
        "sin(x)**6 + cos(x)**6",
        "1 - 3*sin(x)**2*cos(x)**2",
        x,
        True,
        "sixth powers",
    )
    add(
        "trig_identity",
        "sixth_powers_wrong",
        "sin(x)**6 + cos(x)**6",
        "1 - 2*sin(x)**2*cos(x)**2",
        x,
        False,
        "3 → 2",
    )
    add(
        "trig_identity",
        "cos_5x",
        "cos(5*x)",
        "16*cos(x)**5 - 20*cos(x)**3 + 5*cos(x)",
        x,
        True,
        "Chebyshev T5",
    )
    add(
        "trig_identity",
        "cos_5x_wrong",
        "cos(5*x)",
        "16*cos(x)**5 - 20*cos(x)**3 + 4*cos(x)",
        x,
        False,
        "5 → 4",
    )
    add(
        "trig_identity",
        "tan_3x",
        "tan(3*x)",
        "(3*tan(x) - tan(x)**3)/(1 - 3*tan(x)**2)",
        x,
        True,
        "triple angle",
    )
    add(
        "trig_identity",
        "tan_3x_wrong",
        "tan(3*x)",
        "(3*tan(x) + tan(x)**3)/(1 - 3*tan(x)**2)",
        x,
        False,
        "sign",
    )
    add(
        "trig_identity",
        "sum_ratio",
        "(sin(x) + sin(3*x))/(cos(x) + cos(3*x))",
        "tan(2*x)",
        x,
        True,
        "sum-to-product ratio",
    )
    add(
        "trig_identity",
        "sum_ratio_wrong",
        "(sin(x) + sin(3*x))/(cos(x) + cos(3*x))",
        "tan(3*x)",
        x,
        False,
        "2x → 3x",
    )
    add(
        "trig_identity",
        "cos_4x",
        "cos(4*x)",
        "8*cos(x)**4 - 8*cos(x)**2 + 1",
        x,
        True,
        "Chebyshev T4",
    )
    add("trig_identity", "sin_3x", "sin(3*x)", "3*sin(x) - 4*sin(x)**3", x, True, "triple angle")
    add(
        "trig_identity",
        "product_diff",
        "sin(x + y)*sin(x - y)",
        "sin(x)**2 - sin(y)**2",
        xy,
        True,
        "product of sum and difference",
    )
    add(
        "trig_identity",
        "product_diff_wrong",
        "sin(x + y)*sin(x - y)",
        "sin(x)**2 - cos(y)**2",
        xy,
        False,
        "sin → cos",
    )
    add(
        "trig_identity",
        "tan_sum",
        "tan(x + y)",
        "(tan(x) + tan(y))/(1 - tan(x)*tan(y))",
        xy,
        True,
        "tan addition",
    )
    add(
        "trig_identity",
        "pendulum_height",
        "m*g*l*(1 - cos(theta))",
        "2*m*g*l*sin(theta/2)**2",
        {"m": P, "g": P, "l": P, "theta": R},
        True,
        "pendulum potential, half angle",
    )
    add(
        "trig_identity",
        "pendulum_height_wrong",
        "m*g*l*(1 - cos(theta))",
        "m*g*l*sin(theta/2)**2",
        {"m": P, "g": P, "l": P, "theta": R},
        False,
        "factor 2 lost",
    )
    add(
        "trig_identity",
        "weierstrass_form",
        "(1 - tan(x/2)**2)/(1 + tan(x/2)**2)",
        "cos(x)",
        x,
        True,
        "Weierstrass form of cos",
    )
    add(
        "trig_identity",
        "double_pendulum_cross",
        "cos(theta_1)*cos(theta_2)*(1 + tan(theta_1)*tan(theta_2))",
        "cos(theta_1 - theta_2)",
        {"theta_1": R, "theta_2": R},
        True,
        "double pendulum cross term via tan",
    )

    # Near misses: tiny relative differences and high-order terms hidden by small angles.
    wedge = {"g": P, "M": P, "m": P, "alpha": "(0, pi/2)"}
    acc = "g*sin(alpha)*(M + m)/(M + m*sin(alpha)**2)"
    for exponent in (4, 7, 9, 12):
        add(
            "near_miss",
            f"relative_1e-{exponent}",
            f"{acc}*(1 + 1/{10**exponent})",
            acc,
            wedge,
            False,
            f"wedge acceleration off by a relative 1e-{exponent}",
        )
    pend = {"m": P, "g": P, "l": P, "theta": R}
    for exponent in (6, 9, 12):
        add(
            "near_miss",
            f"additive_1e-{exponent}",
            f"m*g*l*cos(theta) + m*g*l/{10**exponent}",
            "m*g*l*cos(theta)",
            pend,
            False,
            f"an extra term 1e-{exponent} of the rest",
        )
    add(
        "near_miss",
        "rational_coefficient",
        f"{acc}*{10**9 + 1}/{10**9 + 1}",
        acc,
        wedge,
        True,
        "a coefficient that is exactly 1",
    )
    small = {"theta": SMALL}
    taylor = ["theta", "- theta**3/6", "+ theta**5/120", "- theta**7/5040", "+ theta**9/362880"]
    add(
        "near_miss",
        "sin_vs_theta",
        "theta",
        "sin(theta)",
        small,
        False,
        "small-angle sin θ ≈ θ (relative θ²/6)",
    )
    add(
        "near_miss",
        "sin_taylor5",
        " ".join(taylor[:3]),
        "sin(theta)",
        small,
        False,
        "Taylor to θ⁵: off by θ⁷/5040",
    )
    add(
        "near_miss",
        "sin_taylor9",
        " ".join(taylor),
        "sin(theta)",
        small,
        False,
        "Taylor to θ⁹: off by θ¹¹/11!",
    )
    add(
        "near_miss",
        "cos_taylor4",
        "1 - theta**2/2 + theta**4/24",
        "cos(theta)",
        small,
        False,
        "Taylor to θ⁴",
    )
    add(
        "near_miss",
        "sin_double_small",
        "2*sin(theta/2)*cos(theta/2)",
        "sin(theta)",
        small,
        True,
        "exact on small angles",
    )
    add(
        "near_miss",
        "taylor_reordered",
        "theta*(1 - theta**2/6 + theta**4/120)",
        " ".join(taylor[:3]),
        small,
        True,
        "the same polynomial, factored",
    )
    spend = {"m": P, "g": P, "l": P, "theta": SMALL}
    add(
        "near_miss",
        "pendulum_small_angle",
        "m*g*l*theta",
        "m*g*l*sin(theta)",
        spend,
        False,
        "linearised restoring term on a small-angle domain",
    )
    add(
        "near_miss",
        "pendulum_cubic",
        "m*g*l*(theta - theta**3/6)",
        "m*g*l*sin(theta)",
        spend,
        False,
        "cubic small-angle term, off by θ⁵/120",
    )

    # Catastrophic cancellation.
    add(
        "cancellation",
        "poly20_near_1",
        _expanded((_X - 1) ** 20),
        "(x - 1)**20",
        {"x": "(0.9, 1.1)"},
        True,
        "(x − 1)²⁰ expanded near x = 1",
    )
    add(
        "cancellation",
        "poly20_near_minus1",
        _expanded((_X + 1) ** 20),
        "(x + 1)**20",
        {"x": "(-1.1, -0.9)"},
        True,
        "(1 + x)²⁰ expanded near x = −1",
    )
    add(
        "cancellation",
        "poly20_large",
        _expanded((_X + 1) ** 20),
        "(x + 1)**20",
        {"x": "(1000, 10000)"},
        True,
        "(1 + x)²⁰ expanded at large x",
    )
    add(
        "cancellation",
        "poly20_near_1_wrong",
        _expanded((_X - 1) ** 20) + " + x/10**12",
        "(x - 1)**20",
        {"x": "(0.9, 1.1)"},
        False,
        "expanded form plus x·1e-12, hidden by the cancellation in float64",
    )
    add(
        "cancellation",
        "poly8_two_vars",
        _expanded((_X - _Y) ** 8),
        "(x - y)**8",
        {"x": "(1000, 1001)", "y": "(1000, 1001)"},
        True,
        "(x − y)⁸ expanded with x ≈ y large",
    )
    big = {"x": "(100000000000, 1000000000000)"}
    add(
        "cancellation",
        "square_difference",
        "(x + 1)**2 - x**2",
        "2*x + 1",
        big,
        True,
        "(x+1)² − x² at x ~ 1e11",
    )
    add(
        "cancellation",
        "square_difference_wrong",
        "(x + 1)**2 - x**2",
        "2*x",
        big,
        False,
        "off by 1 in 1e12",
    )
    add(
        "cancellation",
        "one_minus_cos_tiny",
        "1 - cos(x)",
        "2*sin(x/2)**2",
        {"x": TINY},
        True,
        "1 − cos x at x ~ 1e-9",
    )
    add(
        "cancellation",
        "one_minus_cos_small",
        "1 - cos(x)",
        "2*sin(x/2)**2",
        {"x": "(0.0001, 0.001)"},
        True,
        "1 − cos x at x ~ 1e-4",
    )
    add(
        "cancellation",
        "one_minus_cos_vs_quadratic",
        "1 - cos(x)",
        "x**2/2",
        {"x": TINY},
        False,
        "1 − cos x against x²/2 at x ~ 1e-9: off by x⁴/24",
    )
    rel = {"m": P, "v": "(1, 100)", "c": "(299000000, 300000000)"}
    gamma_minus_1 = "m*c**2*(1/sqrt(1 - v**2/c**2) - 1)"
    add(
        "cancellation",
        "relativistic_kinetic",
        gamma_minus_1,
        "m*v**2/(sqrt(1 - v**2/c**2)*(1 + sqrt(1 - v**2/c**2)))",
        rel,
        True,
        "(γ − 1) m c² at v ≪ c",
    )
    add(
        "cancellation",
        "relativistic_kinetic_newton",
        gamma_minus_1,
        "m*v**2/2",
        rel,
        False,
        "Newton's ½ m v² against (γ − 1) m c²: off by 3/8 m v⁴/c²",
    )
    add(
        "cancellation",
        "energy_momentum",
        "sqrt(m**2*c**4 + p**2*c**2) - m*c**2",
        "p**2*c**2/(sqrt(m**2*c**4 + p**2*c**2) + m*c**2)",
        {
            "m": _interval("1e-28", "1e-26"),
            "p": _interval("1e-26", "1e-25"),
            "c": "(299000000, 300000000)",
        },
        True,
        "kinetic energy from E² = m²c⁴ + p²c², rationalised",
    )
    add(
        "cancellation",
        "sin_squared_small",
        "sin(x)**2",
        "1 - cos(x)**2",
        {"x": "(0.00001, 0.0001)"},
        True,
        "Pythagoras where 1 − cos² cancels",
    )

    # Very large and very small scales (constants written out as exact decimals).
    me = "9109/10**34"  # electron mass, kg
    G = "6674/10**14"  # G, m³/(kg s²)
    add(
        "scale",
        "electron_kinetic",
        "v**2*9109/(2*10**34)",
        f"{me}*v**2/2",
        {"v": "(1000, 1000000)"},
        True,
        "½ mₑ v²",
    )
    add(
        "scale",
        "electron_kinetic_wrong",
        f"{me}*v**2",
        f"{me}*v**2/2",
        {"v": "(1, 10)"},
        False,
        "½ lost: wrong by a factor 2, yet within 1e-4 in absolute terms",
    )
    add(
        "scale",
        "gravity_potential",
        f"-{G}*M*m/r",
        f"-{G}*m*M/r",
        {
            "M": _interval("1e30", "1e31"),
            "m": _interval("1e23", "1e25"),
            "r": _interval("1e10", "1e12"),
        },
        True,
        "G M m / r at planetary scale",
    )
    add(
        "scale",
        "gravity_potential_wrong",
        f"-{G}*M*m/r**2",
        f"-{G}*M*m/r",
        {
            "M": _interval("1e30", "1e31"),
            "m": _interval("1e23", "1e25"),
            "r": _interval("1e10", "1e12"),
        },
        False,
        "r² for r",
    )
    kepler = {
        "G": _interval("1e-11", "1e-10"),
        "M": _interval("1e30", "1e31"),
        "a": _interval("1e10", "1e12"),
    }
    add(
        "scale",
        "kepler_omega",
        "sqrt(G*M/a**3)",
        "sqrt(G*M)/a**(3/2)",
        kepler,
        True,
        "circular-orbit angular velocity",
    )
    add(
        "scale",
        "kepler_omega_wrong",
        "sqrt(G*M/a**3)",
        "sqrt(G*M/a**2)",
        kepler,
        False,
        "a² for a³",
    )
    tiny_m = {"m": _interval("1e-28", "1e-26"), "g": P, "l": P, "theta": R}
    add(
        "scale",
        "tiny_mass_pendulum",
        "m*g*l*(1 - cos(theta))",
        "2*m*g*l*sin(theta/2)**2",
        tiny_m,
        True,
        "pendulum potential with m ~ 1e-27 kg",
    )
    add(
        "scale",
        "tiny_mass_pendulum_wrong",
        "m*g*l*(1 - cos(theta))",
        "m*g*l*(1 + cos(theta))",
        tiny_m,
        False,
        "sign slip, both sides ~1e-27",
    )
    add(
        "scale",
        "tiny_mass_constant_wrong",
        "167/10**29*g*l*cos(theta)",
        "167/10**29*g*l*sin(theta)",
        {"g": P, "l": P, "theta": R},
        False,
        "sin/cos swap with a proton mass written as a number",
    )
    add(
        "scale",
        "light_speed_energy",
        "m*c**2*(1 + v**2/(2*c**2))",
        "m*c**2 + m*v**2/2",
        rel,
        True,
        "expanded rest plus kinetic energy, c = 3e8",
    )
    add(
        "scale",
        "light_speed_energy_wrong",
        "m*c**2*(1 + v**2/(2*c**2))",
        "m*c**2 + m*v**2",
        rel,
        False,
        "½ lost in a term 1e-14 of the total",
    )
    add(
        "scale",
        "large_spring",
        "k*x**2/2",
        "k*x*x/2",
        {"k": _interval("1e8", "1e9"), "x": _interval("1e-9", "1e-8")},
        True,
        "stiff spring, tiny stretch",
    )
    add(
        "scale",
        "large_spring_wrong",
        "k*x**2/2",
        "k*x**2",
        {"k": _interval("1e8", "1e9"), "x": _interval("1e-9", "1e-8")},
        False,
        "½ lost; both sides ~1e-8",
    )

    # Identities that hold only on the declared domain.
    pos, real = {"x": P}, {"x": R}
    add("domain", "sqrt_square_positive", "sqrt(x**2)", "x", pos, True, "√(x²) = x for x > 0")
    add(
        "domain",
        "sqrt_square_real",
        "sqrt(x**2)",
        "x",
        real,
        False,
        "√(x²) = |x|, not x, for real x",
    )
    add(
        "domain",
        "acos_cos_interval",
        "acos(cos(x))",
        "x",
        {"x": "(0, pi)"},
        True,
        "acos(cos x) = x on (0, π)",
    )
    add(
        "domain",
        "acos_cos_real",
        "acos(cos(x))",
        "x",
        {"x": "(-pi, pi)"},
        False,
        "acos(cos x) = |x| on (−π, π)",
    )
    add(
        "domain",
        "asin_sin_interval",
        "asin(sin(x))",
        "x",
        {"x": "(-pi/2, pi/2)"},
        True,
        "asin(sin x) = x on (−π/2, π/2)",
    )
    add(
        "domain",
        "asin_sin_wide",
        "asin(sin(x))",
        "x",
        {"x": "(0, pi)"},
        False,
        "asin(sin x) = π − x on (π/2, π)",
    )
    add(
        "domain",
        "atan_tan_interval",
        "atan(tan(x))",
        "x",
        {"x": "(-pi/2, pi/2)"},
        True,
        "atan(tan x) = x on (−π/2, π/2)",
    )
    add(
        "domain",
        "log_square_positive",
        "log(x**2)",
        "2*log(x)",
        pos,
        True,
        "log x² = 2 log x for x > 0",
    )
    add(
        "domain",
        "log_square_real",
        "2*log(x)",
        "log(x**2)",
        real,
        False,
        "2 log x is undefined for x < 0",
    )
    add(
        "domain",
        "sqrt_product_positive",
        "sqrt(x)*sqrt(y)",
        "sqrt(x*y)",
        {"x": P, "y": P},
        True,
        "√x √y = √(xy), x, y > 0",
    )
    add(
        "domain",
        "sqrt_product_real",
        "sqrt(x)*sqrt(y)",
        "sqrt(x*y)",
        {"x": R, "y": R},
        False,
        "fails for x, y < 0",
    )
    add(
        "domain",
        "sec_from_tan_interval",
        "sqrt(1 + tan(x)**2)",
        "1/cos(x)",
        {"x": "(-pi/2, pi/2)"},
        True,
        "√(1 + tan² x) = sec x where cos x > 0",
    )
    add(
        "domain",
        "sec_from_tan_wide",
        "sqrt(1 + tan(x)**2)",
        "1/cos(x)",
        {"x": "(0, pi)"},
        False,
        "= |sec x|: wrong sign on (π/2, π)",
    )
    add(
        "domain",
        "cos_from_sin_interval",
        "sqrt(1 - sin(theta)**2)",
        "cos(theta)",
        {"theta": "(-pi/2, pi/2)"},
        True,
        "√(1 − sin² θ) = cos θ where cos θ > 0",
    )
    add(
        "domain",
        "cos_from_sin_wide",
        "sqrt(1 - sin(theta)**2)",
        "cos(theta)",
        {"theta": "(0, pi)"},
        False,
        "sign of cos θ lost on (π/2, π)",
    )
    add("domain", "exp_log_positive", "exp(log(x))", "x", pos, True, "exp(log x) = x, x > 0")
    add(
        "domain",
        "hoop_equilibrium",
        "acos(g/(omega**2*R))",
        "atan(sqrt(omega**4*R**2 - g**2)/g)",
        {"g": "(1, 2)", "omega": "(3, 4)", "R": "(1, 2)"},
        True,
        "hoop's off-axis equilibrium angle, two forms",
    )
    add(
        "domain",
        "sqrt_square_parameter",
        "sqrt(m**2*v**2)",
        "m*v",
        {"m": P, "v": R},
        False,
        "|v| lost",
    )
    add(
        "domain",
        "sqrt_square_parameter_pos",
        "sqrt(m**2*v**2)",
        "m*v",
        {"m": P, "v": P},
        True,
        "v > 0 declared",
    )

    # Explicit time dependence (ω t).
    drive = {"m": P, "l": P, "a": P, "omega": P, "g": P, "theta": R}
    add(
        "time",
        "driven_support_expand",
        "cos(omega*t - theta)",
        "cos(omega*t)*cos(theta) + sin(omega*t)*sin(theta)",
        drive,
        True,
        "angle difference with the drive",
    )
    add(
        "time",
        "driven_support_sign",
        "cos(omega*t - theta)",
        "cos(omega*t)*cos(theta) - sin(omega*t)*sin(theta)",
        drive,
        False,
        "sum for difference",
    )
    add(
        "time",
        "drive_double_angle",
        "a**2*m*omega**2*sin(omega*t)**2/2",
        "a**2*m*omega**2*(1 - cos(2*omega*t))/4",
        drive,
        True,
        "sin² of the drive as a double angle",
    )
    add(
        "time",
        "drive_double_angle_wrong",
        "a**2*m*omega**2*sin(omega*t)**2/2",
        "a**2*m*omega**2*(1 + cos(2*omega*t))/4",
        drive,
        False,
        "cos² for sin²",
    )
    add(
        "time",
        "drive_frequency_slip",
        "a*m*omega**2*cos(omega*t)",
        "a*m*omega**2*cos(2*omega*t)",
        drive,
        False,
        "ω t for 2 ω t",
    )
    add(
        "time",
        "drive_dropped_omega",
        "a*m*omega*cos(omega*t)",
        "a*m*omega**2*cos(omega*t)",
        drive,
        False,
        "ω for ω²",
    )
    longt = {"omega": "(1, 2)", "t": "(100000, 1000000)"}
    add(
        "time",
        "long_time_double_angle",
        "sin(omega*t)**2",
        "(1 - cos(2*omega*t))/2",
        longt,
        True,
        "identity at t ~ 1e5 … 1e6: a large trig argument",
    )
    add(
        "time",
        "long_time_phase_slip",
        "sin(omega*t)",
        "sin(omega*t + 1/10**9)",
        longt,
        False,
        "a phase off by 1e-9 rad",
    )
    add(
        "time",
        "rotating_frame",
        "m*omega**2*(x*cos(omega*t) - y*sin(omega*t))**2/2"
        " + m*omega**2*(x*sin(omega*t) + y*cos(omega*t))**2/2",
        "m*omega**2*(x**2 + y**2)/2",
        {"m": P, "omega": P, "x": R, "y": R},
        True,
        "rotation preserves x² + y²",
    )
    add(
        "time",
        "rotating_frame_wrong",
        "m*omega**2*(x*cos(omega*t) - y*sin(omega*t))**2/2",
        "m*omega**2*(x**2 + y**2)/2",
        {"m": P, "omega": P, "x": R, "y": R},
        False,
        "one component lost",
    )
    add(
        "time",
        "explicit_t_power",
        "g*t**2/2 + v*t",
        "t*(g*t + 2*v)/2",
        {"g": P, "v": R},
        True,
        "free fall, factored",
    )
    add(
        "time",
        "damped_exp",
        "exp(-gamma*t)*cos(omega*t)",
        "exp(-gamma*t)*cos(omega*t)*(1 + 1/10**8)",
        {"gamma": "(0.1, 1)", "omega": P},
        False,
        "damped drive off by 1e-8",
    )

    # Points where one side is undefined.
    add("undefined", "x_over_x", "x/x", "1", real, True, "x/x = 1 except at x = 0")
    add(
        "undefined",
        "removable_pole",
        "(x**2 - 1)/(x - 1)",
        "x + 1",
        real,
        True,
        "removable singularity at x = 1",
    )
    add(
        "undefined",
        "removable_pole_wrong",
        "(x**2 - 1)/(x - 1)",
        "x - 1",
        real,
        False,
        "x − 1 for x + 1",
    )
    add(
        "undefined",
        "log_negative_part",
        "log(x - 1)",
        "log(x - 1)",
        {"x": "(0, 3)"},
        True,
        "the same logarithm; undefined for x < 1 on both sides",
    )
    add(
        "undefined",
        "log_answer_undefined",
        "2*log(x)",
        "log(x**2)",
        {"x": "(-1, 1)"},
        False,
        "the answer is undefined where x < 0, the reference is not",
    )
    add(
        "undefined",
        "log_ratio",
        "log(x) - log(y)",
        "log(x/y)",
        {"x": R, "y": R},
        False,
        "log(x/y) exists for x, y < 0, log x − log y does not",
    )
    add(
        "undefined",
        "log_ratio_positive",
        "log(x/y)",
        "log(x) - log(y)",
        {"x": P, "y": P},
        True,
        "x, y > 0",
    )
    add(
        "undefined",
        "sqrt_partly_undefined",
        "sqrt(x - 1)",
        "(x - 1)/sqrt(x - 1)",
        {"x": "(0, 2)"},
        True,
        "the same root; undefined on (0, 1) on both sides",
    )
    add(
        "undefined",
        "reference_narrower",
        "sqrt(x)*sqrt(x - 1)",
        "sqrt(x**2 - x)",
        {"x": "(-1, 2)"},
        False,
        "√(x² − x) exists for x < 0, √x √(x − 1) does not",
    )
    add(
        "undefined",
        "acos_outside",
        "pi/2 - asin(x)",
        "acos(x)",
        {"x": "(-2, 2)"},
        True,
        "both undefined for |x| > 1, equal inside",
    )
    add(
        "undefined",
        "tan_pole",
        "sin(x)/cos(x)",
        "tan(x)",
        {"x": "(0, pi)"},
        True,
        "pole at π/2 on both sides",
    )
    add(
        "undefined", "pole_answer_only", "x**2/x", "x", real, True, "sympy cancels x²/x = x at once"
    )
    add(
        "undefined",
        "one_over_sqrt",
        "1/sqrt(1 - v**2/c**2)",
        "c/sqrt(c**2 - v**2)",
        {"v": "(0, 2)", "c": "(1, 3)"},
        True,
        "γ; undefined where v > c on both sides",
    )
    return H


def hard_pairs() -> list[Pair]:
    pairs = []
    for category, kind, answer, reference, params, label, note in _hard():
        params = dict(params)
        domains = dict(params)
        if _USES_TIME.search(answer + " " + reference):
            domains.setdefault("t", TIME_DOMAIN)
        params.pop("t", None)  # t is the parser's own symbol, not a parameter
        pairs.append(
            Pair(
                id=f"hard/{category}/{kind}",
                category=category,
                kind=kind,
                label=label,
                answer=answer,
                reference=reference,
                coordinates=(),
                parameters=params,
                domains=domains,
                note=note,
            )
        )
    return pairs


def build() -> list[Pair]:
    pairs = bank_pairs() + hard_pairs()
    ids = [p.id for p in pairs]
    assert len(ids) == len(set(ids)), "duplicate pair ids"
    return pairs


def check_round_trip(pairs: list[Pair]) -> None:
    """Every text must parse to a finite expression whose symbols all have a sampling domain."""
    for p in pairs:
        parsed = parse_pair(p)
        for side, expr in (("answer", parsed.answer), ("reference", parsed.reference)):
            if expr.has(sp.zoo, sp.nan):
                raise SystemExit(f"{p.id}: the {side} parses to an undefined value")
        unknown = {
            s.name for s in parsed.answer.free_symbols | parsed.reference.free_symbols
        } - set(p.domains)
        unknown -= {mech.t.name} if "t" in p.domains else set()
        if unknown:
            raise SystemExit(f"{p.id}: no sampling domain for {sorted(unknown)}")


def main() -> None:
    pairs = build()
    check_round_trip(pairs)
    PAIRS.write_text("".join(p.to_json() + "\n" for p in pairs), encoding="utf-8")
    by_category: dict[str, list[int]] = {}
    for p in pairs:
        counts = by_category.setdefault(p.category, [0, 0])
        counts[0 if p.label else 1] += 1
    print(f"wrote {len(pairs)} pairs to {PAIRS.relative_to(ROOT)}")
    for category, (true, false) in by_category.items():
        print(f"  {category:16} {true:4} true {false:4} false")


if __name__ == "__main__":
    main()
