"""A batch: the kernel rows of one run's spec (law, scene, RunSpec), switching on only the effects the scene calls
for."""
import importlib
from dataclasses import dataclass

import numpy as np

from .approach import place
from .resolution import joined, needs_tangential, step_caps
from ..submodels.geometry.pair import centres_less_radius
from ..submodels.registry import check_parameters, code_of, kernel_code, kernel_of
from ..submodels.stepping import STEPPERS
from ..submodels.tangential_damping import CONE_CODES
from . import layout as L
from .dispatch import TANGENTIAL_NONE

NORATCH_WALL_RADIUS = 1e8      # slip 'noratch': the wall's reference radius 1e8 R in the noRatch slip factor
STEPPING = (("end", "end"), ("integrator", "integrator"), ("coulomb", "coulomb"), ("geometry", "geometry"),
            ("touch", "touch"))      # (family, the law's field naming its sub-model)


@dataclass
class Batch:
    """Kernel input for one spec (one sweep at one target e_n, its time step and step cap), with the incident
    conditions kept for the results table."""
    spec: object                # harness.solver.resolution.RunSpec
    params: np.ndarray
    ints: np.ndarray
    tangential_active: np.ndarray
    free_steps: np.ndarray          # per row, the steps of its free approach before its first row step (approach.py)

    e_n = property(lambda self: self.spec.e_n)
    dt = property(lambda self: self.spec.dt)
    steps_per_contact = property(lambda self: self.spec.steps_per_contact)
    v_n0 = property(lambda self: self.spec.v_n0)
    v_t0 = property(lambda self: self.spec.v_t0)
    omega0 = property(lambda self: self.spec.omega0)
    theta_deg = property(lambda self: self.spec.theta_deg)


def join(batches):
    """One batch holding the impacts of several batches of one material and one dt (one engine run)."""
    names = ("params", "ints", "tangential_active", "free_steps")
    return Batch(joined([b.spec for b in batches]), *(np.concatenate([getattr(b, name) for b in batches])
                                                      for name in names))


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
    params = np.zeros((n, L.N_PARAMS))
    params[:, L.MASS] = contact.mass
    params[:, L.INERTIA] = contact.inertia
    params[:, L.RADIUS] = contact.radius
    params[:, L.DT] = spec.dt
    params[:, L.GRAVITY] = scene.gravity
    params[:, L.MU] = scene.mu
    values = check_parameters(law.normal, normal)
    params[:, L.NORMAL_BLOCK:L.NORMAL_BLOCK + len(values)] = values
    params[:, L.DAMPING_C0] = dashpot.c0
    params[:, L.DAMPING_POWER] = dashpot.power
    if tangential.any():                                  # the tangential kernel's one slot, and its dashpot
        params[:, L.TANGENTIAL_BLOCK] = k_t = law.tangential.parameter(contact, normal.linear_stiffness)
        constant_k_t = k_t if law.tangential.constant_stiffness else None
        params[:, L.TANGENTIAL_DAMPING_PREFACTOR] = law.tangential_damping.prefactor(
            contact, dashpot, normal.linear_stiffness, constant_k_t, e_n)
        params[:, L.TANGENTIAL_DAMPING_CONE] = CONE_CODES[law.tangential_damping.cone]
        params[:, L.TANGENTIAL_DAMPING_SHARE] = law.tangential_damping.normal_share
    two_spheres = kernel_of("geometry", code_of("geometry", law.geometry)).two_spheres
    params[:, L.LEVER] = law.lever
    params[:, L.TORQUE_LEVER] = (law.lever if law.torque == "lever" else 0.5 if two_spheres else   # each body's
                                 contact_point_lever(scene))                                        # R_i - c alpha
    params[:, L.SLIP_RADIUS] = (NORATCH_WALL_RADIUS * contact.radius if law.slip == "noratch" else
                                contact.radius if law.slip == "noratch-sphere" else
                                centres_less_radius(scene) if law.slip == "noratch-pair" else 0.0)
    params[:, L.VZ0] = -v_n0
    params[:, L.VX0] = v_t0
    params[:, L.W0] = omega0
    params[:, L.MAX_STEPS] = np.minimum(step_caps(scene, e_n, v_n0, spec.steps_per_contact), spec.step_cap)
    ints = np.zeros((n, L.N_INTS), dtype=np.int64)
    ints[:, L.I_NORMAL] = kernel_code(law.normal)
    ints[:, L.I_TANGENTIAL] = np.where(tangential, kernel_code(law.tangential), TANGENTIAL_NONE)
    for family, field in STEPPING:
        code = code_of(family, getattr(law, field))
        ints[:, getattr(L, f"I_{family.upper()}")] = code
        stepping_slots(params, family, kernel_of(family, code), law, scene)
    ints[:, L.I_STEPPER] = list(STEPPERS).index((law.integrator, law.geometry))
    free_steps = place(params, ints, scene.gap).steps if scene.gap > 0.0 else np.zeros(n, dtype=np.int64)
    return Batch(spec, params, ints, tangential, free_steps)


def stepping_slots(params, family, kernel, law, scene):
    """A stepping sub-model's slots, in its family's block: the values its module's parameters(law, scene) gives."""
    if kernel.slots:
        values = importlib.import_module(kernel.module).parameters(law, scene)
        start = L.BLOCKS[family]
        for k, slot in enumerate(kernel.slots):
            params[:, start + k] = values[slot]
