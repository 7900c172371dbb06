"""A batch: the kernel rows of one run's spec (law, scene, RunSpec), switching on only the effects the scene calls
for."""
from dataclasses import dataclass

import numpy as np

from ..resolution import joined, needs_tangential, step_caps
from ..submodels.registry import COULOMB_RULES, GEOMETRIES, INTEGRATORS, TOUCHES, check_parameters, kernel_code
from ..submodels.tangential_damping import CONE_CODES
from . import codes as C
from .dispatch import TANGENTIAL_NONE

NORATCH_WALL_RADIUS = 1e8      # slip 'noratch': the wall's reference radius 1e8 R in the noRatch slip factor


@dataclass
class Batch:
    """Kernel input for one spec (one sweep at one target e_n, its time step and step cap), with the incident
    conditions kept for the results table."""
    spec: object                # harness.resolution.RunSpec
    params: np.ndarray
    ints: np.ndarray
    tangential_active: np.ndarray

    e_n = property(lambda self: self.spec.e_n)
    dt = property(lambda self: self.spec.dt)
    steps_per_contact = property(lambda self: self.spec.steps_per_contact)
    v_n0 = property(lambda self: self.spec.v_n0)
    v_t0 = property(lambda self: self.spec.v_t0)
    omega0 = property(lambda self: self.spec.omega0)
    theta_deg = property(lambda self: self.spec.theta_deg)


def join(batches):
    """One batch holding the impacts of several batches of one material and one dt (one engine run)."""
    return Batch(joined([b.spec for b in batches]), *(np.concatenate([getattr(b, name) for b in batches])
                                                      for name in ("params", "ints", "tangential_active")))


def centres_less_radius(scene):
    """R1 + R2 - R*: where the pair stepper puts the target's centre below the equivalent sphere's (solver/pair.py)."""
    if not scene.spheres:
        raise ValueError("the pair integrator needs two spheres")
    projectile, target = scene.spheres
    return projectile.radius + target.radius - scene.contact.radius


def contact_point_lever(scene):
    """c of the torque lever R* - c alpha that gives each body the lever R_i - alpha/2 (docs/two-spheres.md): from
    dw*/dt = -F_t (R1 (R1 - alpha/2)/I1 + R2 (R2 - alpha/2)/I2)/R* with w* = (R1 w1 + R2 w2)/R* and solid spheres,
    c = m* R* (1/(m1 R1) + 1/(m2 R2))/2 (a fixed target's term 0); 1/2 against a wall."""
    if not scene.spheres:
        return 0.5
    projectile, target = scene.spheres
    contact = scene.contact
    spread = 1.0 / (projectile.mass * projectile.radius) + (0.0 if target.fixed else
                                                              1.0 / (target.mass * target.radius))
    return 0.5 * contact.mass * contact.radius * spread


def batch_of(law, scene, spec, every_effect=False):
    """Kernel rows for every impact of the scene at the spec's e_n, time step and step cap (each impact's own cap,
    step_caps, at most the spec's). every_effect: the tangential model on every row whether the scene calls for it
    or not (what benchmarks/bench_effects.py measures the saving against)."""
    contact, e_n = scene.contact, spec.e_n
    v_n0, v_t0, omega0 = spec.v_n0, spec.v_t0, spec.omega0
    normal = law.normal.parameters(contact, e_n, scene.speed)
    dashpot = law.damping.dashpot(law.normal, contact, e_n, scene.speed, law.end)
    tangential = np.ones(len(v_n0), dtype=bool) if every_effect else needs_tangential(scene, v_t0, omega0, law)
    n = len(v_n0)
    params = np.zeros((n, C.N_PARAMS))
    params[:, C.P_MASS] = contact.mass
    params[:, C.P_INERTIA] = contact.inertia
    params[:, C.P_RADIUS] = contact.radius
    params[:, C.P_DT] = spec.dt
    params[:, C.P_GRAVITY] = scene.gravity
    params[:, C.P_MU] = scene.mu
    params[:, C.P_N1:C.P_N4 + 1] = check_parameters(law.normal, normal)
    params[:, C.P_DAMP_C0] = dashpot.c0
    params[:, C.P_DAMP_POWER] = dashpot.power
    if tangential.any():
        params[:, C.P_T1] = k_t = law.tangential.parameter(contact, normal.linear_stiffness)
        constant_k_t = k_t if law.tangential.constant_stiffness else None
        params[:, C.P_TDAMP] = law.tangential_damping.prefactor(contact, dashpot, normal.linear_stiffness,
                                                                constant_k_t, e_n)
        params[:, C.P_TCONE] = CONE_CODES[law.tangential_damping.cone]
    params[:, C.P_LEVER] = law.lever
    params[:, C.P_TORQUE_LEVER] = law.lever if law.torque == "lever" else contact_point_lever(scene)
    pair = GEOMETRIES[law.geometry].pair
    if pair:                                              # each body's own levers R_i - c alpha and spins
        params[:, C.P_TORQUE_LEVER] = law.lever if law.torque == "lever" else 0.5
        projectile, target = scene.spheres
        params[:, C.P_R1], params[:, C.P_R2], params[:, C.P_W2] = projectile.radius, target.radius, target.omega
        params[:, C.P_INV_I1] = 1.0 / projectile.inertia
        params[:, C.P_INV_I2] = 0.0 if target.fixed else 1.0 / target.inertia
    params[:, C.P_BIG_R] = (law.normal.stand_in_radius(contact) if law.geometry == "stand-in-sphere" else
                            centres_less_radius(scene) if pair else 0.0)
    params[:, C.P_SLIP_R1] = (NORATCH_WALL_RADIUS * contact.radius if law.slip == "noratch" else
                              contact.radius if law.slip == "noratch-sphere" else
                              centres_less_radius(scene) if law.slip == "noratch-pair" else 0.0)
    params[:, C.P_VZ0] = -v_n0
    params[:, C.P_VX0] = v_t0
    params[:, C.P_W0] = omega0
    params[:, C.P_MAXSTEPS] = np.minimum(step_caps(scene, e_n, v_n0, spec.steps_per_contact), spec.step_cap)
    ints = np.zeros((n, C.N_INTS), dtype=np.int64)
    ints[:, C.I_NORMAL] = kernel_code(law.normal)
    ints[:, C.I_END] = C.END_ALPHA if law.end == "tension" else C.END_FORCE
    ints[:, C.I_TANGENTIAL] = np.where(tangential, kernel_code(law.tangential), TANGENTIAL_NONE)
    ints[:, C.I_INTEGRATOR] = INTEGRATORS[law.integrator].code
    ints[:, C.I_COULOMB] = COULOMB_RULES[law.coulomb].code
    ints[:, C.I_GEOMETRY] = GEOMETRIES[law.geometry].code
    ints[:, C.I_TOUCH] = TOUCHES[law.touch].code
    return Batch(spec, params, ints, tangential)
