"""A particle sliding on the inside of a cone with its vertex down: the azimuth is cyclic and a
circular orbit needs one particular angular velocity at each radius."""

from sympy import cos, sin, sqrt, tan

from lagrade.mechanics.scene import PointMass, Quantity, Scene, gravity, param

SCENE = Scene(
    id="cone_particle",
    title="Particle on a cone",
    statement=(
        "A particle of mass m slides without friction on the inside of a cone whose axis is "
        "vertical, vertex down, with half-angle alpha between the axis and the surface. Use its "
        "distance {r} from the axis and its azimuth {phi} about the axis. Follow-up: with what "
        "angular velocity does it go round a horizontal circle of radius r_0?"
    ),
    coordinates=("r", "phi"),
    parameters=(
        param("m", "positive", "kg", (0.05, 0.1, 0.2), "mass of the particle"),
        param("alpha", "(0, pi/2)", "rad", (0.5236, 0.7854, 1.0472), "half-angle of the cone"),
        param("g", "positive", "m/s^2", (9.81,), "gravitational acceleration"),
        param("r_0", "positive", "m", (0.1, 0.2, 0.5), "radius of a circular orbit"),
    ),
    bodies=lambda s: (
        PointMass("particle", s.m, (s.r * cos(s.phi), s.r * sin(s.phi), s.r / tan(s.alpha))),
    ),
    potential=lambda s, bodies: gravity(s.g, bodies, axis="z"),
    constraints=lambda s, c: (
        c.particle.x**2 + c.particle.y**2 - (c.particle.z * tan(s.alpha)) ** 2,
    ),
    renames={"r": ("r", "rho"), "phi": ("phi", "theta")},
    quantities=(
        Quantity(
            "circular_angular_velocity",
            "angular velocity of the circular orbit of radius r_0",
            lambda s: sqrt(s.g / (s.r_0 * tan(s.alpha))),
            "rad/s",
        ),
    ),
)
