"""The largest stable time step of a law on a scene, so that a too-large one is refused before anything runs.

Each contact mode is a damped oscillator m_eff x'' + c x' + k x = 0 at its stiffest (normal: the law's peak
dF/dalpha at the scene speed; tangential: the spring at the deepest overlap, with 1/m_eff = 1/m + R^2/I).
Explicit schemes (velocity Verlet, leapfrog) are stable for h < 2/(sqrt(w^2 + g^2) + g), w^2 = k/m_eff,
g = c/(2 m_eff), i.e. w h < 2 (sqrt(1 + z^2) - z) with z the damping ratio (O'Sullivan & Bray 2004, Eng. Comput.
21); the paper scheme treats both dashpots implicitly, so its limit is the undamped w h < 2.
"""
import math
from dataclasses import dataclass

from ..infra.errors import UserError
from ..submodels.registry import code_of, kernel_code, kernel_of, python_point


@dataclass(frozen=True)
class Limit:
    """The critical time step and the mode that sets it."""
    dt: float
    mode: str              # "normal" or "tangential"
    stiffness: float       # k of that mode [N/m]
    damping_ratio: float   # z of that mode (0 for the paper scheme, whose dashpots are implicit)
    explicit: bool

    def describe(self):
        rule = "2/(w (sqrt(1 + z^2) + z))" if self.explicit else "2/w (implicit dashpots)"
        return (f"{self.dt:.4g} s = {rule}, {self.mode} mode, k = {self.stiffness:.4g} N/m"
                + (f", z = {self.damping_ratio:.3g}" if self.explicit else ""))


def critical_dt(stiffness, damping, mass, explicit):
    """h_crit = 2/(sqrt(w^2 + g^2) + g), w^2 = k/m, g = c/(2m) (explicit); 2/w (implicit damping)."""
    gamma = max(damping, 0.0) / (2.0 * mass) if explicit else 0.0
    rate = math.sqrt(max(stiffness, 0.0) / mass + gamma * gamma) + gamma
    return math.inf if rate == 0.0 else 2.0 / rate


class UnstableTimeStep(UserError):
    """A time step above the stability limit (a user error: exit code 2 with one line)."""

    def __init__(self, message, limit):
        super().__init__(message)
        self.limit = limit


def stability_limit(law, scene, e_n, tangential=True):
    """Limit for `law` at target e_n, from its normal model's peak stiffness, its dashpots and its tangential spring;
    the tangential mode counts when some impact of the batch has friction and tangential motion."""
    contact, explicit = scene.contact, kernel_of("integrator", code_of("integrator", law.integrator)).explicit
    k_n, alpha = law.normal.peak(contact, e_n, scene.speed)
    dashpot = law.damping.dashpot(law.normal, contact, e_n, scene.speed, law.end)
    c_n = dashpot.c0 * (alpha ** dashpot.power if dashpot.power else 1.0)
    mass = contact.mass
    modes = [("normal", k_n, c_n, mass)]
    code = kernel_code(law.tangential)
    if tangential and scene.mu > 0.0:
        k_lin = law.normal.parameters(contact, e_n, scene.speed).linear_stiffness
        slot = law.tangential.parameter(contact, k_lin)
        prefactor = law.tangential_damping.prefactor(contact, dashpot, k_lin,
                                                     slot if law.tangential.constant_stiffness else None, e_n)
        stiffness = python_point("tangential", code, "stiffness")
        k_t = abs(stiffness(slot, math.sqrt(contact.radius * alpha)))               # |k_s| = |nu| k_n for k_t/k_n = nu
        c_t = abs(prefactor) * math.sqrt(k_t)                                       # CundallStrack with nu < 0
        m_t = 1.0 / (1.0 / mass + contact.radius ** 2 / contact.inertia)
        spring = 0.0 if kernel_of("tangential", code).viscous else k_t
        modes.append(("tangential", spring, c_t, m_t))
    limits = []
    for mode, k, c, m in modes:
        z = c / (2.0 * math.sqrt(k * m)) if explicit and k > 0.0 else 0.0
        limits.append(Limit(critical_dt(k, c, m, explicit), mode, k, z, explicit))
    return min(limits, key=lambda limit: limit.dt)


def check_time_step(law, scene, e_n, dt, contact_time, tangential=True):
    """Refuse dt above the stability limit: one line naming the limit and the steps per contact it allows."""
    limit = stability_limit(law, scene, e_n, tangential)
    if dt > limit.dt:
        raise UnstableTimeStep(f"time step {dt:.4g} s is too large for {law.name} ({law.dialect} dialect, "
                               f"{law.integrator} scheme) at e_n = {e_n:g}: stability limit {limit.describe()}; "
                               f"use dt <= {limit.dt:.4g} s (at least {math.ceil(contact_time / limit.dt)} steps "
                               "per contact)", limit)
    return limit
