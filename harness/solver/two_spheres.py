"""Two spheres colliding, in the reference solver: the relative motion of two spheres is the wall impact of one
equivalent sphere (docs/two-spheres.md).

With levers R1 and R2 (the paper's laws), the contact sees the effective radius R* = R1 R2/(R1 + R2), the effective
mass 1/m* = 1/m1 + 1/m2 (1/m2 = 0 for a fixed target), E* and G* of the two materials, the relative velocities, and
the slip V_s = (v1_t - v2_t) - (R1 omega1 + R2 omega2), which a tangential impulse J changes by J (1/m* + R1^2/I1 +
R2^2/I2) = J/m* (1 + R*^2/(0.4 m* R*^2)) for solid spheres: exactly the wall impact of a solid sphere of radius R* and
mass m* spinning at (R1 omega1 + R2 omega2)/R* against a wall of the target's material. Each body's rebound follows
from the impulses J_n = m* (v_n1 + V) and J_t = m* (v_t1 - v_t0) of that impact.

Frame: the projectile above the target, the line of centres along z at contact; velocities along the line of
centres count positive towards the other sphere; tangential velocities along one x axis; spins about one y axis.
"""
import math
from dataclasses import replace

import numpy as np

from ..scenes.bodies import Sphere
from ..infra.errors import UserError
from ..scenes.scene import Scene, check_body
from .simulate import simulate


def effective(projectile, target):
    """(R*, m*) of the pair: R1 R2/(R1 + R2) and 1/(1/m1 + 1/m2), the target's 1/m2 = 0 when fixed."""
    inverse_mass = 1.0 / projectile.mass + (0.0 if target.fixed else 1.0 / target.mass)
    return projectile.radius * target.radius / (projectile.radius + target.radius), 1.0 / inverse_mass


def reduce(scene, target):
    """The wall impact equivalent to `scene`'s sphere (the projectile: its material and spin omega0, its sweep the
    velocities relative to the target) hitting `target` (a Sphere): radius R*, mass m*, spin (R1 omega1 + R2 omega2)/R*,
    a wall of the target's material; the scene's `spheres` keep both bodies."""
    check_body(target)
    if target.fixed and (target.v_n or target.v_t or target.omega):
        raise UserError("a fixed target has no velocity or spin")
    if scene.wall != "same":
        raise UserError("a sphere target has its own material: give it instead of --wall")
    projectile = Sphere(scene.radius, scene.E, scene.nu, scene.rho, omega=scene.omega0)
    r_star, m_star = effective(projectile, target)
    same = (target.E, target.nu) == (projectile.E, projectile.nu)
    wall = {"wall": "same"} if same else {"wall": "other", "wall_E": target.E, "wall_nu": target.nu}
    return replace(scene, radius=r_star, rho=m_star / (4.0 / 3.0 * math.pi * r_star ** 3),
                   omega0=(projectile.radius * projectile.omega + target.radius * target.omega) / r_star,
                   material=f"{scene.material} on a sphere", spheres=(projectile, target), **wall)


def equivalent_scene(projectile, target, e_n=0.5, mu=0.1):
    """The sphere-wall scene of the pair's relative motion (one impact, at target e_n)."""
    if projectile.fixed:
        raise UserError("the projectile cannot be fixed; fix the target")
    speed = projectile.v_n + target.v_n
    if not speed > 0.0:
        raise UserError(f"the spheres must approach: v_n of projectile and target sum to {speed:g} m/s")
    own = Scene(radius=projectile.radius, E=projectile.E, nu=projectile.nu, rho=projectile.rho, mu=mu, speed=speed,
                e_n=(e_n,), angles_deg=None, v_t=(abs(projectile.v_t - target.v_t),), omega0=projectile.omega,
                material="two spheres")
    return reduce(own, target)


def with_bodies(frame, scene):
    """`frame` (the equivalent impacts of a two-sphere scene) with each body's velocities after the collision and the
    impulses on the projectile: J_n = m* (v_n1 + v_n0), J_t = m* (v_t1 - v_t0), applied to the projectile (its incident
    velocity the relative one plus the target's) and, opposite, to the target unless it is fixed. Each spin takes
    -(R_i J_t - M/2)/I_i, M = int alpha F_t dt the moment of a lever R_i - alpha/2 (0 for levers R_i), found from the
    equivalent spin: R* (w* - w*0) = -J_t (R1^2/I1 + R2^2/I2) + M/2 (R1/I1 + R2/I2)."""
    projectile, target = scene.spheres
    r_star, m_star = effective(projectile, target)
    j_n = m_star * (frame.v_n1 + frame.v_n0)
    j_t = m_star * (frame.v_t1 - frame.v_t0)
    moving = 0.0 if target.fixed else 1.0
    r1, i1, r2, i2 = projectile.radius, projectile.inertia, target.radius, target.inertia
    half_moment = ((r_star * (frame.omega1 - frame.omega0) + j_t * (r1 * r1 / i1 + moving * r2 * r2 / i2))
                   / (r1 / i1 + moving * r2 / i2))
    after = {"J_n": j_n, "J_t": j_t,
             "v1_n": frame.v_n0 - target.v_n - j_n / projectile.mass,
             "v1_t": frame.v_t0 + target.v_t + j_t / projectile.mass,
             "omega1_after": projectile.omega - (r1 * j_t - half_moment) / i1,
             "v2_n": target.v_n - moving * j_n / target.mass, "v2_t": target.v_t - moving * j_t / target.mass,
             "omega2_after": target.omega - moving * (r2 * j_t - half_moment) / i2}
    return frame.assign(**{k: np.asarray(v, dtype=float) for k, v in after.items()})


def collide(law, projectile, target, e_n=0.5, mu=0.1, steps_per_contact=1000):
    """One collision of two spheres under a paper law (levers R1, R2): a one-row table with the equivalent impact's
    results (its v_n1, v_t1, omega1 are the relative motion's; t_contact, f_n_max, overlap_max the contact's) and each
    body's velocities after it (v1_n, v1_t, omega1_after, v2_n, v2_t, omega2_after, the same conventions as the
    inputs) with the impulses J_n, J_t on the projectile."""
    refuse_engine_levers(law)
    scene = equivalent_scene(projectile, target, e_n, mu)
    flip = -1.0 if projectile.v_t - target.v_t < 0 else 1.0      # the sweep's v_t is >= 0: mirror x when it is not
    mirrored = (replace(scene, omega0=flip * scene.omega0,
                        spheres=tuple(replace(b, v_t=flip * b.v_t, omega=flip * b.omega) for b in scene.spheres)))
    frame = with_bodies(simulate(law, mirrored, steps_per_contact=steps_per_contact)[0].reset_index(drop=True),
                        mirrored)
    for column in ("v_t0", "v_t1", "omega0", "omega1", "J_t", "v1_t", "omega1_after", "v2_t", "omega2_after"):
        frame[column] = flip * frame[column]
    return frame


def refuse_engine_levers(law):
    """Two spheres reduce to one wall impact only with slip levers R1, R2 (the torque's may be R_i - alpha/2: its
    equivalent lever is solver.batch.contact_point_lever) (UserError otherwise)."""
    if law.lever != 0.0 or law.slip != "lever":
        raise UserError(f"two spheres reduce to one only with levers R1 and R2; {law.name} in the {law.dialect} "
                        f"dialect has lever {law.describe()['lever']} and slip {law.slip}")
