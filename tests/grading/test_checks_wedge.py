"""The wedge (block on a sliding wedge), part by part: the lecture's first worked example."""

from __future__ import annotations

import pytest

from lagrade.judge.parts import reading

from .conftest import WEDGE, judge

T_TEXT = "1/2 m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2"


@pytest.mark.parametrize(
    "answer, note",
    [
        (T_TEXT + " - m g (h - q sin(alpha))", None),
        (T_TEXT + " + m g q sin(alpha)", "constant"),  # dropped m g h
        (
            T_TEXT + " + m g q sin(alpha) + x_M_dot q + x_M q_dot",
            "total time derivative",
        ),  # + d(x_M q)/dt
        ("2 (" + T_TEXT + " + m g q sin(alpha))", "2 × (T − V)"),
        (
            "L = (M + m)/2 * x_M_dot^2 + m/2 * q_dot^2 + m x_M_dot q_dot cos(alpha)"
            " + m g q sin(alpha)",
            None,
        ),
        (
            r"\frac{1}{2}(M+m)\dot{x}_M^2 + \frac{1}{2} m \dot{q}^2 + m \dot{x}_M \dot{q}\cos\alpha"
            r" + m g q \sin\alpha",
            None,
        ),
    ],
)
def test_lagrangian_in_correct_forms(answer, note):
    v = judge(WEDGE, "lagrangian", answer)
    assert (v.status, v.score) == ("correct", 1.0), v.feedback
    if note:
        assert any(note in f for f in v.feedback), v.feedback


def test_v_minus_t_is_the_same_motion_but_the_wrong_convention():
    v = judge(WEDGE, "lagrangian", "-(" + T_TEXT + ") - m g q sin(alpha)")
    assert v.status == "incorrect" and v.score == 0.5 and v.mistakes == ("V_minus_T",)
    assert "V − T" in v.feedback[0]


def test_missing_cross_term_is_named():
    v = judge(
        WEDGE, "lagrangian", "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha)"
    )
    assert v.status == "incorrect" and v.mistakes == ("missing_cross_term",)
    assert "cross term in q_dot*x_M_dot" in v.feedback[0]
    assert v.witness and set(v.witness) >= {"q_dot", "x_M_dot"}


def test_an_acceleration_in_l_is_named_not_an_error():
    v = judge(WEDGE, "lagrangian", T_TEXT + " + m q x_M_ddot")
    assert (v.status, v.mistakes) == ("incorrect", ("acceleration",))
    assert "not on accelerations" in v.feedback[0]


def test_t_plus_v_is_named():
    v = judge(WEDGE, "lagrangian", T_TEXT + " - m g q sin(alpha)")
    assert v.mistakes == ("sign_of_V",)


def test_unparsable_answer_is_invalid_with_the_parsers_message():
    v = judge(WEDGE, "lagrangian", "1/2 m x_M_dot^^2")
    assert v.status == "invalid" and "^" in v.feedback[0]


@pytest.mark.parametrize(
    "eqs",
    [
        [
            "(M+m) x_M_ddot + m q_ddot cos(alpha) = 0",
            "m q_ddot + m x_M_ddot cos(alpha) - m g sin(alpha) = 0",
        ],
        [
            "q_ddot + x_M_ddot cos(alpha) = g sin(alpha)",
            "(M+m) x_M_ddot = -m q_ddot cos(alpha)",
        ],  # divided, moved
        [
            "2 (M+m) x_M_ddot + 2 m q_ddot cos(alpha)",
            "m q_ddot + m x_M_ddot cos(alpha) - m g sin(alpha)",
        ],
        [
            "(M+m) x_M_ddot + m q_ddot cos(alpha)"
            " + 3 (m q_ddot + m x_M_ddot cos(alpha) - m g sin(alpha)) = 0",
            "m q_ddot + m x_M_ddot cos(alpha) = m g sin(alpha)",
        ],  # row-combined
        [
            "q_ddot = g sin(alpha) (M+m)/(M + m sin(alpha)^2)",
            "x_M_ddot = -m g sin(alpha) cos(alpha)/(M + m sin(alpha)^2)",
        ],  # solved forms
    ],
)
def test_equations_of_motion_in_correct_forms(eqs):
    v = judge(WEDGE, "eom", eqs)
    assert v.status == "correct", v.feedback


def test_one_wrong_equation_gets_partial_credit_and_a_name():
    v = judge(
        WEDGE,
        "eom",
        [
            "(M+m) x_M_ddot + m q_ddot cos(alpha) = 0",
            "m q_ddot + m x_M_ddot cos(alpha) + m g sin(alpha) = 0",
        ],
    )
    assert v.status == "incorrect" and v.score == 0.5
    assert v.mistakes and "Equation 2" in v.feedback[0]


def test_one_equation_for_two_coordinates_is_not_enough():
    v = judge(WEDGE, "eom", ["(M+m) x_M_ddot + m q_ddot cos(alpha) = 0"])
    assert v.status == "incorrect" and v.score == 0.5 and "too_few_equations" in v.mistakes


def test_equations_that_follow_from_the_students_own_wrong_lagrangian():
    own_L = "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha)"  # no cross term
    v = judge(
        WEDGE,
        "eom",
        ["(M+m) x_M_ddot = 0", "m q_ddot = m g sin(alpha)"],
        given={"lagrangian": own_L},
    )
    assert v.status == "incorrect" and v.follows_from_own_answer
    assert any("your own Lagrangian" in f for f in v.feedback)


def test_conserved_quantities_that_follow_from_the_students_own_wrong_lagrangian():
    own_L = "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha)"  # no cross term
    own_conserved = [
        "p_x_M = (M+m) x_M_dot",  # x_M is cyclic in the student's L, without the cross term
        "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 - m g q sin(alpha)",  # its energy
    ]
    v = judge(WEDGE, "conserved", own_conserved, given={"lagrangian": own_L})
    assert v.status == "incorrect" and v.follows_from_own_answer
    assert sum("motion of your own Lagrangian" in f for f in v.feedback) == 2
    # without the student's L, or with a quantity that no motion conserves, no follow-through
    alone = judge(WEDGE, "conserved", own_conserved)
    assert alone.status == "incorrect" and not alone.follows_from_own_answer
    mixed = judge(WEDGE, "conserved", [own_conserved[0], "q_dot x_M"], given={"lagrangian": own_L})
    assert mixed.status == "incorrect" and not mixed.follows_from_own_answer
    # a right answer stays right whatever the student's L
    right = judge(
        WEDGE,
        "conserved",
        ["p_x = (M + m) x_M_dot + m q_dot cos(alpha)", T_TEXT + " - m g q sin(alpha)"],
        given={"lagrangian": own_L},
    )
    assert right.status == "correct" and not right.follows_from_own_answer


def test_a_sheets_own_lagrangian_is_read_once_for_all_its_parts(monkeypatch):
    """Equations, momenta and conserved quantities follow through from one own L: it is read
    once per text (and question structure), and each part judges by the same reading."""
    own_L = "1/2 m (x_M_dot^2 + q_dot^2) + 1/2 M x_M_dot^2 + m g q sin(alpha) + 0*q"
    reads = []
    real = reading._own_lagrangian
    monkeypatch.setattr(reading, "_own_lagrangian", lambda p, t: reads.append(t) or real(p, t))
    eom = judge(
        WEDGE, "eom", ["(M+m) x_M_ddot = 0", "m q_ddot = m g sin(alpha)"], {"lagrangian": own_L}
    )
    kept = judge(WEDGE, "conserved", ["p_x_M = (M+m) x_M_dot"], {"lagrangian": own_L})
    assert eom.follows_from_own_answer and reads == [own_L]
    assert kept.status == "incorrect"  # half of what is conserved, judged by the same reading
    judge(WEDGE, "conserved", ["p_x_M = (M+m) x_M_dot"], {"lagrangian": own_L + " + 0*x_M"})
    assert reads == [own_L, own_L + " + 0*x_M"]  # another text is read on its own


def test_momenta_labelled_or_in_order():
    right = ["p_x_M = (M+m) x_M_dot + m q_dot cos(alpha)", "p_q = m q_dot + m x_M_dot cos(alpha)"]
    assert judge(WEDGE, "momenta", right).status == "correct"
    assert judge(WEDGE, "momenta", right[::-1]).status == "correct"
    in_order = ["(M+m) x_M_dot + m q_dot cos(alpha)", "m (q_dot + x_M_dot cos(alpha))"]
    assert judge(WEDGE, "momenta", in_order).status == "correct"


def test_momentum_of_the_wrong_coordinate_is_named():
    v = judge(
        WEDGE, "momenta", ["m q_dot + m x_M_dot cos(alpha)", "(M+m) x_M_dot + m q_dot cos(alpha)"]
    )
    assert v.score == 0 and v.mistakes == ("wrong_coordinate", "wrong_coordinate")


def test_cyclic():
    assert judge(WEDGE, "cyclic", ["x_M"]).status == "correct"
    v = judge(WEDGE, "cyclic", "none")
    assert v.score == 0 and v.mistakes == ("missed_cyclic",)  # a blind guess earns nothing
    v = judge(WEDGE, "cyclic", ["x_M", "q"])
    assert v.mistakes == ("not_cyclic",) and "g*m*q*sin(alpha)" in v.feedback[0]
    assert v.score == 0


def test_conserved_momentum_and_energy():
    p_x = "p_x = (M + m) x_M_dot + m q_dot cos(alpha)"
    h = "h = " + T_TEXT + " - m g q sin(alpha)"
    assert judge(WEDGE, "conserved", [p_x, h]).status == "correct"
    assert judge(WEDGE, "conserved", [p_x]).status == "correct"  # one true quantity alone
    v = judge(WEDGE, "conserved", [p_x], given={"all": True})  # completeness asked for
    assert v.status == "incorrect" and v.score == 0.5 and "missing_conserved" in v.mistakes
    # any true conserved quantity: a combination of the two
    assert (
        judge(
            WEDGE,
            "conserved",
            [
                p_x,
                "2 (" + T_TEXT + " - m g q sin(alpha)) + 3 ((M + m) x_M_dot + m q_dot cos(alpha))",
            ],
        ).status
        == "correct"
    )


def test_momentum_of_a_non_cyclic_coordinate_is_not_conserved():
    v = judge(WEDGE, "conserved", ["m q_dot + m x_M_dot cos(alpha)"])
    assert "momentum_not_conserved" in v.mistakes


def test_a_constant_is_not_an_answer():
    v = judge(WEDGE, "conserved", ["m g h"])
    assert "constant" in v.mistakes


@pytest.mark.parametrize(
    "answer, status",
    [
        (
            [
                "x_wedge = x_M",
                "y_wedge = 0",
                "x_block = x_M + q cos(alpha)",
                "y_block = h - q sin(alpha)",
            ],
            "correct",
        ),
        (
            [
                "x_wedge = x_M",
                "y_wedge = 0",
                "x_block = x_M + (q + 1) cos(alpha)",
                "y_block = h - (q + 1) sin(alpha)",
            ],
            "correct",
        ),  # q measured from another point of the face
        (
            [
                "x_wedge = x_M",
                "y_wedge = 0",
                "x_block = x_M + q sin(alpha)",
                "y_block = h - q cos(alpha)",
            ],
            "incorrect",
        ),
        (["x_wedge = x_M", "y_wedge = 0", "x_block = x_M", "y_block = h"], "incorrect"),  # rank 1
    ],
)
def test_transformation(answer, status):
    assert judge(WEDGE, "transformation", answer).status == status


def test_transformation_missing_a_coordinate():
    v = judge(WEDGE, "transformation", ["x_wedge = x_M", "x_block = x_M + q cos(alpha)"])
    assert v.status == "incorrect" and "y_wedge" in v.feedback[0]


def test_dof_t_and_v():
    assert judge(WEDGE, "dof", "2").status == "correct"
    assert judge(WEDGE, "dof", "4").mistakes == ("forgot_planarity",)
    assert judge(WEDGE, "dof", "two").status == "invalid"
    assert judge(WEDGE, "T", T_TEXT).status == "correct"
    v = judge(WEDGE, "T", "m (x_M_dot^2 + q_dot^2 + 2 x_M_dot q_dot cos(alpha)) + 1/2 M x_M_dot^2")
    assert v.mistakes == ("dropped_half",) and "block" in v.feedback[0]
    assert judge(WEDGE, "V", "-m g q sin(alpha)").status == "correct"  # another zero level
    assert judge(WEDGE, "V", "m g q sin(alpha)").mistakes == ("sign_of_V",)


def test_expression_for_the_block_acceleration():
    problem = {**WEDGE, "quantity": "block_acceleration"}
    assert (
        judge(problem, "expression", "g sin(alpha) (m+M)/(M + m sin(alpha)^2)").status == "correct"
    )
    v = judge(problem, "expression", "g cos(alpha) (m+M)/(M + m cos(alpha)^2)")
    assert v.mistakes == ("sin_cos_swapped",)


def test_seeded_variant_uses_its_names_and_wants_symbols():
    """Seed 3 calls the wedge's coordinate X; g written as 9.81 (its handout value) is not the
    symbolic L: parameters are sampled over their domains, and the feedback says why."""
    L = "1/2 m (X_dot^2 + q_dot^2 + 2 X_dot q_dot cos(alpha)) + 1/2 M X_dot^2"
    assert judge({"scene": "wedge", "seed": 3}, "lagrangian", L + " + m g q sin(alpha)").status == (
        "correct"
    )
    v = judge({"scene": "wedge", "seed": 3}, "lagrangian", L + " + m 9.81 q sin(alpha)")
    assert v.status == "incorrect"
    assert any("handout's value for g;" in f for f in v.feedback), v.feedback
    assert judge({"scene": "wedge", "seed": 3}, "lagrangian", "x_M_dot^2").status == "invalid"


@pytest.mark.parametrize("factor, shown", [("10^40", "1e+40"), ("10^-40", "1e-40")])
def test_a_huge_or_tiny_factor_of_L_is_named_as_a_number(wedge_L_text, factor, shown):
    # 1e40 printed through a fraction gave its 41 digits of rounding; 1e-40 printed as 0
    v = judge(WEDGE, "lagrangian", f"{factor} ({wedge_L_text})")
    assert v.status == "correct"
    assert any(f"Your L is {shown} × (T − V)" in f for f in v.feedback), v.feedback
