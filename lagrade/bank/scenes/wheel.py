"""A wheel turning freely on a fixed axle: a rigid body whose only freedom is its rotation,
L = ½ I θ̇², with θ cyclic."""

from lagrade.mechanics.scene import RigidBody, Scene, param

SCENE = Scene(
    id="wheel",
    title="Freely rotating wheel",
    statement=(
        "A wheel of mass m and moment of inertia I about its axle turns without friction on a "
        "fixed horizontal axle. Use its angle of rotation {theta}. Count the degrees of freedom, "
        "find L and the conserved quantities."
    ),
    coordinates=("theta",),
    parameters=(
        param("m", "positive", "kg", (1.0, 2.0, 5.0), "mass of the wheel"),
        param("I", "positive", "kg m^2", (0.05, 0.1, 0.2), "moment of inertia about the axle"),
    ),
    bodies=lambda s: (RigidBody("wheel", s.m, (0, 0), s.I, s.theta),),
    potential=lambda s, bodies: 0,
    # The axle holds the centre at the origin.
    constraints=lambda s, c: (c.wheel.x, c.wheel.y),
    renames={"theta": ("theta", "phi", "psi")},
    tags=("lecture", "rigid_body"),
)
