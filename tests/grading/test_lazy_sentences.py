"""A mutant's sentence is written when it is read (most mutants are never named), and it is the
very string the eager sentences were: the formulas below are the ones the catalogue used to
write at once, compared with the lazy ones for every mutant of a few bank scenes."""

from __future__ import annotations

import pytest
import sympy as sp

from lagrade.judge import mutations
from lagrade.judge.mutations import (
    _TERM_MESSAGES,
    Mutant,
    Sentence,
    dropped_factor_mutants,
    expanded_terms,
    kinetic_mutants,
    one_term_mutants,
    replaced,
    term_specs,
    trig_factor_mutant,
    trig_factors,
    velocities_in,
)
from lagrade.judge.problem import build_problem
from lagrade.notation.printer import plain

SCENES = ("wedge", "hoop", "double_pendulum", "rotating_frame", "atwood", "rolling_cylinder")


def _eager_term(kind: str, term, what: str, factor) -> str:
    return _TERM_MESSAGES[kind].format(t=plain(term), w=what, p=factor)


def _eager_kinetic(T, jets, what: str) -> list[str]:
    out = []
    terms = expanded_terms(T)
    for term in terms:
        vel = velocities_in(term, jets)
        coeff = term.as_coeff_Mul()[0]
        if vel and isinstance(coeff, sp.Rational) and coeff.q % 2 == 0:
            out.append(f"the ½ is missing in the kinetic term {plain(term)} of {what}")
        if len(vel) >= 2:
            out.append(f"{what} lacks the cross term in {plain(sp.Mul(*vel))}")
        if not vel:
            out.append(
                f"{what} lacks the term {plain(term)} from the prescribed motion "
                "(the centripetal or ω² term of the kinetic energy)"
            )
    return out


def _eager_dropped(ref) -> list[str]:
    out = []
    factors = [f for f in sp.Mul.make_args(ref) if not f.is_number]
    for f in factors if len(factors) >= 2 else ():
        exponent = f.as_base_exp()[1]
        if exponent.is_number and exponent < 0:
            out.append(f"your answer lacks the division by {plain(1 / f)}")
        else:
            out.append(f"your answer lacks the factor {plain(f)}")
    return out


@pytest.mark.parametrize("scene", SCENES)
def test_lazy_sentences_are_the_eager_ones(scene):
    problem = build_problem({"scene": scene})
    system, params = problem.system, list(problem.parameters.values())
    variant = problem.variant
    wholes = {
        "your L": system.L,
        "your T": variant.kinetic_energy,
        "your V": variant.potential_energy,
    }
    wholes |= {
        f"your p_{j.name}": p for j, p in zip(problem.jets, system.generalized_momenta, strict=True)
    }
    wholes |= {
        f"your equation for {j.name}": e
        for j, e in zip(problem.jets, system.euler_lagrange, strict=True)
    }
    checked = 0
    for what, whole in wholes.items():
        terms = expanded_terms(whole)
        base = sp.Add(*terms)
        for term in terms:
            specs = term_specs(term, params)
            for m, (kind, _, factor) in zip(
                one_term_mutants(base, term, what, params), specs, strict=True
            ):
                assert m.message == _eager_term(kind, term, what, factor), (scene, what, kind)
                checked += 1
            for f in trig_factors(term):
                m = trig_factor_mutant(base, term, f, what)
                eager = _TERM_MESSAGES["missing_factor"].format(t=plain(term), w=what, p=plain(f))
                assert m.message == eager
    T = variant.kinetic_energy
    lazy = [m.message for m in kinetic_mutants(T, problem.jets, "your T")]
    assert lazy == _eager_kinetic(T, problem.jets, "your T")
    for ref in variant.quantities.values():
        assert [m.message for m in dropped_factor_mutants(ref)] == _eager_dropped(ref)
    assert checked


def test_a_catalogue_prints_only_the_sentences_read(monkeypatch):
    """Building every mutant of a question prints none of its terms; naming one prints it."""
    printed = []
    monkeypatch.setattr(mutations, "plain", lambda e, *a: printed.append(e) or plain(e, *a))
    problem = build_problem({"scene": "wedge"})
    catalogue = problem.catalogue
    everything = [*catalogue.lagrangian_mutants, *catalogue.kinetic_mutants]
    everything += [m for k in range(len(problem.jets)) for m in catalogue.momentum_mutants(k)]
    everything += [m for _, m in catalogue.row_mutants]
    assert len(everything) > 20 and printed == []
    first_term = next(m for m in everything if isinstance(m.said, Sentence))
    assert first_term.message and printed


def test_a_sentence_reads_compares_and_hashes_as_its_text():
    x = sp.Symbol("x")
    said = Sentence("{w} lacks the term {t}", {"t": x**2 / 2}, {"w": "your L"})
    assert said.text == "your L lacks the term x^2/2"
    assert said == "your L lacks the term x^2/2" and hash(said) == hash(said.text)
    moved = replaced(replaced(said, "your L", "your p_x"), "p_x", "p_y")
    assert moved.text == "your p_y lacks the term x^2/2" and said.text.startswith("your L")
    assert replaced("your L is wrong", "your L", "your T") == "your T is wrong"
    assert Mutant("k", said, x) == Mutant("k", "your L lacks the term x^2/2", x)
