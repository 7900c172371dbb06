"""Geometry 'pair': two spheres in their relative motion, the normal turning, scalar shear along the tangent."""
NAME = "pair"
SUMMARY = "two spheres in their relative motion, the normal turning; scalar shear kept along the tangent"
SLOTS = ("centres_less_radius", "r1", "r2", "inv_i1", "inv_i2", "w2")
TWO_SPHERES = True          # two bodies: each one's radius, inertia and spin


def centres_less_radius(scene):
    """R1 + R2 - R*: where the pair stepper puts the target's centre below the equivalent sphere's (solver/pair.py)."""
    if not scene.spheres:
        raise ValueError("the pair integrator needs two spheres")
    projectile, target = scene.spheres
    return projectile.radius + target.radius - scene.contact.radius


def parameters(law, scene):
    """R1 + R2 - R*, both radii, both inverse inertias (0: a fixed target) and the target's spin."""
    offset = centres_less_radius(scene)
    projectile, target = scene.spheres
    return {"centres_less_radius": offset, "r1": projectile.radius, "r2": target.radius,
            "inv_i1": 1.0 / projectile.inertia, "inv_i2": 0.0 if target.fixed else 1.0 / target.inertia,
            "w2": target.omega}
