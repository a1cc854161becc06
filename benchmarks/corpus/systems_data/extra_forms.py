"""More forms of answers to the systems above, added across systems: the ways of writing a list
of cyclic coordinates, conserved quantities that are functions or time-dependent combinations of
the obvious ones, equations multiplied by a function of the coordinates or solved for the
accelerations, angles in degrees, Unicode spellings made from plain answers, and wrong answers
that swap two parameters. Each case keeps the source of its system."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System, uni

P = "positive"


def _unicode_twins(s: System) -> None:
    """The Unicode spelling of each plain right eom and momenta answer, where it differs."""
    for case in list(s.cases):
        if case.label != "correct" or case.part not in ("eom", "momenta"):
            continue
        if case.form not in ("plain", "multiplied_through", "solved", "expanded"):
            continue
        texts = case.answer if isinstance(case.answer, list) else [case.answer]
        twins = [uni(t) for t in texts]
        if twins != texts and all("\\" not in t for t in texts):
            s.ok(case.part, twins, case.meaning, f"unicode_of_{case.form}")


def augment(systems: dict[str, System]) -> None:
    """Add the extra forms to the systems (by key)."""
    for s in systems.values():
        _unicode_twins(s)

    top = systems["ll_heavy_symmetric_top"]
    top.ok("cyclic", "phi\npsi", ["phi", "psi"], "one_per_line")
    top.ok("cyclic", "phi and psi", ["phi", "psi"], "joined_by_and")
    top.ok("cyclic", r"\varphi, \psi", ["phi", "psi"], "latex_names")
    top.ok(
        "conserved",
        ["I1 phi_dot sin(theta)^2 + I3 (psi_dot + phi_dot cos(theta)) cos(theta) = const"],
        ["I1*phi_dot*sin(theta)**2 + I3*(psi_dot + phi_dot*cos(theta))*cos(theta)"],
        "equals_const",
    )
    top.ok(
        "conserved",
        ["I1 phi_dot sin(theta)^2 + I3 (psi_dot + phi_dot cos(theta)) (cos(theta) + 2)"],
        ["I1*phi_dot*sin(theta)**2 + I3*(psi_dot + phi_dot*cos(theta))*(cos(theta) + 2)"],
        "p_phi_plus_twice_p_psi",
    )

    kepler = systems["ll_kepler"]
    kepler.ok("cyclic", "φ", ["phi"], "unicode")
    kepler.ok("cyclic", r"\varphi", ["phi"], "latex")
    kepler.ok("conserved", ["m r^2 phi_dot = const"], ["m*r**2*phi_dot"], "equals_const")
    kepler.ok("conserved", ["(m r^2 phi_dot)^2"], ["(m*r**2*phi_dot)**2"], "square")
    kepler.bad("cyclic", "r, phi", ["r", "phi"], "not_cyclic")

    sliding = systems["ll_pendulum_sliding_support"]
    sliding.ok(
        "eom",
        [
            "x_ddot = m2 sin(phi) (l phi_dot^2 + g cos(phi))/(m1 + m2 sin(phi)^2)",
            "phi_ddot = -sin(phi) ((m1 + m2) g + m2 l phi_dot^2 cos(phi))/(l (m1 + m2 sin(phi)^2))",
        ],
        [
            "x_ddot - m2*sin(phi)*(l*phi_dot**2 + g*cos(phi))/(m1 + m2*sin(phi)**2)",
            "phi_ddot + sin(phi)*((m1 + m2)*g + m2*l*phi_dot**2*cos(phi))"
            "/(l*(m1 + m2*sin(phi)**2))",
        ],
        "solved_for_accelerations",
    )
    sliding.ok(
        "eom",
        [
            "(m1 + m2) x_ddot + m2 l (phi_ddot cos(phi) - phi_dot^2 sin(phi)) = 0",
            "l phi_ddot cos(phi) + x_ddot cos(phi)^2 + g sin(phi) cos(phi) = 0",
        ],
        [
            "(m1 + m2)*x_ddot + m2*l*(phi_ddot*cos(phi) - phi_dot**2*sin(phi))",
            "cos(phi)*(l*phi_ddot + x_ddot*cos(phi) + g*sin(phi))",
        ],
        "multiplied_by_cos",
    )
    sliding.bad(
        "lagrangian",
        "1/2 (m1 + m2) x_dot^2 + 1/2 m2 l^2 phi_dot^2 + m1 l x_dot phi_dot cos(phi)"
        " + m2 g l cos(phi)",
        "(m1 + m2)*x_dot**2/2 + m2*l**2*phi_dot**2/2 + m1*l*x_dot*phi_dot*cos(phi)"
        " + m2*g*l*cos(phi)",
        "swapped_parameter",
    )
    sliding.ok(
        "conserved",
        ["(m1 + m2) x - ((m1 + m2) x_dot + m2 l phi_dot cos(phi)) t + m2 l sin(phi)"],
        ["(m1 + m2)*x - ((m1 + m2)*x_dot + m2*l*phi_dot*cos(phi))*t + m2*l*sin(phi)"],
        "centre_of_mass_motion",
    )

    two = systems["tong_two_body_spring"]
    two.ok(
        "conserved",
        ["m1 x1 + m2 x2 - (m1 x1_dot + m2 x2_dot) t"],
        ["m1*x1 + m2*x2 - (m1*x1_dot + m2*x2_dot)*t"],
        "galilean_boost",
    )
    two.bad("conserved", ["m1 x1 + m2 x2"], ["m1*x1 + m2*x2"], "not_conserved")
    two.bad(
        "lagrangian",
        "1/2 m2 x1_dot^2 + 1/2 m1 x2_dot^2 - 1/2 k (x1 - x2)^2",
        "m2*x1_dot**2/2 + m1*x2_dot**2/2 - k*(x1 - x2)**2/2",
        "swapped_parameter",
    )

    wire = systems["goldstein_bead_rotating_wire"]
    wire.ok(
        "conserved",
        ["(r_dot - omega r) exp(omega t)"],
        ["(r_dot - omega*r)*exp(omega*t)"],
        "time_dependent",
    )
    wire.bad(
        "conserved",
        ["(r_dot - omega r) exp(-omega t)"],
        ["(r_dot - omega*r)*exp(-omega*t)"],
        "not_conserved",
    )

    free = systems["relativistic_free_particle"]
    free.ok(
        "conserved",
        ["x - x_dot t", "y - y_dot t"],
        ["x - x_dot*t", "y - y_dot*t"],
        "time_dependent",
    )
    free.ok(
        "conserved",
        ["m x_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)", "x_dot"],
        ["m*x_dot/sqrt(1 - (x_dot**2 + y_dot**2)/c**2)", "x_dot"],
        "momentum_and_velocity",
    )

    simple = systems["sympy_simple_pendulum"]
    simple.ok(
        "conserved",
        ["(1/2 m l^2 theta_dot^2 - m g l cos(theta))^2"],
        ["(m*l**2*theta_dot**2/2 - m*g*l*cos(theta))**2"],
        "energy_squared",
    )
    simple.ok(
        "conserved",
        ["E = 1/2 m l^2 theta_dot^2 - m g l cos(theta)"],
        ["m*l**2*theta_dot**2/2 - m*g*l*cos(theta)"],
        "named_E",
    )
    simple.ok(
        "lagrangian",
        "L = 1/2 m l^2 theta_dot^2 + m g l cos(theta)",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
        "named_L",
    )
    simple.ok(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + m g l cos(theta) + sin(t)",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta) + sin(t)",
        "plus_function_of_t",
    )
    simple.bad(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + m g l cos(theta) + theta",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta) + theta",
        "missing_term",
    )
    simple.ok(
        "eom",
        ["0 = m l^2 theta_ddot + m g l sin(theta)"],
        ["m*l**2*theta_ddot + m*g*l*sin(theta)"],
        "zero_on_the_left",
    )
    simple.ok(
        "eom",
        ["m l^2 theta_ddot cos(theta) + m g l sin(theta) cos(theta) = 0"],
        ["cos(theta)*(m*l**2*theta_ddot + m*g*l*sin(theta))"],
        "multiplied_by_cos",
    )

    hoop = systems["tong_bead_rotating_hoop"]
    hoop.ok(
        "lagrangian",
        "1/2 m R^2 theta_dot^2 + 1/4 m R^2 omega^2 (1 - cos(2 theta)) + m g R cos(theta)",
        "m*R**2*theta_dot**2/2 + m*R**2*omega**2*(1 - cos(2*theta))/4 + m*g*R*cos(theta)",
        "double_angle",
    )
    hoop.bad(
        "lagrangian",
        "1/2 m R^2 theta_dot^2 + 1/2 m R^2 omega^2 (1 - cos(2 theta)) + m g R cos(theta)",
        "m*R**2*theta_dot**2/2 + m*R**2*omega**2*(1 - cos(2*theta))/2 + m*g*R*cos(theta)",
        "factor_2",
    )
    angle = hoop.expression("acos(1/2)", {}, "equilibrium_angle_numeric")
    angle.ok("pi/3", "pi/3", "radians")
    angle.ok("60°", "pi/3", "degrees_sign")
    angle.ok("60 deg", "pi/3", "degrees_word")
    angle.ok("acos(0.5)", "acos(1/2)", "decimal_argument")
    angle.bad("pi/6", "pi/6", "wrong_trig")
    angle.bad("60", "60", "wrong_expression")

    pivot = systems["tripos_accelerated_pivot"]
    tilt = pivot.expression("-atan(1)", {}, "equilibrium_angle_when_A_equals_g")
    tilt.ok("-pi/4", "-pi/4", "radians")
    tilt.ok("-45°", "-pi/4", "degrees_sign")
    tilt.bad("pi/4", "pi/4", "wrong_sign")

    cone = systems["particle_inside_cone"]
    cone.ok("cyclic", "phi\n", ["phi"], "trailing_newline")
    cone.ok(
        "eom",
        ["r̈ = (r φ̇² − g cot α) sin²α", "r² φ̈ + 2 r ṙ φ̇ = 0"],
        [
            "sin(alpha)**2*(r_ddot/sin(alpha)**2 - r*phi_dot**2 + g*cot(alpha))",
            "r**2*phi_ddot + 2*r*r_dot*phi_dot",
        ],
        "unicode_solved",
    )

    gauge = systems["tripos_landau_gauge"]
    gauge.ok("cyclic", "y\n", ["y"], "trailing_newline")
    gauge.ok(
        "momenta",
        ["p_y = q B x + m y_dot", "p_x = m x_dot"],
        ["p_y = q*B*x + m*y_dot", "p_x = m*x_dot"],
        "other_order",
    )

    kepler_si = kepler.expression(
        "2*pi*sqrt(a**3/(G*M))",
        {"a": "(1e10, 1e12)", "G": "(6e-11, 7e-11)", "M": "(1e29, 1e31)"},
        "period_si_scale",
    )
    kepler_si.ok("2 pi a^(3/2)/sqrt(G M)", "2*pi*a**(3/2)/sqrt(G*M)", "si_scale")
    kepler_si.bad("2 pi a^(3/2)/sqrt(G)", "2*pi*a**(3/2)/sqrt(G)", "missing_term")

    atwood = systems["tm_double_atwood"]
    atwood.bad(
        "eom",
        [
            "(m1 + m2 + m3) x_ddot + (m2 - m3) y_ddot = (m1 - m2 - m3) g",
            "(m2 + m3) y_ddot + (m2 - m3) x_ddot = (m2 - m3) g",
        ],
        [
            "(m1 + m2 + m3)*x_ddot + (m2 - m3)*y_ddot - (m1 - m2 - m3)*g",
            "(m2 + m3)*y_ddot + (m2 - m3)*x_ddot - (m2 - m3)*g",
        ],
        "swapped_parameter",
    )

    simple.ok(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + m g l cos(theta) + const",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta) + const",
        "plus_const",
    )
    simple.ok("cyclic", "None", [], "capitalised_none")
    simple.ok("cyclic", "∅", [], "empty_set")
    simple.bad(
        "lagrangian",
        "exp(t) (1/2 m l^2 theta_dot^2 + m g l cos(theta))",
        "exp(t)*(m*l**2*theta_dot**2/2 + m*g*l*cos(theta))",
        "missing_term",
    )
    simple.bad(
        "lagrangian",
        "1/2 m l^2 theta_dot^2 + g l cos(theta)",
        "m*l**2*theta_dot**2/2 + g*l*cos(theta)",
        "missing_term",
    )
    period = simple.expressions[0]
    period.ok("T = 2 pi sqrt(l/g)", "2*pi*sqrt(l/g)", "named_T")

    kepler.bad(
        "lagrangian",
        "-1/2 m (r_dot^2 + r^2 phi_dot^2) - alpha/r",
        "-m*(r_dot**2 + r**2*phi_dot**2)/2 - alpha/r",
        "v_minus_t",
    )
    kepler.ok(
        "lagrangian",
        "L = 1/2 m (r_dot^2 + r^2 phi_dot^2) + alpha/r + const",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 + alpha/r + const",
        "named_L_plus_const",
    )

    unstable = hoop.expression(
        "sqrt(g/R - omega**2)",
        {"g": "(1, 2)", "R": "(1, 2)", "omega": "(3, 4)"},
        "bottom_frequency_above_critical",
    )
    unstable.problem["imaginary_unit"] = "I"
    unstable.ok("I sqrt(omega^2 - g/R)", "I*sqrt(omega**2 - g/R)", "imaginary_frequency")
    unstable.bad("sqrt(omega^2 - g/R)", "sqrt(omega**2 - g/R)", "wrong_sign")

    whole = {"all": True}
    pf = "I1*phi_dot*sin(theta)**2 + I3*(psi_dot + phi_dot*cos(theta))*cos(theta)"
    ps = "I3*(psi_dot + phi_dot*cos(theta))"
    h = (
        "I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2"
        " + I3*(psi_dot + phi_dot*cos(theta))**2/2 + M*g*l*cos(theta)"
    )
    top.ok(
        "conserved",
        [pf.replace("**", "^"), ps.replace("**", "^"), h.replace("**", "^")],
        [pf, ps, h],
        "complete_set",
        given=whole,
    )
    top.bad("conserved", [h.replace("**", "^")], [h], "missing_term", given=whole)
    E = "m*(r_dot**2 + r**2*phi_dot**2)/2 - alpha/r"
    kepler.ok(
        "conserved",
        ["m r^2 phi_dot", E.replace("**", "^")],
        ["m*r**2*phi_dot", E],
        "complete_set",
        given=whole,
    )
    kepler.bad("conserved", ["m r^2 phi_dot"], ["m*r**2*phi_dot"], "missing_term", given=whole)
    gauge.ok(
        "conserved",
        ["m y_dot + q B x", "1/2 m (x_dot^2 + y_dot^2)"],
        ["m*y_dot + q*B*x", "m*(x_dot**2 + y_dot**2)/2"],
        "complete_set",
        given=whole,
    )
    gauge.bad(
        "conserved",
        ["1/2 m (x_dot^2 + y_dot^2)"],
        ["m*(x_dot**2 + y_dot**2)/2"],
        "missing_term",
        given=whole,
    )

    turn = hoop.expressions[0]
    turn.ok("atan(sqrt(omega^4 R^2 - g^2)/g)", "atan(sqrt(omega**4*R**2 - g**2)/g)", "via_tangent")
    turn.ok("asin(sqrt(1 - g^2/(omega^4 R^2)))", "asin(sqrt(1 - g**2/(omega**4*R**2)))", "via_sine")

    simple.ok(
        "lagrangian",
        "L(theta, theta_dot) = 1/2 m l^2 theta_dot^2 + m g l cos(theta)",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
        "named_L_with_arguments",
    )
    simple.ok(
        "lagrangian",
        "½ × m × l² × θ̇² + m × g × l × cos θ",
        "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)",
        "unicode_times_signs",
    )
    kepler.ok(
        "eom",
        [
            r"m\ddot r - m r\dot\varphi^2 + \frac{\alpha}{r^2} = 0",
            r"\frac{d}{dt}\left(m r^2\dot\varphi\right) = 0",
        ],
        ["m*r_ddot - m*r*phi_dot**2 + alpha/r**2", "Dt(m*r**2*phi_dot)"],
        "latex_frac_d_dt",
    )
    kepler.ok(
        "eom",
        ["m r_ddot - m r phi_dot^2 + alpha/r^2 = 0", "diff(m r^2 phi_dot, t) = 0"],
        ["m*r_ddot - m*r*phi_dot**2 + alpha/r**2", "Dt(m*r**2*phi_dot)"],
        "diff_of_expression",
    )
    two.bad("conserved", ["m1 + m2"], ["m1 + m2"], "constant")
    kepler.bad(
        "conserved",
        ["m r^2 phi_dot - r (m r phi_dot)"],
        ["m*r**2*phi_dot - r*(m*r*phi_dot)"],
        "constant",
    )

    bottom = hoop.expression(
        "sqrt(g/R - omega**2)", {"g": P, "R": P, "omega": P}, "bottom_frequency"
    )
    bottom.ok("sqrt(g - omega^2 R)/sqrt(R)", "sqrt(g - omega**2*R)/sqrt(R)", "one_root")
    bottom.ok("sqrt(g/R) sqrt(1 - omega^2 R/g)", "sqrt(g/R)*sqrt(1 - omega**2*R/g)", "factored")
    bottom.bad("sqrt(omega^2 - g/R)", "sqrt(omega**2 - g/R)", "wrong_sign")
    bottom.bad("sqrt(g/R)", "sqrt(g/R)", "missing_centripetal")
