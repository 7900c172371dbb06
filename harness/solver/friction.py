"""The tangential half of a step: spring increment from the slip, the law's Coulomb rule with the tangential
dashpot (coulomb_cap), and the kicks that carry the friction force (paper scheme: a sliding step's impulse exactly mu
times the normal one)."""
import math

from numba import njit

from ..submodels.coulomb import clip
from ..submodels.tangential.state import N_TSTATE, T_HELD, T_MARGIN, T_STEP
from ..submodels.tangential.viscous import friction as viscous_friction
from . import layout as L
from .dispatch import (TANGENTIAL_NONE, TANGENTIAL_VISCOUS, coulomb_cap, tangential_after_cap,
                       tangential_stiffness)
from .spring import spring_force
from .state import S_ALPHA, S_FEL, S_FS, S_FT, S_NOLD, S_U, S_VX, S_VZ, S_W


@njit(cache=True, inline="always")
def friction(s, ot, p, ints, code, h, scratch, alpha, a, f_n, slip, in_contact, midpoint, lever):
    """Tangential force for this step and the spring force kept in history: spring increment from the slip, then
    the law's Coulomb rule on the spring and its tangential dashpot (coulomb_cap). `midpoint`: the paper scheme's
    spring at the step's mean radius and its implicit dashpot, capped again (damped_friction). History cleared out
    of contact."""
    f_t, f_s = 0.0, 0.0
    damping = p[L.TANGENTIAL_DAMPING_PREFACTOR]
    if TANGENTIAL_VISCOUS[code] and alpha > 0.0 and p[L.TANGENTIAL_DAMPING_SHARE] != 0.0:
        f_t = viscous_friction(1.0, dashpot_with_share(p, code, a, alpha), slip, p[L.MU] * abs(f_n))
    elif TANGENTIAL_VISCOUS[code] and alpha > 0.0:
        f_t = viscous_friction(tangential_stiffness(code, p, a), damping, slip, p[L.MU] * abs(f_n))
    elif in_contact:
        limit = p[L.MU] * abs(f_n)
        f_s = spring_force(code, p, s[S_FS], slip * h, a, p[L.MU], abs(f_n), s[S_NOLD], ot, scratch, midpoint)
        ot[T_MARGIN] = ot[T_HELD] = abs(f_s) - limit
        if midpoint and damping != 0.0:
            f_t, f_s = damped_friction(ot, p, code, h, a, f_s, slip, limit, lever)
        else:
            k_t = tangential_stiffness(code, p, a) if damping != 0.0 else 0.0
            if p[L.TANGENTIAL_DAMPING_SHARE] != 0.0:          # c_t = damping sqrt(k_t) with k_t = 1
                damping, k_t = dashpot_with_share(p, code, a, alpha), 1.0
            f_t, f_s, cut = coulomb_cap(ints[L.I_COULOMB], p, f_s, damping, k_t, slip, limit)
            if cut:
                tangential_after_cap(code, p, f_s, a, ot)
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
    return f_t, f_s


@njit(cache=True, inline="always")
def dashpot_with_share(p, code, a, alpha):
    """The tangential dashpot with a share of the normal one: c_t = prefactor sqrt(k_t) + normal_share."""
    damping = p[L.TANGENTIAL_DAMPING_PREFACTOR]
    c_t = damping * math.sqrt(tangential_stiffness(code, p, a)) if damping != 0.0 else 0.0
    return c_t + normal_share(p, alpha)


@njit(cache=True, inline="always")
def normal_share(p, alpha):
    """share c_n(alpha) = share c0 alpha^power: the tangential dashpot's share of the normal one."""
    power = p[L.DAMPING_POWER]
    return p[L.TANGENTIAL_DAMPING_SHARE] * p[L.DAMPING_C0] * (1.0 if power == 0.0 else alpha ** power)


@njit(cache=True, inline="always")
def damped_friction(ot, p, code, h, a, f_s, slip, limit, lever):
    """The paper scheme's spring and tangential dashpot, F_s - c_t V_s with V_s at the step's end (implicit:
    V_s(end) = V_s(half) + h/2 F_t (1/m + lever^2/I); docs/laws.md#tangential-dashpot). Spring first (cone 0): a
    spring beyond mu F_n slides on the cone and is the whole force, a sticking one gets the dashpot, the sum clipped
    to mu F_n. Total (cone 1): the spring held within the cone, then the sum clipped. Returns (F_t, F_s); T_HELD
    = |F_s| - mu F_n for a sliding spring, else the sum's excess over mu F_n, along the spring for spring first (a
    dashpot carrying the force across the cone ends the slide, an event)."""
    if abs(f_s) > limit:
        f_s = clip(f_s, limit)
        tangential_after_cap(code, p, f_s, a, ot)
        if p[L.TANGENTIAL_DAMPING_CONE] == 0.0:
            return f_s, f_s
    c_t = p[L.TANGENTIAL_DAMPING_PREFACTOR] * math.sqrt(tangential_stiffness(code, p, a))
    trial = (f_s - c_t * slip) / (1.0 + 0.5 * h * c_t * (1.0 / p[L.MASS] + lever * lever / p[L.INERTIA]))
    if p[L.TANGENTIAL_DAMPING_CONE] == 0.0 and f_s != 0.0:
        ot[T_HELD] = trial * math.copysign(1.0, f_s) - limit    # held on the spring's side of the cone
    else:
        ot[T_HELD] = abs(trial) - limit
    return clip(trial, limit), f_s


@njit(cache=True, inline="always")
def slip_velocity(p, alpha, vx, w, lever):
    """Contact-point slip: V_t - lever omega, or the noRatch form alpha_f V_t - R omega with
    alpha_f = (r1 + R)/(r1 + R - d) (r1 the wall's reference radius)."""
    r1 = p[L.SLIP_RADIUS]
    if r1 == 0.0:
        return vx - lever * w
    radius = p[L.RADIUS]
    return (r1 + radius) / (r1 + radius - alpha) * vx - radius * w


@njit(cache=True, inline="always")
def tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, in_contact, midpoint):
    """Tangential half of a Verlet step: half kick with the previous force, slip at the half step, friction,
    closing half kick (the paper and velocity Verlet schemes; `midpoint`: the paper's, see friction)."""
    for k in range(N_TSTATE):
        ot[k] = st[k]
    code = ints[L.I_TANGENTIAL]
    if code == TANGENTIAL_NONE:                       # normal impact without spin, or mu = 0: nothing to do
        o[S_VX], o[S_W], o[S_FT], o[S_FS], o[S_NOLD] = s[S_VX], s[S_W], 0.0, 0.0, f_n
        return
    m, inertia, radius = p[L.MASS], p[L.INERTIA], p[L.RADIUS]
    lever = radius - p[L.LEVER] * alpha
    torque_old = radius - p[L.TORQUE_LEVER] * s[S_ALPHA]
    torque = radius - p[L.TORQUE_LEVER] * alpha
    vx_half = s[S_VX] + 0.5 * h * s[S_FT] / m
    w_half = s[S_W] - 0.5 * h * torque_old * s[S_FT] / inertia
    slip = slip_velocity(p, alpha, vx_half, w_half, lever)
    f_t, f_s = friction(s, ot, p, ints, code, h, scratch, alpha, a, f_n, slip, in_contact, midpoint, lever)
    kick = f_t
    sliding = (st[T_HELD] >= 0.0 and ot[T_HELD] > 0.0        # on the same side of the Coulomb cone at both ends
               and s[S_FT] * f_t >= 0.0)                     # (a dashpot-held force may cross to the other side)
    if midpoint and sliding and f_n > 0.0 and not TANGENTIAL_VISCOUS[code]:
        kick = sliding_kick(s, o, m, h, f_t / f_n)
    o[S_VX] = vx_half + 0.5 * h * kick / m
    o[S_W] = w_half - 0.5 * h * torque * kick / inertia
    o[S_FT], o[S_FS], o[S_NOLD] = f_t, f_s, abs(f_n)
    ot[T_STEP] = h


@njit(cache=True, inline="always")
def sliding_kick(s, o, m, h, ratio):
    """Closing half kick of a sliding step (paper scheme) such that the friction impulse is -sign(V_s) mu times the
    normal impulse of the step, h/2 (F_el0 + F_el1) + D(alpha_1) - D(alpha_0): the dashpot's impulse exact (its
    force ~ t^p at first touch would make the trapezoid's error O(h^(1+p))); `ratio` = F_t/F_n = -sign mu."""
    if h <= 0.0:                                      # a step of length 0 (an event at a step's end) kicks nothing
        return 0.0
    d_old = s[S_U] + m * s[S_VZ]                      # D = u - m alpha_dot, alpha_dot = -v_z
    d_new = o[S_U] + m * o[S_VZ]
    impulse = 0.5 * h * (s[S_FEL] + o[S_FEL]) + d_new - d_old
    return 2.0 * ratio * impulse / h - s[S_FT]
