"""Systems from public lecture notes: D. Tong, Classical Dynamics (University of Cambridge Part II
Mathematical Tripos lecture notes, 2004-5, http://www.damtp.cam.ac.uk/user/tong/dynamics.html;
section numbers of that edition's contents, e.g. §2.5.1 Bead on a Rotating Hoop)."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System

TONG = "D. Tong, Classical Dynamics (Cambridge lecture notes, 2005), "
P = "positive"


def bead_on_hoop() -> System:
    s = System(
        "tong_bead_rotating_hoop",
        TONG + "§2.5.1 (bead on a hoop of radius R rotating with constant angular velocity "
        "omega about its vertical diameter; theta measured from the downward vertical; its "
        "equilibria); the equilibrium cos(theta0) = g/(omega^2 R) and the frequency of small "
        "oscillations about it are derived here by linearising that L",
        "m*R**2*(theta_dot**2 + omega**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
        {"theta": "(0, pi)"},
        {"m": P, "R": P, "omega": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m R^2 (theta_dot^2 + omega^2 sin(theta)^2) + m g R cos(theta)", L)
    s.ok("lagrangian", "½ m R² θ̇² + ½ m R² ω² sin²θ + m g R cos θ", L, "unicode_expanded")
    s.ok(
        "lagrangian",
        r"\frac{1}{2} m R^2\left(\dot\theta^2 + \omega^2\sin^2\theta\right) - m g R(1-\cos\theta)",
        L + " - m*g*R",
        "latex_shifted_V",
    )
    s.ok(
        "lagrangian",
        "R (theta_dot^2 + omega^2 sin(theta)^2)/2 + g cos(theta)",
        f"({L})/(m*R)",
        "divided_by_m_R",
    )
    s.bad(
        "lagrangian",
        "1/2 m R^2 theta_dot^2 + m g R cos(theta)",
        "m*R**2*theta_dot**2/2 + m*g*R*cos(theta)",
        "missing_centripetal",
    )
    s.bad(
        "lagrangian",
        "1/2 m R^2 (theta_dot^2 + omega^2 sin(theta)^2) - m g R cos(theta)",
        "m*R**2*(theta_dot**2 + omega**2*sin(theta)**2)/2 - m*g*R*cos(theta)",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 m R^2 (theta_dot^2 + omega^2 cos(theta)^2) + m g R cos(theta)",
        "m*R**2*(theta_dot**2 + omega**2*cos(theta)**2)/2 + m*g*R*cos(theta)",
        "wrong_trig",
    )
    s.bad(
        "lagrangian",
        "1/2 m R^2 (theta_dot^2 + omega^2) + m g R cos(theta)",
        "m*R**2*(theta_dot**2 + omega**2)/2 + m*g*R*cos(theta)",
        "missing_term",
    )
    eq = "R*theta_ddot - (R*omega**2*cos(theta) - g)*sin(theta)"
    s.ok("eom", ["R theta_ddot = (R omega^2 cos(theta) - g) sin(theta)"], [eq])
    s.ok("eom", ["θ̈ = (ω² cos θ − g/R) sin θ"], [f"({eq})/R"], "unicode")
    s.ok(
        "eom",
        [r"m R^2\ddot\theta - m R^2\omega^2\sin\theta\cos\theta + m g R\sin\theta = 0"],
        [f"m*R*({eq})"],
        "latex",
    )
    s.ok(
        "eom",
        ["theta_ddot = omega^2 sin(2 theta)/2 - g/R sin(theta)"],
        [f"({eq})/R"],
        "double_angle",
    )
    s.bad(
        "eom",
        ["R theta_ddot = -g sin(theta)"],
        ["R*theta_ddot + g*sin(theta)"],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        ["R theta_ddot = (R omega^2 cos(theta) + g) sin(theta)"],
        ["R*theta_ddot - (R*omega**2*cos(theta) + g)*sin(theta)"],
        "wrong_sign",
    )
    s.bad(
        "eom",
        ["R theta_ddot = (R omega^2 - g) sin(theta)"],
        ["R*theta_ddot - (R*omega**2 - g)*sin(theta)"],
        "wrong_chain_rule",
    )
    s.ok("momenta", ["p_theta = m R^2 theta_dot"], ["p_theta = m*R**2*theta_dot"])
    s.bad(
        "momenta",
        ["p_theta = m R^2 (theta_dot + omega sin(theta))"],
        ["p_theta = m*R**2*(theta_dot + omega*sin(theta))"],
        "missing_term",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "theta", ["theta"], "not_cyclic")
    h = "m*R**2*(theta_dot**2 - omega**2*sin(theta)**2)/2 - m*g*R*cos(theta)"
    s.ok(
        "conserved",
        ["1/2 m R^2 (theta_dot^2 - omega^2 sin(theta)^2) - m g R cos(theta)"],
        [h],
        "jacobi_integral",
    )
    s.ok(
        "conserved",
        ["θ̇² − ω² sin²θ − 2 g/R cos θ"],
        ["theta_dot**2 - omega**2*sin(theta)**2 - 2*g/R*cos(theta)"],
        "unicode_scaled",
    )
    s.bad(
        "conserved",
        ["1/2 m R^2 (theta_dot^2 + omega^2 sin(theta)^2) - m g R cos(theta)"],
        ["m*R**2*(theta_dot**2 + omega**2*sin(theta)**2)/2 - m*g*R*cos(theta)"],
        "not_conserved",
    )
    s.bad("conserved", ["m R^2 theta_dot"], ["m*R**2*theta_dot"], "not_conserved")
    e = s.expression("acos(g/(omega**2*R))", {"g": P, "omega": P, "R": P}, "equilibrium_angle")
    e.ok("arccos(g/(R omega^2))", "acos(g/(R*omega**2))")
    e.ok(r"\arccos\left(\frac{g}{\omega^2 R}\right)", "acos(g/(omega**2*R))", "latex")
    e.bad("acos(R omega^2/g)", "acos(R*omega**2/g)")
    e.bad("asin(g/(omega^2 R))", "asin(g/(omega**2*R))", "wrong_trig")
    f = s.expression(
        "omega*sqrt(1 - (g/(omega**2*R))**2)",
        {"g": P, "omega": P, "R": P},
        "oscillation_about_equilibrium",
    )
    f.ok("sqrt(omega^2 - g^2/(omega^2 R^2))", "sqrt(omega**2 - g**2/(omega**2*R**2))")
    f.ok("sqrt(omega^4 R^2 - g^2)/(omega R)", "sqrt(omega**4*R**2 - g**2)/(omega*R)", "one_root")
    f.ok("ω √(1 − g²/(ω⁴R²))", "omega*sqrt(1 - g**2/(omega**4*R**2))", "unicode_root")
    f.bad("sqrt(omega^2 - g/R)", "sqrt(omega**2 - g/R)")
    f.bad("omega sqrt(1 - g/(omega^2 R))", "omega*sqrt(1 - g/(omega**2*R))")
    return s


def spherical_pendulum() -> System:
    s = System(
        "tong_spherical_pendulum",
        TONG + "§2.5.3 (spherical pendulum: bob m on a rod l, polar angle theta from the "
        "downward vertical, azimuth phi); conical motion phi_dot^2 = g/(l cos theta0)",
        "m*l**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2 + m*g*l*cos(theta)",
        {"theta": "(0, pi)", "phi": None},
        {"m": P, "l": P, "g": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m l^2 (theta_dot^2 + sin(theta)^2 phi_dot^2) + m g l cos(theta)", L)
    s.ok("lagrangian", "½ m l² (θ̇² + φ̇² sin²θ) + m g l cos θ", L, "unicode")
    s.ok(
        "lagrangian",
        r"\tfrac12 m l^2\dot\theta^2 + \tfrac12 m l^2\dot\varphi^2\sin^2\theta + m g l\cos\theta",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 (theta_dot^2 + phi_dot^2) + m g l cos(theta)",
        "m*l**2*(theta_dot**2 + phi_dot**2)/2 + m*g*l*cos(theta)",
        "missing_term",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 (theta_dot^2 + cos(theta)^2 phi_dot^2) + m g l cos(theta)",
        "m*l**2*(theta_dot**2 + cos(theta)**2*phi_dot**2)/2 + m*g*l*cos(theta)",
        "wrong_trig",
    )
    s.bad(
        "lagrangian",
        "1/2 m l^2 (theta_dot^2 + sin(theta)^2 phi_dot^2) - m g l cos(theta)",
        "m*l**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2 - m*g*l*cos(theta)",
        "sign_of_V",
    )
    et = "l*theta_ddot - l*sin(theta)*cos(theta)*phi_dot**2 + g*sin(theta)"
    ef = "sin(theta)**2*phi_ddot + 2*sin(theta)*cos(theta)*theta_dot*phi_dot"
    s.ok(
        "eom",
        [
            "l theta_ddot - l sin(theta) cos(theta) phi_dot^2 + g sin(theta) = 0",
            "sin(theta)^2 phi_ddot + 2 sin(theta) cos(theta) theta_dot phi_dot = 0",
        ],
        [et, ef],
    )
    s.ok(
        "eom",
        [
            "l theta_ddot - l sin(theta) cos(theta) phi_dot^2 + g sin(theta) = 0",
            "sin(theta) phi_ddot + 2 cos(theta) theta_dot phi_dot = 0",
        ],
        [et, f"({ef})/sin(theta)"],
        "divided_by_sin",
    )
    s.ok(
        "eom",
        ["θ̈ = φ̇² sin θ cos θ − (g/l) sin θ", "d/dt(m l² φ̇ sin²θ) = 0"],
        [f"({et})/l", "Dt(m*l**2*sin(theta)**2*phi_dot)"],
        "unicode_conservation_form",
    )
    s.bad(
        "eom",
        [
            "l theta_ddot + g sin(theta) = 0",
            "sin(theta)^2 phi_ddot + 2 sin(theta) cos(theta) theta_dot phi_dot = 0",
        ],
        ["l*theta_ddot + g*sin(theta)", ef],
        "missing_centripetal",
    )
    s.bad(
        "eom",
        [
            "l theta_ddot - l sin(theta) cos(theta) phi_dot^2 + g sin(theta) = 0",
            "sin(theta)^2 phi_ddot = 0",
        ],
        [et, "sin(theta)**2*phi_ddot"],
        "wrong_chain_rule",
    )
    s.ok(
        "momenta",
        ["p_theta = m l^2 theta_dot", "p_phi = m l^2 sin(theta)^2 phi_dot"],
        ["p_theta = m*l**2*theta_dot", "p_phi = m*l**2*sin(theta)**2*phi_dot"],
    )
    s.bad(
        "momenta",
        ["p_theta = m l^2 theta_dot", "p_phi = m l^2 phi_dot"],
        ["p_theta = m*l**2*theta_dot", "p_phi = m*l**2*phi_dot"],
        "missing_term",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "phi, theta", ["phi", "theta"], "not_cyclic")
    E = "m*l**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2 - m*g*l*cos(theta)"
    s.ok(
        "conserved",
        ["m l^2 sin(theta)^2 phi_dot", E.replace("**", "^")],
        ["m*l**2*sin(theta)**2*phi_dot", E],
        "momentum_and_energy",
    )
    s.bad("conserved", ["m l^2 phi_dot"], ["m*l**2*phi_dot"], "not_conserved")
    s.bad("conserved", ["m l^2 theta_dot"], ["m*l**2*theta_dot"], "not_conserved")
    e = s.expression(
        "sqrt(g/(l*cos(theta0)))", {"g": P, "l": P, "theta0": "(0, pi/2)"}, "conical_rate"
    )
    e.ok("sqrt(g sec(theta0)/l)", "sqrt(g*sec(theta0)/l)", "secant")
    e.ok(r"\sqrt{\frac{g}{l\cos\theta_0}}", "sqrt(g/(l*cos(theta0)))", "latex")
    e.bad("sqrt(g cos(theta0)/l)", "sqrt(g*cos(theta0)/l)")
    e.bad("sqrt(g/l)", "sqrt(g/l)", "missing_term")
    return s


def two_body() -> System:
    s = System(
        "tong_two_body_spring",
        TONG + "§2.5.4 (two-body problem, L = m1 r1'^2/2 + m2 r2'^2/2 - V(|r1 - r2|); "
        "centre-of-mass momentum conserved, relative motion with the reduced mass) on a line, "
        "with V a spring k (x1 - x2)^2/2",
        "m1*x1_dot**2/2 + m2*x2_dot**2/2 - k*(x1 - x2)**2/2",
        ["x1", "x2"],
        {"m1": P, "m2": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m1 x1_dot^2 + 1/2 m2 x2_dot^2 - 1/2 k (x1 - x2)^2", L)
    s.ok("lagrangian", "½ m₁ ẋ₁² + ½ m₂ ẋ₂² − ½ k (x₂ − x₁)²", L, "unicode")
    s.bad(
        "lagrangian",
        "1/2 m1 x1_dot^2 + 1/2 m2 x2_dot^2 + 1/2 k (x1 - x2)^2",
        "m1*x1_dot**2/2 + m2*x2_dot**2/2 + k*(x1 - x2)**2/2",
        "sign_of_V",
    )
    s.bad(
        "lagrangian",
        "1/2 m1 x1_dot^2 + 1/2 m2 x2_dot^2 - 1/2 k (x1^2 + x2^2)",
        "m1*x1_dot**2/2 + m2*x2_dot**2/2 - k*(x1**2 + x2**2)/2",
        "missing_cross_term",
    )
    s.ok(
        "eom",
        ["m1 x1_ddot = -k (x1 - x2)", "m2 x2_ddot = k (x1 - x2)"],
        ["m1*x1_ddot + k*(x1 - x2)", "m2*x2_ddot - k*(x1 - x2)"],
    )
    s.ok(
        "eom",
        ["m1 x1_ddot + m2 x2_ddot = 0", "x1_ddot - x2_ddot = -k (1/m1 + 1/m2)(x1 - x2)"],
        ["m1*x1_ddot + m2*x2_ddot", "x1_ddot - x2_ddot + k*(1/m1 + 1/m2)*(x1 - x2)"],
        "centre_of_mass_and_relative",
    )
    s.bad(
        "eom",
        ["m1 x1_ddot = -k (x1 - x2)", "m2 x2_ddot = -k (x1 - x2)"],
        ["m1*x1_ddot + k*(x1 - x2)", "m2*x2_ddot + k*(x1 - x2)"],
        "wrong_sign",
    )
    s.ok(
        "momenta",
        ["p_x1 = m1 x1_dot", "p_x2 = m2 x2_dot"],
        ["p_x1 = m1*x1_dot", "p_x2 = m2*x2_dot"],
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "x1, x2", ["x1", "x2"], "not_cyclic")
    P_ = "m1*x1_dot + m2*x2_dot"
    E = "m1*x1_dot**2/2 + m2*x2_dot**2/2 + k*(x1 - x2)**2/2"
    s.ok("conserved", ["m1 x1_dot + m2 x2_dot"], [P_], "total_momentum")
    s.ok(
        "conserved", ["m1 x1_dot + m2 x2_dot", E.replace("**", "^")], [P_, E], "momentum_and_energy"
    )
    s.bad("conserved", ["m1 x1_dot"], ["m1*x1_dot"], "not_conserved")
    s.bad(
        "conserved",
        ["m1 x1_dot + m2 x2_dot", "(m1 x1_dot + m2 x2_dot)/(m1 + m2)"],
        [P_, f"({P_})/(m1 + m2)"],
        "not_independent",
    )
    e = s.expression("sqrt(k*(m1 + m2)/(m1*m2))", {"k": P, "m1": P, "m2": P}, "relative_frequency")
    e.ok("sqrt(k/m1 + k/m2)", "sqrt(k/m1 + k/m2)")
    e.ok("sqrt(k/(m1 m2/(m1 + m2)))", "sqrt(k/(m1*m2/(m1 + m2)))", "reduced_mass")
    e.bad("sqrt(k/(m1 + m2))", "sqrt(k/(m1 + m2))")
    e.bad("sqrt(k m1 m2/(m1 + m2))", "sqrt(k*m1*m2/(m1 + m2))")
    return s


def triatomic() -> System:
    s = System(
        "tong_linear_triatomic",
        TONG + "§2.6.2 (linear triatomic molecule: masses m, M, m joined by springs k; normal "
        "frequencies 0, sqrt(k/m), sqrt(k/m (1 + 2m/M))); also Goldstein, Poole & Safko, "
        "Classical Mechanics 3rd ed., §6.4",
        "m*(x1_dot**2 + x3_dot**2)/2 + M*x2_dot**2/2 - k*(x2 - x1)**2/2 - k*(x3 - x2)**2/2",
        ["x1", "x2", "x3"],
        {"m": P, "M": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok(
        "lagrangian",
        "1/2 m (x1_dot^2 + x3_dot^2) + 1/2 M x2_dot^2 - 1/2 k (x2 - x1)^2 - 1/2 k (x3 - x2)^2",
        L,
    )
    s.ok(
        "lagrangian",
        r"\frac{m}{2}(\dot x_1^2 + \dot x_3^2) + \frac{M}{2}\dot x_2^2"
        r" - \frac{k}{2}\left((x_2 - x_1)^2 + (x_3 - x_2)^2\right)",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x1_dot^2 + x3_dot^2) + 1/2 M x2_dot^2 - 1/2 k (x2 - x1)^2 - 1/2 k (x3 - x1)^2",
        "m*(x1_dot**2 + x3_dot**2)/2 + M*x2_dot**2/2 - k*(x2 - x1)**2/2 - k*(x3 - x1)**2/2",
        "forgot_constraint",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x1_dot^2 + x2_dot^2 + x3_dot^2) - 1/2 k (x2 - x1)^2 - 1/2 k (x3 - x2)^2",
        "m*(x1_dot**2 + x2_dot**2 + x3_dot**2)/2 - k*(x2 - x1)**2/2 - k*(x3 - x2)**2/2",
        "wrong_moment_of_inertia",
    )
    s.ok(
        "eom",
        ["m x1_ddot = k (x2 - x1)", "M x2_ddot = k (x1 - 2 x2 + x3)", "m x3_ddot = k (x2 - x3)"],
        ["m*x1_ddot - k*(x2 - x1)", "M*x2_ddot - k*(x1 - 2*x2 + x3)", "m*x3_ddot - k*(x2 - x3)"],
    )
    s.bad(
        "eom",
        ["m x1_ddot = k (x2 - x1)", "M x2_ddot = k (x1 - x2 + x3)", "m x3_ddot = k (x2 - x3)"],
        ["m*x1_ddot - k*(x2 - x1)", "M*x2_ddot - k*(x1 - x2 + x3)", "m*x3_ddot - k*(x2 - x3)"],
        "factor_2",
    )
    s.bad(
        "eom",
        ["m x1_ddot = k (x2 - x1)", "m x3_ddot = k (x2 - x3)"],
        ["m*x1_ddot - k*(x2 - x1)", "m*x3_ddot - k*(x2 - x3)"],
        "too_few_equations",
    )
    s.ok(
        "momenta",
        ["p_x1 = m x1_dot", "p_x2 = M x2_dot", "p_x3 = m x3_dot"],
        ["p_x1 = m*x1_dot", "p_x2 = M*x2_dot", "p_x3 = m*x3_dot"],
    )
    s.bad(
        "momenta",
        ["p_x1 = m x1_dot", "p_x2 = m x2_dot", "p_x3 = m x3_dot"],
        ["p_x1 = m*x1_dot", "p_x2 = m*x2_dot", "p_x3 = m*x3_dot"],
        "wrong_moment_of_inertia",
    )
    s.ok("cyclic", "none", [], "none")
    s.ok(
        "conserved",
        ["m (x1_dot + x3_dot) + M x2_dot"],
        ["m*(x1_dot + x3_dot) + M*x2_dot"],
        "total_momentum",
    )
    s.bad(
        "conserved",
        ["m (x1_dot + x2_dot + x3_dot)"],
        ["m*(x1_dot + x2_dot + x3_dot)"],
        "not_conserved",
    )
    e = s.expression("sqrt(k/m*(1 + 2*m/M))", {"k": P, "m": P, "M": P}, "asymmetric_mode")
    e.ok("sqrt(k (M + 2 m)/(m M))", "sqrt(k*(M + 2*m)/(m*M))")
    e.ok("√(k/m + 2k/M)", "sqrt(k/m + 2*k/M)", "unicode_root")
    e.bad("sqrt(k/m (1 + m/M))", "sqrt(k/m*(1 + m/M))")
    e.bad("sqrt(2 k/m)", "sqrt(2*k/m)")
    f = s.expression("sqrt(k/m)", {"k": P, "m": P, "M": P}, "symmetric_mode")
    f.ok("(k/m)^(1/2)", "(k/m)**(1/2)", "power")
    f.bad("sqrt(k/M)", "sqrt(k/M)")
    return s


def rotating_frame() -> System:
    s = System(
        "tong_rotating_frame_oscillator",
        TONG + "§2.2.1 (rotating coordinate systems: L = m[(x' - omega y)^2 + (y' + omega x)^2]/2"
        " - V in a frame turning with angular velocity omega), with the isotropic potential "
        "V = k (x^2 + y^2)/2",
        "m*((x_dot - omega*y)**2 + (y_dot + omega*x)**2)/2 - k*(x**2 + y**2)/2",
        ["x", "y"],
        {"m": P, "omega": P, "k": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m ((x_dot - omega y)^2 + (y_dot + omega x)^2) - 1/2 k (x^2 + y^2)", L)
    s.ok(
        "lagrangian",
        "½ m (ẋ² + ẏ²) + m ω (x ẏ − y ẋ) + ½ m ω² (x² + y²) − ½ k (x² + y²)",
        L,
        "unicode_expanded",
    )
    s.ok(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + 2 m omega x y_dot + 1/2 (m omega^2 - k)(x^2 + y^2)",
        "m*(x_dot**2 + y_dot**2)/2 + 2*m*omega*x*y_dot + (m*omega**2 - k)*(x**2 + y**2)/2",
        "coriolis_gauge_shifted",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + m omega (x y_dot - y x_dot) - 1/2 k (x^2 + y^2)",
        "m*(x_dot**2 + y_dot**2)/2 + m*omega*(x*y_dot - y*x_dot) - k*(x**2 + y**2)/2",
        "missing_centripetal",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + 1/2 m omega^2 (x^2 + y^2) - 1/2 k (x^2 + y^2)",
        "m*(x_dot**2 + y_dot**2)/2 + m*omega**2*(x**2 + y**2)/2 - k*(x**2 + y**2)/2",
        "missing_cross_term",
    )
    ex = "m*x_ddot - 2*m*omega*y_dot - m*omega**2*x + k*x"
    ey = "m*y_ddot + 2*m*omega*x_dot - m*omega**2*y + k*y"
    s.ok(
        "eom",
        [
            "m x_ddot - 2 m omega y_dot - m omega^2 x + k x = 0",
            "m y_ddot + 2 m omega x_dot - m omega^2 y + k y = 0",
        ],
        [ex, ey],
    )
    s.ok(
        "eom",
        [
            r"\ddot x = 2\omega\dot y + (\omega^2 - k/m)\,x",
            r"\ddot y = -2\omega\dot x + (\omega^2 - k/m)\,y",
        ],
        [f"({ex})/m", f"({ey})/m"],
        "latex_solved",
    )
    s.bad(
        "eom",
        [
            "m x_ddot - m omega y_dot - m omega^2 x + k x = 0",
            "m y_ddot + m omega x_dot - m omega^2 y + k y = 0",
        ],
        [
            "m*x_ddot - m*omega*y_dot - m*omega**2*x + k*x",
            "m*y_ddot + m*omega*x_dot - m*omega**2*y + k*y",
        ],
        "factor_2",
    )
    s.bad(
        "eom",
        [
            "m x_ddot + 2 m omega y_dot - m omega^2 x + k x = 0",
            "m y_ddot - 2 m omega x_dot - m omega^2 y + k y = 0",
        ],
        [
            "m*x_ddot + 2*m*omega*y_dot - m*omega**2*x + k*x",
            "m*y_ddot - 2*m*omega*x_dot - m*omega**2*y + k*y",
        ],
        "wrong_sign",
    )
    s.ok(
        "momenta",
        ["p_x = m (x_dot - omega y)", "p_y = m (y_dot + omega x)"],
        ["p_x = m*(x_dot - omega*y)", "p_y = m*(y_dot + omega*x)"],
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot"],
        ["p_x = m*x_dot", "p_y = m*y_dot"],
        "kinetic_momentum",
    )
    s.ok("cyclic", "none", [], "none")
    h = "m*(x_dot**2 + y_dot**2)/2 - m*omega**2*(x**2 + y**2)/2 + k*(x**2 + y**2)/2"
    J = "m*(x*y_dot - y*x_dot) + m*omega*(x**2 + y**2)"
    s.ok(
        "conserved",
        [h.replace("**", "^"), J.replace("**", "^")],
        [h, J],
        "jacobi_and_angular_momentum",
    )
    s.bad(
        "conserved",
        ["1/2 m (x_dot^2 + y_dot^2) + 1/2 k (x^2 + y^2)"],
        ["m*(x_dot**2 + y_dot**2)/2 + k*(x**2 + y**2)/2"],
        "not_conserved",
    )
    s.bad("conserved", ["m (x_dot - omega y)"], ["m*(x_dot - omega*y)"], "not_conserved")
    return s


SYSTEMS = (bead_on_hoop, spherical_pendulum, two_body, triatomic, rotating_frame)
