"""Independent references for the bank's derivations: sympy.physics.mechanics and scipy."""

from __future__ import annotations

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics import mechanics as me

from lagrade.mechanics import lagrange as mech
from lagrade.mechanics.bodies import RigidBody
from lagrade.mechanics.scene import SceneVariant


def to_dynamic(variant: SceneVariant):
    """Substitutions jets → dynamicsymbols q(t) (and back), with our t → mechanics' t."""
    T_ = me.dynamicsymbols._t
    qs = [me.dynamicsymbols(j.name) for j in variant.jets]
    forward = {mech.t: T_}
    for j, q in zip(variant.jets, qs, strict=True):
        forward |= {j.q: q, j.dot: q.diff(T_), j.ddot: q.diff(T_, 2)}
    backward = []
    for j, q in zip(variant.jets, qs, strict=True):
        backward += [(q.diff(T_, 2), j.ddot), (q.diff(T_), j.dot), (q, j.q)]
    return qs, forward, backward + [(T_, mech.t)]


def lagranges_method_equations(variant: SceneVariant) -> list[sp.Expr]:
    """EL equations from sympy.physics.mechanics: T from Particle/RigidBody velocities in an
    inertial frame (not from our speed_squared), V as declared, LagrangesMethod for the EL."""
    qs, forward, backward = to_dynamic(variant)
    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)
    kinetic = sp.S.Zero
    for body in variant.bodies:
        coords = list(body.position) + [0] * (3 - len(body.position))
        axes = (N.x, N.y, N.z)
        r = sum(
            (sp.sympify(c).xreplace(forward) * a for c, a in zip(coords, axes, strict=True)),
            0 * N.x,
        )
        point = origin.locatenew(f"P_{body.name}", r)
        point.set_vel(N, r.dt(N))
        if isinstance(body, RigidBody):
            frame = me.ReferenceFrame(f"B_{body.name}")
            frame.orient_axis(N, N.z, sp.sympify(body.angle).xreplace(forward))
            inertia = me.inertia(frame, 0, 0, body.inertia)
            rb = me.RigidBody(body.name, point, frame, body.mass, (inertia, point))
            kinetic += rb.kinetic_energy(N)
        else:
            kinetic += me.Particle(body.name, point, body.mass).kinetic_energy(N)
    L = kinetic - variant.potential_energy.xreplace(forward)
    method = me.LagrangesMethod(L, qs)
    equations = method.form_lagranges_equations()
    return [sp.expand(e.subs(backward)) for e in equations]


def numeric_point(variant: SceneVariant) -> dict[sp.Symbol, float]:
    """Parameters of order one inside their sampling ranges, staggered (golden-ratio steps) so
    that no two coincide: equal masses would make an Atwood machine stand still."""
    point = {}
    for i, (name, sym) in enumerate(variant.parameter_symbols.items()):
        lo, hi = variant.domains[name].sample_range()
        fraction = (0.3 + 0.618034 * i) % 1.0
        point[sym] = lo + (hi - lo) * (0.15 + 0.7 * fraction)
    return point


def integrate(
    variant: SceneVariant, y0, t_end: float, method: str = "DOP853", rtol=1e-12, atol=1e-12
):
    """Integrate A q̈ = b numerically from y0 = (q, q̇); returns (t, y) with dense samples."""
    params = numeric_point(variant)
    jets = variant.jets
    A = variant.system.mass_matrix.xreplace(params)
    b = variant.system.forcing.xreplace(params)
    args = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    A_f = sp.lambdify(args, A, "numpy")  # bank expressions only, never student text
    b_f = sp.lambdify(args, b, "numpy")
    n = len(jets)

    def rhs(time, y):
        qdd = np.linalg.solve(
            np.array(A_f(time, *y), dtype=float), np.array(b_f(time, *y), dtype=float).ravel()
        )
        return np.concatenate([y[n:], qdd])

    sol = solve_ivp(
        rhs,
        (0.0, t_end),
        y0,
        method=method,
        rtol=rtol,
        atol=atol,
        dense_output=False,
        t_eval=np.linspace(0.0, t_end, 400),
    )
    assert sol.success, sol.message
    return sol.t, sol.y, params


def evaluate_along(variant: SceneVariant, expr: sp.Expr, ts, ys, params) -> np.ndarray:
    jets = variant.jets
    args = [mech.t] + [j.q for j in jets] + [j.dot for j in jets]
    f = sp.lambdify(args, expr.xreplace(params), "numpy")
    return np.array([float(f(time, *y)) for time, y in zip(ts, ys.T, strict=True)])


def term_scale(variant: SceneVariant, expr: sp.Expr, ts, ys, params) -> float:
    """The size of the terms of expr along the run: what a drift is measured against."""
    terms = sp.Add.make_args(sp.expand(expr))
    return max(float(np.max(np.abs(evaluate_along(variant, t, ts, ys, params)))) for t in terms)
