"""Feedback that is always true (issue 36): each specific sentence is said only when the
correction it implies, applied to the answer, makes it right — the three false classes the
claims benchmark found (benchmarks/claims.py), and every state number a sentence quotes is in
the verdict's witness."""

from __future__ import annotations

import re

import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lagrade.bank.registry import get_scene
from lagrade.notation import plain

from .conftest import judge

HALF_MISSING = "The ½ is missing in the kinetic energy."


def _momenta(sid: str, seed: int, factor_of) -> list[str]:
    v = get_scene(sid).variant(seed)
    p = v.system.generalized_momenta
    return [
        f"p_{j.name} = {plain(factor_of(k) * e)}"
        for k, (j, e) in enumerate(zip(v.jets, p, strict=True))
    ]


def test_one_doubled_momentum_is_not_a_missing_half_of_T():
    """Only p_x doubled: a T without its ½ would double p_y and p_z too, so that is not said;
    the weaker sentence's correction (halve p_x) makes the answer right."""
    answer = ["p_x = 2 m x_dot", "p_y = m y_dot", "p_z = m z_dot"]
    verdict = judge({"scene": "free_particle"}, "momenta", answer)
    assert HALF_MISSING not in verdict.feedback
    assert verdict.feedback[0].startswith("p_x is twice ∂L/∂x_dot"), verdict.feedback
    fixed = ["p_x = m x_dot", "p_y = m y_dot", "p_z = m z_dot"]
    assert judge({"scene": "free_particle"}, "momenta", fixed).status == "correct"


def test_every_momentum_doubled_is_still_a_missing_half():
    answer = ["p_x = 2 m x_dot", "p_y = 2 m y_dot", "p_z = 2 m z_dot"]
    verdict = judge({"scene": "free_particle"}, "momenta", answer)
    assert verdict.feedback[0] == HALF_MISSING


def test_a_momentum_with_a_vector_potential_doubled_is_no_missing_half():
    """2 p for p = m v + e A is not ∂(2T − V)/∂q̇ (the e A part is not kinetic)."""
    answer = _momenta("charged_particle", 1, lambda k: 2)
    verdict = judge({"scene": "charged_particle", "seed": 1}, "momenta", answer)
    assert HALF_MISSING not in verdict.feedback, verdict.feedback


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    sid=st.sampled_from(
        ["wedge", "double_pendulum", "spherical_pendulum", "kepler", "pendulum_on_cart"]
    ),
    seed=st.integers(1, 4),
    data=st.data(),
)
def test_a_whole_L_sentence_needs_every_momentum(sid, seed, data):
    """Property: with one momentum doubled and the others right, no sentence blames all of T."""
    n = len(get_scene(sid).variant(seed).jets)
    k = data.draw(st.integers(0, n - 1))
    answer = _momenta(sid, seed, lambda i: 2 if i == k else 1)
    verdict = judge({"scene": sid, "seed": seed}, "momenta", answer)
    assert verdict.status == "incorrect"
    assert HALF_MISSING not in verdict.feedback, verdict.feedback


def test_h_is_not_said_conserved_for_a_driven_system():
    """The driven pendulum's L depends on t: neither T + V nor h is conserved."""
    v = get_scene("driven_pendulum").variant(1)
    energy = sp.expand(v.kinetic_energy + v.potential_energy)
    verdict = judge({"scene": "driven_pendulum", "seed": 1}, "conserved", [plain(energy)])
    text = " ".join(verdict.feedback)
    assert "T + V is not conserved" in text
    assert "h = Σ q̇ ∂L/∂q̇ − L is" not in text
    assert "h is not conserved either" in text
    h = v.system.energy_function
    assert judge({"scene": "driven_pendulum", "seed": 1}, "conserved", [plain(h)]).score == 0


def test_h_is_said_conserved_where_it_is():
    """The bead on a rotating hoop: L has no explicit t, so h is conserved and said to be."""
    v = get_scene("hoop").variant(1)
    energy = sp.expand(v.kinetic_energy + v.potential_energy)
    verdict = judge({"scene": "hoop", "seed": 1}, "conserved", [plain(energy)])
    assert any("the Jacobi integral h = Σ q̇ ∂L/∂q̇ − L is" in s for s in verdict.feedback)
    h = v.system.energy_function
    assert judge({"scene": "hoop", "seed": 1}, "conserved", [plain(h)]).status == "correct"


_STATE = re.compile(r"([^\s,()]+) = (−?[\d.]+)")


def _quoted_in_witness(verdict, jets) -> None:
    from lagrade.judge.situation import symbol_text

    shown = {symbol_text(j.name, d): j.name + s for j in jets for d, s in ((0, ""), (1, "_dot"))}
    for sentence in verdict.feedback:
        if "(for example" not in sentence:
            continue
        state = sentence[sentence.index("(for example") :].partition(", where ")[0]
        for sym, number in _STATE.findall(state):
            if sym in shown:
                got = verdict.witness[shown[sym]]
                assert float(f"{got:.3g}") == float(number.replace("−", "-")), sentence


def test_a_wrong_solved_equation_quotes_only_witness_numbers():
    """q̈ = −f/2: the state quoted (θ and θ̇) is the witness's, whole. (q̈ = −f is named
    without numbers: tests/grading/test_named_mistakes.py.)"""
    v = get_scene("hoop").variant(1)
    acc = sp.cancel(v.system.forcing[0] / v.system.mass_matrix[0, 0])
    answer = [f"{plain(v.jets[0].ddot)} = {plain(-acc / 2)}"]
    verdict = judge({"scene": "hoop", "seed": 1}, "eom", answer)
    assert verdict.status == "incorrect"
    assert "θ̇ = " in verdict.feedback[0] or "φ̇ = " in verdict.feedback[0]
    _quoted_in_witness(verdict, v.jets)


def test_two_wrong_equations_quote_one_state():
    """The double pendulum's equations from a wrong L: a second sentence quotes no other state
    than the witness's."""
    v = get_scene("double_pendulum").variant(1)
    from lagrade.mechanics import LagrangianSystem

    terms = sp.Add.make_args(sp.expand(v.lagrangian))
    cross = next(x for x in terms if sum(x.has(j.dot) for j in v.jets) == 2)
    rows = LagrangianSystem(sp.expand(v.lagrangian - cross / 2), v.jets).euler_lagrange
    verdict = judge(
        {"scene": "double_pendulum", "seed": 1}, "eom", [f"{plain(r)} = 0" for r in rows]
    )
    assert verdict.status == "incorrect"
    _quoted_in_witness(verdict, v.jets)


def test_a_mistake_of_l_seen_in_every_momentum_is_said_once():
    from lagrade.judge.driver import judge

    verdict = judge(
        {"scene": "kepler"}, "momenta", ["p_r = 2*m*r_dot", "p_theta = 2*m*r^2*theta_dot"]
    )
    assert verdict.feedback == ("The ½ is missing in the kinetic energy.",)
    assert verdict.mistakes == ("dropped_half_all",)


def test_one_term_of_a_momentum_doubled_is_named_where_the_half_of_t_is_refused():
    """p_y = m ẏ + e B x with m ẏ doubled: the p_y of "the ½ is missing in T" (the other
    momenta right, so that is not said), and the term's own mistake is named instead."""
    from lagrade.judge.driver import judge as judged

    answer = ["p_x = m*x_dot", "p_y = B*e*x + 2*m*y_dot", "p_z = m*z_dot"]
    verdict = judged({"scene": "charged_particle"}, "momenta", answer)
    assert verdict.feedback == ("The term m*y_dot in your p_y is twice too large.",)
    assert verdict.mistakes == ("factor_two",)
