"""Where equivalence methods break, pinned: each hard case of the corpus that some method gets
wrong is a regression test that the default (lagrade.judge.adaptive.ExactThenAdaptive, which
is `exact_then_adaptive`) must get right — and the test also checks that the named weak method
still gets it wrong, so the case stays hard. The cases that made the study replace the previous
default (`numeric_hybrid`) are pinned the same way; the default must decide every hard case.

Figures and chart: docs/methods.csv, docs/methods.png (benchmarks/bench_methods.py).
"""

from __future__ import annotations

import pytest

from benchmarks.methods import DEFAULT_NAME, Method, all_methods, method_named
from lagrade.judge.adaptive import ExactThenAdaptive

# (pair id, a method that gets it wrong) — the default decides each of these correctly.
PINS = [
    # trig identities sympy.simplify cannot prove
    ("hard/trig_identity/half_angle", "simplify"),
    ("hard/trig_identity/sixth_powers", "simplify"),
    ("hard/trig_identity/cos_5x", "simplify"),
    ("hard/trig_identity/tan_3x", "simplify"),
    ("hard/trig_identity/csc_minus_cot", "float10pt_rtol1e-9"),
    ("hard/trig_identity/product_diff", "structural_expand"),
    # near misses a loose tolerance accepts
    ("hard/near_miss/relative_1e-4", "webwork"),
    ("hard/near_miss/relative_1e-7", "float10pt_rtol1e-6"),
    ("hard/near_miss/relative_1e-9", "numbas"),
    ("hard/near_miss/additive_1e-9", "float50pt_rtol1e-6"),
    ("hard/near_miss/sin_vs_theta", "float10pt_rtol1e-3"),
    ("hard/near_miss/pendulum_small_angle", "float50pt_rtol1e-3"),
    # cancellation: true identities rejected when the tolerance is relative to the value
    ("hard/cancellation/poly20_near_1", "mp50_10pt"),
    ("hard/cancellation/poly8_two_vars", "mp50_10pt"),
    ("hard/cancellation/one_minus_cos_tiny", "mp50_10pt"),
    ("hard/cancellation/sin_squared_small", "mp30_10pt"),
    ("hard/cancellation/energy_momentum", "float50pt_rtol1e-3"),
    ("hard/cancellation/square_difference", "float10pt_rtol1e-9"),
    ("hard/cancellation/poly20_large", "webwork"),
    # very large and very small scales
    ("hard/scale/electron_kinetic_wrong", "numbas"),
    ("hard/scale/gravity_potential_wrong", "numbas"),
    ("hard/scale/tiny_mass_constant_wrong", "webwork"),
    # identities that hold only on the declared domain
    ("hard/domain/acos_cos_interval", "simplify"),
    ("hard/domain/acos_cos_interval", "webwork"),
    ("hard/domain/sqrt_square_real", "numbas"),
    ("hard/domain/log_square_real", "numbas"),
    ("hard/domain/sqrt_product_real", "webwork"),
    ("hard/domain/sec_from_tan_wide", "float1pt_rtol1e-9"),
    ("hard/domain/hoop_equilibrium", "simplify"),
    ("hard/domain/hoop_equilibrium", "numbas"),
    ("hard/domain/sqrt_square_parameter", "float1pt_rtol1e-3"),
    # explicit time dependence
    ("hard/time/driven_support_expand", "structural_expand"),
    ("hard/time/long_time_phase_slip", "float20pt_rtol1e-6"),
    ("hard/time/damped_exp", "float50pt_rtol1e-6"),
    ("hard/time/damped_exp", "webwork"),
    # one side undefined on part of the domain
    ("hard/undefined/log_answer_undefined", "numbas"),
    ("hard/undefined/log_ratio", "webwork"),
    ("hard/undefined/one_over_sqrt", "webwork"),
    ("hard/undefined/reference_narrower", "exact_rational"),  # out of its scope: None
]

# Cases the previous default (numeric_hybrid) got wrong (measured), with another method that
# also gets them wrong (None: no other method of the study does).
DEFAULT_MISSES = [
    ("hard/near_miss/relative_1e-12", "float50pt_rtol1e-9"),
    ("hard/near_miss/additive_1e-12", "float50pt_rtol1e-9"),
    ("hard/near_miss/sin_taylor5", "float50pt_rtol1e-9"),
    ("hard/near_miss/sin_taylor9", "mp30_10pt"),
    ("hard/near_miss/cos_taylor4", "float50pt_rtol1e-9"),
    ("hard/near_miss/pendulum_cubic", "float50pt_rtol1e-9"),
    ("hard/cancellation/poly20_near_1_wrong", "numbas"),
    ("hard/cancellation/square_difference_wrong", "float50pt_rtol1e-3"),
    ("hard/cancellation/one_minus_cos_vs_quadratic", None),  # only the default misses it
    ("hard/cancellation/relativistic_kinetic", "mp50_10pt"),
    ("hard/scale/light_speed_energy_wrong", "float50pt_rtol1e-9"),
]


def _verdict(method: Method, pair):
    return method.decide(pair.answer, pair.reference, pair.domains)


def _ids(cases):
    return [f"{pid.removeprefix('hard/')}-vs-{weak or 'none'}" for pid, weak in cases]


@pytest.mark.parametrize(("pair_id", "weak"), PINS, ids=_ids(PINS))
def test_default_decides_where_weak_method_fails(corpus, pair_id, weak):
    pair = corpus[pair_id]
    assert _verdict(method_named(DEFAULT_NAME), pair) is pair.label, pair.pair.note
    assert _verdict(method_named(weak), pair) is not pair.label, f"{weak} no longer fails {pair_id}"


@pytest.mark.parametrize(("pair_id", "weak"), DEFAULT_MISSES, ids=_ids(DEFAULT_MISSES))
def test_weak_method_still_fails_the_default_misses(corpus, pair_id, weak):
    if weak is None:
        pytest.skip("no other method of the study misses this case")
    pair = corpus[pair_id]
    assert _verdict(method_named(weak), pair) is not pair.label


@pytest.mark.parametrize(("pair_id", "weak"), DEFAULT_MISSES, ids=_ids(DEFAULT_MISSES))
def test_default_decides_what_the_previous_default_missed(corpus, pair_id, weak):
    """The study replaced the numeric hybrid as default because of these cases: the default
    must decide each, and the numeric hybrid still gets each wrong (so the case stays hard)."""
    pair = corpus[pair_id]
    assert _verdict(method_named(DEFAULT_NAME), pair) is pair.label
    assert _verdict(method_named("numeric_hybrid"), pair) is not pair.label


def test_proposal_decides_every_hard_case(corpus):
    proposal = ExactThenAdaptive()
    wrong = [
        pid
        for pid, pair in corpus.items()
        if pid.startswith("hard/") and _verdict(proposal, pair) is not pair.label
    ]
    assert wrong == []


def test_every_hard_category_is_pinned():
    categories = {pid.split("/")[1] for pid, _ in PINS}
    assert categories == {
        "trig_identity",
        "near_miss",
        "cancellation",
        "scale",
        "domain",
        "time",
        "undefined",
    }


def test_methods_share_one_interface():
    methods = all_methods()
    names = [m.name for m in methods]
    assert len(names) == len(set(names))
    assert all(isinstance(m, Method) for m in methods)
    assert DEFAULT_NAME in names
