"""Systems from sympy's own mechanics tests and tutorials (sympy/sympy, read at commit
e950d313a932bc6cccbc95376b3821cd2f8b5af4): each reference Lagrangian is the one those files build
with sympy.physics.mechanics, and the equations they assert are among the right answers."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System, uni

SYMPY = "sympy/sympy@e950d313a932: "
P = "positive"


def simple_pendulum() -> System:
    s = System(
        "sympy_simple_pendulum",
        SYMPY + "sympy/physics/mechanics/tests/test_lagrange.py::test_simp_pen (bob of mass m on a "
        "massless rod of length l, V = -m g l cos q; asserts q'' = -g sin(q)/l) and "
        "tests/test_kane.py::test_pend; coordinate q renamed theta",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
        ["theta"],
        {"m": P, "g": P, "l": P},
    )
    L = "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)"
    s.ok("lagrangian", "1/2 m l^2 theta_dot^2 + m g l cos(theta)", L, "plain")
    s.ok("lagrangian", "½ m l² θ̇² + m g l cos θ", L, "unicode")
    s.ok("lagrangian", r"\frac{1}{2} m l^2 \dot{\theta}^2 + m g l \cos\theta", L, "latex")
    s.ok("lagrangian", "m*l**2*theta_dot**2/2 - m*g*l*(1 - cos(theta))", None, "shifted_V")
    s.ok(
        "lagrangian",
        "l thetadot^2/2 + g cos(theta)",
        "l*theta_dot**2/2 + g*cos(theta)",
        "divided_by_m_l",
    )
    s.ok(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + m g l cos(theta) + m l^2 theta_dot sin(theta)",
        L + " + m*l**2*theta_dot*sin(theta)",
        "plus_total_derivative",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 - m g l cos(theta)",
        "m*l**2*theta_dot**2/2 - m*g*l*cos(theta)",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 m l theta_dot^2 + m g l cos(theta)",
        "m*l*theta_dot**2/2 + m*g*l*cos(theta)",
        "wrong_moment_of_inertia",
    )
    s.bad(
        "lagrangian",
        "m l^2 theta_dot^2 + m g l cos(theta)",
        "m*l**2*theta_dot**2 + m*g*l*cos(theta)",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + m g l sin(theta)",
        "m*l**2*theta_dot**2/2 + m*g*l*sin(theta)",
        "wrong_trig",
    )
    s.bad(
        "lagrangian",
        "-1/2 m l^2 theta_dot^2 - m g l cos(theta)",
        "-m*l**2*theta_dot**2/2 - m*g*l*cos(theta)",
        "v_minus_t",
    )

    s.ok(
        "eom",
        ["m l^2 theta_ddot + m g l sin(theta) = 0"],
        ["m*l**2*theta_ddot + m*g*l*sin(theta)"],
        "multiplied_through",
    )
    s.ok(
        "eom",
        ["theta_ddot = -g/l sin(theta)"],
        ["theta_ddot + g/l*sin(theta)"],
        "solved_as_in_sympy_test",
    )
    s.ok("eom", ["θ̈ + (g/l) sin θ = 0"], ["theta_ddot + g/l*sin(theta)"], "unicode")
    s.ok(
        "eom", [r"\ddot{\theta} = -\frac{g}{l}\sin\theta"], ["theta_ddot + g/l*sin(theta)"], "latex"
    )
    s.ok(
        "eom",
        ["l theta_ddot + g sin(theta) = 0"],
        ["l*theta_ddot + g*sin(theta)"],
        "divided_by_m_l",
    )
    s.ok(
        "eom",
        ["d/dt(m l^2 theta_dot) = -m g l sin(theta)"],
        ["Dt(m*l**2*theta_dot) + m*g*l*sin(theta)"],
        "time_derivative_of_momentum",
    )
    s.bad("eom", ["theta_ddot = g/l sin(theta)"], ["theta_ddot - g/l*sin(theta)"], "wrong_sign")
    s.bad("eom", ["theta_ddot = -g/l theta"], ["theta_ddot + g/l*theta"], "small_angle")
    s.bad(
        "eom",
        ["m l^2 theta_ddot + m g l cos(theta) = 0"],
        ["m*l**2*theta_ddot + m*g*l*cos(theta)"],
        "wrong_trig",
    )

    s.ok("momenta", ["p_theta = m l^2 theta_dot"], ["p_theta = m*l**2*theta_dot"], "plain")
    s.ok("momenta", ["p_θ = m l² θ̇"], ["p_theta = m*l**2*theta_dot"], "unicode")
    s.bad(
        "momenta",
        ["p_theta = m l theta_dot"],
        ["p_theta = m*l*theta_dot"],
        "wrong_moment_of_inertia",
    )
    s.bad(
        "momenta", ["p_theta = 1/2 m l^2 theta_dot"], ["p_theta = m*l**2*theta_dot/2"], "factor_2"
    )

    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "theta", ["theta"], "not_cyclic")

    E = "m*l**2*theta_dot**2/2 - m*g*l*cos(theta)"
    s.ok("conserved", ["1/2 m l^2 theta_dot^2 - m g l cos(theta)"], [E], "energy")
    s.ok(
        "conserved",
        ["theta_dot^2 - 2 g/l cos(theta)"],
        ["theta_dot**2 - 2*g/l*cos(theta)"],
        "energy_scaled",
    )
    s.bad("conserved", ["m l^2 theta_dot"], ["m*l**2*theta_dot"], "not_conserved")
    s.bad(
        "conserved",
        ["1/2 m l^2 theta_dot^2 + m g l cos(theta)"],
        ["m*l**2*theta_dot**2/2 + m*g*l*cos(theta)"],
        "not_conserved",
    )

    e = s.expression("2*pi*sqrt(l/g)", {"l": P, "g": P}, "small_oscillation_period")
    e.ok("2 pi sqrt(l/g)", "2*pi*sqrt(l/g)", "plain")
    e.ok(r"2\pi\sqrt{\frac{l}{g}}", "2*pi*sqrt(l/g)", "latex")
    e.ok("2 π √(l/g)", "2*pi*sqrt(l/g)", "unicode_root")
    e.ok("2*pi*l^(1/2)*g^(-1/2)", "2*pi*l**(1/2)*g**(-1/2)", "powers")
    e.bad("2 pi sqrt(g/l)", "2*pi*sqrt(g/l)")
    e.bad("pi sqrt(l/g)", "pi*sqrt(l/g)", "factor_2")
    e.bad("sqrt(l/g)", "sqrt(l/g)", "missing_term")
    return s


def double_pendulum() -> System:
    s = System(
        "sympy_double_pendulum",
        SYMPY + "sympy/physics/mechanics/tests/test_lagrange.py::test_dub_pen (two bobs of mass m "
        "on rods of length l, angles q1, q2 from the direction of gravity; the test asserts the "
        "two Euler-Lagrange expressions in expanded form)",
        "m*l**2*q1_dot**2 + m*l**2*q2_dot**2/2 + m*l**2*q1_dot*q2_dot*cos(q1 - q2)"
        " + 2*m*g*l*cos(q1) + m*g*l*cos(q2)",
        ["q1", "q2"],
        {"m": P, "g": P, "l": P},
    )
    T = "m*l**2*q1_dot**2 + m*l**2*q2_dot**2/2 + m*l**2*q1_dot*q2_dot*cos(q1 - q2)"
    V = "-2*m*g*l*cos(q1) - m*g*l*cos(q2)"
    s.ok(
        "lagrangian",
        "m l^2 q1_dot^2 + 1/2 m l^2 q2_dot^2 + m l^2 q1_dot q2_dot cos(q1 - q2)"
        " + 2 m g l cos(q1) + m g l cos(q2)",
        f"{T} - ({V})",
        "plain",
    )
    s.ok(
        "lagrangian",
        "1/2 m l^2 q1dot^2 + 1/2 m (l^2 q1dot^2 + l^2 q2dot^2 + 2 l^2 q1dot q2dot "
        "(cos(q1) cos(q2) + sin(q1) sin(q2))) + 2 m g l cos(q1) + m g l cos(q2)",
        f"{T} - ({V})",
        "per_bob_trig_expanded",
    )
    s.ok(
        "lagrangian",
        r"m l^2 \dot{q}_1^2 + \frac{1}{2} m l^2 \dot{q}_2^2 + m l^2 \dot{q}_1 \dot{q}_2"
        r" \cos(q_1 - q_2) + 2 m g l \cos q_1 + m g l \cos q_2",
        f"{T} - ({V})",
        "latex",
    )
    s.bad(
        "lagrangian",
        "m l^2 q1_dot^2 + 1/2 m l^2 q2_dot^2 + 2 m g l cos(q1) + m g l cos(q2)",
        "m*l**2*q1_dot**2 + m*l**2*q2_dot**2/2 + 2*m*g*l*cos(q1) + m*g*l*cos(q2)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 q1_dot^2 + 1/2 m l^2 q2_dot^2 + m l^2 q1_dot q2_dot cos(q1 - q2)"
        " + 2 m g l cos(q1) + m g l cos(q2)",
        f"m*l**2*q1_dot**2/2 + m*l**2*q2_dot**2/2 + m*l**2*q1_dot*q2_dot*cos(q1 - q2) - ({V})",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "m l^2 q1_dot^2 + 1/2 m l^2 q2_dot^2 + m l^2 q1_dot q2_dot cos(q1 - q2)"
        " + m g l cos(q1) + m g l cos(q2)",
        f"{T} + m*g*l*cos(q1) + m*g*l*cos(q2)",
        "forgot_constraint",
    )

    e0 = (
        "l*m*(2*g*sin(q1) + l*sin(q1)*sin(q2)*q2_ddot + l*sin(q1)*cos(q2)*q2_dot**2"
        " - l*sin(q2)*cos(q1)*q2_dot**2 + l*cos(q1)*cos(q2)*q2_ddot + 2*l*q1_ddot)"
    )
    e1 = (
        "l*m*(g*sin(q2) + l*sin(q1)*sin(q2)*q1_ddot - l*sin(q1)*cos(q2)*q1_dot**2"
        " + l*sin(q2)*cos(q1)*q1_dot**2 + l*cos(q1)*cos(q2)*q1_ddot + l*q2_ddot)"
    )
    s.ok(
        "eom",
        [e0.replace("**", "^") + " = 0", e1.replace("**", "^") + " = 0"],
        [e0, e1],
        "as_asserted_by_sympy",
    )
    r0 = "2*q1_ddot + q2_ddot*cos(q1 - q2) + q2_dot**2*sin(q1 - q2) + 2*g/l*sin(q1)"
    r1 = "q2_ddot + q1_ddot*cos(q1 - q2) - q1_dot**2*sin(q1 - q2) + g/l*sin(q2)"
    s.ok(
        "eom",
        [
            "2 q1_ddot + q2_ddot cos(q1 - q2) + q2_dot^2 sin(q1 - q2) + 2 g/l sin(q1) = 0",
            "q2_ddot + q1_ddot cos(q1 - q2) - q1_dot^2 sin(q1 - q2) + g/l sin(q2) = 0",
        ],
        [r0, r1],
        "divided_by_m_l2",
    )
    s.ok(
        "eom",
        [
            "q2_ddot + q1_ddot cos(q1 - q2) - q1_dot^2 sin(q1 - q2) + g/l sin(q2) = 0",
            "2 q1_ddot + q2_ddot cos(q1 - q2) + q2_dot^2 sin(q1 - q2) + 2 g/l sin(q1) = 0",
        ],
        [r1, r0],
        "other_order",
    )
    s.ok(
        "eom",
        [
            uni("2 q1_ddot + q2_ddot cos(q1 - q2) + q2_dot^2 sin(q1 - q2) = -2 g/l sin(q1)"),
            "(2 - cos(q1 - q2)^2) q2_ddot = 2 q1_dot^2 sin(q1 - q2) + q2_dot^2 sin(q1 - q2)"
            " cos(q1 - q2) + 2 g/l sin(q1) cos(q1 - q2) - 2 g/l sin(q2)",
        ],
        [r0, f"2*({r1}) - cos(q1 - q2)*({r0})"],
        "row_combination",
    )
    s.bad(
        "eom",
        [
            "2 q1_ddot + q2_ddot cos(q1 - q2) + 2 g/l sin(q1) = 0",
            "q2_ddot + q1_ddot cos(q1 - q2) - q1_dot^2 sin(q1 - q2) + g/l sin(q2) = 0",
        ],
        ["2*q1_ddot + q2_ddot*cos(q1 - q2) + 2*g/l*sin(q1)", r1],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "2 q1_ddot + q2_ddot cos(q1 - q2) + q2_dot^2 sin(q1 - q2) + 2 g/l sin(q1) = 0",
            "q2_ddot + q1_ddot cos(q1 - q2) + q1_dot^2 sin(q1 - q2) + g/l sin(q2) = 0",
        ],
        [r0, "q2_ddot + q1_ddot*cos(q1 - q2) + q1_dot**2*sin(q1 - q2) + g/l*sin(q2)"],
        "wrong_sign",
    )
    s.bad("eom", [e0.replace("**", "^") + " = 0"], [e0], "too_few_equations")

    p1 = "2*m*l**2*q1_dot + m*l**2*q2_dot*cos(q1 - q2)"
    p2 = "m*l**2*q2_dot + m*l**2*q1_dot*cos(q1 - q2)"
    s.ok(
        "momenta",
        [
            "p_q1 = 2 m l^2 q1_dot + m l^2 q2_dot cos(q1 - q2)",
            "p_q2 = m l^2 q2_dot + m l^2 q1_dot cos(q1 - q2)",
        ],
        [f"p_q1 = {p1}", f"p_q2 = {p2}"],
        "plain",
    )
    s.ok(
        "momenta",
        [
            "p_q2 = m l^2 (q2_dot + q1_dot cos(q2 - q1))",
            "p_q1 = m l^2 (2 q1_dot + q2_dot cos(q2 - q1))",
        ],
        [f"p_q2 = {p2}", f"p_q1 = {p1}"],
        "other_order_factored",
    )
    s.bad(
        "momenta",
        [
            "p_q1 = m l^2 q1_dot + m l^2 q2_dot cos(q1 - q2)",
            "p_q2 = m l^2 q2_dot + m l^2 q1_dot cos(q1 - q2)",
        ],
        ["p_q1 = m*l**2*q1_dot + m*l**2*q2_dot*cos(q1 - q2)", f"p_q2 = {p2}"],
        "factor_2",
    )
    s.bad(
        "momenta",
        ["p_q1 = 2 m l^2 q1_dot", "p_q2 = m l^2 q2_dot"],
        ["p_q1 = 2*m*l**2*q1_dot", "p_q2 = m*l**2*q2_dot"],
        "missing_cross_term",
    )

    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "q2", ["q2"], "not_cyclic")

    s.ok("conserved", [f"{T} + {V}".replace("**", "^")], [f"{T} + {V}"], "energy")
    s.bad("conserved", [p1.replace("**", "^")], [p1], "not_conserved")
    s.bad(
        "conserved",
        [
            "m l^2 q1_dot^2 + 1/2 m l^2 q2_dot^2 - m l^2 q1_dot q2_dot cos(q1 - q2)"
            " - 2 m g l cos(q1) - m g l cos(q2)"
        ],
        [f"m*l**2*q1_dot**2 + m*l**2*q2_dot**2/2 - m*l**2*q1_dot*q2_dot*cos(q1 - q2) + {V}"],
        "not_conserved",
    )
    return s


def rolling_disc() -> System:
    s = System(
        "sympy_disc_on_incline",
        SYMPY + "sympy/physics/mechanics/tests/test_lagrange.py::test_disc_on_an_incline_plane "
        "(uniform disc, mass m, radius R, rolling without slipping down a plane inclined at "
        "alpha; y along the plane from the top, y = R theta; asserts y'' = 2 g sin(alpha)/3); "
        "here the constraint is used to keep y alone",
        "3*m*y_dot**2/4 - m*g*(l - y)*sin(alpha)",
        ["y"],
        {"m": P, "g": P, "l": P, "R": P, "alpha": "(0, pi/2)"},
    )
    s.ok(
        "lagrangian",
        "3/4 m y_dot^2 + m g y sin(alpha)",
        "3*m*y_dot**2/4 + m*g*y*sin(alpha)",
        "constant_dropped",
    )
    s.ok(
        "lagrangian",
        "1/2 m y_dot^2 + 1/2 (1/2 m R^2) (y_dot/R)^2 - m g (l - y) sin(alpha)",
        "m*y_dot**2/2 + (m*R**2/2)*(y_dot/R)**2/2 - m*g*(l - y)*sin(alpha)",
        "translation_plus_rotation",
    )
    s.ok(
        "lagrangian",
        r"\frac{3}{4} m \dot{y}^2 - m g (l - y)\sin\alpha",
        "3*m*y_dot**2/4 - m*g*(l - y)*sin(alpha)",
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m y_dot^2 + 1/2 m R^2 (y_dot/R)^2 + m g y sin(alpha)",
        "m*y_dot**2/2 + m*R**2*(y_dot/R)**2/2 + m*g*y*sin(alpha)",
        "wrong_moment_of_inertia",
    )
    s.bad(
        "lagrangian",
        "1/2 m y_dot^2 + m g y sin(alpha)",
        "m*y_dot**2/2 + m*g*y*sin(alpha)",
        "missing_term",
    )
    s.bad(
        "lagrangian",
        "3/4 m y_dot^2 - m g y sin(alpha)",
        "3*m*y_dot**2/4 - m*g*y*sin(alpha)",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "3/4 m y_dot^2 + m g y cos(alpha)",
        "3*m*y_dot**2/4 + m*g*y*cos(alpha)",
        "wrong_trig",
    )

    s.ok(
        "eom", ["y_ddot = 2/3 g sin(alpha)"], ["y_ddot - 2*g*sin(alpha)/3"], "as_asserted_by_sympy"
    )
    s.ok("eom", ["3/2 m ÿ = m g sin α"], ["3*m*y_ddot/2 - m*g*sin(alpha)"], "unicode")
    s.ok(
        "eom",
        [r"\frac{3}{2} m \ddot{y} - m g \sin\alpha = 0"],
        ["3*m*y_ddot/2 - m*g*sin(alpha)"],
        "latex",
    )
    s.ok("eom", ["3 y_ddot - 2 g sin(alpha) = 0"], ["3*y_ddot - 2*g*sin(alpha)"], "integers")
    s.bad("eom", ["y_ddot = g sin(alpha)"], ["y_ddot - g*sin(alpha)"], "missing_term")
    s.bad(
        "eom", ["y_ddot = 1/2 g sin(alpha)"], ["y_ddot - g*sin(alpha)/2"], "wrong_moment_of_inertia"
    )
    s.bad("eom", ["y_ddot = 2/3 g cos(alpha)"], ["y_ddot - 2*g*cos(alpha)/3"], "wrong_trig")

    s.ok("momenta", ["p_y = 3/2 m y_dot"], ["p_y = 3*m*y_dot/2"], "plain")
    s.bad("momenta", ["p_y = m y_dot"], ["p_y = m*y_dot"], "missing_term")
    s.bad("momenta", ["p_y = 3/4 m y_dot"], ["p_y = 3*m*y_dot/4"], "factor_2")
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "y", ["y"], "not_cyclic")
    s.ok(
        "conserved",
        ["3/4 m y_dot^2 - m g y sin(alpha)"],
        ["3*m*y_dot**2/4 - m*g*y*sin(alpha)"],
        "energy",
    )
    s.bad("conserved", ["3/2 m y_dot"], ["3*m*y_dot/2"], "not_conserved")

    e = s.expression("2*g*sin(alpha)/3", {"g": P, "alpha": "(0, pi/2)"}, "acceleration")
    e.ok("2/3 g sin(alpha)", "2*g*sin(alpha)/3")
    e.ok(r"\frac{2 g \sin\alpha}{3}", "2*g*sin(alpha)/3", "latex")
    e.ok("g sin(alpha)/(1 + 1/2)", "g*sin(alpha)/(1 + 1/2)", "unsimplified")
    e.bad("g sin(alpha)/(1 + 2/5)", "g*sin(alpha)/(1 + 2/5)", "wrong_moment_of_inertia")
    e.bad("g sin(alpha)/2", "g*sin(alpha)/2", "wrong_moment_of_inertia")
    return s


def atwood() -> System:
    s = System(
        "sympy_atwood_machine",
        SYMPY + "doc/src/tutorials/physics/mechanics/atwoods_machine_example.rst (masses m1, m2 "
        "over a fixed pulley; q the downward displacement of m1, P1 at z = -(h + q), P2 at "
        "z = -(h - q)); also Goldstein, Poole & Safko, Classical Mechanics 3rd ed., §1.6 "
        "(Atwood's machine)",
        "(m1 + m2)*q_dot**2/2 + (m1 - m2)*g*q",
        ["q"],
        {"m1": P, "m2": P, "g": P},
    )
    L = "(m1 + m2)*q_dot**2/2 + (m1 - m2)*g*q"
    s.ok("lagrangian", "1/2 (m1 + m2) q_dot^2 + (m1 - m2) g q", L, "plain")
    s.ok("lagrangian", "½ m₁ q̇² + ½ m₂ q̇² + m₁ g q − m₂ g q", L, "unicode_subscripts")
    s.ok("lagrangian", r"\frac{1}{2}(m_1+m_2)\dot{q}^2 + (m_1-m_2) g q", L, "latex")
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 - (m1 - m2) g q",
        "(m1 + m2)*q_dot**2/2 - (m1 - m2)*g*q",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 - m2) q_dot^2 + (m1 - m2) g q",
        "(m1 - m2)*q_dot**2/2 + (m1 - m2)*g*q",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 + (m1 + m2) g q",
        "(m1 + m2)*q_dot**2/2 + (m1 + m2)*g*q",
        "wrong_sign",
    )
    s.ok("eom", ["q_ddot = (m1 - m2) g/(m1 + m2)"], ["q_ddot - (m1 - m2)*g/(m1 + m2)"], "solved")
    s.ok(
        "eom",
        ["(m1 + m2) q_ddot = (m1 - m2) g"],
        ["(m1 + m2)*q_ddot - (m1 - m2)*g"],
        "multiplied_through",
    )
    s.ok("eom", ["(m₁ + m₂) q̈ − (m₁ − m₂) g = 0"], ["(m1 + m2)*q_ddot - (m1 - m2)*g"], "unicode")
    s.ok(
        "eom",
        [r"\ddot{q} = \frac{(m_1 - m_2) g}{m_1 + m_2}"],
        ["q_ddot - (m1 - m2)*g/(m1 + m2)"],
        "latex",
    )
    s.bad(
        "eom", ["q_ddot = (m2 - m1) g/(m1 + m2)"], ["q_ddot - (m2 - m1)*g/(m1 + m2)"], "wrong_sign"
    )
    s.bad("eom", ["q_ddot = (m1 - m2) g/m1"], ["q_ddot - (m1 - m2)*g/m1"], "missing_term")
    s.ok("momenta", ["p_q = (m1 + m2) q_dot"], ["p_q = (m1 + m2)*q_dot"])
    s.bad("momenta", ["p_q = m1 q_dot"], ["p_q = m1*q_dot"], "missing_term")
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "q", ["q"], "not_cyclic")
    s.ok(
        "conserved",
        ["1/2 (m1 + m2) q_dot^2 - (m1 - m2) g q"],
        ["(m1 + m2)*q_dot**2/2 - (m1 - m2)*g*q"],
        "energy",
    )
    s.bad("conserved", ["(m1 + m2) q_dot"], ["(m1 + m2)*q_dot"], "not_conserved")
    e = s.expression("(m1 - m2)*g/(m1 + m2)", {"m1": P, "m2": P, "g": P}, "acceleration")
    e.ok("g (m1 - m2)/(m1 + m2)", "g*(m1 - m2)/(m1 + m2)")
    e.ok(r"\frac{m_1 - m_2}{m_1 + m_2}\, g", "g*(m1 - m2)/(m1 + m2)", "latex")
    e.ok("g - 2 m2 g/(m1 + m2)", "g - 2*m2*g/(m1 + m2)", "split")
    e.bad("g (m1 - m2)/(m1 - m2)", "g*(m1 - m2)/(m1 - m2)")
    e.bad("g (m2 - m1)/(m1 + m2)", "g*(m2 - m1)/(m1 + m2)", "wrong_sign")
    return s


def duffing_pendulum() -> System:
    s = System(
        "sympy_duffing_pendulum",
        SYMPY + "doc/src/tutorials/physics/mechanics/duffing-example.rst (block of mass M on a "
        "Duffing spring k1 q1 + k2 q1^3 along the direction of gravity, pendulum of length l "
        "with a ball of mass m and radius r; its Lagrangian and, with c1 = 0, its equations); "
        "the conservative loads are written here as the potential "
        "-(M + m) g q1 - m g l cos(q2) + k1 q1^2/2 + k2 q1^4/4",
        "M*q1_dot**2/2 + m*r**2*q2_dot**2/5 + m*(l**2*q2_dot**2 - 2*l*sin(q2)*q1_dot*q2_dot"
        " + q1_dot**2)/2 + (M + m)*g*q1 + m*g*l*cos(q2) - k1*q1**2/2 - k2*q1**4/4",
        ["q1", "q2"],
        {"M": P, "m": P, "l": P, "r": P, "g": P, "k1": P, "k2": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "M q1_dot^2/2 + m r^2 q2_dot^2/5 + m (l^2 q2_dot^2 - 2 l sin(q2) q1_dot q2_dot"
        " + q1_dot^2)/2 + (M + m) g q1 + m g l cos(q2) - k1 q1^2/2 - k2 q1^4/4",
        L,
        "as_printed_by_sympy",
    )
    s.ok(
        "lagrangian",
        "1/2 (M + m) q1_dot^2 + (1/2 m l^2 + 1/5 m r^2) q2_dot^2 - m l sin(q2) q1_dot q2_dot"
        " + (M + m) g q1 + m g l cos(q2) - 1/2 k1 q1^2 - 1/4 k2 q1^4",
        L,
        "collected",
    )
    s.bad(
        "lagrangian",
        "1/2 (M + m) q1_dot^2 + (1/2 m l^2 + 1/5 m r^2) q2_dot^2"
        " + (M + m) g q1 + m g l cos(q2) - 1/2 k1 q1^2 - 1/4 k2 q1^4",
        "(M + m)*q1_dot**2/2 + (m*l**2/2 + m*r**2/5)*q2_dot**2 + (M + m)*g*q1"
        " + m*g*l*cos(q2) - k1*q1**2/2 - k2*q1**4/4",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 (M + m) q1_dot^2 + (1/2 m l^2 + 1/5 m r^2) q2_dot^2 - m l sin(q2) q1_dot q2_dot"
        " + (M + m) g q1 + m g l cos(q2) - 1/2 k1 q1^2 + 1/4 k2 q1^4",
        "(M + m)*q1_dot**2/2 + (m*l**2/2 + m*r**2/5)*q2_dot**2"
        " - m*l*sin(q2)*q1_dot*q2_dot + (M + m)*g*q1 + m*g*l*cos(q2) - k1*q1**2/2"
        " + k2*q1**4/4",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 (M + m) q1_dot^2 + 1/2 m l^2 q2_dot^2 - m l sin(q2) q1_dot q2_dot"
        " + (M + m) g q1 + m g l cos(q2) - 1/2 k1 q1^2 - 1/4 k2 q1^4",
        "(M + m)*q1_dot**2/2 + m*l**2*q2_dot**2/2 - m*l*sin(q2)*q1_dot*q2_dot"
        " + (M + m)*g*q1 + m*g*l*cos(q2) - k1*q1**2/2 - k2*q1**4/4",
        "wrong_moment_of_inertia",
    )
    e1 = (
        "-M*g + M*q1_ddot - g*m - m*(l*sin(q2)*q2_ddot + l*cos(q2)*q2_dot**2 - q1_ddot)"
        " + (k1 + k2*q1**2)*q1"
    )
    e2 = "m*(5*g*l*sin(q2) + 5*l**2*q2_ddot - 5*l*sin(q2)*q1_ddot + 2*r**2*q2_ddot)/5"
    s.ok(
        "eom",
        [e1.replace("**", "^") + " = 0", e2.replace("**", "^") + " = 0"],
        [e1, e2],
        "as_printed_by_sympy",
    )
    s.ok(
        "eom",
        [
            "(M + m) q1_ddot - m l sin(q2) q2_ddot - m l cos(q2) q2_dot^2 = (M + m) g - k1 q1"
            " - k2 q1^3",
            "(l^2 + 2/5 r^2) q2_ddot - l sin(q2) q1_ddot + g l sin(q2) = 0",
        ],
        [e1, "(l**2 + 2*r**2/5)*q2_ddot - l*sin(q2)*q1_ddot + g*l*sin(q2)"],
        "rearranged",
    )
    s.bad(
        "eom",
        [
            "(M + m) q1_ddot - m l cos(q2) q2_dot^2 = (M + m) g - k1 q1 - k2 q1^3",
            "(l^2 + 2/5 r^2) q2_ddot - l sin(q2) q1_ddot + g l sin(q2) = 0",
        ],
        [
            "(M + m)*q1_ddot - m*l*cos(q2)*q2_dot**2 - (M + m)*g + k1*q1 + k2*q1**3",
            "(l**2 + 2*r**2/5)*q2_ddot - l*sin(q2)*q1_ddot + g*l*sin(q2)",
        ],
        "missing_cross_term",
    )
    s.bad(
        "eom",
        [
            "(M + m) q1_ddot - m l sin(q2) q2_ddot - m l cos(q2) q2_dot^2 = (M + m) g - k1 q1"
            " - k2 q1^3",
            "l^2 q2_ddot - l sin(q2) q1_ddot + g l sin(q2) = 0",
        ],
        [e1, "l**2*q2_ddot - l*sin(q2)*q1_ddot + g*l*sin(q2)"],
        "wrong_moment_of_inertia",
    )
    s.ok(
        "momenta",
        [
            "p_q1 = (M + m) q1_dot - m l sin(q2) q2_dot",
            "p_q2 = (m l^2 + 2/5 m r^2) q2_dot - m l sin(q2) q1_dot",
        ],
        [
            "p_q1 = (M + m)*q1_dot - m*l*sin(q2)*q2_dot",
            "p_q2 = (m*l**2 + 2*m*r**2/5)*q2_dot - m*l*sin(q2)*q1_dot",
        ],
    )
    s.bad(
        "momenta",
        ["p_q1 = (M + m) q1_dot", "p_q2 = (m l^2 + 2/5 m r^2) q2_dot - m l sin(q2) q1_dot"],
        ["p_q1 = (M + m)*q1_dot", "p_q2 = (m*l**2 + 2*m*r**2/5)*q2_dot - m*l*sin(q2)*q1_dot"],
        "missing_cross_term",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "q2", ["q2"], "not_cyclic")
    h = (
        "(M + m)*q1_dot**2/2 + (m*l**2/2 + m*r**2/5)*q2_dot**2 - m*l*sin(q2)*q1_dot*q2_dot"
        " - (M + m)*g*q1 - m*g*l*cos(q2) + k1*q1**2/2 + k2*q1**4/4"
    )
    s.ok("conserved", [h.replace("**", "^")], [h], "energy")
    s.bad(
        "conserved",
        ["(M + m) q1_dot - m l sin(q2) q2_dot"],
        ["(M + m)*q1_dot - m*l*sin(q2)*q2_dot"],
        "not_conserved",
    )
    return s


def pendulum_on_cart() -> System:
    s = System(
        "sympy_inverted_pendulum_cart",
        SYMPY + "sympy/physics/mechanics/models.py::n_link_pendulum_on_cart(1) and "
        "tests/test_models.py::test_n_link_pendulum_on_cart_inputs (cart of mass m0 at q0, "
        "upright link of length l0 with a particle m1 at angle q1, gravity along -y; the test "
        "asserts the mass matrix [[m0+m1, -l0 m1 cos q1], [-l0 m1 cos q1, l0^2 m1]] and the "
        "forcing [-l0 m1 u1^2 sin q1, g l0 m1 sin q1] without the cart force)",
        "(m0 + m1)*q0_dot**2/2 - m1*l0*cos(q1)*q0_dot*q1_dot + m1*l0**2*q1_dot**2/2"
        " - m1*g*l0*cos(q1)",
        ["q0", "q1"],
        {"m0": P, "m1": P, "l0": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", L.replace("**", "^"), L, "plain")
    s.ok(
        "lagrangian",
        r"\frac{1}{2}(m_0 + m_1)\dot{q}_0^2 - m_1 l_0 \dot{q}_0\dot{q}_1 \cos q_1"
        r" + \frac{1}{2} m_1 l_0^2 \dot{q}_1^2 - m_1 g l_0\cos q_1",
        L,
        "latex",
    )
    s.ok(
        "lagrangian",
        "1/2 m0 q0_dot^2 + 1/2 m1 ((q0_dot - l0 cos(q1) q1_dot)^2 + (l0 sin(q1) q1_dot)^2)"
        " - m1 g l0 cos(q1)",
        "m0*q0_dot**2/2 + m1*((q0_dot - l0*cos(q1)*q1_dot)**2 + (l0*sin(q1)*q1_dot)**2)/2"
        " - m1*g*l0*cos(q1)",
        "from_velocities",
    )
    s.bad(
        "lagrangian",
        "1/2 (m0 + m1) q0_dot^2 - m1 l0 cos(q1) q0_dot q1_dot + 1/2 m1 l0^2 q1_dot^2"
        " + m1 g l0 cos(q1)",
        "(m0 + m1)*q0_dot**2/2 - m1*l0*cos(q1)*q0_dot*q1_dot + m1*l0**2*q1_dot**2/2"
        " + m1*g*l0*cos(q1)",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 (m0 + m1) q0_dot^2 + 1/2 m1 l0^2 q1_dot^2 - m1 g l0 cos(q1)",
        "(m0 + m1)*q0_dot**2/2 + m1*l0**2*q1_dot**2/2 - m1*g*l0*cos(q1)",
        "missing_cross_term",
    )
    r0 = "(m0 + m1)*q0_ddot - l0*m1*cos(q1)*q1_ddot + l0*m1*q1_dot**2*sin(q1)"
    r1 = "-l0*m1*cos(q1)*q0_ddot + l0**2*m1*q1_ddot - g*l0*m1*sin(q1)"
    s.ok(
        "eom",
        [
            "(m0 + m1) q0_ddot - l0 m1 cos(q1) q1_ddot = -l0 m1 q1_dot^2 sin(q1)",
            "-l0 m1 cos(q1) q0_ddot + l0^2 m1 q1_ddot = g l0 m1 sin(q1)",
        ],
        [r0, r1],
        "mass_matrix_and_forcing",
    )
    s.ok(
        "eom",
        [
            "d/dt((m0 + m1) q0_dot - m1 l0 cos(q1) q1_dot) = 0",
            "l0 q1_ddot - cos(q1) q0_ddot - g sin(q1) = 0",
        ],
        ["Dt((m0 + m1)*q0_dot - m1*l0*cos(q1)*q1_dot)", "l0*q1_ddot - cos(q1)*q0_ddot - g*sin(q1)"],
        "conservation_form",
    )
    s.bad(
        "eom",
        [
            "(m0 + m1) q0_ddot - l0 m1 cos(q1) q1_ddot = 0",
            "-l0 m1 cos(q1) q0_ddot + l0^2 m1 q1_ddot = g l0 m1 sin(q1)",
        ],
        ["(m0 + m1)*q0_ddot - l0*m1*cos(q1)*q1_ddot", r1],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "(m0 + m1) q0_ddot - l0 m1 cos(q1) q1_ddot = -l0 m1 q1_dot^2 sin(q1)",
            "-l0 m1 cos(q1) q0_ddot + l0^2 m1 q1_ddot = -g l0 m1 sin(q1)",
        ],
        [r0, "-l0*m1*cos(q1)*q0_ddot + l0**2*m1*q1_ddot + g*l0*m1*sin(q1)"],
        "sign_of_V",
    )
    p0 = "(m0 + m1)*q0_dot - m1*l0*cos(q1)*q1_dot"
    p1 = "m1*l0**2*q1_dot - m1*l0*cos(q1)*q0_dot"
    s.ok(
        "momenta",
        [f"p_q0 = {p0}".replace("**", "^"), f"p_q1 = {p1}".replace("**", "^")],
        [f"p_q0 = {p0}", f"p_q1 = {p1}"],
    )
    s.bad(
        "momenta",
        ["p_q0 = (m0 + m1) q0_dot", f"p_q1 = {p1}".replace("**", "^")],
        ["p_q0 = (m0 + m1)*q0_dot", f"p_q1 = {p1}"],
        "missing_cross_term",
    )
    s.ok("cyclic", "q0", ["q0"], "one")
    s.bad("cyclic", "none", [], "missed_cyclic")
    s.bad("cyclic", "q0, q1", ["q0", "q1"], "not_cyclic")
    h = (
        "(m0 + m1)*q0_dot**2/2 - m1*l0*cos(q1)*q0_dot*q1_dot + m1*l0**2*q1_dot**2/2"
        " + m1*g*l0*cos(q1)"
    )
    s.ok("conserved", [p0.replace("**", "^")], [p0], "momentum_of_cyclic")
    s.ok("conserved", [p0.replace("**", "^"), h.replace("**", "^")], [p0, h], "momentum_and_energy")
    s.bad("conserved", ["(m0 + m1) q0_dot"], ["(m0 + m1)*q0_dot"], "not_conserved")
    s.bad(
        "conserved",
        [p0.replace("**", "^"), f"({p0})/m0".replace("**", "^")],
        [p0, f"({p0})/m0"],
        "not_independent",
    )
    return s


def two_springs() -> System:
    s = System(
        "sympy_two_masses_two_springs",
        SYMPY + "sympy/physics/mechanics/tests/test_lagrange2.py::test_lagrange_2forces (two "
        "particles of mass m at q1, q2, potentials k q1^2/2 and k (q1 - q2)^2/2); the dampers of "
        "that test are left out, since a Lagrangian holds only the conservative part",
        "m*(q1_dot**2 + q2_dot**2)/2 - k*q1**2/2 - k*(q1 - q2)**2/2",
        ["q1", "q2"],
        {"m": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (q1_dot^2 + q2_dot^2) - 1/2 k q1^2 - 1/2 k (q1 - q2)^2", L)
    s.ok("lagrangian", "½ m q̇₁² + ½ m q̇₂² − k q₁² + k q₁ q₂ − ½ k q₂²", L, "unicode_expanded")
    s.bad(
        "lagrangian",
        "1/2 m (q1_dot^2 + q2_dot^2) + 1/2 k q1^2 + 1/2 k (q1 - q2)^2",
        "m*(q1_dot**2 + q2_dot**2)/2 + k*q1**2/2 + k*(q1 - q2)**2/2",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 m (q1_dot^2 + q2_dot^2) - 1/2 k q1^2 - k (q1 - q2)^2",
        "m*(q1_dot**2 + q2_dot**2)/2 - k*q1**2/2 - k*(q1 - q2)**2",
        "factor_2",
    )
    s.ok(
        "eom",
        ["m q1_ddot + k q1 + k (q1 - q2) = 0", "m q2_ddot + k (q2 - q1) = 0"],
        ["m*q1_ddot + k*q1 + k*(q1 - q2)", "m*q2_ddot + k*(q2 - q1)"],
    )
    s.ok(
        "eom",
        ["q1_ddot = (k q2 - 2 k q1)/m", "q2_ddot = k/m (q1 - q2)"],
        ["q1_ddot - (k*q2 - 2*k*q1)/m", "q2_ddot - k/m*(q1 - q2)"],
        "solved",
    )
    s.bad(
        "eom",
        ["m q1_ddot + k q1 + k (q1 - q2) = 0", "m q2_ddot + k (q1 - q2) = 0"],
        ["m*q1_ddot + k*q1 + k*(q1 - q2)", "m*q2_ddot + k*(q1 - q2)"],
        "wrong_sign",
    )
    s.bad(
        "eom",
        ["m q1_ddot + k q1 = 0", "m q2_ddot + k (q2 - q1) = 0"],
        ["m*q1_ddot + k*q1", "m*q2_ddot + k*(q2 - q1)"],
        "missing_term",
    )
    s.ok("momenta", ["p_q1 = m q1_dot", "p_q2 = m q2_dot"], ["p_q1 = m*q1_dot", "p_q2 = m*q2_dot"])
    s.bad("momenta", ["p_q1 = m q1_dot"], ["p_q1 = m*q1_dot"], "missing_term")
    s.ok("cyclic", "none", [], "none")
    s.ok(
        "conserved",
        ["1/2 m (q1_dot^2 + q2_dot^2) + 1/2 k q1^2 + 1/2 k (q1 - q2)^2"],
        ["m*(q1_dot**2 + q2_dot**2)/2 + k*q1**2/2 + k*(q1 - q2)**2/2"],
        "energy",
    )
    s.bad("conserved", ["m q1_dot + m q2_dot"], ["m*q1_dot + m*q2_dot"], "not_conserved")
    e = s.expression("sqrt((3 - sqrt(5))*k/(2*m))", {"k": P, "m": P}, "slow_mode_frequency")
    e.ok("sqrt(k/m) (sqrt(5) - 1)/2", "sqrt(k/m)*(sqrt(5) - 1)/2", "golden_ratio_form")
    e.ok("sqrt((3 - sqrt(5)) k/(2 m))", "sqrt((3 - sqrt(5))*k/(2*m))")
    e.bad("sqrt(k/m)", "sqrt(k/m)")
    e.bad("sqrt((3 + sqrt(5)) k/(2 m))", "sqrt((3 + sqrt(5))*k/(2*m))")
    return s


SYSTEMS = (
    simple_pendulum,
    double_pendulum,
    rolling_disc,
    atwood,
    duffing_pendulum,
    pendulum_on_cart,
    two_springs,
)
