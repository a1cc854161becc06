"""The labelled grading cases of issue 12 from public sources (benchmarks/corpus/judged.jsonl:
textbook systems and sympy's mechanics tests, each with its source): every case gets its label,
and the labels of L, EOM and conserved cases are verified here independently of the judge, with
sympy.physics.mechanics.LagrangesMethod on the variant's Lagrangian and values at 30 digits."""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

from lagrade.judge.check import check
from lagrade.judge.parts.reading import read, read_labelled
from lagrade.judge.problem import build_problem
from lagrade.mechanics.lagrange import t

CASES = [
    json.loads(line)
    for line in Path(__file__).parents[2].joinpath("benchmarks/corpus/judged.jsonl").open()
]


@pytest.mark.parametrize("case", CASES, ids=[c["id"] for c in CASES])
def test_case_gets_its_label(case):
    verdict = check(
        case["problem"], case["part"], case["answer"], time_limit=None, given=case.get("given")
    )
    assert verdict.status == case["status"], verdict
    if "score" in case:
        assert verdict.score == pytest.approx(case["score"]), verdict
    text = " ".join(verdict.feedback)
    assert case.get("feedback_has", "") in text, verdict.feedback
    if "feedback_lacks" in case:
        assert case["feedback_lacks"] not in text, verdict.feedback


def _mechanics(problem):
    """The variant's L in dynamicsymbols, its equations from LagrangesMethod, and the maps."""
    jets = problem.jets
    qs = dynamicsymbols(" ".join(f"{j.name}_q" for j in jets), seq=True)
    time = dynamicsymbols._t
    to_dyn = {}
    for j, q in zip(jets, qs, strict=True):
        to_dyn |= {j.q: q, j.dot: q.diff(time), j.ddot: q.diff(time, 2)}
    L = problem.lagrangian.xreplace(to_dyn).xreplace({t: time})
    lm = LagrangesMethod(L, qs)
    eom = list(lm.form_lagranges_equations())
    back = {}
    for j, q in zip(jets, qs, strict=True):
        back |= {q.diff(time, 2): j.ddot, q.diff(time): j.dot, q: j.q}
    rows = [sp.expand(e.xreplace(back)) for e in eom]
    return rows, to_dyn, lm


def _read(problem, text):
    """The project parser reads the text (as for any answer); the physics is checked here."""
    return read(problem, text, (), "answer" if "=" in text else "expression").expr


def _points(problem, k=3, per=2, seed=3):
    """k parameter draws, each with `per` draws of the coordinates, velocities, accelerations."""
    rng = random.Random(seed)
    for _ in range(k):
        params = {
            s: sp.Float(rng.uniform(*d.sample_range()), 30) for s, d in problem.domains.items()
        }
        for _ in range(per):
            env = dict(params)
            for j in problem.jets:
                lo = 0.5 if j.name == "r" else -1.2
                env |= {s: sp.Float(rng.uniform(lo, 1.4), 30) for s in (j.q, j.dot, j.ddot)}
            yield env


def _zero(x, scale):
    return abs(x) <= 1e-20 * max(1, abs(scale))


def _eom_label(problem, answer):
    """Each answer row a multiple of the LagrangesMethod row of its coordinate (the cases are
    written row by row)."""
    rows, _, _ = _mechanics(problem)
    exprs = [_read(problem, a) for a in answer]
    for env in _points(problem):
        for a, r, j in zip(exprs, rows, problem.jets, strict=True):
            c = sp.diff(a, j.ddot).evalf(30, subs=env) / sp.diff(r, j.ddot).evalf(30, subs=env)
            if not _zero((a - c * r).evalf(30, subs=env), a.evalf(30, subs=env)):
                return "incorrect"
    return "correct"


def _lagrangian_label(problem, answer):
    rows, _, _ = _mechanics(problem)
    L = _read(problem, answer)
    mine = []
    for j in problem.jets:
        p = sp.diff(L, j.dot)
        dt = sum(sp.diff(p, k.q) * k.dot + sp.diff(p, k.dot) * k.ddot for k in problem.jets)
        mine.append(sp.expand(dt + sp.diff(p, t) - sp.diff(L, j.q)))
    ratios = []
    for env in _points(problem):
        ref = [r.evalf(30, subs=env) for r in rows]
        got = [m.evalf(30, subs=env) for m in mine]
        k = max(range(len(ref)), key=lambda i: abs(ref[i]))
        c = got[k] / ref[k]
        if not all(_zero(g - c * r, r) for g, r in zip(got, ref, strict=True)):
            return "incorrect"
        ratios.append(c)
    # one factor c > 0 per parameter draw (pairs of points share their parameters)
    same = all(_zero(a - b, a) for a, b in zip(ratios[::2], ratios[1::2], strict=True))
    return "correct" if same and all(c > 0 for c in ratios) else "incorrect"


def _conserved_label(problem, answer):
    """Every quantity conserved (sympy's D_t Q on the LagrangesMethod accelerations), and none a
    parameter multiple of one before it plus a constant: grad Q = c grad K on phase space (q, q̇)
    with c free of the coordinates and velocities (issue 25: the parameters are numbers)."""
    rows, _, _ = _mechanics(problem)
    acc = sp.solve(rows, [j.ddot for j in problem.jets], dict=True)[0]
    phase = [j.q for j in problem.jets] + [j.dot for j in problem.jets]
    grads = []
    for text in answer:
        Q = read_labelled(problem, text).expr
        dQ = sum(sp.diff(Q, j.q) * j.dot + sp.diff(Q, j.dot) * acc[j.ddot] for j in problem.jets)
        if sp.simplify(dQ) != 0:
            return "incorrect"
        grad = [sp.diff(Q, v) for v in phase]
        if any(_parameter_multiple(grad, earlier, phase) for earlier in grads):
            return "incorrect"
        grads.append(grad)
    return "correct"


def _parameter_multiple(grad, earlier, phase) -> bool:
    k = next((i for i, g in enumerate(earlier) if g != 0), None)
    if k is None:
        return False
    c = sp.simplify(grad[k] / earlier[k])
    if c.free_symbols & set(phase):
        return False
    return all(sp.simplify(g - c * e) == 0 for g, e in zip(grad, earlier, strict=True))


LABELLERS = {"eom": _eom_label, "lagrangian": _lagrangian_label, "conserved": _conserved_label}


@pytest.mark.parametrize(
    "case",
    [c for c in CASES if c["part"] in LABELLERS and "could not" not in c.get("feedback_has", "")],
    ids=lambda c: c["id"],
)
def test_label_verified_with_sympy_mechanics(case):
    """The label, recomputed: a case that asks for all quantities is labelled by the truth of
    what was given (completeness changes the score, checked above)."""
    problem = build_problem(case["problem"])
    label = LABELLERS[case["part"]](problem, case["answer"])
    expected = case["status"]
    if case.get("given", {}).get("all"):
        # what was given is true unless the case says otherwise; completeness is the score's
        expected = case.get("given_is", "correct")
    assert label == expected, (case["id"], label)
