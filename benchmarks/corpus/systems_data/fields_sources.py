"""Charged particles in magnetic fields (two gauges, and crossed fields) and relativistic
particles: Landau & Lifshitz vol. 2 (The Classical Theory of Fields, 4th ed.), a Cambridge
Tripos question, and the gauges of D. Tong's quantum Hall lectures. SI units (L = m v²/2 +
q v·A − q φ), charge q > 0, field B along z."""

from __future__ import annotations

from benchmarks.corpus.systems_dsl import System

LL2 = "Landau & Lifshitz, The Classical Theory of Fields, 4th ed. (1975), "
P = "positive"


def landau_gauge() -> System:
    s = System(
        "tripos_landau_gauge",
        "Cambridge Mathematical Tripos Part II 2011, Paper 1, Section I, Classical Dynamics "
        "(L = m x'^2/2 - q(phi - x'·A) with phi = 0, A = (0, x B, 0)), "
        "https://questions.tripos.org/part-ii/2011-19; the same Landau gauge as D. Tong, "
        "Lectures on the Quantum Hall Effect (arXiv:1606.06687), §1.4 (Landau levels)",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*x*y_dot",
        ["x", "y"],
        {"m": P, "q": P, "B": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (x_dot^2 + y_dot^2) + q B x y_dot", L, "plain")
    s.ok(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + 1/2 q B (x y_dot - y x_dot)",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*(x*y_dot - y*x_dot)/2",
        "symmetric_gauge",
    )
    s.ok(
        "lagrangian",
        "½ m (ẋ² + ẏ²) − q B y ẋ",
        "m*(x_dot**2 + y_dot**2)/2 - q*B*y*x_dot",
        "other_landau_gauge_unicode",
    )
    s.ok(
        "lagrangian",
        r"\frac{1}{2} m (\dot{x}^2 + \dot{y}^2) + qB x\dot{y}",
        L,
        "latex_adjacent_letters",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) - q B x y_dot",
        "m*(x_dot**2 + y_dot**2)/2 - q*B*x*y_dot",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + 1/2 q B x y_dot",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*x*y_dot/2",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + q B y x_dot",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*y*x_dot",
        "wrong_sign",
    )
    ex, ey = "m*x_ddot - q*B*y_dot", "m*y_ddot + q*B*x_dot"
    s.ok("eom", ["m x_ddot = q B y_dot", "m y_ddot = -q B x_dot"], [ex, ey])
    s.ok(
        "eom",
        ["m x_ddot - q B y_dot = 0", "d/dt(m y_dot + q B x) = 0"],
        [ex, "Dt(m*y_dot + q*B*x)"],
        "conservation_form",
    )
    s.ok(
        "eom",
        [r"\ddot x = \frac{qB}{m}\dot y", r"\ddot y = -\frac{qB}{m}\dot x"],
        [f"({ex})/m", f"({ey})/m"],
        "latex",
    )
    s.bad(
        "eom",
        ["m x_ddot = -q B y_dot", "m y_ddot = q B x_dot"],
        ["m*x_ddot + q*B*y_dot", "m*y_ddot - q*B*x_dot"],
        "wrong_sign",
    )
    s.bad("eom", ["m x_ddot = q B y_dot", "m y_ddot = 0"], [ex, "m*y_ddot"], "missing_term")
    s.ok(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot + q B x"],
        ["p_x = m*x_dot", "p_y = m*y_dot + q*B*x"],
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot"],
        ["p_x = m*x_dot", "p_y = m*y_dot"],
        "kinetic_momentum",
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot - 1/2 q B y", "p_y = m y_dot + 1/2 q B x"],
        ["p_x = m*x_dot - q*B*y/2", "p_y = m*y_dot + q*B*x/2"],
        "other_lagrangian",
    )
    s.ok("cyclic", "y", ["y"], "one")
    s.bad("cyclic", "x", ["x"], "other_lagrangian")
    s.bad("cyclic", "none", [], "missed_cyclic")
    py, gx = "m*y_dot + q*B*x", "m*x_dot - q*B*y"
    E = "m*(x_dot**2 + y_dot**2)/2"
    s.ok("conserved", ["m y_dot + q B x"], [py], "canonical_momentum")
    s.ok("conserved", ["m x_dot - q B y"], [gx], "other_guiding_centre")
    s.ok(
        "conserved",
        ["m y_dot + q B x", "m x_dot - q B y", "1/2 m (x_dot^2 + y_dot^2)"],
        [py, gx, E],
        "three_integrals",
    )
    s.bad("conserved", ["m y_dot"], ["m*y_dot"], "not_conserved")
    s.bad("conserved", ["m x_dot"], ["m*x_dot"], "not_conserved")
    e = s.expression("q*B/m", {"q": P, "B": P, "m": P}, "cyclotron_frequency")
    e.ok("B q/m", "B*q/m")
    e.bad("q B/(2 m)", "q*B/(2*m)", "factor_2")
    e.bad("m/(q B)", "m/(q*B)")
    return s


def symmetric_gauge() -> System:
    s = System(
        "symmetric_gauge_cartesian",
        "Charged particle in a uniform field B in the symmetric gauge A = (1/2)(-y B, x B, 0), "
        "as in D. Tong, Lectures on the Quantum Hall Effect (arXiv:1606.06687), §1.4, and "
        "Harvard Homework #3 (D. Ham, 2023) at https://fanyv88.com:443/https/www.scribd.com/document/"
        "824441707/HW3-2023; L = m v^2/2 + q v·A",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*(x*y_dot - y*x_dot)/2",
        ["x", "y"],
        {"m": P, "q": P, "B": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (x_dot^2 + y_dot^2) + 1/2 q B (x y_dot - y x_dot)", L)
    s.ok("lagrangian", "½ m (ẋ² + ẏ²) + ½ q B (x ẏ − y ẋ)", L, "unicode")
    s.ok(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + q B x y_dot",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*x*y_dot",
        "landau_gauge",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + 1/2 q B (x y_dot + y x_dot)",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*(x*y_dot + y*x_dot)/2",
        "wrong_sign",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) - 1/2 q B (x y_dot - y x_dot)",
        "m*(x_dot**2 + y_dot**2)/2 - q*B*(x*y_dot - y*x_dot)/2",
        "wrong_sign",
    )
    s.ok(
        "eom",
        ["m x_ddot - q B y_dot = 0", "m y_ddot + q B x_dot = 0"],
        ["m*x_ddot - q*B*y_dot", "m*y_ddot + q*B*x_dot"],
    )
    s.bad(
        "eom",
        ["m x_ddot - 1/2 q B y_dot = 0", "m y_ddot + 1/2 q B x_dot = 0"],
        ["m*x_ddot - q*B*y_dot/2", "m*y_ddot + q*B*x_dot/2"],
        "factor_2",
    )
    s.ok(
        "momenta",
        ["p_x = m x_dot - 1/2 q B y", "p_y = m y_dot + 1/2 q B x"],
        ["p_x = m*x_dot - q*B*y/2", "p_y = m*y_dot + q*B*x/2"],
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot + q B x"],
        ["p_x = m*x_dot", "p_y = m*y_dot + q*B*x"],
        "other_lagrangian",
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot"],
        ["p_x = m*x_dot", "p_y = m*y_dot"],
        "kinetic_momentum",
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "y", ["y"], "other_lagrangian")
    s.ok(
        "conserved",
        ["m (x y_dot - y x_dot) + 1/2 q B (x^2 + y^2)"],
        ["m*(x*y_dot - y*x_dot) + q*B*(x**2 + y**2)/2"],
        "canonical_angular_momentum",
    )
    s.ok(
        "conserved",
        ["m y_dot + q B x", "m x_dot - q B y"],
        ["m*y_dot + q*B*x", "m*x_dot - q*B*y"],
        "guiding_centre",
    )
    s.bad("conserved", ["m y_dot + 1/2 q B x"], ["m*y_dot + q*B*x/2"], "not_conserved")
    s.bad("conserved", ["m (x y_dot - y x_dot)"], ["m*(x*y_dot - y*x_dot)"], "not_conserved")
    return s


def symmetric_gauge_polar() -> System:
    s = System(
        "symmetric_gauge_polar",
        "The symmetric gauge of D. Tong, Lectures on the Quantum Hall Effect (arXiv:1606.06687),"
        " §1.4, in plane polar coordinates: A = (B r/2) phi-hat, L = m(r'^2 + r^2 phi'^2)/2 "
        "+ q B r^2 phi'/2",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 + q*B*r**2*phi_dot/2",
        {"r": "positive", "phi": None},
        {"m": P, "q": P, "B": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (r_dot^2 + r^2 phi_dot^2) + 1/2 q B r^2 phi_dot", L)
    s.ok("lagrangian", "½ m (ṙ² + r² φ̇²) + ½ q B r² φ̇", L, "unicode")
    s.ok(
        "lagrangian",
        r"\frac{m}{2}\left(\dot r^2 + r^2\dot\phi^2\right) + \frac{1}{2} q B r^2\dot\phi",
        L,
        "latex",
    )
    s.bad(
        "lagrangian",
        "1/2 m (r_dot^2 + r^2 phi_dot^2) + q B r^2 phi_dot",
        "m*(r_dot**2 + r**2*phi_dot**2)/2 + q*B*r**2*phi_dot",
        "factor_2",
    )
    s.bad(
        "lagrangian",
        "1/2 m r_dot^2 + 1/2 q B r^2 phi_dot",
        "m*r_dot**2/2 + q*B*r**2*phi_dot/2",
        "missing_term",
    )
    er = "m*r_ddot - m*r*phi_dot**2 - q*B*r*phi_dot"
    ep = "m*r**2*phi_ddot + 2*m*r*r_dot*phi_dot + q*B*r*r_dot"
    s.ok(
        "eom",
        [
            "m r_ddot - m r phi_dot^2 - q B r phi_dot = 0",
            "m r^2 phi_ddot + 2 m r r_dot phi_dot + q B r r_dot = 0",
        ],
        [er, ep],
    )
    s.ok(
        "eom",
        ["m r̈ = m r φ̇² + q B r φ̇", "d/dt(m r² φ̇ + ½ q B r²) = 0"],
        [er, "Dt(m*r**2*phi_dot + q*B*r**2/2)"],
        "unicode_conservation_form",
    )
    s.bad(
        "eom",
        [
            "m r_ddot - m r phi_dot^2 - q B r phi_dot = 0",
            "m r^2 phi_ddot + 2 m r r_dot phi_dot = 0",
        ],
        [er, "m*r**2*phi_ddot + 2*m*r*r_dot*phi_dot"],
        "wrong_chain_rule",
    )
    s.bad(
        "eom",
        ["m r_ddot - m r phi_dot^2 = 0", "m r^2 phi_ddot + 2 m r r_dot phi_dot + q B r r_dot = 0"],
        ["m*r_ddot - m*r*phi_dot**2", ep],
        "missing_term",
    )
    s.ok(
        "momenta",
        ["p_r = m r_dot", "p_phi = m r^2 phi_dot + 1/2 q B r^2"],
        ["p_r = m*r_dot", "p_phi = m*r**2*phi_dot + q*B*r**2/2"],
    )
    s.bad(
        "momenta",
        ["p_r = m r_dot", "p_phi = m r^2 phi_dot"],
        ["p_r = m*r_dot", "p_phi = m*r**2*phi_dot"],
        "kinetic_momentum",
    )
    s.ok("cyclic", "phi", ["phi"], "one")
    s.bad("cyclic", "none", [], "missed_cyclic")
    s.ok(
        "conserved",
        ["m r^2 phi_dot + 1/2 q B r^2", "1/2 m (r_dot^2 + r^2 phi_dot^2)"],
        ["m*r**2*phi_dot + q*B*r**2/2", "m*(r_dot**2 + r**2*phi_dot**2)/2"],
        "momentum_and_energy",
    )
    s.bad("conserved", ["m r^2 phi_dot"], ["m*r**2*phi_dot"], "not_conserved")
    e = s.expression("-q*B/m", {"q": P, "B": P, "m": P}, "circular_orbit_rate")
    e.ok("-(q B)/m", "-(q*B)/m")
    e.bad("q B/m", "q*B/m", "wrong_sign")
    e.bad("-q B/(2 m)", "-q*B/(2*m)", "factor_2")
    return s


def relativistic_in_field() -> System:
    s = System(
        "relativistic_uniform_field",
        LL2 + "§8 (free particle, L = -m c^2 sqrt(1 - v^2/c^2)), §16 (charge in a field) and "
        "§20 (motion in a constant uniform electric field: x = (m c^2/(q E)) sqrt(1 + "
        "(q E t/(m c))^2) for a start from rest), on a line, SI units",
        "-m*c**2*sqrt(1 - x_dot**2/c**2) + q*E*x",
        ["x"],
        {"m": P, "c": P, "q": P, "E": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "-m c^2 sqrt(1 - x_dot^2/c^2) + q E x", L)
    s.ok(
        "lagrangian",
        "-m c sqrt(c^2 - x_dot^2) + q E x",
        "-m*c*sqrt(c**2 - x_dot**2) + q*E*x",
        "root_rewritten",
    )
    s.ok("lagrangian", r"-mc^2\sqrt{1-\dot{x}^2/c^2} + qEx", L, "latex_adjacent_letters")
    s.ok("lagrangian", "−m c² √(1 − ẋ²/c²) + q E x", L, "unicode_root")
    s.bad("lagrangian", "1/2 m x_dot^2 + q E x", "m*x_dot**2/2 + q*E*x", "nonrelativistic")
    s.bad(
        "lagrangian",
        "m c^2 sqrt(1 - x_dot^2/c^2) + q E x",
        "m*c**2*sqrt(1 - x_dot**2/c**2) + q*E*x",
        "wrong_sign",
    )
    s.ok(
        "eom",
        ["d/dt(m x_dot/sqrt(1 - x_dot^2/c^2)) = q E"],
        ["Dt(m*x_dot/sqrt(1 - x_dot**2/c**2)) - q*E"],
        "momentum_form",
    )
    s.ok(
        "eom",
        ["m x_ddot/(1 - x_dot^2/c^2)^(3/2) = q E"],
        ["m*x_ddot/(1 - x_dot**2/c**2)**(3/2) - q*E"],
        "gamma_cubed",
    )
    s.ok(
        "eom",
        ["x_ddot = q E/m (1 - x_dot^2/c^2)^(3/2)"],
        ["x_ddot - q*E/m*(1 - x_dot**2/c**2)**(3/2)"],
        "solved",
    )
    s.bad("eom", ["m x_ddot = q E"], ["m*x_ddot - q*E"], "nonrelativistic")
    s.bad(
        "eom",
        ["m x_ddot/sqrt(1 - x_dot^2/c^2) = q E"],
        ["m*x_ddot/sqrt(1 - x_dot**2/c**2) - q*E"],
        "wrong_chain_rule",
    )
    s.ok(
        "momenta",
        ["p_x = m x_dot/sqrt(1 - x_dot^2/c^2)"],
        ["p_x = m*x_dot/sqrt(1 - x_dot**2/c**2)"],
    )
    s.ok(
        "momenta",
        ["p_x = m c x_dot/sqrt(c^2 - x_dot^2)"],
        ["p_x = m*c*x_dot/sqrt(c**2 - x_dot**2)"],
        "root_rewritten",
    )
    s.bad("momenta", ["p_x = m x_dot"], ["p_x = m*x_dot"], "nonrelativistic")
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "x", ["x"], "not_cyclic")
    s.ok(
        "conserved",
        ["m c^2/sqrt(1 - x_dot^2/c^2) - q E x"],
        ["m*c**2/sqrt(1 - x_dot**2/c**2) - q*E*x"],
        "energy",
    )
    s.bad("conserved", ["1/2 m x_dot^2 - q E x"], ["m*x_dot**2/2 - q*E*x"], "nonrelativistic")
    s.bad(
        "conserved",
        ["m x_dot/sqrt(1 - x_dot^2/c^2)"],
        ["m*x_dot/sqrt(1 - x_dot**2/c**2)"],
        "not_conserved",
    )
    params = {"m": P, "c": P, "q": P, "E": P, "t": "real"}
    e = s.expression("m*c**2/(q*E)*sqrt(1 + (q*E*t/(m*c))**2)", params, "trajectory")
    e.ok("sqrt((m c^2)^2 + (q E c t)^2)/(q E)", "sqrt((m*c**2)**2 + (q*E*c*t)**2)/(q*E)")
    e.bad("m c^2/(q E) + q E t^2/(2 m)", "m*c**2/(q*E) + q*E*t**2/(2*m)", "nonrelativistic")
    e.bad("m c^2/(q E) sqrt(1 + q E t/(m c))", "m*c**2/(q*E)*sqrt(1 + q*E*t/(m*c))")
    f = s.expression("q*E*c*t/sqrt((m*c)**2 + (q*E*t)**2)", params, "velocity")
    f.ok("c (q E t/(m c))/sqrt(1 + (q E t/(m c))^2)", "c*(q*E*t/(m*c))/sqrt(1 + (q*E*t/(m*c))**2)")
    f.bad("q E t/m", "q*E*t/m", "nonrelativistic")
    return s


def relativistic_free() -> System:
    s = System(
        "relativistic_free_particle",
        LL2 + "§8 (the action of a free material particle, L = -m c^2 sqrt(1 - v^2/c^2)) and "
        "§9 (p = m v/sqrt(1 - v^2/c^2), E = m c^2/sqrt(1 - v^2/c^2)), in the plane",
        "-m*c**2*sqrt(1 - (x_dot**2 + y_dot**2)/c**2)",
        ["x", "y"],
        {"m": P, "c": P},
    )
    L = s.problem["lagrangian"]
    g = "sqrt(1 - (x_dot**2 + y_dot**2)/c**2)"
    s.ok("lagrangian", "-m c^2 sqrt(1 - (x_dot^2 + y_dot^2)/c^2)", L)
    s.ok(
        "lagrangian",
        "-m c sqrt(c^2 - x_dot^2 - y_dot^2)",
        "-m*c*sqrt(c**2 - x_dot**2 - y_dot**2)",
        "root_rewritten",
    )
    s.bad("lagrangian", "1/2 m (x_dot^2 + y_dot^2)", "m*(x_dot**2 + y_dot**2)/2", "nonrelativistic")
    s.bad(
        "lagrangian",
        "-m c^2 sqrt(1 - x_dot^2/c^2) - m c^2 sqrt(1 - y_dot^2/c^2)",
        "-m*c**2*sqrt(1 - x_dot**2/c**2) - m*c**2*sqrt(1 - y_dot**2/c**2)",
        "missing_cross_term",
    )
    s.ok("eom", ["x_ddot = 0", "y_ddot = 0"], ["x_ddot", "y_ddot"], "uniform_motion")
    s.ok(
        "eom",
        [
            "d/dt(m x_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)) = 0",
            "d/dt(m y_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)) = 0",
        ],
        [f"Dt(m*x_dot/{g})", f"Dt(m*y_dot/{g})"],
        "momentum_form",
    )
    s.bad("eom", ["x_ddot = 0"], ["x_ddot"], "too_few_equations")
    s.ok(
        "momenta",
        [
            "p_x = m x_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)",
            "p_y = m y_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)",
        ],
        [f"p_x = m*x_dot/{g}", f"p_y = m*y_dot/{g}"],
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot/sqrt(1 - x_dot^2/c^2)", "p_y = m y_dot/sqrt(1 - y_dot^2/c^2)"],
        ["p_x = m*x_dot/sqrt(1 - x_dot**2/c**2)", "p_y = m*y_dot/sqrt(1 - y_dot**2/c**2)"],
        "missing_cross_term",
    )
    s.bad(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot"],
        ["p_x = m*x_dot", "p_y = m*y_dot"],
        "nonrelativistic",
    )
    s.ok("cyclic", "x, y", ["x", "y"], "both")
    s.bad("cyclic", "none", [], "missed_cyclic")
    s.ok(
        "conserved",
        ["m x_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)", "m y_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)"],
        [f"m*x_dot/{g}", f"m*y_dot/{g}"],
        "momenta",
    )
    s.ok("conserved", ["x_dot", "y_dot"], ["x_dot", "y_dot"], "velocities")
    s.ok("conserved", ["m c^2/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)"], [f"m*c**2/{g}"], "energy")
    s.bad(
        "conserved",
        [
            "m x_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)",
            "m y_dot/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)",
            "m c^2/sqrt(1 - (x_dot^2 + y_dot^2)/c^2)",
        ],
        [f"m*x_dot/{g}", f"m*y_dot/{g}", f"m*c**2/{g}"],
        "not_independent",
    )
    s.bad("conserved", ["x"], ["x"], "not_conserved")
    return s


def crossed_fields() -> System:
    s = System(
        "crossed_fields_drift",
        LL2 + "§22 (motion in constant uniform electric and magnetic fields; drift velocity "
        "c E/H in Gaussian units, E/B in SI), non-relativistic, with E along y, B along z, "
        "A = (0, x B, 0) and phi = -E y",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*x*y_dot + q*E*y",
        ["x", "y"],
        {"m": P, "q": P, "B": P, "E": P},
    )
    L = s.problem["lagrangian"]
    s.ok("lagrangian", "1/2 m (x_dot^2 + y_dot^2) + q B x y_dot + q E y", L)
    s.ok(
        "lagrangian",
        "½ m (ẋ² + ẏ²) − q B y ẋ + q E y",
        "m*(x_dot**2 + y_dot**2)/2 - q*B*y*x_dot + q*E*y",
        "other_landau_gauge",
    )
    s.bad(
        "lagrangian",
        "1/2 m (x_dot^2 + y_dot^2) + q B x y_dot - q E y",
        "m*(x_dot**2 + y_dot**2)/2 + q*B*x*y_dot - q*E*y",
        "sign_of_V",
    )
    s.ok(
        "eom",
        ["m x_ddot = q B y_dot", "m y_ddot = q E - q B x_dot"],
        ["m*x_ddot - q*B*y_dot", "m*y_ddot - q*E + q*B*x_dot"],
    )
    s.bad(
        "eom",
        ["m x_ddot = q B y_dot", "m y_ddot = -q B x_dot"],
        ["m*x_ddot - q*B*y_dot", "m*y_ddot + q*B*x_dot"],
        "missing_term",
    )
    s.ok(
        "momenta",
        ["p_x = m x_dot", "p_y = m y_dot + q B x"],
        ["p_x = m*x_dot", "p_y = m*y_dot + q*B*x"],
    )
    s.ok("cyclic", "none", [], "none")
    s.bad("cyclic", "y", ["y"], "not_cyclic")
    s.ok(
        "conserved",
        ["1/2 m (x_dot^2 + y_dot^2) - q E y", "m x_dot - q B y"],
        ["m*(x_dot**2 + y_dot**2)/2 - q*E*y", "m*x_dot - q*B*y"],
        "energy_and_guiding_centre",
    )
    s.bad("conserved", ["m y_dot + q B x"], ["m*y_dot + q*B*x"], "not_conserved")
    s.bad(
        "conserved", ["1/2 m (x_dot^2 + y_dot^2)"], ["m*(x_dot**2 + y_dot**2)/2"], "not_conserved"
    )
    e = s.expression("E/B", {"E": P, "B": P}, "drift_velocity")
    e.ok(r"\frac{E}{B}", "E/B", "latex")
    e.bad("B/E", "B/E")
    return s


SYSTEMS = (
    landau_gauge,
    symmetric_gauge,
    symmetric_gauge_polar,
    relativistic_in_field,
    relativistic_free,
    crossed_fields,
)
