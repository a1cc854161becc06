"""Right answers that lost points on a real round trip, and feedback that did not help (issue 38),
judged through `check` as every command judges them. Each answer is written as the textbook
named beside it prints the quantity; each lost points (or was refused) before this issue."""

from __future__ import annotations

import pytest

from lagrade.judge.check import check

OSCILLATOR = {"scene": "harmonic_oscillator", "seed": 1}  # q; m, k, g (handout g = 9.81)
PENDULUM = {"scene": "simple_pendulum", "seed": 1}  # phi from the horizontal; m, l, g
KEPLER = {"scene": "kepler", "seed": 1}  # rho, theta; m, M, G, a
CART = {"scene": "pendulum_on_cart", "seed": 1}  # s, psi; M, m, l, g


def judge(problem, part, answer, given=None):
    return check(problem, part, answer, time_limit=None, given=given)


# --- right answers -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("problem", "part", "answer"),
    [
        # the sheet's names inside LaTeX (Taylor, Classical Mechanics, sec. 7.1)
        (OSCILLATOR, "lagrangian", r"\frac{1}{2} m q_dot^2 - \frac{1}{2} k q^2 + m g q"),
        (PENDULUM, "eom", r"m l^2 phi_ddot - m g l \cos\phi = 0"),
        # GMm typed as in Goldstein sec. 3.7 / Taylor sec. 8.2, in plain text
        (KEPLER, "lagrangian", "1/2 m (rho_dot^2 + rho^2 theta_dot^2) + GMm/rho"),
        (PENDULUM, "V", "-mgl sin(phi)"),
        # primes as time derivatives (Boas, ch. 8: y'')
        (PENDULUM, "eom", "m l^2 phi'' - m g l cos(phi) = 0"),
        (KEPLER, "momenta", ["p_rho = m rho'", "p_theta = m rho^2 theta'"]),
        # labels in any letters: ℓ (Goldstein writes l, Taylor ℓ for angular momentum), L_z, p_θ
        (
            KEPLER,
            "conserved",
            ["ℓ = m rho^2 theta_dot", "E = 1/2 m (rho_dot^2 + rho^2 theta_dot^2) - G M m/rho"],
        ),
        (
            KEPLER,
            "conserved",
            ["L_z = m rho^2 theta_dot", "E = 1/2 m (rho_dot^2 + rho^2 theta_dot^2) - G M m/rho"],
        ),
        (
            KEPLER,
            "conserved",
            ["p_θ = m ρ^2 θ̇", "h = 1/2 m (rho_dot^2 + rho^2 theta_dot^2) - G M m/rho"],
        ),
        (KEPLER, "momenta", ["p_ρ = m rho_dot", "ℓ = m rho^2 theta_dot"]),
        (KEPLER, "momenta", ["p_rho = m rho_dot", "L_z = m rho^2 theta_dot"]),
        # a thin space ends a bracket-less function's argument (the TeXbook, ch. 18)
        (
            CART,
            "momenta",
            [
                r"p_s = (M + m)\dot{s} + m l \cos\psi \, \dot{\psi}",
                r"p_\psi = m l^2 \dot{\psi} + m l \cos\psi \, \dot{s}",
            ],
        ),  # fmt: skip
    ],
)
def test_a_right_answer_in_the_students_notation_gets_full_marks(problem, part, answer):
    verdict = judge(problem, part, answer)
    assert verdict.status == "correct" and verdict.score == 1.0, verdict.feedback


@pytest.mark.parametrize(
    ("problem", "part", "answer", "note"),
    [
        (
            KEPLER,
            "lagrangian",
            "1/2 m (rho_dot^2 + rho^2 theta_dot^2) + 2GMm/rho",
            "GMm is read as G*M*m: separate names with * or a space.",
        ),  # fmt: skip
        (
            PENDULUM,
            "eom",
            "m l^2 phi'' + m g l cos(phi) = 0",
            "phi'' is read as phi_ddot (a prime as d/dt).",
        ),
    ],
)
def test_the_note_on_a_reading_reaches_the_feedback_of_a_wrong_answer(problem, part, answer, note):
    """The notes travel as the `g/2 l` warning does: in the feedback when the answer is wrong
    (a right one carries none: its reading was the right one)."""
    verdict = judge(problem, part, answer)
    assert verdict.status == "incorrect" and note in verdict.feedback


# --- feedback that helps -------------------------------------------------------------------------


@pytest.mark.parametrize(
    "answer",
    [
        "1/2 m q_dot^2 - 1/2 k q^2 + 9.81 m q",
        "1/2 m q_dot^2 - 1/2 k q^2 + 9.81 q",
        "1/2 m q_dot^2 - 2.5 q^2 + m g q",  # k = 5 N/m typed as 5/2
    ],
)
def test_numbers_typed_for_parameters_get_no_claim_about_their_units(answer):
    """A number typed for g has g's units, which no dimension analysis of the text can see:
    the feedback names the handout value put in, and says nothing of "units of m" nor quotes
    the number as 981/100."""
    verdict = judge(OSCILLATOR, "lagrangian", answer)
    text = " ".join(verdict.feedback)
    assert verdict.status == "incorrect"
    assert "handout's value for" in text
    assert "units of" not in text and "981" not in text


@pytest.mark.parametrize(
    ("problem", "part", "answer", "named"),
    [
        (OSCILLATOR, "V", "-1/2 k q^2 + m g q", "Your V has the wrong sign"),
        (PENDULUM, "lagrangian", "1/2 m l^2 phi_dot^2 - m g l sin(phi)", "Your L adds V"),
        (PENDULUM, "T", "m l^2 phi_dot^2", "½"),
    ],
)
def test_a_named_mistake_is_one_sentence_with_where_it_shows(problem, part, answer, named):
    """ "Your V has the wrong sign …" and "Your V is not the potential energy …" said one thing
    twice: the named mistake carries the point where it shows, and stands alone."""
    verdict = judge(problem, part, answer)
    assert verdict.status == "incorrect"
    (sentence,) = verdict.feedback
    assert named in sentence and "for example" in sentence


@pytest.mark.parametrize(
    ("part", "text", "note"),
    [
        (
            "lagrangian",
            "1/2 m (rho_dot^2 + rho^2 theta_dot^2) + GMm/rho",
            "GMm is read as G*M*m: separate names with * or a space.",
        ),  # fmt: skip
        (
            "eom",
            "m rho'' - m rho theta_dot^2 + G M m/rho^2 = 0",
            "rho'' is read as rho_ddot (a prime as d/dt).",
        ),  # fmt: skip
    ],
)
def test_the_answer_pages_preview_shows_the_note(part, text, note):
    """The page's live preview reads through the grader's door and lists the parser's notes,
    right answer or not: the student sees how the answer was read before it is graded."""
    from lagrade.grading.answer_page.preview import preview

    row = {"key": part, "part": part, "points": 1, "quantity": None}
    shown = preview({"scene": "kepler", "seed": 1}, row, text)
    assert shown["status"] == "read" and note in shown["warnings"]


# --- an ambiguity alone never zeroes a list part ----------------------------------------------
# Wikipedia's "Inverted pendulum" (the cart and pendulum, Lagrange's equations) prints the terms
# as "m ℓ v θ̇ cos θ", a function without brackets; a student who types "m l cos psi psi_dot" in
# a sheet cannot add the brackets after the deadline.

BRACKETLESS = [
    "p_s = (M+m) s_dot + m l cos psi psi_dot",
    "p_psi = m l^2 psi_dot + m l cos psi s_dot",
]


@pytest.mark.parametrize(
    ("answer", "status", "score"),
    [
        (BRACKETLESS, "correct", 1.0),  # every line ambiguous: was invalid, 0
        ([BRACKETLESS[0], "p_psi = m l^2 psi_dot + m l cos(psi) s_dot"], "correct", 1.0),
        ([BRACKETLESS[0], "p_psi = m l^2 psi_dot + m l cos(psi) s_dot + ("], "incorrect", 0.5),
    ],
)
def test_an_ambiguous_line_is_judged_under_the_reading_that_scores_best(answer, status, score):
    verdict = judge(CART, "momenta", answer)
    assert (verdict.status, verdict.score) == (status, score), verdict.feedback
    notes = [f for f in verdict.feedback if "write the brackets" in f]
    assert notes and all("it was read as cos(psi)*" in f for f in notes)


def test_an_ambiguous_line_wrong_under_every_reading_still_counts_as_wrong():
    """No reading is right: the line stays unread, with the parser's message, and costs its
    share; nothing is credited for the ambiguity itself."""
    wrong = [
        "p_s = (M+m) s_dot - m l cos psi psi_dot",
        "p_psi = m l^2 psi_dot + m l cos(psi) s_dot",
    ]
    verdict = judge(CART, "momenta", wrong)
    assert (verdict.status, verdict.score) == ("incorrect", 0.5)
    assert verdict.feedback[0].startswith("Line 1 could not be read: Ambiguous 'cos'")


def test_a_one_line_part_keeps_its_ambiguity_as_a_message():
    """A single-expression part is not a list: its ambiguity is a message the student can act
    on (invalid, no attempt spent), as before."""
    verdict = judge(CART, "lagrangian", "1/2 (M+m) s_dot^2 + m l cos psi s_dot psi_dot")
    assert verdict.status == "invalid" and "Ambiguous 'cos'" in verdict.feedback[0]
