"""Parse typical answers with lagrade's parser and with sympy's parse_expr, side by side.

    python benchmarks/bench_parse.py [--repeat N]

For each answer: median and p99 time per parse for both parsers, and the ratio of medians.
"Warm" runs reuse sympy's global cache (as a grading batch does); "cold" runs clear it before
every parse, for both parsers alike. parse_expr is used here only on our own benchmark strings.
"""

from __future__ import annotations

import argparse
import statistics
import time

import sympy as sp
from sympy.core.cache import clear_cache
from sympy.parsing.sympy_parser import (
    convert_xor,
    implicit_multiplication_application,
    parse_expr,
    standard_transformations,
)

from lagrade import bank
from lagrade.notation.parse import Vocabulary, parse_answer

TRANSFORMATIONS = standard_transformations + (implicit_multiplication_application, convert_xor)


def cases() -> list[tuple[str, str, str, Vocabulary, dict]]:
    """(label, our text, parse_expr text, vocabulary, parse_expr local dict)."""
    out = []
    for scene_id in ("wedge", "hoop"):
        variant = bank.get_scene(scene_id).default
        vocab = Vocabulary.from_variant(variant)
        local = {s.name: s for j in variant.jets for s in (j.q, j.dot, j.ddot)}
        local |= dict(variant.parameter_symbols)
        L = str(variant.lagrangian)
        out.append((f"{scene_id}: L as printed by sympy", L, L, vocab, local))
        for i, eq in enumerate(variant.euler_lagrange):
            text = f"{eq} = 0"
            out.append((f"{scene_id}: EL equation {i + 1}", text, str(eq), vocab, local))
    wedge = bank.get_scene("wedge").default
    vocab = Vocabulary.from_variant(wedge)
    local = {s.name: s for j in wedge.jets for s in (j.q, j.dot, j.ddot)} | dict(
        wedge.parameter_symbols
    )
    student = (
        "1/2 (M + m) x_M_dot^2 + m x_M_dot q_dot cos(alpha) + 1/2 m q_dot^2 + m g q sin(alpha)"
    )
    out.append(("wedge: student L (implicit products)", student, student, vocab, local))
    student_eq = "(M + m) x_M_ddot + m q_ddot cos(alpha) = 0"
    out.append(
        (
            "wedge: student EL equation",
            student_eq,
            "(M + m) x_M_ddot + m q_ddot cos(alpha)",
            vocab,
            local,
        )
    )
    hoop = bank.get_scene("hoop").default
    vocab = Vocabulary.from_variant(hoop)
    local = {s.name: s for j in hoop.jets for s in (j.q, j.dot, j.ddot)} | dict(
        hoop.parameter_symbols
    )
    student = "1/2 m R^2 (theta_dot^2 + omega^2 sin(theta)^2) + m g R cos(theta)"
    out.append(("hoop: student L", student, student, vocab, local))
    latex = (
        r"\frac{1}{2} m R^2 \left(\dot{\theta}^2 + \omega^2 \sin^2\theta\right) + m g R \cos\theta"
    )
    out.append(("hoop: student L in LaTeX (ours only)", latex, "", vocab, local))
    return out


def timings(fn, repeat: int, cold: bool) -> list[float]:
    result = []
    for _ in range(repeat):
        if cold:
            clear_cache()
        start = time.perf_counter()
        fn()
        result.append(time.perf_counter() - start)
    return result


def p99(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))]


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeat", type=int, default=300)
    args = parser.parse_args()
    rows = cases()
    for label, ours, theirs, vocab, local in rows:  # both must agree before we time them
        if theirs:
            mine = parse_answer(ours, vocab)
            reference = parse_expr(theirs, local_dict=local, transformations=TRANSFORMATIONS)
            assert sp.expand(mine.expr - reference) == 0, label
    header = ["ours med", "ours p99", "sympy med", "sympy p99"]
    print(f"{'answer':42} {'chars':>5}  " + " ".join(f"{h:>9}" for h in header) + "  ratio")
    for cold in (False, True):
        mode = "cold (sympy cache cleared before each parse)" if cold else "warm (sympy cache kept)"
        print(f"--- {mode}")
        ratios = []
        for label, ours, theirs, vocab, local in rows:
            a = timings(lambda ours=ours, vocab=vocab: parse_answer(ours, vocab), args.repeat, cold)
            line = f"{label:42} {len(ours):5}  "
            line += f"{statistics.median(a) * 1e3:7.3f}ms {p99(a) * 1e3:7.3f}ms"
            if theirs:
                b = timings(
                    lambda theirs=theirs, local=local: parse_expr(
                        theirs, local_dict=local, transformations=TRANSFORMATIONS
                    ),
                    args.repeat,
                    cold,
                )
                ratio = statistics.median(b) / statistics.median(a)
                ratios.append(ratio)
                line += (
                    f"  {statistics.median(b) * 1e3:7.3f}ms {p99(b) * 1e3:7.3f}ms  {ratio:5.1f}x"
                )
            print(line)
        print(f"median ratio (sympy / ours): {statistics.median(ratios):.1f}x")


if __name__ == "__main__":
    main()
