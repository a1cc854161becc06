"""A charge in a uniform magnetic field through a vector potential: L = ½ m v² + e v·A is a
velocity-dependent generalized potential, and which coordinates are cyclic depends on the gauge."""

from sympy import Rational

from lagrade.mechanics.scene import PointMass, Quantity, Scene, param

# A with curl A = B e_z, in three gauges.
_VECTOR_POTENTIALS = {
    "landau_y": lambda s: (0, s.B * s.x, 0),
    "landau_x": lambda s: (-s.B * s.y, 0, 0),
    "symmetric": lambda s: (-Rational(1, 2) * s.B * s.y, Rational(1, 2) * s.B * s.x, 0),
}


def _magnetic_potential(s):
    """U = −e v·A, so that L = T − U = ½ m v² + e v·A."""
    velocity = (s.x_dot, s.y_dot, s.z_dot)
    return -s.e * sum(
        v * a for v, a in zip(velocity, _VECTOR_POTENTIALS[s.opt["gauge"]](s), strict=True)
    )


SCENE = Scene(
    id="charged_particle",
    title="Charged particle in a magnetic field",
    statement=(
        "A particle of mass m and charge e moves in a uniform magnetic field B along the z axis. "
        "Describe the field by {gauge}, so that L = m v^2/2 + e v.A. Use the Cartesian "
        "coordinates {x}, {y}, {z}. Find the canonical momenta p = m v + e A and the cyclic "
        "coordinates. Which of them would change in another gauge?"
    ),
    coordinates=("x", "y", "z"),
    parameters=(
        param("m", "positive", "kg", (9.109e-31, 1.673e-27), "mass of the particle"),
        param("e", "positive", "C", (1.602e-19,), "charge of the particle"),
        param("B", "positive", "T", (0.5, 1.0, 2.0), "magnetic field strength"),
    ),
    bodies=lambda s: (PointMass("particle", s.m, (s.x, s.y, s.z)),),
    potential=lambda s, bodies: _magnetic_potential(s),
    options={"gauge": tuple(_VECTOR_POTENTIALS)},
    wording={
        "gauge": {
            "landau_y": "the vector potential A = (0, B x, 0) (a Landau gauge)",
            "landau_x": "the vector potential A = (-B y, 0, 0) (a Landau gauge)",
            "symmetric": "the vector potential A = (-B y, B x, 0)/2 (the symmetric gauge)",
        }
    },
    quantities=(
        Quantity(
            "cyclotron_frequency",
            "angular frequency of the circular motion in the plane perpendicular to B",
            lambda s: s.e * s.B / s.m,
            "rad/s",
        ),
    ),
    tags=("lecture", "velocity_dependent_potential"),
)
