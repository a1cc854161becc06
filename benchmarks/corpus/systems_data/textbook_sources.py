"""Systems from textbooks and from public problem statements and exams: Goldstein, Poole & Safko
(3rd ed., 2002), Thornton & Marion (5th ed.), Taylor (2005), Morin, MIT OCW 8.01SC, the
Cambridge Tripos, A. J. Brizard's lecture notes, and exercise statements as posted publicly
(each with its address). Where a source prints a result (an equation of motion, an acceleration,
an energy), that result is among the right answers."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System

GPS = "Goldstein, Poole & Safko, Classical Mechanics, 3rd ed. (2002), "
P = "positive"


def rotating_wire() -> System:
    s = System(
        "goldstein_bead_rotating_wire",
        GPS + "§1.6, third example (bead sliding on a uniformly rotating wire in a force-free "
        "space: r'' - r omega^2 = 0, solution A e^(omega t) + B e^(-omega t); the energy "
        "m(r'^2 + r^2 omega^2)/2 is not conserved)",
        "m*(r_dot**2 + r**2*omega**2)/2",
        {"r": "positive"},
        {"m": P, "omega": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (r_dot^2 + r^2 omega^2)", L)
    s.ok("lagrangian", "½ m ṙ² + ½ m ω² r²", L, "unicode")
    s.ok("lagrangian", r"\frac{m}{2}\left(\dot r^2 + \omega^2 r^2\right)", L, "latex")
    s.bad("lagrangian", "1/2 m r_dot^2", "m*r_dot**2/2", "missing_centripetal")
    s.bad(
        "lagrangian",
        "1/2 m r_dot^2 - 1/2 m omega^2 r^2",
        "m*r_dot**2/2 - m*omega**2*r**2/2",
        "wrong_sign",
    )
    s.bad(
        "lagrangian", "1/2 m r_dot^2 + m omega^2 r^2", "m*r_dot**2/2 + m*omega**2*r**2", "factor_2"
    )
    s.ok("eom", ["r_ddot - r omega^2 = 0"], ["r_ddot - r*omega**2"], "as_printed")
    s.ok("eom", ["m r̈ = m ω² r"], ["m*r_ddot - m*omega**2*r"], "unicode")
    s.bad("eom", ["r_ddot + omega^2 r = 0"], ["r_ddot + omega**2*r"], "wrong_sign")
    s.bad("eom", ["r_ddot = 0"], ["r_ddot"], "missing_centripetal")
    s.ok("momenta", ["p_r = m r_dot"], ["p_r = m*r_dot"])
    s.bad("momenta", ["p_r = m r^2 omega"], ["p_r = m*r**2*omega"], "wrong_moment_of_inertia")
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "r", ["r"], "not_cyclic")
    s.ok(
        "conserved",
        ["1/2 m (r_dot^2 - r^2 omega^2)"],
        ["m*(r_dot**2 - r**2*omega**2)/2"],
        "jacobi_integral",
    )
    s.bad(
        "conserved",
        ["1/2 m (r_dot^2 + r^2 omega^2)"],
        ["m*(r_dot**2 + r**2*omega**2)/2"],
        "not_conserved",
    )
    s.bad("conserved", ["m r^2 omega"], ["m*r**2*omega"], "not_conserved")
    e = s.expression("r0*cosh(omega*t)", {"r0": P, "omega": P, "t": "real"}, "released_at_rest")
    e.ok("r0 (exp(omega t) + exp(-omega t))/2", "r0*(exp(omega*t) + exp(-omega*t))/2")
    e.ok(
        r"\frac{r_0}{2}\left(e^{\omega t} + e^{-\omega t}\right)",
        "r0*(exp(omega*t) + exp(-omega*t))/2",
        "latex_exponentials",
    )
    e.bad("r0 cos(omega t)", "r0*cos(omega*t)", "wrong_sign")
    e.bad("r0 exp(omega t)", "r0*exp(omega*t)", "missing_term")
    return s


def table_and_hanging_mass() -> System:
    s = System(
        "goldstein_mass_through_table",
        GPS + "Chapter 1 Exercise 21 (Exercise 19 in the 2nd edition, as quoted at "
        "https://www.physicsforums.com/threads/mass-hanging-under-a-table-a-problem-from-"
        "goldstein.864036): m1 on a smooth table, a string through a hole to m2 hanging "
        "vertically; r the distance of m1 from the hole",
        "(m1 + m2)*r_dot**2/2 + m1*r**2*theta_dot**2/2 - m2*g*r",
        {"r": "positive", "theta": None},
        {"m1": P, "m2": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 (m1 + m2) r_dot^2 + 1/2 m1 r^2 theta_dot^2 - m2 g r", L)
    s.ok("lagrangian", "½ m₁ (ṙ² + r² θ̇²) + ½ m₂ ṙ² − m₂ g r", L, "unicode")
    s.ok(
        "lagrangian",
        r"\frac{1}{2}(m_1+m_2)\dot r^2 + \frac{1}{2}m_1 r^2\dot\theta^2 - m_2 g r",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m1 r_dot^2 + 1/2 m1 r^2 theta_dot^2 - m2 g r",
        "m1*r_dot**2/2 + m1*r**2*theta_dot**2/2 - m2*g*r",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) r_dot^2 + 1/2 m1 r^2 theta_dot^2 + m2 g r",
        "(m1 + m2)*r_dot**2/2 + m1*r**2*theta_dot**2/2 + m2*g*r",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) (r_dot^2 + r^2 theta_dot^2) - m2 g r",
        "(m1 + m2)*(r_dot**2 + r**2*theta_dot**2)/2 - m2*g*r",
        "wrong_moment_of_inertia",
    )
    er = "(m1 + m2)*r_ddot - m1*r*theta_dot**2 + m2*g"
    et = "m1*r**2*theta_ddot + 2*m1*r*r_dot*theta_dot"
    s.ok(
        "eom",
        [
            "(m1 + m2) r_ddot - m1 r theta_dot^2 + m2 g = 0",
            "m1 r^2 theta_ddot + 2 m1 r r_dot theta_dot = 0",
        ],
        [er, et],
    )
    s.ok(
        "eom",
        ["(m₁ + m₂) r̈ = m₁ r θ̇² − m₂ g", "r θ̈ + 2 ṙ θ̇ = 0"],
        [er, f"({et})/(m1*r)"],
        "unicode",
    )
    s.ok(
        "eom",
        ["(m1 + m2) r_ddot - m1 r theta_dot^2 + m2 g = 0", "d/dt(m1 r^2 theta_dot) = 0"],
        [er, "Dt(m1*r**2*theta_dot)"],
        "conservation_form",
    )
    s.bad(
        "eom",
        ["(m1 + m2) r_ddot + m2 g = 0", "m1 r^2 theta_ddot + 2 m1 r r_dot theta_dot = 0"],
        ["(m1 + m2)*r_ddot + m2*g", et],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "m1 r_ddot - m1 r theta_dot^2 + m2 g = 0",
            "m1 r^2 theta_ddot + 2 m1 r r_dot theta_dot = 0",
        ],
        ["m1*r_ddot - m1*r*theta_dot**2 + m2*g", et],
        "forgot_constraint",
    )
    s.ok(
        "momenta",
        ["p_r = (m1 + m2) r_dot", "p_theta = m1 r^2 theta_dot"],
        ["p_r = (m1 + m2)*r_dot", "p_theta = m1*r**2*theta_dot"],
    )
    s.bad(
        "momenta",
        ["p_r = m1 r_dot", "p_theta = m1 r^2 theta_dot"],
        ["p_r = m1*r_dot", "p_theta = m1*r**2*theta_dot"],
        "forgot_constraint",
    )
    s.ok("cyclic", "theta", ["theta"], "one")
    s.bad("cyclic", "r, theta", ["r", "theta"], "not_cyclic")
    E = "(m1 + m2)*r_dot**2/2 + m1*r**2*theta_dot**2/2 + m2*g*r"
    s.ok(
        "conserved",
        ["m1 r^2 theta_dot", E.replace("**", "^")],
        ["m1*r**2*theta_dot", E],
        "angular_momentum_and_energy",
    )
    s.ok(
        "conserved",
        ["1/2 (m1 + m2) r_dot^2 + (m1 r^2 theta_dot)^2/(2 m1 r^2) + m2 g r"],
        [E],
        "first_integral_with_l",
    )
    s.bad("conserved", ["(m1 + m2) r_dot"], ["(m1 + m2)*r_dot"], "not_conserved")
    e = s.expression(
        "sqrt(m2*g/(m1*r0))", {"m1": P, "m2": P, "g": P, "r0": P}, "circular_orbit_rate"
    )
    e.ok("sqrt(m2 g/(m1 r0))", "sqrt(m2*g/(m1*r0))")
    e.bad("sqrt(g/r0)", "sqrt(g/r0)", "missing_term")
    e.bad("sqrt((m1 + m2) g/(m1 r0))", "sqrt((m1 + m2)*g/(m1*r0))")
    return s


def quartic_lagrangian() -> System:
    s = System(
        "goldstein_quartic_lagrangian",
        GPS + "Chapter 1 Exercise 20 (L = m^2 x'^4/12 + m x'^2 V(x) - V^2(x); the equation of "
        "motion factors as (m x'^2/2 + V)(m x'' + V') = 0, as in the solution posted at "
        "https://pdfcoffee.com/goldstein-120-solution-pdf-free.html; also in D. Tong's "
        "Classical Dynamics example sheet), with V = k x^2/2 chosen here",
        "m**2*x_dot**4/12 + m*x_dot**2*k*x**2/2 - k**2*x**4/4",
        ["x"],
        {"m": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "m^2 x_dot^4/12 + m x_dot^2 (1/2 k x^2) - (1/2 k x^2)^2", L)
    s.ok(
        "lagrangian",
        r"\frac{m^2\dot x^4}{12} + \frac{1}{2} m k x^2\dot x^2 - \frac{k^2x^4}{4}",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "m^2 x_dot^4/12 + m x_dot^2 (1/2 k x^2) + (1/2 k x^2)^2",
        "m**2*x_dot**4/12 + m*x_dot**2*k*x**2/2 + k**2*x**4/4",
        "wrong_sign",
    )
    s.ok("eom", ["m x_ddot + k x = 0"], ["m*x_ddot + k*x"], "newtonian_factor")
    s.ok(
        "eom",
        ["(m x_dot^2/2 + k x^2/2)(m x_ddot + k x) = 0"],
        ["(m*x_dot**2/2 + k*x**2/2)*(m*x_ddot + k*x)"],
        "factored_as_printed",
    )
    s.ok(
        "eom",
        ["(m^2 x_dot^2 + m k x^2) x_ddot + m k x x_dot^2 + k^2 x^3 = 0"],
        ["(m**2*x_dot**2 + m*k*x**2)*x_ddot + m*k*x*x_dot**2 + k**2*x**3"],
        "expanded",
    )
    s.bad("eom", ["m x_ddot - k x = 0"], ["m*x_ddot - k*x"], "wrong_sign")
    s.bad(
        "eom",
        ["(m^2 x_dot^2 + m k x^2) x_ddot + 2 m k x x_dot^2 + k^2 x^3 = 0"],
        ["(m**2*x_dot**2 + m*k*x**2)*x_ddot + 2*m*k*x*x_dot**2 + k**2*x**3"],
        "missing_term",
    )
    s.ok(
        "momenta",
        ["p_x = m^2 x_dot^3/3 + m k x^2 x_dot"],
        ["p_x = m**2*x_dot**3/3 + m*k*x**2*x_dot"],
    )
    s.bad("momenta", ["p_x = m x_dot"], ["p_x = m*x_dot"], "other_lagrangian")
    s.ok("cyclic", "none", [], "none")
    s.ok(
        "conserved",
        ["m^2 x_dot^4/4 + 1/2 m k x^2 x_dot^2 + 1/4 k^2 x^4"],
        ["m**2*x_dot**4/4 + m*k*x**2*x_dot**2/2 + k**2*x**4/4"],
        "energy_function",
    )
    s.ok(
        "conserved", ["1/2 m x_dot^2 + 1/2 k x^2"], ["m*x_dot**2/2 + k*x**2/2"], "square_root_of_h"
    )
    s.bad("conserved", ["1/2 m x_dot^2 - 1/2 k x^2"], ["m*x_dot**2/2 - k*x**2/2"], "not_conserved")
    return s


def double_atwood() -> System:
    s = System(
        "tm_double_atwood",
        "Thornton & Marion, Classical Dynamics of Particles and Systems, 5th ed., Example 7.8 "
        "(double Atwood machine, x the distance of m1 below the fixed pulley, y that of m2 below "
        "the movable one; cf. Problem 7.37 as worked at https://ro.scribd.com/document/440762741);"
        " accelerations as printed in A. J. Brizard, An Introduction to Lagrangian Mechanics "
        "(lecture notes), §2.3.4 Compound Atwood machine, with m± = m2 ± m3",
        "m1*x_dot**2/2 + m2*(y_dot - x_dot)**2/2 + m3*(x_dot + y_dot)**2/2"
        " + (m1 - m2 - m3)*g*x + (m2 - m3)*g*y",
        ["x", "y"],
        {"m1": P, "m2": P, "m3": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 m1 x_dot^2 + 1/2 m2 (y_dot - x_dot)^2 + 1/2 m3 (x_dot + y_dot)^2"
        " + m1 g x + m2 g (y - x) - m3 g (x + y)",
        L,
        "heights_from_pulley",
    )
    s.ok(
        "lagrangian",
        "½ m₁ ẋ² + ½ m₂ (ẏ − ẋ)² + ½ m₃ (ẋ + ẏ)² + (m₁ − m₂ − m₃) g x + (m₂ − m₃) g y",
        L,
        "unicode",
    )
    s.bad(
        "lagrangian",
        "1/2 m1 x_dot^2 + 1/2 m2 y_dot^2 + 1/2 m3 y_dot^2 + (m1 - m2 - m3) g x + (m2 - m3) g y",
        "m1*x_dot**2/2 + m2*y_dot**2/2 + m3*y_dot**2/2 + (m1 - m2 - m3)*g*x + (m2 - m3)*g*y",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 m1 x_dot^2 + 1/2 m2 (y_dot - x_dot)^2 + 1/2 m3 (x_dot + y_dot)^2"
        " - (m1 - m2 - m3) g x - (m2 - m3) g y",
        "m1*x_dot**2/2 + m2*(y_dot - x_dot)**2/2 + m3*(x_dot + y_dot)**2/2"
        " - (m1 - m2 - m3)*g*x - (m2 - m3)*g*y",
        "sign_of_V",
    )
    ex = "(m1 + m2 + m3)*x_ddot + (m3 - m2)*y_ddot - (m1 - m2 - m3)*g"
    ey = "(m2 + m3)*y_ddot + (m3 - m2)*x_ddot - (m2 - m3)*g"
    s.ok(
        "eom",
        [
            "(m1 + m2 + m3) x_ddot + (m3 - m2) y_ddot = (m1 - m2 - m3) g",
            "(m2 + m3) y_ddot + (m3 - m2) x_ddot = (m2 - m3) g",
        ],
        [ex, ey],
    )
    s.ok(
        "eom",
        [
            "m1 x_ddot - m2 (y_ddot - x_ddot) + m3 (x_ddot + y_ddot) = (m1 - m2 - m3) g",
            "m2 (y_ddot - x_ddot) + m3 (x_ddot + y_ddot) = (m2 - m3) g",
        ],
        [ex, ey],
        "unexpanded",
    )
    s.ok(
        "eom",
        [
            "x_ddot = g (m1 (m2 + m3) - 4 m2 m3)/(m1 (m2 + m3) + 4 m2 m3)",
            "y_ddot = 2 g m1 (m2 - m3)/(m1 (m2 + m3) + 4 m2 m3)",
        ],
        [
            "x_ddot - g*(m1*(m2 + m3) - 4*m2*m3)/(m1*(m2 + m3) + 4*m2*m3)",
            "y_ddot - 2*g*m1*(m2 - m3)/(m1*(m2 + m3) + 4*m2*m3)",
        ],
        "solved_as_in_brizard",
    )
    s.bad(
        "eom",
        ["(m1 + m2 + m3) x_ddot = (m1 - m2 - m3) g", "(m2 + m3) y_ddot = (m2 - m3) g"],
        ["(m1 + m2 + m3)*x_ddot - (m1 - m2 - m3)*g", "(m2 + m3)*y_ddot - (m2 - m3)*g"],
        "missing_cross_term",
    )
    s.bad(
        "eom",
        [
            "(m1 + m2 + m3) x_ddot + (m3 - m2) y_ddot = (m1 - m2 - m3) g",
            "(m2 + m3) y_ddot + (m2 - m3) x_ddot = (m2 - m3) g",
        ],
        [ex, "(m2 + m3)*y_ddot + (m2 - m3)*x_ddot - (m2 - m3)*g"],
        "wrong_sign",
    )
    s.ok(
        "momenta",
        [
            "p_x = m1 x_dot - m2 (y_dot - x_dot) + m3 (x_dot + y_dot)",
            "p_y = m2 (y_dot - x_dot) + m3 (x_dot + y_dot)",
        ],
        [
            "p_x = m1*x_dot - m2*(y_dot - x_dot) + m3*(x_dot + y_dot)",
            "p_y = m2*(y_dot - x_dot) + m3*(x_dot + y_dot)",
        ],
    )
    s.bad(
        "momenta",
        ["p_x = m1 x_dot", "p_y = (m2 + m3) y_dot"],
        ["p_x = m1*x_dot", "p_y = (m2 + m3)*y_dot"],
        "missing_cross_term",
    )
    s.ok("cyclic", "none", [], "none")
    s.ok(
        "conserved",
        [
            "1/2 m1 x_dot^2 + 1/2 m2 (y_dot - x_dot)^2 + 1/2 m3 (x_dot + y_dot)^2"
            " - (m1 - m2 - m3) g x - (m2 - m3) g y"
        ],
        [
            "m1*x_dot**2/2 + m2*(y_dot - x_dot)**2/2 + m3*(x_dot + y_dot)**2/2"
            " - (m1 - m2 - m3)*g*x - (m2 - m3)*g*y"
        ],
        "energy",
    )
    s.bad(
        "conserved",
        ["m2 (y_dot - x_dot) + m3 (x_dot + y_dot)"],
        ["m2*(y_dot - x_dot) + m3*(x_dot + y_dot)"],
        "not_conserved",
    )
    params = {"m1": P, "m2": P, "m3": P, "g": P}
    e = s.expression(
        "g*(m1*(m2 + m3) - 4*m2*m3)/(m1*(m2 + m3) + 4*m2*m3)", params, "acceleration_m1"
    )
    e.ok(
        "g (m1 (m2 + m3) - ((m2 + m3)^2 - (m2 - m3)^2))/(m1 (m2 + m3) + ((m2 + m3)^2"
        " - (m2 - m3)^2))",
        "g*(m1*(m2 + m3) - ((m2 + m3)**2 - (m2 - m3)**2))/(m1*(m2 + m3)"
        " + ((m2 + m3)**2 - (m2 - m3)**2))",
        "as_printed_with_m_plus_minus",
    )
    e.ok(
        "g (m1 m2 + m1 m3 - 4 m2 m3)/(m1 m2 + m1 m3 + 4 m2 m3)",
        "g*(m1*m2 + m1*m3 - 4*m2*m3)/(m1*m2 + m1*m3 + 4*m2*m3)",
        "expanded",
    )
    e.bad("g (m1 - m2 - m3)/(m1 + m2 + m3)", "g*(m1 - m2 - m3)/(m1 + m2 + m3)", "forgot_constraint")
    e.bad(
        "g (m1 (m2 + m3) - 2 m2 m3)/(m1 (m2 + m3) + 2 m2 m3)",
        "g*(m1*(m2 + m3) - 2*m2*m3)/(m1*(m2 + m3) + 2*m2*m3)",
        "factor_2",
    )
    f = s.expression("2*g*m1*(m2 - m3)/(m1*(m2 + m3) + 4*m2*m3)", params, "acceleration_y")
    f.ok(
        r"\frac{2 g m_1 (m_2 - m_3)}{m_1(m_2+m_3) + 4 m_2 m_3}",
        "2*g*m1*(m2 - m3)/(m1*(m2 + m3) + 4*m2*m3)",
        "latex",
    )
    f.bad("g (m2 - m3)/(m2 + m3)", "g*(m2 - m3)/(m2 + m3)", "forgot_constraint")
    return s


def cart_spring_pendulum() -> System:
    s = System(
        "taylor_cart_spring_pendulum",
        "J. R. Taylor, Classical Mechanics (2005), Problem 7.31 (cart of mass M on a spring k "
        "along a horizontal track, a pendulum of length l and mass m hanging from it; as "
        "identified at https://github.com/wwaldron/Physics-TeachingResources, "
        "SpringCartWithPendulum)",
        "(M + m)*x_dot**2/2 + m*l*x_dot*phi_dot*cos(phi) + m*l**2*phi_dot**2/2 - k*x**2/2"
        " + m*g*l*cos(phi)",
        ["x", "phi"],
        {"M": P, "m": P, "l": P, "k": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 (M + m) x_dot^2 + m l x_dot phi_dot cos(phi) + 1/2 m l^2 phi_dot^2 - 1/2 k x^2"
        " + m g l cos(phi)",
        L,
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2}M\dot x^2 + \frac{1}{2}m\left((\dot x + l\dot\phi\cos\phi)^2"
        r" + (l\dot\phi\sin\phi)^2\right) - \frac{1}{2}k x^2 + m g l\cos\phi",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 (M + m) x_dot^2 + 1/2 m l^2 phi_dot^2 - 1/2 k x^2 + m g l cos(phi)",
        "(M + m)*x_dot**2/2 + m*l**2*phi_dot**2/2 - k*x**2/2 + m*g*l*cos(phi)",
        "missing_cross_term",
    )
    s.bad(
        "lagrangian",
        "1/2 (M + m) x_dot^2 + m l x_dot phi_dot cos(phi) + 1/2 m l^2 phi_dot^2 + 1/2 k x^2"
        " + m g l cos(phi)",
        "(M + m)*x_dot**2/2 + m*l*x_dot*phi_dot*cos(phi) + m*l**2*phi_dot**2/2 + k*x**2/2"
        " + m*g*l*cos(phi)",
        "sign_of_V",
    )
    ex = "(M + m)*x_ddot + m*l*(phi_ddot*cos(phi) - phi_dot**2*sin(phi)) + k*x"
    ep = "l*phi_ddot + x_ddot*cos(phi) + g*sin(phi)"
    s.ok(
        "eom",
        [
            "(M + m) x_ddot + m l (phi_ddot cos(phi) - phi_dot^2 sin(phi)) + k x = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        [ex, ep],
    )
    s.ok(
        "eom",
        ["(M + m) ẍ + m l φ̈ cos φ = m l φ̇² sin φ − k x", "m l² φ̈ + m l ẍ cos φ = −m g l sin φ"],
        [ex, f"m*l*({ep})"],
        "unicode",
    )
    s.bad(
        "eom",
        [
            "(M + m) x_ddot + m l phi_ddot cos(phi) + k x = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        ["(M + m)*x_ddot + m*l*phi_ddot*cos(phi) + k*x", ep],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        [
            "(M + m) x_ddot + m l (phi_ddot cos(phi) - phi_dot^2 sin(phi)) = 0",
            "l phi_ddot + x_ddot cos(phi) + g sin(phi) = 0",
        ],
        ["(M + m)*x_ddot + m*l*(phi_ddot*cos(phi) - phi_dot**2*sin(phi))", ep],
        "missing_term",
    )
    s.ok(
        "momenta",
        [
            "p_x = (M + m) x_dot + m l phi_dot cos(phi)",
            "p_phi = m l^2 phi_dot + m l x_dot cos(phi)",
        ],
        [
            "p_x = (M + m)*x_dot + m*l*phi_dot*cos(phi)",
            "p_phi = m*l**2*phi_dot + m*l*x_dot*cos(phi)",
        ],
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "x", ["x"], "not_cyclic")
    h = (
        "(M + m)*x_dot**2/2 + m*l*x_dot*phi_dot*cos(phi) + m*l**2*phi_dot**2/2 + k*x**2/2"
        " - m*g*l*cos(phi)"
    )
    s.ok("conserved", [h.replace("**", "^")], [h], "energy")
    s.bad(
        "conserved",
        ["(M + m) x_dot + m l phi_dot cos(phi)"],
        ["(M + m)*x_dot + m*l*phi_dot*cos(phi)"],
        "not_conserved",
    )
    return s


def massive_pulley() -> System:
    s = System(
        "mit_atwood_massive_pulley",
        "MIT OpenCourseWare 8.01SC Classical Mechanics (Fall 2016), Week 10, 31.4 Worked "
        "Example - Atwood Machine (uniform pulley of radius R and moment of inertia I_A, string "
        "without slipping; https://ocw.mit.edu/courses/8-01sc-classical-mechanics-fall-2016/"
        "pages/week-10-rotational-motion/31-4-worked-example-atwood-machine/); q the downward "
        "displacement of m1; for a uniform disc pulley of mass m_p the acceleration "
        "g (M - m)/(M + m + m_p/2) of http://physics.bu.edu/~duffy/semester1/c14_atwood2.html",
        "(m1 + m2 + I_A/R**2)*q_dot**2/2 + (m1 - m2)*g*q",
        ["q"],
        {"m1": P, "m2": P, "I_A": P, "R": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 + 1/2 I_A (q_dot/R)^2 + (m1 - m2) g q",
        L,
        "rolling_constraint_used",
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2}\left(m_1 + m_2 + \frac{I_A}{R^2}\right)\dot q^2 + (m_1-m_2)gq",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 + (m1 - m2) g q",
        "(m1 + m2)*q_dot**2/2 + (m1 - m2)*g*q",
        "missing_term",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 + 1/2 I_A q_dot^2 + (m1 - m2) g q",
        "(m1 + m2)*q_dot**2/2 + I_A*q_dot**2/2 + (m1 - m2)*g*q",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) q_dot^2 + 1/2 I_A R^2 q_dot^2 + (m1 - m2) g q",
        "(m1 + m2)*q_dot**2/2 + I_A*R**2*q_dot**2/2 + (m1 - m2)*g*q",
        "wrong_moment_of_inertia",
    )
    s.ok(
        "eom",
        ["(m1 + m2 + I_A/R^2) q_ddot = (m1 - m2) g"],
        ["(m1 + m2 + I_A/R**2)*q_ddot - (m1 - m2)*g"],
    )
    s.ok(
        "eom",
        ["((m1 + m2) R^2 + I_A) q_ddot = (m1 - m2) g R^2"],
        ["((m1 + m2)*R**2 + I_A)*q_ddot - (m1 - m2)*g*R**2"],
        "cleared_denominator",
    )
    s.bad(
        "eom",
        ["(m1 + m2 + I_A R^2) q_ddot = (m1 - m2) g"],
        ["(m1 + m2 + I_A*R**2)*q_ddot - (m1 - m2)*g"],
        "wrong_moment_of_inertia",
    )
    s.ok("momenta", ["p_q = (m1 + m2 + I_A/R^2) q_dot"], ["p_q = (m1 + m2 + I_A/R**2)*q_dot"])
    s.bad("momenta", ["p_q = (m1 + m2) q_dot"], ["p_q = (m1 + m2)*q_dot"], "missing_term")
    s.ok(
        "conserved",
        ["1/2 (m1 + m2 + I_A/R^2) q_dot^2 - (m1 - m2) g q"],
        ["(m1 + m2 + I_A/R**2)*q_dot**2/2 - (m1 - m2)*g*q"],
        "energy",
    )
    e = s.expression(
        "(m1 - m2)*g/(m1 + m2 + I_A/R**2)",
        {"m1": P, "m2": P, "I_A": P, "R": P, "g": P},
        "acceleration",
    )
    e.ok("(m1 - m2) g R^2/((m1 + m2) R^2 + I_A)", "(m1 - m2)*g*R**2/((m1 + m2)*R**2 + I_A)")
    e.bad("(m1 - m2) g/(m1 + m2)", "(m1 - m2)*g/(m1 + m2)", "missing_term")
    e.bad(
        "(m1 - m2) g/(m1 + m2 + I_A R^2)",
        "(m1 - m2)*g/(m1 + m2 + I_A*R**2)",
        "wrong_moment_of_inertia",
    )
    f = s.expression(
        "g*(M - m)/(M + m + m_p/2)", {"M": P, "m": P, "m_p": P, "g": P}, "disc_pulley_acceleration"
    )
    f.ok("2 g (M - m)/(2 M + 2 m + m_p)", "2*g*(M - m)/(2*M + 2*m + m_p)")
    f.ok(r"\frac{g(M-m)}{M+m+\frac{1}{2}m_p}", "g*(M - m)/(M + m + m_p/2)", "latex")
    f.bad("g (M - m)/(M + m + m_p)", "g*(M - m)/(M + m + m_p)", "wrong_moment_of_inertia")
    return s


def rotating_parabola() -> System:
    s = System(
        "bead_rotating_parabola",
        "Textbook exercise (bead on a wire bent into the parabola z = k rho^2 spun at constant "
        "omega about its vertical axis) with the book's equation of motion "
        "rho omega^2 - 4 k^2 rho rho'^2 - 2 k g rho = rho''(1 + 4 k^2 rho^2), as quoted at "
        "https://physicsforums.com/threads/using-lagrange-to-solve-rotating-parabolic-motion-"
        "and-equilibrium.741576; the critical omega^2 = 2 g k as in the solution at "
        "http://www.jkwiens.com/2007/12/13/question-a-bead-sliding-on-a-rotating-parabola-2/",
        "m*(rho_dot**2 + rho**2*omega**2 + 4*k**2*rho**2*rho_dot**2)/2 - m*g*k*rho**2",
        {"rho": "positive"},
        {"m": P, "k": P, "omega": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m ((1 + 4 k^2 rho^2) rho_dot^2 + rho^2 omega^2) - m g k rho^2", L)
    s.ok("lagrangian", "½ m (ρ̇² + ρ² ω² + 4 k² ρ² ρ̇²) − m g k ρ²", L, "unicode")
    s.bad(
        "lagrangian",
        "1/2 m (rho_dot^2 + rho^2 omega^2) - m g k rho^2",
        "m*(rho_dot**2 + rho**2*omega**2)/2 - m*g*k*rho**2",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 m (rho_dot^2 + 4 k^2 rho^2 rho_dot^2) - m g k rho^2",
        "m*(rho_dot**2 + 4*k**2*rho**2*rho_dot**2)/2 - m*g*k*rho**2",
        "missing_centripetal",
    )
    s.bad(
        "lagrangian",
        "1/2 m (rho_dot^2 + rho^2 omega^2 + 2 k rho rho_dot^2) - m g k rho^2",
        "m*(rho_dot**2 + rho**2*omega**2 + 2*k*rho*rho_dot**2)/2 - m*g*k*rho**2",
        "wrong_chain_rule",
    )
    eq = "rho*omega**2 - 4*k**2*rho*rho_dot**2 - 2*k*g*rho - rho_ddot*(1 + 4*k**2*rho**2)"
    s.ok(
        "eom",
        ["rho omega^2 - 4 k^2 rho rho_dot^2 - 2 k g rho = rho_ddot (1 + 4 k^2 rho^2)"],
        [eq],
        "as_printed",
    )
    s.ok(
        "eom",
        [r"(1 + 4k^2\rho^2)\ddot\rho + 4k^2\rho\dot\rho^2 + (2gk - \omega^2)\rho = 0"],
        [f"-({eq})"],
        "latex",
    )
    s.bad(
        "eom",
        ["rho omega^2 - 2 k g rho = rho_ddot (1 + 4 k^2 rho^2)"],
        ["rho*omega**2 - 2*k*g*rho - rho_ddot*(1 + 4*k**2*rho**2)"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        ["rho omega^2 - 4 k^2 rho rho_dot^2 - 2 k g rho = rho_ddot"],
        ["rho*omega**2 - 4*k**2*rho*rho_dot**2 - 2*k*g*rho - rho_ddot"],
        "missing_term",
    )
    s.ok(
        "momenta",
        ["p_rho = m (1 + 4 k^2 rho^2) rho_dot"],
        ["p_rho = m*(1 + 4*k**2*rho**2)*rho_dot"],
    )
    s.ok("cyclic", "none", [], "none")
    h = "m*((1 + 4*k**2*rho**2)*rho_dot**2 - rho**2*omega**2)/2 + m*g*k*rho**2"
    s.ok("conserved", [h.replace("**", "^")], [h], "jacobi_integral")
    s.bad(
        "conserved",
        ["1/2 m ((1 + 4 k^2 rho^2) rho_dot^2 + rho^2 omega^2) + m g k rho^2"],
        ["m*((1 + 4*k**2*rho**2)*rho_dot**2 + rho**2*omega**2)/2 + m*g*k*rho**2"],
        "not_conserved",
    )
    e = s.expression("sqrt(2*g*k)", {"g": P, "k": P}, "critical_omega")
    e.ok("sqrt(2 k g)", "sqrt(2*k*g)")
    e.bad("sqrt(g k)", "sqrt(g*k)", "factor_2")
    e.bad("sqrt(2 g/k)", "sqrt(2*g/k)")
    return s


def cone() -> System:
    s = System(
        "particle_inside_cone",
        "Textbook exercise (particle on the inside of a smooth cone of half-angle alpha, axis "
        "vertical, apex at the origin; cylindrical coordinates, z = r cot(alpha) eliminated; "
        "U_eff(r) = m g r cot(alpha) + l^2/(2 m r^2)) as stated at "
        "http://www.chegg.com/homework-help/questions-and-answers/a-particle-of-mass-m-is-"
        "constrained-to-move-on-the-inside-surface-of-a-smooth-cone-of-half-q1690623",
        "m*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)/2 - m*g*r*cot(alpha)",
        {"r": "positive", "phi": None},
        {"m": P, "g": P, "alpha": "(0, pi/2)"},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 m (r_dot^2 (1 + cot(alpha)^2) + r^2 phi_dot^2) - m g r cot(alpha)",
        L,
        "with_z_dot",
    )
    s.ok("lagrangian", "½ m (ṙ² csc²α + r² φ̇²) − m g r cot α", L, "unicode_csc")
    s.ok(
        "lagrangian",
        r"\frac{m}{2}\left(\frac{\dot r^2}{\sin^2\alpha} + r^2\dot\phi^2\right)"
        r" - \frac{m g r\cos\alpha}{\sin\alpha}",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 phi_dot^2) - m g r cot(alpha)",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 - m*g*r*cot(alpha)",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2/sin(alpha)^2 + r^2 phi_dot^2) - m g r tan(alpha)",
        "m*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)/2 - m*g*r*tan(alpha)",
        "wrong_trig",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2/sin(alpha)^2 + r^2 phi_dot^2) + m g r cot(alpha)",
        "m*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)/2 + m*g*r*cot(alpha)",
        "sign_of_V",
    )
    er = "r_ddot/sin(alpha)**2 - r*phi_dot**2 + g*cot(alpha)"
    ep = "r**2*phi_ddot + 2*r*r_dot*phi_dot"
    s.ok(
        "eom",
        [
            "r_ddot/sin(alpha)^2 - r phi_dot^2 + g cot(alpha) = 0",
            "r^2 phi_ddot + 2 r r_dot phi_dot = 0",
        ],
        [er, ep],
    )
    s.ok(
        "eom",
        ["r̈ = (r φ̇² − g cot α) sin²α", "d/dt(m r² φ̇) = 0"],
        [f"sin(alpha)**2*({er})", f"m*({ep})"],
        "unicode_conservation_form",
    )
    s.bad(
        "eom",
        ["r_ddot - r phi_dot^2 + g cot(alpha) = 0", "r^2 phi_ddot + 2 r r_dot phi_dot = 0"],
        ["r_ddot - r*phi_dot**2 + g*cot(alpha)", ep],
        "forgot_constraint",
    )
    s.bad(
        "eom",
        ["r_ddot/sin(alpha)^2 + g cot(alpha) = 0", "r^2 phi_ddot + 2 r r_dot phi_dot = 0"],
        ["r_ddot/sin(alpha)**2 + g*cot(alpha)", ep],
        "missing_centripetal",
    )
    s.ok(
        "momenta",
        ["p_r = m r_dot/sin(alpha)^2", "p_phi = m r^2 phi_dot"],
        ["p_r = m*r_dot/sin(alpha)**2", "p_phi = m*r**2*phi_dot"],
    )
    s.bad(
        "momenta",
        ["p_r = m r_dot", "p_phi = m r^2 phi_dot"],
        ["p_r = m*r_dot", "p_phi = m*r**2*phi_dot"],
        "forgot_constraint",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "none", [], "missed_cyclic")
    E = "m*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)/2 + m*g*r*cot(alpha)"
    s.ok(
        "conserved",
        ["m r^2 phi_dot", E.replace("**", "^")],
        ["m*r**2*phi_dot", E],
        "angular_momentum_and_energy",
    )
    s.ok(
        "conserved",
        ["1/2 m r_dot^2/sin(alpha)^2 + (m r^2 phi_dot)^2/(2 m r^2) + m g r cot(alpha)"],
        [E],
        "effective_potential_form",
    )
    s.bad("conserved", ["m r phi_dot"], ["m*r*phi_dot"], "not_conserved")
    e = s.expression(
        "sqrt(g*cot(alpha)/r0)", {"g": P, "alpha": "(0, pi/2)", "r0": P}, "circular_orbit_rate"
    )
    e.ok("sqrt(g/(r0 tan(alpha)))", "sqrt(g/(r0*tan(alpha)))")
    e.bad("sqrt(g tan(alpha)/r0)", "sqrt(g*tan(alpha)/r0)", "wrong_trig")
    e.bad("sqrt(g/r0)", "sqrt(g/r0)", "missing_term")
    return s


def spring_pendulum() -> System:
    s = System(
        "spring_pendulum",
        "Thornton & Marion-style exercise as stated at https://brainmass.com/engineering/"
        "mechanical-engineering/equation-motion-lagrange-method-107726 (a pendulum: mass m on "
        "a massless spring of unstretched length b and constant k, swinging in a plane); r the "
        "length of the spring, theta from the downward vertical",
        "m*(r_dot**2 + r**2*theta_dot**2)/2 + m*g*r*cos(theta) - k*(r - b)**2/2",
        {"r": "positive", "theta": None},
        {"m": P, "g": P, "k": P, "b": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (r_dot^2 + r^2 theta_dot^2) + m g r cos(theta) - 1/2 k (r - b)^2", L)
    s.ok("lagrangian", "½ m (ṙ² + r² θ̇²) + m g r cos θ − ½ k (r − b)²", L, "unicode")
    s.ok(
        "lagrangian",
        r"\frac{1}{2}m\left(\dot r^2 + r^2\dot\theta^2\right) + m g r\cos\theta"
        r" - \frac{1}{2}k(r-b)^2",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 theta_dot^2) + m g r cos(theta) - 1/2 k r^2",
        "m*(r_dot**2 + r**2*theta_dot**2)/2 + m*g*r*cos(theta) - k*r**2/2",
        "missing_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + b^2 theta_dot^2) + m g r cos(theta) - 1/2 k (r - b)^2",
        "m*(r_dot**2 + b**2*theta_dot**2)/2 + m*g*r*cos(theta) - k*(r - b)**2/2",
        "wrong_moment_of_inertia",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 theta_dot^2) - m g r cos(theta) - 1/2 k (r - b)^2",
        "m*(r_dot**2 + r**2*theta_dot**2)/2 - m*g*r*cos(theta) - k*(r - b)**2/2",
        "sign_of_V",
    )
    er = "m*r_ddot - m*r*theta_dot**2 - m*g*cos(theta) + k*(r - b)"
    et = "m*r**2*theta_ddot + 2*m*r*r_dot*theta_dot + m*g*r*sin(theta)"
    s.ok(
        "eom",
        [
            "m r_ddot - m r theta_dot^2 - m g cos(theta) + k (r - b) = 0",
            "m r^2 theta_ddot + 2 m r r_dot theta_dot + m g r sin(theta) = 0",
        ],
        [er, et],
    )
    s.ok(
        "eom",
        ["r̈ = r θ̇² + g cos θ − (k/m)(r − b)", "r θ̈ + 2 ṙ θ̇ + g sin θ = 0"],
        [f"({er})/m", f"({et})/(m*r)"],
        "unicode_solved",
    )
    s.bad(
        "eom",
        [
            "m r_ddot - m g cos(theta) + k (r - b) = 0",
            "m r^2 theta_ddot + 2 m r r_dot theta_dot + m g r sin(theta) = 0",
        ],
        ["m*r_ddot - m*g*cos(theta) + k*(r - b)", et],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "m r_ddot - m r theta_dot^2 - m g cos(theta) + k (r - b) = 0",
            "m r^2 theta_ddot + m g r sin(theta) = 0",
        ],
        [er, "m*r**2*theta_ddot + m*g*r*sin(theta)"],
        "wrong_chain_rule",
    )
    s.ok(
        "momenta",
        ["p_r = m r_dot", "p_theta = m r^2 theta_dot"],
        ["p_r = m*r_dot", "p_theta = m*r**2*theta_dot"],
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "theta", ["theta"], "not_cyclic")
    E = "m*(r_dot**2 + r**2*theta_dot**2)/2 - m*g*r*cos(theta) + k*(r - b)**2/2"
    s.ok("conserved", [E.replace("**", "^")], [E], "energy")
    s.bad("conserved", ["m r^2 theta_dot"], ["m*r**2*theta_dot"], "not_conserved")
    e = s.expression("b + m*g/k", {"b": P, "m": P, "g": P, "k": P}, "equilibrium_length")
    e.ok("(k b + m g)/k", "(k*b + m*g)/k")
    e.bad("b - m g/k", "b - m*g/k", "wrong_sign")
    e.bad("m g/k", "m*g/k", "missing_term")
    return s


def coupled_pendula() -> System:
    s = System(
        "coupled_pendula_small",
        "Two identical pendula (mass m, length l) joined by a spring k, small oscillations, "
        "with the Lagrangian L = m(x1'^2 + x2'^2)/2 - m g (x1^2 + x2^2)/(2 l) - k (x2 - x1)^2/2 "
        "as printed at https://alkaline-monitor-a80.notion.site/Normal-Modes-70442693a30b45f7a3e"
        "29d89c9d44c46 (the exercise of https://tutorsglobe.com/question/two-pendula-of-equal-"
        "length-b-and-equal-masses-m-connected-5611041.aspx); normal frequencies sqrt(g/l) and "
        "sqrt(g/l + 2k/m)",
        "m*(x1_dot**2 + x2_dot**2)/2 - m*g*(x1**2 + x2**2)/(2*l) - k*(x2 - x1)**2/2",
        ["x1", "x2"],
        {"m": P, "g": P, "l": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian", "1/2 m (x1_dot^2 + x2_dot^2) - m g/(2 l) (x1^2 + x2^2) - 1/2 k (x2 - x1)^2", L
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2}m(\dot x_1^2+\dot x_2^2) - \frac{mg}{2l}(x_1^2+x_2^2)"
        r" - \frac{1}{2}k(x_2-x_1)^2",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x1_dot^2 + x2_dot^2) - m g/(2 l) (x1^2 + x2^2) - 1/2 k (x2 + x1)^2",
        "m*(x1_dot**2 + x2_dot**2)/2 - m*g*(x1**2 + x2**2)/(2*l) - k*(x2 + x1)**2/2",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x1_dot^2 + x2_dot^2) - 1/2 k (x2 - x1)^2",
        "m*(x1_dot**2 + x2_dot**2)/2 - k*(x2 - x1)**2/2",
        "missing_term",
    )
    e1 = "x1_ddot + (g/l + k/m)*x1 - k/m*x2"
    e2 = "x2_ddot + (g/l + k/m)*x2 - k/m*x1"
    s.ok(
        "eom",
        ["x1_ddot + (g/l + k/m) x1 - (k/m) x2 = 0", "x2_ddot + (g/l + k/m) x2 - (k/m) x1 = 0"],
        [e1, e2],
        "as_in_numerade_form",
    )
    s.ok(
        "eom",
        ["x1_ddot + x2_ddot = -g/l (x1 + x2)", "x1_ddot - x2_ddot = -(g/l + 2 k/m)(x1 - x2)"],
        [f"{e1} + {e2}", f"{e1} - ({e2})"],
        "normal_coordinates",
    )
    s.bad(
        "eom",
        ["x1_ddot + g/l x1 - (k/m) x2 = 0", "x2_ddot + g/l x2 - (k/m) x1 = 0"],
        ["x1_ddot + g/l*x1 - k/m*x2", "x2_ddot + g/l*x2 - k/m*x1"],
        "missing_term",
    )
    s.ok("momenta", ["p_x1 = m x1_dot", "p_x2 = m x2_dot"], ["p_x1 = m*x1_dot", "p_x2 = m*x2_dot"])
    s.ok("cyclic", "none", [], "none")
    E = "m*(x1_dot**2 + x2_dot**2)/2 + m*g*(x1**2 + x2**2)/(2*l) + k*(x2 - x1)**2/2"
    s.ok("conserved", [E.replace("**", "^")], [E], "energy")
    s.ok(
        "conserved",
        ["m/2 (x1_dot + x2_dot)^2 + m g/(2 l) (x1 + x2)^2"],
        ["m*(x1_dot + x2_dot)**2/2 + m*g*(x1 + x2)**2/(2*l)"],
        "energy_of_one_mode",
    )
    s.bad("conserved", ["m (x1_dot + x2_dot)"], ["m*(x1_dot + x2_dot)"], "not_conserved")
    e = s.expression("sqrt(g/l + 2*k/m)", {"g": P, "l": P, "k": P, "m": P}, "antisymmetric_mode")
    e.ok("sqrt((m g + 2 k l)/(m l))", "sqrt((m*g + 2*k*l)/(m*l))")
    e.bad("sqrt(g/l + k/m)", "sqrt(g/l + k/m)", "factor_2")
    e.bad("sqrt(g/l)", "sqrt(g/l)", "missing_term")
    return s


def cylinder() -> System:
    s = System(
        "particle_on_cylinder",
        "Exercise: particle of mass m on the surface of a cylinder of radius R, attracted to "
        "the origin by F = -k r, as stated at https://askfilo.com/user-question-answers-smart-"
        "solutions/a-particle-of-mass-is-constrained-to-move-on-the-surface-of-3338393132303830",
        "m*(R**2*phi_dot**2 + z_dot**2)/2 - k*(R**2 + z**2)/2",
        ["phi", "z"],
        {"m": P, "R": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (R^2 phi_dot^2 + z_dot^2) - 1/2 k (R^2 + z^2)", L)
    s.ok("lagrangian", "½ m R² φ̇² + ½ m ż² − ½ k z²", f"{L} + k*R**2/2", "constant_dropped")
    s.bad(
        "lagrangian",
        "1/2 m (R phi_dot^2 + z_dot^2) - 1/2 k (R^2 + z^2)",
        "m*(R*phi_dot**2 + z_dot**2)/2 - k*(R**2 + z**2)/2",
        "wrong_moment_of_inertia",
    )
    s.bad(
        "lagrangian",
        "1/2 m (R^2 phi_dot^2 + z_dot^2) + 1/2 k (R^2 + z^2)",
        "m*(R**2*phi_dot**2 + z_dot**2)/2 + k*(R**2 + z**2)/2",
        "sign_of_V",
    )
    s.ok("eom", ["m R^2 phi_ddot = 0", "m z_ddot + k z = 0"], ["m*R**2*phi_ddot", "m*z_ddot + k*z"])
    s.ok("eom", ["φ̈ = 0", "z̈ = −(k/m) z"], ["phi_ddot", "z_ddot + k/m*z"], "unicode")
    s.bad(
        "eom",
        ["m R^2 phi_ddot = 0", "m z_ddot - k z = 0"],
        ["m*R**2*phi_ddot", "m*z_ddot - k*z"],
        "wrong_sign",
    )
    s.bad("eom", ["m z_ddot + k z = 0"], ["m*z_ddot + k*z"], "too_few_equations")
    s.ok(
        "momenta",
        ["p_phi = m R^2 phi_dot", "p_z = m z_dot"],
        ["p_phi = m*R**2*phi_dot", "p_z = m*z_dot"],
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "phi, z", ["phi", "z"], "not_cyclic")
    s.ok(
        "conserved",
        ["m R^2 phi_dot", "1/2 m z_dot^2 + 1/2 k z^2"],
        ["m*R**2*phi_dot", "m*z_dot**2/2 + k*z**2/2"],
        "separate_energies",
    )
    s.bad(
        "conserved",
        [
            "m R^2 phi_dot",
            "1/2 m z_dot^2 + 1/2 k z^2",
            "1/2 m (R^2 phi_dot^2 + z_dot^2) + 1/2 k z^2",
        ],
        [
            "m*R**2*phi_dot",
            "m*z_dot**2/2 + k*z**2/2",
            "m*(R**2*phi_dot**2 + z_dot**2)/2 + k*z**2/2",
        ],
        "not_independent",
    )
    s.bad("conserved", ["m z_dot"], ["m*z_dot"], "not_conserved")
    return s


def free_parabola() -> System:
    s = System(
        "bead_parabola_free_rotation",
        "Exercise with printed energies T = m[(1 + x^2) x'^2 + x^2 phi'^2]/2, V = m g x^2/2 "
        "(bead on the parabolic wire z = x^2/2 whose plane turns freely about the vertical "
        "axis; x^2 phi' = K; circular solution x0 = (K^2/g)^(1/4)), as stated at "
        "https://tutorsglobe.com/question/equation-of-motion-of-a-bead-on-a-rotating-"
        "parabola-51919719.aspx",
        "m*((1 + x**2)*x_dot**2 + x**2*phi_dot**2)/2 - m*g*x**2/2",
        {"x": "positive", "phi": None},
        {"m": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "m/2 ((1 + x^2) x_dot^2 + x^2 phi_dot^2) - m g x^2/2", L)
    s.ok("lagrangian", "½ m (ẋ² + x² ẋ² + x² φ̇²) − ½ m g x²", L, "unicode")
    s.bad(
        "lagrangian",
        "m/2 (x_dot^2 + x^2 phi_dot^2) - m g x^2/2",
        "m*(x_dot**2 + x**2*phi_dot**2)/2 - m*g*x**2/2",
        "forgot_constraint",
    )
    s.ok(
        "eom",
        ["(1 + x^2) x_ddot + x x_dot^2 - x phi_dot^2 + g x = 0", "d/dt(x^2 phi_dot) = 0"],
        ["(1 + x**2)*x_ddot + x*x_dot**2 - x*phi_dot**2 + g*x", "Dt(x**2*phi_dot)"],
        "conservation_form",
    )
    s.ok(
        "eom",
        [
            "(1 + x^2) x_ddot + x x_dot^2 - x phi_dot^2 + g x = 0",
            "x phi_ddot + 2 x_dot phi_dot = 0",
        ],
        ["(1 + x**2)*x_ddot + x*x_dot**2 - x*phi_dot**2 + g*x", "x*phi_ddot + 2*x_dot*phi_dot"],
        "expanded",
    )
    s.bad(
        "eom",
        [
            "(1 + x^2) x_ddot + 2 x x_dot^2 - x phi_dot^2 + g x = 0",
            "x phi_ddot + 2 x_dot phi_dot = 0",
        ],
        ["(1 + x**2)*x_ddot + 2*x*x_dot**2 - x*phi_dot**2 + g*x", "x*phi_ddot + 2*x_dot*phi_dot"],
        "wrong_chain_rule",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.ok("conserved", ["x^2 phi_dot"], ["x**2*phi_dot"], "printed_K")
    s.ok(
        "conserved",
        ["x^2 phi_dot", "m/2 ((1 + x^2) x_dot^2 + x^2 phi_dot^2) + m g x^2/2"],
        ["x**2*phi_dot", "m*((1 + x**2)*x_dot**2 + x**2*phi_dot**2)/2 + m*g*x**2/2"],
        "K_and_energy",
    )
    s.bad("conserved", ["x phi_dot"], ["x*phi_dot"], "not_conserved")
    s.bad(
        "conserved",
        ["x^2 phi_dot", "m x^2 phi_dot"],
        ["x**2*phi_dot", "m*x**2*phi_dot"],
        "not_independent",
    )
    e = s.expression("(K**2/g)**(1/4)", {"K": P, "g": P}, "circular_radius")
    e.ok("sqrt(K/sqrt(g))", "sqrt(K/sqrt(g))")
    e.ok("K^(1/2) g^(-1/4)", "K**(1/2)*g**(-1/4)", "powers")
    e.bad("(K^2/g)^(1/2)", "(K**2/g)**(1/2)")
    return s


def cycloid() -> System:
    s = System(
        "bead_on_cycloid",
        "Bead on a cycloid x = a(phi + sin phi), y = a(1 - cos phi), vertex down (Huygens' "
        "tautochrone; period 4 pi sqrt(a/g) independent of amplitude: "
        "https://mathworld.wolfram.com/TautochroneProblem.html; the equation u'' = -g u/(4a) "
        "for u = sin(phi/2) as in the worked model at http://www.phy.ntnu.edu.tw/ntnujava/"
        "msg.php?id=4683)",
        "m*a**2*(1 + cos(phi))*phi_dot**2 - m*g*a*(1 - cos(phi))",
        {"phi": "(-2, 2)"},
        {"m": P, "a": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "m a^2 (1 + cos(phi)) phi_dot^2 - m g a (1 - cos(phi))", L)
    s.ok(
        "lagrangian",
        "1/2 m a^2 ((1 + cos(phi))^2 + sin(phi)^2) phi_dot^2 + m g a cos(phi)",
        f"{L} + m*g*a",
        "from_velocities",
    )
    s.ok("lagrangian", "2 m a² cos²(φ/2) φ̇² − 2 m g a sin²(φ/2)", L, "unicode_half_angle")
    s.bad(
        "lagrangian",
        "1/2 m a^2 (1 + cos(phi)) phi_dot^2 - m g a (1 - cos(phi))",
        "m*a**2*(1 + cos(phi))*phi_dot**2/2 - m*g*a*(1 - cos(phi))",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "m a^2 (1 + cos(phi)) phi_dot^2 + m g a (1 - cos(phi))",
        "m*a**2*(1 + cos(phi))*phi_dot**2 + m*g*a*(1 - cos(phi))",
        "sign_of_V",
    )
    eq = "2*a*(1 + cos(phi))*phi_ddot - a*sin(phi)*phi_dot**2 + g*sin(phi)"
    s.ok("eom", ["2 a (1 + cos(phi)) phi_ddot - a sin(phi) phi_dot^2 + g sin(phi) = 0"], [eq])
    s.ok(
        "eom",
        ["4 a cos(phi/2)^2 phi_ddot - a sin(phi) phi_dot^2 + g sin(phi) = 0"],
        [eq],
        "half_angle",
    )
    s.bad(
        "eom",
        ["2 a (1 + cos(phi)) phi_ddot + g sin(phi) = 0"],
        ["2*a*(1 + cos(phi))*phi_ddot + g*sin(phi)"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        ["2 a (1 + cos(phi)) phi_ddot - 2 a sin(phi) phi_dot^2 + g sin(phi) = 0"],
        ["2*a*(1 + cos(phi))*phi_ddot - 2*a*sin(phi)*phi_dot**2 + g*sin(phi)"],
        "missing_term",
    )
    s.ok(
        "momenta",
        ["p_phi = 2 m a^2 (1 + cos(phi)) phi_dot"],
        ["p_phi = 2*m*a**2*(1 + cos(phi))*phi_dot"],
    )
    s.ok("cyclic", "none", [], "none")
    E = "m*a**2*(1 + cos(phi))*phi_dot**2 + m*g*a*(1 - cos(phi))"
    s.ok("conserved", [E.replace("**", "^")], [E], "energy")
    e = s.expression("4*pi*sqrt(a/g)", {"a": P, "g": P}, "period")
    e.ok("2 pi sqrt(4 a/g)", "2*pi*sqrt(4*a/g)")
    e.ok(r"4\pi\sqrt{a/g}", "4*pi*sqrt(a/g)", "latex")
    e.bad("2 pi sqrt(a/g)", "2*pi*sqrt(a/g)", "factor_2")
    return s


def accelerated_pivot() -> System:
    s = System(
        "tripos_accelerated_pivot",
        "Cambridge Mathematical Tripos Part II 2005, Paper 1, 15C, last part (pendulum whose "
        "pivot is driven with constant acceleration A along the rail; find the equilibrium "
        "angle), https://deploy-preview-103--nimble-strudel-fc6e42.netlify.app/part-ii/2005-49;"
        " pivot at x = A t^2/2, total derivatives dropped from L",
        "m*l**2*phi_dot**2/2 - m*A*l*sin(phi) + m*g*l*cos(phi)",
        ["phi"],
        {"m": P, "l": P, "A": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m l^2 phi_dot^2 - m A l sin(phi) + m g l cos(phi)", L, "reduced")
    s.ok(
        "lagrangian",
        "1/2 m ((A t + l phi_dot cos(phi))^2 + (l phi_dot sin(phi))^2) + m g l cos(phi)",
        "m*((A*t + l*phi_dot*cos(phi))**2 + (l*phi_dot*sin(phi))**2)/2 + m*g*l*cos(phi)",
        "unreduced_with_time",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 phi_dot^2 + m A l sin(phi) + m g l cos(phi)",
        "m*l**2*phi_dot**2/2 + m*A*l*sin(phi) + m*g*l*cos(phi)",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m ((A t)^2 + l^2 phi_dot^2) + m g l cos(phi)",
        "m*((A*t)**2 + l**2*phi_dot**2)/2 + m*g*l*cos(phi)",
        "missing_cross_term",
    )
    s.ok(
        "eom",
        ["l phi_ddot + A cos(phi) + g sin(phi) = 0"],
        ["l*phi_ddot + A*cos(phi) + g*sin(phi)"],
    )
    s.bad("eom", ["l phi_ddot + g sin(phi) = 0"], ["l*phi_ddot + g*sin(phi)"], "wrong_chain_rule")
    s.bad(
        "eom",
        ["l phi_ddot + A sin(phi) + g cos(phi) = 0"],
        ["l*phi_ddot + A*sin(phi) + g*cos(phi)"],
        "wrong_trig",
    )
    s.ok("momenta", ["p_phi = m l^2 phi_dot"], ["p_phi = m*l**2*phi_dot"])
    s.ok(
        "conserved",
        ["1/2 m l^2 phi_dot^2 + m A l sin(phi) - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 + m*A*l*sin(phi) - m*g*l*cos(phi)"],
        "energy_in_moving_frame",
    )
    s.bad(
        "conserved",
        ["1/2 m l^2 phi_dot^2 - m g l cos(phi)"],
        ["m*l**2*phi_dot**2/2 - m*g*l*cos(phi)"],
        "not_conserved",
    )
    e = s.expression("-atan(A/g)", {"A": P, "g": P}, "equilibrium_angle")
    e.ok("-arctan(A/g)", "-atan(A/g)")
    e.ok("-asin(A/sqrt(A^2 + g^2))", "-asin(A/sqrt(A**2 + g**2))", "via_sine")
    e.bad("atan(A/g)", "atan(A/g)", "wrong_sign")
    e.bad("-atan(g/A)", "-atan(g/A)")
    return s


def half_atwood() -> System:
    s = System(
        "half_atwood",
        "Half Atwood machine (m1 on a frictionless horizontal table, string over a pulley at "
        "the edge to m2 hanging; x the distance moved), as worked at https://rjallain.medium."
        "com/lagrangian-mechanics-example-motion-of-a-half-atwood-machine-65285e45500b",
        "(m1 + m2)*x_dot**2/2 + m2*g*x",
        ["x"],
        {"m1": P, "m2": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 (m1 + m2) x_dot^2 + m2 g x", L)
    s.ok("lagrangian", "½ m₁ ẋ² + ½ m₂ ẋ² + m₂ g x", L, "unicode")
    s.bad("lagrangian", "1/2 m2 x_dot^2 + m2 g x", "m2*x_dot**2/2 + m2*g*x", "forgot_constraint")
    s.bad(
        "lagrangian",
        "1/2 (m1 + m2) x_dot^2 + (m1 + m2) g x",
        "(m1 + m2)*x_dot**2/2 + (m1 + m2)*g*x",
        "missing_term",
    )
    s.ok("eom", ["x_ddot = m2 g/(m1 + m2)"], ["x_ddot - m2*g/(m1 + m2)"])
    s.bad("eom", ["x_ddot = g"], ["x_ddot - g"], "forgot_constraint")
    s.ok("momenta", ["p_x = (m1 + m2) x_dot"], ["p_x = (m1 + m2)*x_dot"])
    s.ok(
        "conserved", ["1/2 (m1 + m2) x_dot^2 - m2 g x"], ["(m1 + m2)*x_dot**2/2 - m2*g*x"], "energy"
    )
    e = s.expression("m2*g/(m1 + m2)", {"m1": P, "m2": P, "g": P}, "acceleration")
    e.ok("g/(1 + m1/m2)", "g/(1 + m1/m2)")
    e.bad("m2 g/m1", "m2*g/m1", "forgot_constraint")
    return s


def spherical_oscillator() -> System:
    s = System(
        "isotropic_oscillator_spherical",
        "Particle in the central field U = k r^2/2 in spherical coordinates: the central field "
        "of Landau & Lifshitz, Mechanics, §14, kept in three dimensions (the potential and "
        "the coordinates are our choice); conserved: p_phi and the square of the angular "
        "momentum p_theta^2 + p_phi^2/sin^2(theta)",
        "m*(r_dot**2 + r**2*theta_dot**2 + r**2*sin(theta)**2*phi_dot**2)/2 - k*r**2/2",
        {"r": "positive", "theta": "(0, pi)", "phi": None},
        {"m": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 theta_dot^2 + r^2 sin(theta)^2 phi_dot^2) - 1/2 k r^2",
        L,
    )
    s.ok("lagrangian", "½ m (ṙ² + r² θ̇² + r² φ̇² sin²θ) − ½ k r²", L, "unicode")
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 theta_dot^2 + r^2 phi_dot^2) - 1/2 k r^2",
        "m*(r_dot**2 + r**2*theta_dot**2 + r**2*phi_dot**2)/2 - k*r**2/2",
        "missing_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 theta_dot^2 + r^2 cos(theta)^2 phi_dot^2) - 1/2 k r^2",
        "m*(r_dot**2 + r**2*theta_dot**2 + r**2*cos(theta)**2*phi_dot**2)/2 - k*r**2/2",
        "wrong_trig",
    )
    er = "m*r_ddot - m*r*theta_dot**2 - m*r*sin(theta)**2*phi_dot**2 + k*r"
    et = "m*r**2*theta_ddot + 2*m*r*r_dot*theta_dot - m*r**2*sin(theta)*cos(theta)*phi_dot**2"
    ef = "Dt(m*r**2*sin(theta)**2*phi_dot)"
    s.ok(
        "eom",
        [
            er.replace("**", "^") + " = 0",
            et.replace("**", "^") + " = 0",
            "m r^2 sin(theta)^2 phi_ddot + 2 m r r_dot sin(theta)^2 phi_dot"
            " + 2 m r^2 sin(theta) cos(theta) theta_dot phi_dot = 0",
        ],
        [er, et, ef],
    )
    s.bad(
        "eom",
        [
            er.replace("**", "^") + " = 0",
            "m r^2 theta_ddot - m r^2 sin(theta) cos(theta) phi_dot^2 = 0",
            "m r^2 sin(theta)^2 phi_ddot + 2 m r r_dot sin(theta)^2 phi_dot"
            " + 2 m r^2 sin(theta) cos(theta) theta_dot phi_dot = 0",
        ],
        [er, "m*r**2*theta_ddot - m*r**2*sin(theta)*cos(theta)*phi_dot**2", ef],
        "wrong_chain_rule",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "theta, phi", ["theta", "phi"], "not_cyclic")
    pf = "m*r**2*sin(theta)**2*phi_dot"
    L2 = "m**2*r**4*(theta_dot**2 + sin(theta)**2*phi_dot**2)"
    E = "m*(r_dot**2 + r**2*theta_dot**2 + r**2*sin(theta)**2*phi_dot**2)/2 + k*r**2/2"
    s.ok(
        "conserved",
        [pf.replace("**", "^"), L2.replace("**", "^"), E.replace("**", "^")],
        [pf, L2, E],
        "p_phi_angular_momentum_squared_energy",
    )
    s.ok(
        "conserved",
        ["(m r^2 theta_dot)^2 + (m r^2 sin(theta)^2 phi_dot)^2/sin(theta)^2"],
        [L2],
        "angular_momentum_squared_from_momenta",
    )
    s.bad("conserved", ["m r^2 theta_dot"], ["m*r**2*theta_dot"], "not_conserved")
    s.bad("conserved", [pf.replace("**", "^"), f"({pf})^2"], [pf, f"({pf})**2"], "not_independent")
    return s


SYSTEMS = (
    rotating_wire,
    table_and_hanging_mass,
    quartic_lagrangian,
    double_atwood,
    cart_spring_pendulum,
    massive_pulley,
    rotating_parabola,
    cone,
    spring_pendulum,
    coupled_pendula,
    cylinder,
    free_parabola,
    cycloid,
    accelerated_pivot,
    half_atwood,
    spherical_oscillator,
)
