"""A batch: (law, scene, e_n) as kernel rows, switching on only the effects the scene calls for."""
from dataclasses import dataclass, replace

import numpy as np

from ..errors import UserError

from ..submodels.registry import COULOMB_RULES, GEOMETRIES, INTEGRATORS, TOUCHES, check_parameters, kernel_code
from ..submodels.tangential_damping import CONE_CODES
from . import codes as C
from .dispatch import TANGENTIAL_NONE
from .stability import check_time_step

NORATCH_WALL_RADIUS = 1e8      # slip 'noratch': the wall's reference radius 1e8 R in the noRatch slip factor


MAX_STEPS_PER_CONTACT = 10 ** 6      # beyond, a run of one impact takes minutes and round-off dominates


@dataclass(frozen=True)
class FixedTimeStep:
    """One time step in seconds (--dt) for every law and e_n; each batch's steps per contact follow from it."""
    seconds: float


@dataclass
class Batch:
    """Kernel input for one sweep at one target e_n, with the incident conditions kept for the results table."""
    params: np.ndarray
    ints: np.ndarray
    e_n: float
    v_n0: np.ndarray
    v_t0: np.ndarray
    omega0: np.ndarray
    theta_deg: np.ndarray
    dt: float
    steps_per_contact: float
    tangential_active: np.ndarray

    @property
    def step_cap(self):
        """The most steps any of its impacts may take (the largest of the rows' caps)."""
        return int(self.params[:, C.P_MAXSTEPS].max())


def join(batches):
    """One batch holding the impacts of several batches of one material and one dt (one engine run)."""
    if len({b.dt for b in batches}) != 1:
        raise ValueError("batches run together must share one dt")
    per_impact = ("params", "ints", "v_n0", "v_t0", "omega0", "theta_deg", "tangential_active")
    return replace(batches[0], **{name: np.concatenate([getattr(b, name) for b in batches]) for name in per_impact})


def needs_tangential(scene, v_t0, omega0, law=None):
    """Per impact: a tangential model (and rotation) only with some tangential motion or spin, and friction or a
    tangential dashpot (engines add it while the spring is within the cap, which at mu = 0 is when it is zero)."""
    acts = scene.mu > 0.0 or (law is not None and law.tangential_damping.rule != "none")
    return acts & ((v_t0 != 0.0) | (omega0 != 0.0))


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


def batch_of(law, scene, e_n, steps_per_contact, check_stability=True, every_effect=False, bounded=True):
    """Kernel rows for every impact of the scene at target e_n; dt = (contact-time estimate at V) / steps, or the
    given FixedTimeStep; a dt above the stability limit is refused (harness.stability) unless the rows are for the
    adaptive integrator, which chooses its own steps. every_effect: the tangential model on every row whether the
    scene calls for it or not (what benchmarks/bench_effects.py measures the saving against). bounded: a FixedTimeStep
    (a user's --dt) giving more than MAX_STEPS_PER_CONTACT is refused; the converged ladder's own finest levels are
    not a user's request and pass bounded=False."""
    contact = scene.contact
    v_n0, v_t0, omega0, theta = scene.impacts(e_n)
    normal = law.normal.parameters(contact, e_n, scene.speed)
    dashpot = law.damping.dashpot(law.normal, contact, e_n, scene.speed, law.end)
    if isinstance(steps_per_contact, FixedTimeStep):
        steps_per_contact = normal.contact_time / steps_per_contact.seconds
        if bounded and steps_per_contact > MAX_STEPS_PER_CONTACT:
            raise UserError(f"--dt gives {steps_per_contact:.3g} steps per contact at e_n {e_n:g}; at most "
                            f"{MAX_STEPS_PER_CONTACT:.0e} (a contact lasts {normal.contact_time:.3g} s)")
    if not steps_per_contact > 0:
        raise ValueError(f"steps per contact must be positive, got {steps_per_contact}")
    dt = normal.contact_time / steps_per_contact
    tangential = np.ones(len(v_n0), dtype=bool) if every_effect else needs_tangential(scene, v_t0, omega0, law)
    n = len(v_n0)
    params = np.zeros((n, C.N_PARAMS))
    params[:, C.P_MASS] = contact.mass
    params[:, C.P_INERTIA] = contact.inertia
    params[:, C.P_RADIUS] = contact.radius
    params[:, C.P_DT] = dt
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
        params[:, C.P_TSHARE] = law.tangential_damping.normal_share
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
    slow = np.maximum(scene.speed / np.maximum(v_n0, 1e-12 * scene.speed), 1.0) ** 0.4
    # step cap: 20 slowed contact times, plus leaving a latched dent (engine hysteresis laws keep the contact at zero
    # force until the gap opens): depth <= alpha_max <= V_n t_c, crossed at e_n V_n, so at most t_c/e_n more
    params[:, C.P_MAXSTEPS] = np.ceil(steps_per_contact * (slow * (20.0 + 1.0 / e_n) + 20.0))
    active = np.flatnonzero(tangential)
    if check_stability:
        check_time_step(law, scene, e_n, dt, params[active[0] if len(active) else 0], normal.contact_time,
                        len(active) > 0)
    ints = np.zeros((n, C.N_INTS), dtype=np.int64)
    ints[:, C.I_NORMAL] = kernel_code(law.normal)
    ints[:, C.I_END] = C.END_ALPHA if law.end == "tension" else C.END_FORCE
    ints[:, C.I_TANGENTIAL] = np.where(tangential, kernel_code(law.tangential), TANGENTIAL_NONE)
    ints[:, C.I_INTEGRATOR] = INTEGRATORS[law.integrator].code
    ints[:, C.I_COULOMB] = COULOMB_RULES[law.coulomb].code
    ints[:, C.I_GEOMETRY] = GEOMETRIES[law.geometry].code
    ints[:, C.I_TOUCH] = TOUCHES[law.touch].code
    return Batch(params, ints, e_n, v_n0, v_t0, omega0, theta, dt, steps_per_contact, tangential)
