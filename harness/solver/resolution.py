"""A run's resolution and what it gives on a scene: the time step (the law's contact time at the scene over the
steps per contact, or a fixed one), checked against the law's stability limit, and the step cap: what every engine
is told (RunSpec), computed from the law and the scene before any kernel row exists. The plan makes the specs; the
solver's kernel rows follow from them."""
from dataclasses import dataclass

import numpy as np

from ..infra.errors import UserError
from .stability import check_time_step

CONVERGED = "converged"             # the resolution of the converged mode (the reference's alone)
MAX_STEPS_PER_CONTACT = 10 ** 6     # beyond, a run of one impact takes minutes and round-off dominates
MIN_CHUNK = 10                      # steps between an engine's separation checks: a tenth of a contact, at least this
CAP_CONTACTS, CAP_SLOWEST = 20.0, 20.0


@dataclass(frozen=True)
class FixedTimeStep:
    """One time step in seconds (--dt) for every law and e_n; each batch's steps per contact follow from it."""
    seconds: float


@dataclass(frozen=True)
class RunSpec:
    """What an engine runs: every impact (incident velocities at the target e_n), the time step, the step cap and the
    output cadence (a separation check every `chunk` steps, at most `chunks` of them, which covers the cap)."""
    e_n: float
    dt: float
    steps_per_contact: float
    step_cap: int
    theta_deg: np.ndarray
    v_n0: np.ndarray
    v_t0: np.ndarray
    omega0: np.ndarray

    @property
    def impacts(self):
        return len(self.v_n0)

    @property
    def chunk(self):
        return max(MIN_CHUNK, int(self.steps_per_contact // 10))

    @property
    def chunks(self):
        return max(1, self.step_cap // self.chunk + 1)


def contact_time(law, scene, e_n):
    """The law's contact-time estimate at the scene's speed (what steps per contact divide)."""
    return law.normal.parameters(scene.contact, e_n, scene.speed).contact_time


def steps_per_contact_of(law, scene, e_n, resolution, bounded=True):
    """Steps per contact of a resolution: itself, or a FixedTimeStep's t_c/dt (refused beyond MAX_STEPS_PER_CONTACT
    when `bounded`: a user's --dt; the converged ladder's finest levels pass bounded=False)."""
    if resolution == CONVERGED:
        raise UserError("an engine runs at a time step, not converged: give --steps-per-contact or --dt (the "
                        "converged mode is the reference's)")
    if isinstance(resolution, FixedTimeStep):
        t_c = contact_time(law, scene, e_n)
        steps = t_c / resolution.seconds
        if bounded and steps > MAX_STEPS_PER_CONTACT:
            raise UserError(f"--dt gives {steps:.3g} steps per contact at e_n {e_n:g}; at most "
                            f"{MAX_STEPS_PER_CONTACT:.0e} (a contact lasts {t_c:.3g} s)")
        return steps
    if not resolution > 0:
        raise ValueError(f"steps per contact must be positive, got {resolution}")
    return resolution


def step_caps(scene, e_n, v_n0, steps_per_contact):
    """Each impact's step cap: 20 contact times slowed by (V/V_n)^0.4, plus leaving a latched dent (engine
    hysteresis laws keep the contact at zero force until the gap opens: depth <= alpha_max <= V_n t_c, crossed at
    e_n V_n, so at most t_c/e_n more), plus 20 contact times."""
    slow = np.maximum(scene.speed / np.maximum(v_n0, 1e-12 * scene.speed), 1.0) ** 0.4
    return np.ceil(steps_per_contact * (slow * (CAP_CONTACTS + 1.0 / e_n) + CAP_SLOWEST))


def needs_tangential(scene, v_t0, omega0, law=None):
    """Per impact: a tangential model (and rotation) only with some tangential motion or spin, and friction or a
    tangential dashpot (engines add it while the spring is within the cap, which at mu = 0 is when it is zero)."""
    acts = scene.mu > 0.0 or (law is not None and law.tangential_damping.rule != "none")
    return acts & ((v_t0 != 0.0) | (omega0 != 0.0))


def run_spec(law, scene, e_n, resolution, step_cap=None, check_stability=True, bounded=True):
    """The RunSpec of `law` on every impact of the scene at target e_n: dt = t_c / steps per contact; a dt above
    the stability limit is refused (harness.solver.stability) unless check_stability is False (the adaptive
    integrator's rows, which choose their own steps); step_cap: stop every impact after that many steps instead
    of the largest of their own caps (step_caps)."""
    steps = steps_per_contact_of(law, scene, e_n, resolution, bounded)
    t_c = contact_time(law, scene, e_n)
    dt = t_c / steps
    v_n0, v_t0, omega0, theta = scene.impacts(e_n)
    if check_stability:
        check_time_step(law, scene, e_n, dt, t_c, bool(needs_tangential(scene, v_t0, omega0, law).any()))
    cap = int(step_caps(scene, e_n, v_n0, steps).max()) if step_cap is None else step_cap
    return RunSpec(e_n, dt, steps, cap, theta, v_n0, v_t0, omega0)


def joined(specs):
    """One spec holding the impacts of several specs of one e_n and one dt (scenes run together by one engine)."""
    if len({s.dt for s in specs}) != 1:
        raise ValueError("scenes run together must share one dt")
    first = specs[0]
    return RunSpec(first.e_n, first.dt, first.steps_per_contact, max(s.step_cap for s in specs),
                   *(np.concatenate([getattr(s, name) for s in specs]) for name in ("theta_deg", "v_n0", "v_t0",
                                                                                      "omega0")))
