"""Systems from Landau & Lifshitz, Mechanics (Course of Theoretical Physics vol. 1, 3rd ed.,
1976): the problems of §5 (whose printed Lagrangians are the references here), §14–15 (central
field, Kepler's problem), §30 (rapidly oscillating field) and §35 (the heavy symmetric top)."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System

LL = "Landau & Lifshitz, Mechanics, 3rd ed. (1976), "
P = "positive"


def double_pendulum() -> System:
    s = System(
        "ll_double_pendulum",
        LL + "§5 Problem 1 (coplanar double pendulum, masses m1, m2 on rods l1, l2; printed "
        "solution L); also D. Tong, Classical Dynamics (Cambridge lecture notes, 2005), "
        "§2.5.2 and, for the normal modes with equal masses and lengths, §2.6.1",
        "(m1 + m2)*l1**2*phi1_dot**2/2 + m2*l2**2*phi2_dot**2/2"
        " + m2*l1*l2*cos(phi1 - phi2)*phi1_dot*phi2_dot + (m1 + m2)*g*l1*cos(phi1)"
        " + m2*g*l2*cos(phi2)",
        ["phi1", "phi2"],
        {"m1": P, "m2": P, "l1": P, "l2": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "½(m₁ + m₂) l₁² φ̇₁² + ½ m₂ l₂² φ̇₂² + m₂ l₁ l₂ φ̇₁ φ̇₂ cos(φ₁ − φ₂)"
        " + (m₁ + m₂) g l₁ cos φ₁ + m₂ g l₂ cos φ₂",
        L,
        "unicode",
    )
    s.ok(
        "lagrangian",
        r"\frac{m_1+m_2}{2} l_1^2\dot\varphi_1^2 + \frac{m_2}{2} l_2^2\dot\varphi_2^2"
        r" + m_2 l_1 l_2 \dot\varphi_1\dot\varphi_2\cos(\varphi_1-\varphi_2)"
        r" + (m_1+m_2) g l_1\cos\varphi_1 + m_2 g l_2\cos\varphi_2",
        L,
        "latex",
    )
    s.ok("lagrangian", L.replace("**", "^"), L, "plain")
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) l1^2 phi1_dot^2 + 1/2 m2 l2^2 phi2_dot^2 + (m1 + m2) g l1 cos(phi1)"
        " + m2 g l2 cos(phi2)",
        "(m1 + m2)*l1**2*phi1_dot**2/2 + m2*l2**2*phi2_dot**2/2 + (m1 + m2)*g*l1*cos(phi1)"
        " + m2*g*l2*cos(phi2)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) l1^2 phi1_dot^2 + 1/2 m2 l2^2 phi2_dot^2"
        " + m2 l1 l2 cos(phi1 - phi2) phi1_dot phi2_dot + m1 g l1 cos(phi1) + m2 g l2 cos(phi2)",
        "(m1 + m2)*l1**2*phi1_dot**2/2 + m2*l2**2*phi2_dot**2/2"
        " + m2*l1*l2*cos(phi1 - phi2)*phi1_dot*phi2_dot + m1*g*l1*cos(phi1)"
        " + m2*g*l2*cos(phi2)",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) l1^2 phi1_dot^2 + 1/2 m2 l2^2 phi2_dot^2"
        " + m2 l1 l2 cos(phi1 + phi2) phi1_dot phi2_dot + (m1 + m2) g l1 cos(phi1)"
        " + m2 g l2 cos(phi2)",
        L.replace("cos(phi1 - phi2)", "cos(phi1 + phi2)"),
        "wrong_sign",
    )
    e1 = (
        "(m1 + m2)*l1**2*phi1_ddot + m2*l1*l2*cos(phi1 - phi2)*phi2_ddot"
        " + m2*l1*l2*sin(phi1 - phi2)*phi2_dot**2 + (m1 + m2)*g*l1*sin(phi1)"
    )
    e2 = (
        "m2*l2**2*phi2_ddot + m2*l1*l2*cos(phi1 - phi2)*phi1_ddot"
        " - m2*l1*l2*sin(phi1 - phi2)*phi1_dot**2 + m2*g*l2*sin(phi2)"
    )
    s.ok("eom", [e1.replace("**", "^") + " = 0", e2.replace("**", "^") + " = 0"], [e1, e2])
    s.ok(
        "eom",
        [
            "(m1 + m2) l1 phi1_ddot + m2 l2 cos(phi1 - phi2) phi2_ddot"
            " + m2 l2 sin(phi1 - phi2) phi2_dot^2 + (m1 + m2) g sin(phi1) = 0",
            "l2 phi2_ddot + l1 cos(phi1 - phi2) phi1_ddot - l1 sin(phi1 - phi2) phi1_dot^2"
            " + g sin(phi2) = 0",
        ],
        [f"({e1})/l1", f"({e2})/(m2*l2)"],
        "divided_through",
    )
    s.ok(
        "eom",
        [
            r"(m_1+m_2) l_1 \ddot\varphi_1 + m_2 l_2 \ddot\varphi_2 \cos(\varphi_1-\varphi_2)"
            r" + m_2 l_2 \dot\varphi_2^2 \sin(\varphi_1-\varphi_2) + (m_1+m_2) g \sin\varphi_1 = 0",
            r"l_2\ddot\varphi_2 + l_1\ddot\varphi_1\cos(\varphi_1-\varphi_2)"
            r" - l_1\dot\varphi_1^2\sin(\varphi_1-\varphi_2) + g\sin\varphi_2 = 0",
        ],
        [f"({e1})/l1", f"({e2})/(m2*l2)"],
        "latex",
    )
    s.bad(
        "eom",
        [
            "(m1 + m2) l1 phi1_ddot + m2 l2 cos(phi1 - phi2) phi2_ddot + (m1 + m2) g sin(phi1) = 0",
            "l2 phi2_ddot + l1 cos(phi1 - phi2) phi1_ddot - l1 sin(phi1 - phi2) phi1_dot^2"
            " + g sin(phi2) = 0",
        ],
        [
            "(m1 + m2)*l1*phi1_ddot + m2*l2*cos(phi1 - phi2)*phi2_ddot + (m1 + m2)*g*sin(phi1)",
            f"({e2})/(m2*l2)",
        ],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "(m1 + m2) l1 phi1_ddot + m2 l2 cos(phi1 - phi2) phi2_ddot"
            " + m2 l2 sin(phi1 - phi2) phi2_dot^2 + (m1 + m2) g sin(phi1) = 0",
            "l2 phi2_ddot + l1 cos(phi1 - phi2) phi1_ddot + l1 sin(phi1 - phi2) phi1_dot^2"
            " + g sin(phi2) = 0",
        ],
        [
            f"({e1})/l1",
            "l2*phi2_ddot + l1*cos(phi1 - phi2)*phi1_ddot"
            " + l1*sin(phi1 - phi2)*phi1_dot**2 + g*sin(phi2)",
        ],
        "wrong_sign",
    )
    s.bad("eom", [e1.replace("**", "^") + " = 0"], [e1], "too_few_equations")
    p1 = "(m1 + m2)*l1**2*phi1_dot + m2*l1*l2*cos(phi1 - phi2)*phi2_dot"
    p2 = "m2*l2**2*phi2_dot + m2*l1*l2*cos(phi1 - phi2)*phi1_dot"
    s.ok(
        "momenta",
        [f"p_phi1 = {p1}".replace("**", "^"), f"p_phi2 = {p2}".replace("**", "^")],
        [f"p_phi1 = {p1}", f"p_phi2 = {p2}"],
    )
    s.ok(
        "momenta",
        [
            "p_φ₂ = m₂ l₂² φ̇₂ + m₂ l₁ l₂ φ̇₁ cos(φ₁ − φ₂)",
            "p_φ₁ = (m₁ + m₂) l₁² φ̇₁ + m₂ l₁ l₂ φ̇₂ cos(φ₁ − φ₂)",
        ],
        [f"p_phi2 = {p2}", f"p_phi1 = {p1}"],
        "unicode_other_order",
    )
    s.bad(
        "momenta",
        ["p_phi1 = (m1 + m2) l1^2 phi1_dot", "p_phi2 = m2 l2^2 phi2_dot"],
        ["p_phi1 = (m1 + m2)*l1**2*phi1_dot", "p_phi2 = m2*l2**2*phi2_dot"],
        "missing_cross_term",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "phi1, phi2", ["phi1", "phi2"], "not_cyclic")
    h = (
        "(m1 + m2)*l1**2*phi1_dot**2/2 + m2*l2**2*phi2_dot**2/2"
        " + m2*l1*l2*cos(phi1 - phi2)*phi1_dot*phi2_dot - (m1 + m2)*g*l1*cos(phi1)"
        " - m2*g*l2*cos(phi2)"
    )
    s.ok("conserved", [h.replace("**", "^")], [h], "energy")
    s.bad("conserved", [f"{p1} + {p2}".replace("**", "^")], [f"{p1} + {p2}"], "not_conserved")

    e = s.expression("sqrt((2 - sqrt(2))*g/l)", {"g": P, "l": P}, "slow_mode_equal")
    e.ok("sqrt(g/l) sqrt(2 - sqrt(2))", "sqrt(g/l)*sqrt(2 - sqrt(2))", "factored")
    e.ok("sqrt(2 g/l - sqrt(2) g/l)", "sqrt(2*g/l - sqrt(2)*g/l)", "expanded")
    e.ok(r"\sqrt{(2-\sqrt{2})\frac{g}{l}}", "sqrt((2 - sqrt(2))*g/l)", "latex")
    e.bad("sqrt((2 + sqrt(2)) g/l)", "sqrt((2 + sqrt(2))*g/l)")
    e.bad("sqrt(g/l)", "sqrt(g/l)", "missing_term")
    return s


def sliding_support() -> System:
    s = System(
        "ll_pendulum_sliding_support",
        LL + "§5 Problem 2 (pendulum of mass m2 whose point of support, a mass m1, moves on a "
        "horizontal line; printed solution L); the frequency question is Cambridge Mathematical "
        "Tripos Part II 2005, Paper 1, 15C (https://deploy-preview-103--nimble-strudel-fc6e42."
        "netlify.app/part-ii/2005-49)",
        "(m1 + m2)*x_dot**2/2 + m2*(l**2*phi_dot**2 + 2*l*x_dot*phi_dot*cos(phi))/2"
        " + m2*g*l*cos(phi)",
        ["x", "phi"],
        {"m1": P, "m2": P, "l": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "½(m₁ + m₂) ẋ² + ½ m₂ (l² φ̇² + 2 l ẋ φ̇ cos φ) + m₂ g l cos φ",
        L,
        "unicode_as_printed",
    )
    s.ok(
        "lagrangian",
        "1/2 m1 x_dot^2 + 1/2 m2 ((x_dot + l phi_dot cos(phi))^2 + (l phi_dot sin(phi))^2)"
        " - m2 g l (1 - cos(phi))",
        "m1*x_dot**2/2 + m2*((x_dot + l*phi_dot*cos(phi))**2 + (l*phi_dot*sin(phi))**2)/2"
        " - m2*g*l*(1 - cos(phi))",
        "from_velocities",
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2}(m_1+m_2)\dot{x}^2 + \frac{1}{2} m_2 l^2\dot\phi^2"
        r" + m_2 l \dot{x}\dot\phi\cos\phi + m_2 g l\cos\phi",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) x_dot^2 + 1/2 m2 l^2 phi_dot^2 + m2 g l cos(phi)",
        "(m1 + m2)*x_dot**2/2 + m2*l**2*phi_dot**2/2 + m2*g*l*cos(phi)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m1 x_dot^2 + 1/2 m2 (l^2 phi_dot^2 + 2 l x_dot phi_dot cos(phi)) + m2 g l cos(phi)",
        "m1*x_dot**2/2 + m2*(l**2*phi_dot**2 + 2*l*x_dot*phi_dot*cos(phi))/2 + m2*g*l*cos(phi)",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) x_dot^2 + 1/2 m2 (l^2 phi_dot^2 + 2 l x_dot phi_dot sin(phi))"
        " + m2 g l cos(phi)",
        "(m1 + m2)*x_dot**2/2 + m2*(l**2*phi_dot**2 + 2*l*x_dot*phi_dot*sin(phi))/2"
        " + m2*g*l*cos(phi)",
        "wrong_trig",
    )
    ex = "(m1 + m2)*x_ddot + m2*l*(phi_ddot*cos(phi) - phi_dot**2*sin(phi))"
    ep = "l*phi_ddot + x_ddot*cos(phi) + g*sin(phi)"
    s.ok(
        "eom",
        [
            "(m1 + m2) x_ddot + m2 l (phi_ddot cos(phi) - phi_dot^2 sin(phi)) = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        [ex, ep],
    )
    s.ok(
        "eom",
        [
            "d/dt((m1 + m2) x_dot + m2 l phi_dot cos(phi)) = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        ["Dt((m1 + m2)*x_dot + m2*l*phi_dot*cos(phi))", ep],
        "conservation_form",
    )
    s.ok(
        "eom",
        ["(m₁ + m₂) ẍ = m₂ l (φ̇² sin φ − φ̈ cos φ)", "φ̈ = −(ẍ cos φ + g sin φ)/l"],
        [ex, f"({ep})/l"],
        "unicode",
    )
    s.bad(
        "eom",
        [
            "(m1 + m2) x_ddot + m2 l phi_ddot cos(phi) = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        ["(m1 + m2)*x_ddot + m2*l*phi_ddot*cos(phi)", ep],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        [
            "(m1 + m2) x_ddot + m2 l (phi_ddot cos(phi) - phi_dot^2 sin(phi)) = 0",
            "l phi_ddot + g sin(phi) = 0",
        ],
        [ex, "l*phi_ddot + g*sin(phi)"],
        "missing_cross_term",
    )
    px = "(m1 + m2)*x_dot + m2*l*phi_dot*cos(phi)"
    pp = "m2*l**2*phi_dot + m2*l*x_dot*cos(phi)"
    s.ok(
        "momenta",
        [
            "p_x = (m1 + m2) x_dot + m2 l phi_dot cos(phi)",
            "p_phi = m2 l^2 phi_dot + m2 l x_dot cos(phi)",
        ],
        [f"p_x = {px}", f"p_phi = {pp}"],
    )
    s.bad(
        "momenta",
        ["p_x = (m1 + m2) x_dot", "p_phi = m2 l^2 phi_dot"],
        ["p_x = (m1 + m2)*x_dot", "p_phi = m2*l**2*phi_dot"],
        "missing_cross_term",
    )
    s.ok("cyclic", "x", ["x"], "one")
    s.bad("cyclic", "none", [], "missed_cyclic")
    s.bad("cyclic", "x, phi", ["x", "phi"], "not_cyclic")
    h = (
        "(m1 + m2)*x_dot**2/2 + m2*(l**2*phi_dot**2 + 2*l*x_dot*phi_dot*cos(phi))/2"
        " - m2*g*l*cos(phi)"
    )
    s.ok("conserved", ["(m1 + m2) x_dot + m2 l phi_dot cos(phi)"], [px], "momentum_of_cyclic")
    s.ok(
        "conserved",
        ["(m1 + m2) x_dot + m2 l phi_dot cos(phi)", h.replace("**", "^")],
        [px, h],
        "momentum_and_energy",
    )
    s.bad("conserved", ["(m1 + m2) x_dot"], ["(m1 + m2)*x_dot"], "not_conserved")
    s.bad(
        "conserved",
        ["(m1 + m2) x_dot + m2 l phi_dot cos(phi)", "x_dot + m2 l phi_dot cos(phi)/(m1 + m2)"],
        [px, f"({px})/(m1 + m2)"],
        "not_independent",
    )
    e = s.expression(
        "sqrt(g*(m1 + m2)/(l*m1))",
        {"g": P, "l": P, "m1": P, "m2": P},
        "small_oscillation_frequency",
    )
    e.ok("sqrt(g/l (1 + m2/m1))", "sqrt(g/l*(1 + m2/m1))")
    e.ok("sqrt((m1 + m2) g/(m1 l))", "sqrt((m1 + m2)*g/(m1*l))", "as_one_fraction")
    e.ok(r"\sqrt{\frac{(m_1+m_2)g}{m_1 l}}", "sqrt((m1 + m2)*g/(m1*l))", "latex")
    e.bad("sqrt(g/l)", "sqrt(g/l)", "missing_term")
    e.bad("sqrt(g (m1 + m2)/(l m2))", "sqrt(g*(m1 + m2)/(l*m2))")
    return s


def support_on_circle() -> System:
    s = System(
        "ll_pendulum_support_on_circle",
        LL + "§5 Problem 3(a) (simple pendulum whose point of support moves uniformly on a "
        "vertical circle of radius a with frequency gamma; printed solution L, total "
        "derivatives dropped); the unreduced form and its sign slip as discussed at "
        "https://www.physicsforums.com/threads/typo-in-landau-mechanics-pendulum-problem.620775",
        "m*l**2*phi_dot**2/2 + m*l*a*gamma**2*sin(phi - gamma*t) + m*g*l*cos(phi)",
        ["phi"],
        {"m": P, "l": P, "a": P, "gamma": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "½ m l² φ̇² + m l a γ² sin(φ − γt) + m g l cos φ", L, "unicode_as_printed")
    s.ok(
        "lagrangian",
        "1/2 m (a^2 gamma^2 + l^2 phi_dot^2 + 2 a gamma l phi_dot sin(phi - gamma t))"
        " - m g a sin(gamma t) + m g l cos(phi)",
        "m*(a**2*gamma**2 + l**2*phi_dot**2 + 2*a*gamma*l*phi_dot*sin(phi - gamma*t))/2"
        " - m*g*a*sin(gamma*t) + m*g*l*cos(phi)",
        "unreduced_from_coordinates",
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2} m l^2 \dot{\phi}^2 + m l a \gamma^2 \sin(\phi - \gamma t) + m g l\cos\phi",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (l^2 phi_dot^2 + 2 a gamma l phi_dot sin(gamma t - phi)) + m g l cos(phi)",
        "m*(l**2*phi_dot**2 + 2*a*gamma*l*phi_dot*sin(gamma*t - phi))/2 + m*g*l*cos(phi)",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m g l cos(phi)",
        "m*l**2*phi_dot**2/2 + m*g*l*cos(phi)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m l a gamma^2 sin(phi - gamma t) - m g l cos(phi)",
        "m*l**2*phi_dot**2/2 + m*l*a*gamma**2*sin(phi - gamma*t) - m*g*l*cos(phi)",
        "sign_of_V",
    )
    s.ok(
        "eom",
        ["m l^2 phi_ddot - m l a gamma^2 cos(phi - gamma t) + m g l sin(phi) = 0"],
        ["m*l**2*phi_ddot - m*l*a*gamma**2*cos(phi - gamma*t) + m*g*l*sin(phi)"],
    )
    s.ok(
        "eom",
        ["l φ̈ = a γ² cos(φ − γ t) − g sin φ"],
        ["l*phi_ddot - a*gamma**2*cos(phi - gamma*t) + g*sin(phi)"],
        "unicode_solved",
    )
    s.ok(
        "eom",
        [r"\ddot\phi = \frac{a\gamma^2}{l}\cos(\phi-\gamma t) - \frac{g}{l}\sin\phi"],
        ["phi_ddot - a*gamma**2/l*cos(phi - gamma*t) + g/l*sin(phi)"],
        "latex",
    )
    s.bad(
        "eom",
        ["m l^2 phi_ddot + m g l sin(phi) = 0"],
        ["m*l**2*phi_ddot + m*g*l*sin(phi)"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        ["l phi_ddot = a gamma^2 sin(phi - gamma t) - g sin(phi)"],
        ["l*phi_ddot - a*gamma**2*sin(phi - gamma*t) + g*sin(phi)"],
        "wrong_trig",
    )
    s.ok("momenta", ["p_phi = m l^2 phi_dot"], ["p_phi = m*l**2*phi_dot"])
    s.bad(
        "momenta",
        ["p_phi = m l^2 phi_dot + m a gamma l sin(phi - gamma t)"],
        ["p_phi = m*l**2*phi_dot + m*a*gamma*l*sin(phi - gamma*t)"],
        "other_lagrangian",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "phi", ["phi"], "not_cyclic")
    s.bad(
        "conserved",
        ["1/2 m l^2 phi_dot^2 - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 - m*g*l*cos(phi)"],
        "not_conserved",
    )
    s.bad(
        "conserved",
        ["1/2 m l^2 phi_dot^2 - m l a gamma^2 sin(phi - gamma t) - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 - m*l*a*gamma**2*sin(phi - gamma*t) - m*g*l*cos(phi)"],
        "not_conserved",
    )
    return s


def support_horizontal() -> System:
    s = System(
        "ll_pendulum_support_horizontal",
        LL + "§5 Problem 3(b) (point of support oscillating horizontally, x = a cos(gamma t); "
        "printed solution L); the same system is D. Morin, Introduction to Classical Mechanics "
        "(2008), Problem 6.3, whose equation of motion is printed in the worked notebook "
        "https://github.com/vhvitro/Moving-Pendulum",
        "m*l**2*phi_dot**2/2 + m*l*a*gamma**2*cos(gamma*t)*sin(phi) + m*g*l*cos(phi)",
        ["phi"],
        {"m": P, "l": P, "a": P, "gamma": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "½ m l² φ̇² + m l a γ² cos(γ t) sin φ + m g l cos φ", L, "unicode")
    s.ok(
        "lagrangian",
        "1/2 m (a^2 gamma^2 sin(gamma t)^2 - 2 a gamma l phi_dot sin(gamma t) cos(phi)"
        " + l^2 phi_dot^2) + m g l cos(phi)",
        "m*(a**2*gamma**2*sin(gamma*t)**2 - 2*a*gamma*l*phi_dot*sin(gamma*t)*cos(phi)"
        " + l**2*phi_dot**2)/2 + m*g*l*cos(phi)",
        "unreduced_from_coordinates",
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2} m l^2\dot\phi^2 + m l a\gamma^2\cos(\gamma t)\sin\phi + m g l\cos\phi",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (a^2 gamma^2 sin(gamma t)^2 + l^2 phi_dot^2) + m g l cos(phi)",
        "m*(a**2*gamma**2*sin(gamma*t)**2 + l**2*phi_dot**2)/2 + m*g*l*cos(phi)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m l a gamma^2 cos(gamma t) sin(phi) - m g l cos(phi)",
        "m*l**2*phi_dot**2/2 + m*l*a*gamma**2*cos(gamma*t)*sin(phi) - m*g*l*cos(phi)",
        "sign_of_V",
    )
    s.ok(
        "eom",
        ["phi_ddot - a/l gamma^2 cos(gamma t) cos(phi) + g/l sin(phi) = 0"],
        ["phi_ddot - a/l*gamma**2*cos(gamma*t)*cos(phi) + g/l*sin(phi)"],
        "as_in_morin_6_3",
    )
    s.ok(
        "eom",
        [r"l\ddot\phi + g\sin\phi = a\gamma^2\cos(\gamma t)\cos\phi"],
        ["l*phi_ddot + g*sin(phi) - a*gamma**2*cos(gamma*t)*cos(phi)"],
        "latex",
    )
    s.ok(
        "eom",
        ["m l² φ̈ = m l a γ² cos(γt) cos φ − m g l sin φ"],
        ["m*l**2*phi_ddot - m*l*a*gamma**2*cos(gamma*t)*cos(phi) + m*g*l*sin(phi)"],
        "unicode",
    )
    s.bad(
        "eom",
        ["phi_ddot + a/l gamma^2 cos(gamma t) cos(phi) + g/l sin(phi) = 0"],
        ["phi_ddot + a/l*gamma**2*cos(gamma*t)*cos(phi) + g/l*sin(phi)"],
        "wrong_sign",
    )
    s.bad(
        "eom",
        ["phi_ddot - a/l gamma^2 cos(gamma t) sin(phi) + g/l sin(phi) = 0"],
        ["phi_ddot - a/l*gamma**2*cos(gamma*t)*sin(phi) + g/l*sin(phi)"],
        "wrong_trig",
    )
    s.ok("momenta", ["p_phi = m l^2 phi_dot"], ["p_phi = m*l**2*phi_dot"])
    s.bad(
        "momenta",
        ["p_phi = m l^2 phi_dot - m a gamma l sin(gamma t) cos(phi)"],
        ["p_phi = m*l**2*phi_dot - m*a*gamma*l*sin(gamma*t)*cos(phi)"],
        "other_lagrangian",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad(
        "conserved",
        ["1/2 m l^2 phi_dot^2 - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 - m*g*l*cos(phi)"],
        "not_conserved",
    )
    return s


def support_vertical() -> System:
    s = System(
        "ll_pendulum_support_vertical",
        LL + "§5 Problem 3(c) (point of support oscillating vertically, y = a cos(gamma t); "
        "printed solution L); stability of the inverted position: §30 Problem 1 "
        "(upper position stable when a^2 gamma^2 > 2 g l)",
        "m*l**2*phi_dot**2/2 + m*l*a*gamma**2*cos(gamma*t)*cos(phi) + m*g*l*cos(phi)",
        ["phi"],
        {"m": P, "l": P, "a": P, "gamma": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "½ m l² φ̇² + m l a γ² cos(γ t) cos φ + m g l cos φ", L, "unicode")
    s.ok(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m l (g + a gamma^2 cos(gamma t)) cos(phi)",
        "m*l**2*phi_dot**2/2 + m*l*(g + a*gamma**2*cos(gamma*t))*cos(phi)",
        "effective_gravity",
    )
    s.ok(
        "lagrangian",
        "1/2 m (l^2 phi_dot^2 + 2 a gamma l phi_dot sin(gamma t) sin(phi)"
        " + a^2 gamma^2 sin(gamma t)^2) + m g (l cos(phi) + a cos(gamma t))",
        "m*(l**2*phi_dot**2 + 2*a*gamma*l*phi_dot*sin(gamma*t)*sin(phi)"
        " + a**2*gamma**2*sin(gamma*t)**2)/2 + m*g*(l*cos(phi) + a*cos(gamma*t))",
        "unreduced_from_coordinates",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m l (g - a gamma^2 cos(gamma t)) cos(phi)",
        "m*l**2*phi_dot**2/2 + m*l*(g - a*gamma**2*cos(gamma*t))*cos(phi)",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 - m l (g + a gamma^2 cos(gamma t)) cos(phi)",
        "m*l**2*phi_dot**2/2 - m*l*(g + a*gamma**2*cos(gamma*t))*cos(phi)",
        "sign_of_V",
    )
    s.ok(
        "eom",
        ["l phi_ddot + (g + a gamma^2 cos(gamma t)) sin(phi) = 0"],
        ["l*phi_ddot + (g + a*gamma**2*cos(gamma*t))*sin(phi)"],
    )
    s.ok(
        "eom",
        [r"\ddot{\phi} = -\frac{g + a\gamma^{2}\cos(\gamma t)}{l}\,\sin\phi"],
        ["phi_ddot + (g + a*gamma**2*cos(gamma*t))/l*sin(phi)"],
        "latex",
    )
    s.bad(
        "eom",
        ["l phi_ddot + (g - a gamma^2 cos(gamma t)) sin(phi) = 0"],
        ["l*phi_ddot + (g - a*gamma**2*cos(gamma*t))*sin(phi)"],
        "wrong_sign",
    )
    s.bad("eom", ["l phi_ddot + g sin(phi) = 0"], ["l*phi_ddot + g*sin(phi)"], "missing_term")
    s.ok("momenta", ["p_phi = m l^2 phi_dot"], ["p_phi = m*l**2*phi_dot"])
    s.ok("cyclic", "none", [], "none")
    s.bad(
        "conserved",
        ["1/2 m l^2 phi_dot^2 - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 - m*g*l*cos(phi)"],
        "not_conserved",
    )
    e = s.expression(
        "sqrt(a**2*gamma**2/(2*l**2) - g/l)",
        {"a": P, "gamma": P, "l": P, "g": P},
        "inverted_frequency",
    )
    e.ok("sqrt(a^2 gamma^2 - 2 g l)/(sqrt(2) l)", "sqrt(a**2*gamma**2 - 2*g*l)/(sqrt(2)*l)")
    e.ok(r"\frac{1}{l}\sqrt{\frac{a^2\gamma^2}{2} - g l}", "sqrt(a**2*gamma**2/2 - g*l)/l", "latex")
    e.bad("sqrt(a^2 gamma^2/(2 l^2) + g/l)", "sqrt(a**2*gamma**2/(2*l**2) + g/l)", "wrong_sign")
    e.bad("sqrt(a^2 gamma^2/l^2 - g/l)", "sqrt(a**2*gamma**2/l**2 - g/l)", "factor_2")
    return s


def governor() -> System:
    s = System(
        "ll_centrifugal_governor",
        LL + "§5 Problem 4 (m2 slides on the vertical axis, two masses m1 at the joints of four "
        "rods of length a, the system turning about the axis with angular velocity Omega; "
        "printed solution L)",
        "m1*a**2*(theta_dot**2 + Omega**2*sin(theta)**2) + 2*m2*a**2*theta_dot**2*sin(theta)**2"
        " + 2*g*a*(m1 + m2)*cos(theta)",
        {"theta": "(0, pi/2)"},
        {"m1": P, "m2": P, "a": P, "Omega": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "m₁ a² (θ̇² + Ω² sin²θ) + 2 m₂ a² θ̇² sin²θ + 2 g a (m₁ + m₂) cos θ",
        L,
        "unicode",
    )
    s.ok(
        "lagrangian",
        r"m_1 a^2(\dot\theta^2 + \Omega^2\sin^2\theta) + 2 m_2 a^2\dot\theta^2\sin^2\theta"
        r" + 2 g a (m_1+m_2)\cos\theta",
        L,
        "latex",
    )
    s.ok(
        "lagrangian",
        "m1 a^2 (theta_dot^2 + Omega^2 sin(theta)^2)/(m1 + m2) + 2 m2 a^2 theta_dot^2"
        " sin(theta)^2/(m1 + m2) + 2 g a cos(theta)",
        f"({L})/(m1 + m2)",
        "divided_by_total_mass",
    )
    s.bad(
        "lagrangian",
        "m1 a^2 theta_dot^2 + 2 m2 a^2 theta_dot^2 sin(theta)^2 + 2 g a (m1 + m2) cos(theta)",
        "m1*a**2*theta_dot**2 + 2*m2*a**2*theta_dot**2*sin(theta)**2 + 2*g*a*(m1 + m2)*cos(theta)",
        "missing_centripetal",
    )
    s.bad(
        "lagrangian",
        "m1 a^2 (theta_dot^2 + Omega^2 sin(theta)^2) + 2 m2 a^2 theta_dot^2 sin(theta)^2"
        " + g a (m1 + m2) cos(theta)",
        "m1*a**2*(theta_dot**2 + Omega**2*sin(theta)**2) + 2*m2*a**2*theta_dot**2"
        "*sin(theta)**2 + g*a*(m1 + m2)*cos(theta)",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "m1 a^2 (theta_dot^2 + Omega^2 sin(theta)^2) + 2 m2 a^2 theta_dot^2 cos(theta)^2"
        " + 2 g a (m1 + m2) cos(theta)",
        "m1*a**2*(theta_dot**2 + Omega**2*sin(theta)**2) + 2*m2*a**2*theta_dot**2"
        "*cos(theta)**2 + 2*g*a*(m1 + m2)*cos(theta)",
        "wrong_trig",
    )
    eq = (
        "a*(m1 + 2*m2*sin(theta)**2)*theta_ddot + 2*m2*a*theta_dot**2*sin(theta)*cos(theta)"
        " - m1*a*Omega**2*sin(theta)*cos(theta) + g*(m1 + m2)*sin(theta)"
    )
    s.ok(
        "eom",
        [
            "a (m1 + 2 m2 sin(theta)^2) theta_ddot + 2 m2 a theta_dot^2 sin(theta) cos(theta)"
            " - m1 a Omega^2 sin(theta) cos(theta) + g (m1 + m2) sin(theta) = 0"
        ],
        [eq],
    )
    s.ok(
        "eom",
        [
            "a (m1 + 2 m2 sin(theta)^2) theta_ddot + m2 a theta_dot^2 sin(2 theta)"
            " = m1 a Omega^2 sin(2 theta)/2 - g (m1 + m2) sin(theta)"
        ],
        [eq],
        "double_angle",
    )
    s.bad(
        "eom",
        [
            "a (m1 + 2 m2 sin(theta)^2) theta_ddot - m1 a Omega^2 sin(theta) cos(theta)"
            " + g (m1 + m2) sin(theta) = 0"
        ],
        [
            "a*(m1 + 2*m2*sin(theta)**2)*theta_ddot - m1*a*Omega**2*sin(theta)*cos(theta)"
            " + g*(m1 + m2)*sin(theta)"
        ],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        [
            "a (m1 + 2 m2 sin(theta)^2) theta_ddot + 2 m2 a theta_dot^2 sin(theta) cos(theta)"
            " + m1 a Omega^2 sin(theta) cos(theta) + g (m1 + m2) sin(theta) = 0"
        ],
        [
            "a*(m1 + 2*m2*sin(theta)**2)*theta_ddot + 2*m2*a*theta_dot**2*sin(theta)*cos(theta)"
            " + m1*a*Omega**2*sin(theta)*cos(theta) + g*(m1 + m2)*sin(theta)"
        ],
        "wrong_sign",
    )
    s.ok(
        "momenta",
        ["p_theta = 2 a^2 (m1 + 2 m2 sin(theta)^2) theta_dot"],
        ["p_theta = 2*a**2*(m1 + 2*m2*sin(theta)**2)*theta_dot"],
    )
    s.bad(
        "momenta",
        ["p_theta = a^2 (m1 + 2 m2 sin(theta)^2) theta_dot"],
        ["p_theta = a**2*(m1 + 2*m2*sin(theta)**2)*theta_dot"],
        "factor_2",
    )
    s.ok("cyclic", "none", [], "none")
    h = (
        "m1*a**2*theta_dot**2 + 2*m2*a**2*theta_dot**2*sin(theta)**2"
        " - m1*a**2*Omega**2*sin(theta)**2 - 2*g*a*(m1 + m2)*cos(theta)"
    )
    s.ok("conserved", [h.replace("**", "^")], [h], "jacobi_integral")
    s.bad(
        "conserved",
        [
            "m1 a^2 (theta_dot^2 + Omega^2 sin(theta)^2) + 2 m2 a^2 theta_dot^2 sin(theta)^2"
            " - 2 g a (m1 + m2) cos(theta)"
        ],
        [
            "m1*a**2*(theta_dot**2 + Omega**2*sin(theta)**2) + 2*m2*a**2*theta_dot**2"
            "*sin(theta)**2 - 2*g*a*(m1 + m2)*cos(theta)"
        ],
        "not_conserved",
    )
    e = s.expression(
        "acos(g*(m1 + m2)/(m1*a*Omega**2))",
        {"g": P, "m1": P, "m2": P, "a": P, "Omega": P},
        "equilibrium_angle",
    )
    e.ok("acos((1 + m2/m1) g/(a Omega^2))", "acos((1 + m2/m1)*g/(a*Omega**2))")
    e.ok("arccos(g (m₁ + m₂)/(m₁ a Ω²))", "acos(g*(m1 + m2)/(m1*a*Omega**2))", "unicode")
    e.bad("acos(g/(a Omega^2))", "acos(g/(a*Omega**2))", "missing_term")
    e.bad("asin(g (m1 + m2)/(m1 a Omega^2))", "asin(g*(m1 + m2)/(m1*a*Omega**2))", "wrong_trig")
    return s


def kepler() -> System:
    s = System(
        "ll_kepler",
        LL + "§14 (motion in a central field, L = m(r'^2 + r^2 phi'^2)/2 - U(r)) and §15 "
        "(Kepler's problem, U = -alpha/r; period T = 2 pi a^(3/2) sqrt(m/alpha) = "
        "pi alpha sqrt(m/(2|E|^3))); the x-component of the Laplace-Runge-Lenz vector "
        "p x M - m alpha r/r (conserved for U = -alpha/r) written out here in polar coordinates",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 + alpha/r",
        {"r": "positive", "phi": None},
        {"m": P, "alpha": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "m/2 (r_dot^2 + r^2 phi_dot^2) + alpha/r", L)
    s.ok("lagrangian", "½ m (ṙ² + r² φ̇²) + α/r", L, "unicode")
    s.ok(
        "lagrangian",
        r"\frac{m}{2}\left(\dot r^2 + r^2\dot\varphi^2\right) + \frac{\alpha}{r}",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 phi_dot^2) - alpha/r",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 - alpha/r",
        "sign_of_V",
    )
    s.bad("lagrangian", "1/2 m r_dot^2 + alpha/r", "m*r_dot**2/2 + alpha/r", "missing_term")
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r phi_dot^2) + alpha/r",
        "m*(r_dot**2 + r*phi_dot**2)/2 + alpha/r",
        "wrong_moment_of_inertia",
    )
    er = "m*r_ddot - m*r*phi_dot**2 + alpha/r**2"
    ep = "m*r**2*phi_ddot + 2*m*r*r_dot*phi_dot"
    s.ok(
        "eom",
        ["m r_ddot - m r phi_dot^2 + alpha/r^2 = 0", "m r^2 phi_ddot + 2 m r r_dot phi_dot = 0"],
        [er, ep],
    )
    s.ok(
        "eom",
        ["m r̈ = m r φ̇² − α/r²", "d/dt(m r² φ̇) = 0"],
        [er, "Dt(m*r**2*phi_dot)"],
        "unicode_conservation_form",
    )
    s.ok(
        "eom",
        ["r_ddot = r phi_dot^2 - alpha/(m r^2)", "phi_ddot = -2 r_dot phi_dot/r"],
        [f"({er})/m", f"({ep})/(m*r**2)"],
        "solved",
    )
    s.bad(
        "eom",
        ["m r_ddot + alpha/r^2 = 0", "m r^2 phi_ddot + 2 m r r_dot phi_dot = 0"],
        ["m*r_ddot + alpha/r**2", ep],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        ["m r_ddot - m r phi_dot^2 + alpha/r^2 = 0", "m r^2 phi_ddot = 0"],
        [er, "m*r**2*phi_ddot"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        ["m r_ddot - m r phi_dot^2 - alpha/r^2 = 0", "m r^2 phi_ddot + 2 m r r_dot phi_dot = 0"],
        ["m*r_ddot - m*r*phi_dot**2 - alpha/r**2", ep],
        "wrong_sign",
    )
    s.ok(
        "momenta",
        ["p_r = m r_dot", "p_phi = m r^2 phi_dot"],
        ["p_r = m*r_dot", "p_phi = m*r**2*phi_dot"],
    )
    s.ok(
        "momenta",
        ["p_φ = m r² φ̇", "p_r = m ṙ"],
        ["p_phi = m*r**2*phi_dot", "p_r = m*r_dot"],
        "unicode_other_order",
    )
    s.bad(
        "momenta",
        ["p_r = m r_dot", "p_phi = m r phi_dot"],
        ["p_r = m*r_dot", "p_phi = m*r*phi_dot"],
        "wrong_moment_of_inertia",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "r", ["r"], "not_cyclic")
    s.bad("cyclic", "none", [], "missed_cyclic")
    E = "m*(r_dot**2 + r**2*phi_dot**2)/2 - alpha/r"
    s.ok(
        "conserved",
        ["m r^2 phi_dot", "1/2 m (r_dot^2 + r^2 phi_dot^2) - alpha/r"],
        ["m*r**2*phi_dot", E],
        "angular_momentum_and_energy",
    )
    s.ok("conserved", ["r^2 phi_dot"], ["r**2*phi_dot"], "areal_velocity")
    s.ok(
        "conserved",
        ["m^2 r^2 phi_dot (r_dot sin(phi) + r phi_dot cos(phi)) - m alpha cos(phi)"],
        ["m**2*r**2*phi_dot*(r_dot*sin(phi) + r*phi_dot*cos(phi)) - m*alpha*cos(phi)"],
        "runge_lenz_x",
    )
    s.bad(
        "conserved",
        ["m r^2 phi_dot", "r^2 phi_dot"],
        ["m*r**2*phi_dot", "r**2*phi_dot"],
        "not_independent",
    )
    s.bad("conserved", ["m r phi_dot"], ["m*r*phi_dot"], "not_conserved")
    s.bad("conserved", ["m r_dot"], ["m*r_dot"], "not_conserved")
    e = s.expression("2*pi*a**(3/2)*sqrt(m/alpha)", {"a": P, "m": P, "alpha": P}, "period")
    e.ok("2 pi sqrt(m a^3/alpha)", "2*pi*sqrt(m*a**3/alpha)")
    e.ok("2 π a^(3/2) √(m/α)", "2*pi*a**(3/2)*sqrt(m/alpha)", "unicode_root")
    e.ok(r"2\pi a^{3/2}\sqrt{\frac{m}{\alpha}}", "2*pi*a**(3/2)*sqrt(m/alpha)", "latex")
    e.bad("2 pi sqrt(m a^2/alpha)", "2*pi*sqrt(m*a**2/alpha)")
    e.bad("2 pi a^(3/2) sqrt(alpha/m)", "2*pi*a**(3/2)*sqrt(alpha/m)")
    e2 = s.expression(
        "pi*alpha*sqrt(m/(2*Abs(E)**3))",
        {"alpha": P, "m": P, "E": "(-10, 0)"},
        "period_from_energy",
    )
    e2.ok("pi alpha sqrt(-m/(2 E^3))", "pi*alpha*sqrt(-m/(2*E**3))", "negative_energy")
    e2.ok("π α sqrt(m/2) (−E)^(−3/2)", "pi*alpha*sqrt(m/2)*(-E)**(-3/2)", "unicode")
    e2.bad("pi alpha sqrt(m/(2 E^3))", "pi*alpha*sqrt(m/(2*E**3))", "wrong_sign")
    e2.bad("pi alpha sqrt(m/(2 E^2))", "pi*alpha*sqrt(m/(2*E**2))")
    return s


def symmetric_top() -> System:
    s = System(
        "ll_heavy_symmetric_top",
        LL + "§35 (Eulerian angles; the heavy symmetric top, L = I1'(theta'^2 + phi'^2 "
        "sin^2 theta)/2 + I3(psi' + phi' cos theta)^2/2 - mu g l cos theta); also Goldstein, "
        "Poole & Safko, Classical Mechanics 3rd ed., §5.7, and D. Tong, Classical Dynamics, "
        "§3.6 (sleeping top: stable when omega3^2 > 4 I1 M g l/I3^2)",
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 + I3*(psi_dot + phi_dot*cos(theta))**2/2"
        " - M*g*l*cos(theta)",
        {"theta": "(0, pi)", "phi": None, "psi": None},
        {"I1": P, "I3": P, "M": P, "g": P, "l": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "I1/2 (theta_dot^2 + phi_dot^2 sin(theta)^2) + I3/2 (psi_dot + phi_dot cos(theta))^2"
        " - M g l cos(theta)",
        L,
    )
    s.ok(
        "lagrangian",
        r"\frac{I_1}{2}(\dot\theta^2 + \dot\phi^2\sin^2\theta)"
        r" + \frac{I_3}{2}(\dot\psi + \dot\phi\cos\theta)^2 - M g l\cos\theta",
        L,
        "latex",
    )
    s.ok(
        "lagrangian",
        "½ I1 θ̇² + ½ I1 φ̇² sin²θ + ½ I3 ψ̇² + I3 ψ̇ φ̇ cos θ + ½ I3 φ̇² cos²θ − M g l cos θ",
        L,
        "unicode_expanded",
    )
    s.bad(
        "lagrangian",
        "I1/2 (theta_dot^2 + phi_dot^2 sin(theta)^2) + I3/2 (psi_dot + phi_dot cos(theta))^2"
        " + M g l cos(theta)",
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 + I3*(psi_dot + phi_dot*cos(theta))**2/2"
        " + M*g*l*cos(theta)",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "I1/2 (theta_dot^2 + phi_dot^2 sin(theta)^2) + I3/2 (psi_dot + phi_dot sin(theta))^2"
        " - M g l cos(theta)",
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 + I3*(psi_dot + phi_dot*sin(theta))**2/2"
        " - M*g*l*cos(theta)",
        "wrong_trig",
    )
    s.bad(
        "lagrangian",
        "I1/2 (theta_dot^2 + phi_dot^2 sin(theta)^2) + I3/2 (psi_dot^2 + phi_dot^2 cos(theta)^2)"
        " - M g l cos(theta)",
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2"
        " + I3*(psi_dot**2 + phi_dot**2*cos(theta)**2)/2 - M*g*l*cos(theta)",
        "missing_cross_term",
    )
    w3 = "(psi_dot + phi_dot*cos(theta))"
    et = (
        f"I1*theta_ddot - I1*phi_dot**2*sin(theta)*cos(theta) + I3*{w3}*phi_dot*sin(theta)"
        " - M*g*l*sin(theta)"
    )
    ef = (
        f"I1*(phi_ddot*sin(theta)**2 + 2*phi_dot*theta_dot*sin(theta)*cos(theta))"
        f" + I3*(psi_ddot + phi_ddot*cos(theta) - phi_dot*theta_dot*sin(theta))*cos(theta)"
        f" - I3*{w3}*theta_dot*sin(theta)"
    )
    es = "I3*(psi_ddot + phi_ddot*cos(theta) - phi_dot*theta_dot*sin(theta))"
    s.ok("eom", [x.replace("**", "^") + " = 0" for x in (et, ef, es)], [et, ef, es], "expanded")
    s.ok(
        "eom",
        [
            et.replace("**", "^") + " = 0",
            "d/dt(I1 phi_dot sin(theta)^2 + I3 (psi_dot + phi_dot cos(theta)) cos(theta)) = 0",
            "d/dt(I3 (psi_dot + phi_dot cos(theta))) = 0",
        ],
        [et, f"Dt(I1*phi_dot*sin(theta)**2 + I3*{w3}*cos(theta))", f"Dt(I3*{w3})"],
        "conservation_form",
    )
    s.ok(
        "eom",
        [
            es.replace("**", "^") + " = 0",
            et.replace("**", "^") + " = 0",
            "I1 (phi_ddot sin(theta)^2 + 2 phi_dot theta_dot sin(theta) cos(theta))"
            " - I3 (psi_dot + phi_dot cos(theta)) theta_dot sin(theta) = 0",
        ],
        [
            es,
            et,
            f"I1*(phi_ddot*sin(theta)**2 + 2*phi_dot*theta_dot*sin(theta)*cos(theta))"
            f" - I3*{w3}*theta_dot*sin(theta)",
        ],
        "row_combination",
    )
    s.bad(
        "eom",
        [
            et.replace("**", "^") + " = 0",
            ef.replace("**", "^") + " = 0",
            "I3 (psi_ddot + phi_ddot cos(theta)) = 0",
        ],
        [et, ef, "I3*(psi_ddot + phi_ddot*cos(theta))"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        [
            et.replace("**", "^").replace("- M*g*l", "+ M*g*l") + " = 0",
            ef.replace("**", "^") + " = 0",
            es.replace("**", "^") + " = 0",
        ],
        [et.replace("- M*g*l", "+ M*g*l"), ef, es],
        "wrong_sign",
    )
    pf = f"I1*phi_dot*sin(theta)**2 + I3*{w3}*cos(theta)"
    ps = f"I3*{w3}"
    s.ok(
        "momenta",
        [
            "p_theta = I1 theta_dot",
            "p_phi = I1 phi_dot sin(theta)^2 + I3 (psi_dot + phi_dot cos(theta)) cos(theta)",
            "p_psi = I3 (psi_dot + phi_dot cos(theta))",
        ],
        ["p_theta = I1*theta_dot", f"p_phi = {pf}", f"p_psi = {ps}"],
    )
    s.ok(
        "momenta",
        ["p_ψ = I3 (ψ̇ + φ̇ cos θ)", "p_θ = I1 θ̇", "p_φ = (I1 sin²θ + I3 cos²θ) φ̇ + I3 ψ̇ cos θ"],
        [f"p_psi = {ps}", "p_theta = I1*theta_dot", f"p_phi = {pf}"],
        "unicode_collected",
    )
    s.bad(
        "momenta",
        [
            "p_theta = I1 theta_dot",
            "p_phi = I1 phi_dot sin(theta)^2",
            "p_psi = I3 (psi_dot + phi_dot cos(theta))",
        ],
        ["p_theta = I1*theta_dot", "p_phi = I1*phi_dot*sin(theta)**2", f"p_psi = {ps}"],
        "missing_term",
    )
    s.ok("cyclic", "phi, psi", ["phi", "psi"], "two")
    s.ok("cyclic", "ψ, φ", ["phi", "psi"], "unicode_other_order")
    s.bad("cyclic", "psi", ["psi"], "missed_cyclic")
    s.bad("cyclic", "theta, phi, psi", ["theta", "phi", "psi"], "not_cyclic")
    h = (
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 + I3*(psi_dot + phi_dot*cos(theta))**2/2"
        " + M*g*l*cos(theta)"
    )
    s.ok(
        "conserved",
        [pf.replace("**", "^"), ps.replace("**", "^"), h.replace("**", "^")],
        [pf, ps, h],
        "momenta_and_energy",
    )
    s.ok("conserved", ["psi_dot + phi_dot cos(theta)"], [w3], "spin_omega3")
    s.bad("conserved", ["I1 phi_dot sin(theta)^2"], ["I1*phi_dot*sin(theta)**2"], "not_conserved")
    s.bad(
        "conserved",
        ["I3 (psi_dot + phi_dot cos(theta))", "psi_dot + phi_dot cos(theta)"],
        [ps, w3],
        "not_independent",
    )
    e = s.expression(
        "2*sqrt(I1*M*g*l)/I3", {"I1": P, "I3": P, "M": P, "g": P, "l": P}, "sleeping_top_spin"
    )
    e.ok("sqrt(4 I1 M g l)/I3", "sqrt(4*I1*M*g*l)/I3")
    e.ok(r"\frac{2\sqrt{I_1 M g l}}{I_3}", "2*sqrt(I1*M*g*l)/I3", "latex")
    e.bad("sqrt(4 I1 M g l/I3)", "sqrt(4*I1*M*g*l/I3)")
    e.bad("sqrt(I1 M g l)/I3", "sqrt(I1*M*g*l)/I3", "factor_2")
    return s


def total_derivative_term() -> System:
    s = System(
        "ll_total_derivative_term",
        LL + "§2 (a Lagrangian is defined only to within a total time derivative df(q, t)/dt), "
        "for a free particle with the term k x x' = d(k x^2/2)/dt added: x is not cyclic (L "
        "depends on x), m x' is conserved and the canonical momentum m x' + k x is not",
        "m*x_dot**2/2 + k*x*x_dot",
        ["x"],
        {"m": P, "k": P},
    )
    s.ok("lagrangian", "1/2 m x_dot^2", "m*x_dot**2/2", "without_the_derivative")
    s.ok("lagrangian", "1/2 m x_dot^2 + k x x_dot", "m*x_dot**2/2 + k*x*x_dot", "as_given")
    s.bad("lagrangian", "1/2 m x_dot^2 + k x^2", "m*x_dot**2/2 + k*x**2", "missing_term")
    s.ok("eom", ["m x_ddot = 0"], ["m*x_ddot"], "free_motion")
    s.ok(
        "eom",
        ["d/dt(m x_dot + k x) = k x_dot"],
        ["Dt(m*x_dot + k*x) - k*x_dot"],
        "from_the_momentum",
    )
    s.bad("eom", ["d/dt(m x_dot + k x) = 0"], ["Dt(m*x_dot + k*x)"], "missing_term")
    s.ok("momenta", ["p_x = m x_dot + k x"], ["p_x = m*x_dot + k*x"])
    s.bad("momenta", ["p_x = m x_dot"], ["p_x = m*x_dot"], "other_lagrangian")
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "x", ["x"], "not_cyclic")
    s.ok("conserved", ["m x_dot"], ["m*x_dot"], "kinetic_momentum")
    s.bad("conserved", ["m x_dot + k x"], ["m*x_dot + k*x"], "not_conserved")
    return s


SYSTEMS = (
    double_pendulum,
    sliding_support,
    support_on_circle,
    support_horizontal,
    support_vertical,
    governor,
    kepler,
    symmetric_top,
    total_derivative_term,
)
