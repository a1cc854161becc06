"""A free particle in space under a conservative force: the Euler–Lagrange equations are
Newton's second law, m r̈ = −∇V."""

from sympy import Rational

from lagrade.mechanics.scene import PointMass, Scene, param

_HALF = Rational(1, 2)

# Concrete potentials stand in for a general V(x, y, z), which would need undefined functions.
_POTENTIALS = {
    "harmonic": lambda s: _HALF * s.k * (s.x**2 + s.y**2 + s.z**2),
    "gravity": lambda s: s.m * s.g * s.z,
    "anisotropic": lambda s: _HALF * s.k * (s.x**2 + s.y**2) + _HALF * s.k_z * s.z**2,
}

SCENE = Scene(
    id="free_particle",
    title="Particle in a potential",
    statement=(
        "A particle of mass m moves freely in space under a conservative force with potential "
        "V(x, y, z); use its Cartesian coordinates {x}, {y}, {z} (z up). Take {potential}. Show "
        "that the Euler-Lagrange equations are Newton's second law: m times the acceleration "
        "equals -grad V."
    ),
    coordinates=("x", "y", "z"),
    parameters=(
        param("m", "positive", "kg", (0.5, 1.0, 2.0), "mass of the particle"),
        param("k", "positive", "N/m", (2.0, 5.0, 10.0), "spring constant of the harmonic force"),
        param("k_z", "positive", "N/m", (1.0, 4.0, 8.0), "vertical spring constant (anisotropic)"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
    ),
    bodies=lambda s: (PointMass("particle", s.m, (s.x, s.y, s.z)),),
    potential=lambda s, bodies: _POTENTIALS[s.opt["potential"]](s),
    options={"potential": tuple(_POTENTIALS)},
    wording={
        "potential": {
            "harmonic": "the harmonic potential V = k (x^2 + y^2 + z^2)/2",
            "gravity": "the potential of uniform gravity, V = m g z",
            "anisotropic": "the anisotropic harmonic potential V = k (x^2 + y^2)/2 + k_z z^2/2",
        }
    },
    tags=("lecture",),
)
