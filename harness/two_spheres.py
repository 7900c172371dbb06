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
from dataclasses import dataclass

import pandas as pd

from .errors import UserError
from .scene import Scene


@dataclass(frozen=True)
class Sphere:
    """One body: radius, material, and its velocity at first touch (v_n towards the other sphere, v_t along x, omega
    about y); a fixed sphere neither moves nor turns whatever its mass."""
    radius: float
    E: float = 70e9
    nu: float = 0.3
    rho: float = 2650.0
    v_n: float = 0.0
    v_t: float = 0.0
    omega: float = 0.0
    fixed: bool = False

    @property
    def mass(self):
        return 4.0 / 3.0 * math.pi * self.radius ** 3 * self.rho

    @property
    def inertia(self):
        return 0.4 * self.mass * self.radius ** 2


def effective(projectile, target):
    """(R*, m*) of the pair: R1 R2/(R1 + R2) and 1/(1/m1 + 1/m2), the target's 1/m2 = 0 when fixed."""
    inverse_mass = 1.0 / projectile.mass + (0.0 if target.fixed else 1.0 / target.mass)
    return projectile.radius * target.radius / (projectile.radius + target.radius), 1.0 / inverse_mass


def equivalent_scene(projectile, target, e_n=0.5, mu=0.1):
    """The sphere-wall scene of the pair's relative motion (one impact, at target e_n)."""
    if projectile.fixed:
        raise UserError("the projectile cannot be fixed; fix the target")
    if target.fixed and (target.v_n or target.v_t or target.omega):
        raise UserError("a fixed target has no velocity or spin")
    speed = projectile.v_n + target.v_n
    if not speed > 0.0:
        raise UserError(f"the spheres must approach: v_n of projectile and target sum to {speed:g} m/s")
    r_star, m_star = effective(projectile, target)
    same = (target.E, target.nu) == (projectile.E, projectile.nu)
    wall = {"wall": "same"} if same else {"wall": "other", "wall_E": target.E, "wall_nu": target.nu}
    return Scene(radius=r_star, E=projectile.E, nu=projectile.nu, rho=m_star / (4.0 / 3.0 * math.pi * r_star ** 3),
                 mu=mu, speed=speed, e_n=(e_n,), angles_deg=None, psi1_star=None,
                 v_t=(projectile.v_t - target.v_t,),
                 omega0=(projectile.radius * projectile.omega + target.radius * target.omega) / r_star,
                 material="two spheres", **wall)


def collide(law, projectile, target, e_n=0.5, mu=0.1, steps_per_contact=1000):
    """One collision of two spheres under a paper law (levers R1, R2): a one-row table with the equivalent impact's
    results (its v_n1, v_t1, omega1 are the relative motion's; t_contact, f_n_max, overlap_max the contact's) and each
    body's velocities after it (v1_n, v1_t, omega1_after, v2_n, v2_t, omega2_after, the same conventions as the
    inputs) with the impulses J_n, J_t on the projectile."""
    from .solver.reference import simulate
    if law.lever != 0.0 or law.slip != "lever":
        raise UserError(f"two spheres reduce to one only with levers R1 and R2; {law.name} in the {law.dialect} "
                        f"dialect has lever {law.describe()['lever']} and slip {law.slip}")
    scene = equivalent_scene(projectile, target, e_n, mu)
    frame = simulate(law, scene, steps_per_contact=steps_per_contact)[0]
    _, m_star = effective(projectile, target)
    row = frame.iloc[0]
    j_n = m_star * (row.v_n1 + scene.speed)
    j_t = m_star * (row.v_t1 - (projectile.v_t - target.v_t))
    moving = 0.0 if target.fixed else 1.0
    after = {"J_n": j_n, "J_t": j_t,
             "v1_n": projectile.v_n - j_n / projectile.mass, "v1_t": projectile.v_t + j_t / projectile.mass,
             "omega1_after": projectile.omega - projectile.radius * j_t / projectile.inertia,
             "v2_n": target.v_n - moving * j_n / target.mass, "v2_t": target.v_t - moving * j_t / target.mass,
             "omega2_after": target.omega - moving * target.radius * j_t / target.inertia}
    return pd.concat([frame.reset_index(drop=True), pd.DataFrame([after])], axis=1)
