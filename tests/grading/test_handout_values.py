"""One rule for handout values put into a symbolic answer (issue 30): every parameter whose
handout value the answer holds instead of its symbol is named — all of them, integers and
squares too — and none that the answer merely leaves out (a dropped constant m g h, a forgotten
m). The sentence speaks to the student, naming the symbols as printed."""

from __future__ import annotations

from lagrade.judge.check import check

HINT = "handout's value for"


def _hint(verdict) -> str:
    found = [f for f in verdict.feedback if HINT in f]
    assert len(found) <= 1, verdict.feedback
    return found[0] if found else ""


def test_a_t_with_m_r_and_omega_plugged_in_names_all_three():
    # hoop, seed 3: m = 0.05 kg, R = 0.5 m, omega = 8 rad/s (an integer, and squared: 64)
    v = check({"scene": "hoop", "seed": 3}, "T", "1/2*0.05*0.5^2*(phi_dot^2 + 64 sin(phi)^2)")
    assert v.status == "incorrect"
    assert "for R, m and ω; write them as symbols" in _hint(v), v.feedback


def test_an_l_with_every_value_plugged_in_names_every_one():
    answer = "1/2*0.05*0.5^2*(phi_dot^2 + 8^2 sin(phi)^2) + 0.05*9.81*0.5 cos(phi)"
    v = check({"scene": "hoop", "seed": 3}, "lagrangian", answer)
    assert "for R, g, m and ω;" in _hint(v), v.feedback


def test_whole_number_values_are_named_too():
    # harmonic oscillator, seed 3: m = 1 kg, k = 50 N/m, horizontal: no decimal point anywhere
    v = check({"scene": "harmonic_oscillator", "seed": 3}, "lagrangian", "1/2 u_dot^2 - 25 u^2")
    assert v.status == "incorrect"
    assert "for k and m;" in _hint(v), v.feedback


def test_a_dropped_constant_is_not_a_plugged_in_value():
    """The wedge's L without its constant −m g h, values put in: h is not named."""
    answer = "1/2 (2+5) X_dot^2 + 1/2*2*q_dot^2 + 2*X_dot*q_dot*cos(0.5236) + 2*9.81*q*sin(0.5236)"
    v = check({"scene": "wedge", "seed": 3}, "lagrangian", answer)
    assert "for M, α, g and m;" in _hint(v), v.feedback


def test_a_parameter_only_left_out_is_not_said_to_be_plugged_in():
    v = check({"scene": "hoop", "seed": 3}, "T", "1/2 R^2 (phi_dot^2 + omega^2 sin(phi)^2)")
    assert v.status == "incorrect" and _hint(v) == "", v.feedback


def test_a_v_with_a_value_in_it():
    v = check({"scene": "hoop", "seed": 3}, "V", "-m 9.81 R cos(phi)")
    assert "for g; write it as a symbol" in _hint(v), v.feedback
