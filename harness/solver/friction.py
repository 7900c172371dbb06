"""The tangential half of a step: spring increment from the slip, Coulomb cap, tangential dashpot, and the kicks
that carry the friction force (paper scheme: a sliding step's impulse exactly mu times the normal one)."""
import math

from numba import njit

from ..submodels.tangential.state import N_TSTATE, T_HELD, T_MARGIN, T_STEP
from ..submodels.tangential.viscous import friction as viscous_friction
from . import codes as C
from .switches import LEAPFROG, LEAPFROG_SCALAR_PAIR, PAPER, VELOCITY_VERLET, VERLET_PAIR
from .dispatch import TANGENTIAL_NONE, TANGENTIAL_VISCOUS, tangential_after_cap, tangential_stiffness
from .spring import cap, spring_force
from .state import S_ALPHA, S_FEL, S_FS, S_FT, S_NOLD, S_U, S_VX, S_VZ, S_W


@njit(cache=True, inline="always")
def friction(s, ot, p, code, h, scratch, alpha, a, f_n, slip, in_contact, scheme, coulomb, lever):
    """Tangential force for this step and the spring force kept in history: spring increment from the slip,
    Coulomb cap, tangential dashpot. The paper scheme's dashpot is implicit and capped again; the explicit schemes'
    is added after the Coulomb test only (Coulomb rule 'spring'), capped with the spring (rule 'total', 'total-cases')
    or added to a spring within the cone and capped again (rule 'spring-first'). History cleared out of contact."""
    paper = scheme == C.INTEGRATOR_PAPER
    f_t, f_s = 0.0, 0.0
    if TANGENTIAL_VISCOUS[code] and alpha > 0.0 and p[C.P_TSHARE] != 0.0:
        f_t = viscous_friction(1.0, normal_share(p, alpha), slip, p[C.P_MU] * abs(f_n))
    elif TANGENTIAL_VISCOUS[code] and alpha > 0.0:
        f_t = viscous_friction(tangential_stiffness(code, p[C.P_T1], a), p[C.P_TDAMP], slip, p[C.P_MU] * abs(f_n))
    elif in_contact:
        limit = p[C.P_MU] * abs(f_n)
        f_s = spring_force(code, s[S_FS], slip * h, a, p[C.P_T1], p[C.P_MU], abs(f_n), s[S_NOLD], ot, scratch, paper)
        ot[T_MARGIN] = ot[T_HELD] = abs(f_s) - limit
        if PAPER and paper and p[C.P_TDAMP] != 0.0:
            f_t, f_s = damped_friction(ot, p, code, h, a, f_s, slip, limit, lever)
        elif (VELOCITY_VERLET or VERLET_PAIR or LEAPFROG or LEAPFROG_SCALAR_PAIR) and coulomb == C.COULOMB_TOTAL:
            f_t, f_s = capped_total(ot, p, code, a, f_s, slip, limit, alpha)
        elif (LEAPFROG or LEAPFROG_SCALAR_PAIR) and coulomb == C.COULOMB_TOTAL_CASES:
            f_t, f_s = capped_cases(ot, p, code, a, f_s, slip, limit)
        elif (VELOCITY_VERLET or VERLET_PAIR or LEAPFROG or LEAPFROG_SCALAR_PAIR) and coulomb == C.COULOMB_SPRING_FIRST:
            f_t, f_s = capped_spring_first(ot, p, code, a, f_s, slip, limit)
        elif abs(f_s) > limit:
            f_s = cap(f_s, limit)
            tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
            f_t = f_s
        elif p[C.P_TDAMP] == 0.0 and p[C.P_TSHARE] == 0.0:
            f_t = f_s
        elif p[C.P_TSHARE] != 0.0:                   # Coulomb rule 'spring' with a share of the normal dashpot
            c_t = p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) if p[C.P_TDAMP] != 0.0 else 0.0
            f_t = f_s - (c_t + normal_share(p, alpha)) * slip
        else:
            f_t = f_s - p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) * slip
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
    return f_t, f_s


@njit(cache=True, inline="always")
def capped_total(ot, p, code, a, f_s, slip, limit, alpha):
    """Coulomb rule 'total': the spring and its dashpot together, F_s - c_t V_s, capped at mu |F_n|; when capped,
    the spring is set to what the capped total leaves to it, F_t + c_t V_s. Returns (F_t, F_s)."""
    c_t = p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) if p[C.P_TDAMP] != 0.0 else 0.0
    if p[C.P_TSHARE] != 0.0:
        c_t += normal_share(p, alpha)
    total = f_s - c_t * slip
    if abs(total) <= limit:
        return total, f_s
    f_t = cap(total, limit)
    f_s = f_t + c_t * slip
    tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
    return f_t, f_s


@njit(cache=True, inline="always")
def normal_share(p, alpha):
    """P_TSHARE c_n(alpha): a tangential dashpot that is a share of the normal one, c_n = c0 alpha^power."""
    power = p[C.P_DAMP_POWER]
    return p[C.P_TSHARE] * p[C.P_DAMP_C0] * (1.0 if power == 0.0 else alpha ** power)


@njit(cache=True, inline="always")
def capped_spring_first(ot, p, code, a, f_s, slip, limit):
    """Coulomb rule 'spring-first' of an explicit scheme: a spring beyond mu |F_n| is capped and is the whole force;
    a spring within it gets the dashpot, F_s - c_t V_s, and the sum is capped at mu |F_n|. Returns (F_t, F_s)."""
    if abs(f_s) > limit:
        f_s = cap(f_s, limit)
        tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
        return f_s, f_s
    if p[C.P_TDAMP] == 0.0:
        return f_s, f_s
    return cap(f_s - p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) * slip, limit), f_s


@njit(cache=True, inline="always")
def capped_cases(ot, p, code, a, f_s, slip, limit):
    """Coulomb rule 'total-cases': spring F_s and dashpot F_d = -c_t V_s capped together at mu |F_n| by four cases:
    on one side, a spring beyond the cap is cut to it and the dashpot dropped, else the dashpot is shortened to the
    cap's rest; opposed, a dashpot at least as strong as the spring is scaled to mu |F_n| + |F_s|, else the spring
    is cut to the cap and the dashpot dropped. Returns (F_t, F_s)."""
    c_t = p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) if p[C.P_TDAMP] != 0.0 else 0.0
    f_d = -c_t * slip
    if abs(f_s + f_d) <= limit:
        return f_s + f_d, f_s
    if (f_s * f_d >= 0.0 and abs(f_s) > limit) or (f_s * f_d < 0.0 and abs(f_d) < abs(f_s)):
        f_s = f_s * (limit / abs(f_s))
        tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
        return f_s, f_s
    if f_s * f_d >= 0.0:
        return f_s + f_d * ((limit - abs(f_s)) / abs(f_d)), f_s
    return f_s + f_d * ((limit + abs(f_s)) / abs(f_d)), f_s


@njit(cache=True, inline="always")
def damped_friction(ot, p, code, h, a, f_s, slip, limit, lever):
    """The paper scheme's spring and tangential dashpot, F_s - c_t V_s with V_s at the step's end (implicit:
    V_s(end) = V_s(half) + h/2 F_t (1/m + lever^2/I); docs/laws.md#tangential-dashpot). Spring first (P_TCONE 0): a
    spring beyond mu F_n slides on the cone and is the whole force, a sticking one gets the dashpot, the sum clipped
    to mu F_n. Total (P_TCONE 1): the spring held within the cone, then the sum clipped. Returns (F_t, F_s); T_HELD
    = |F_s| - mu F_n for a sliding spring, else the sum's excess over mu F_n, along the spring for spring first (a
    dashpot carrying the force across the cone ends the slide, an event)."""
    if abs(f_s) > limit:
        f_s = cap(f_s, limit)
        tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
        if p[C.P_TCONE] == 0.0:
            return f_s, f_s
    c_t = p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a))
    trial = (f_s - c_t * slip) / (1.0 + 0.5 * h * c_t * (1.0 / p[C.P_MASS] + lever * lever / p[C.P_INERTIA]))
    if p[C.P_TCONE] == 0.0 and f_s != 0.0:
        ot[T_HELD] = trial * math.copysign(1.0, f_s) - limit    # held on the spring's side of the cone
    else:
        ot[T_HELD] = abs(trial) - limit
    return cap(trial, limit), f_s


@njit(cache=True, inline="always")
def slip_velocity(p, alpha, vx, w, lever):
    """Contact-point slip: V_t - lever omega, or the noRatch form alpha_f V_t - R omega with
    alpha_f = (r1 + R)/(r1 + R - d) (r1 the wall's reference radius)."""
    r1 = p[C.P_SLIP_R1]
    if r1 == 0.0:
        return vx - lever * w
    radius = p[C.P_RADIUS]
    return (r1 + radius) / (r1 + radius - alpha) * vx - radius * w


@njit(cache=True, inline="always")
def tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, in_contact, scheme):
    """Tangential half of a Verlet step: half kick with the previous force, slip at the half step, friction,
    closing half kick (the paper and velocity Verlet schemes)."""
    for k in range(N_TSTATE):
        ot[k] = st[k]
    code = ints[C.I_TANGENTIAL]
    if code == TANGENTIAL_NONE:                       # normal impact without spin, or mu = 0: nothing to do
        o[S_VX], o[S_W], o[S_FT], o[S_FS], o[S_NOLD] = s[S_VX], s[S_W], 0.0, 0.0, f_n
        return
    m, inertia, radius = p[C.P_MASS], p[C.P_INERTIA], p[C.P_RADIUS]
    lever = radius - p[C.P_LEVER] * alpha
    torque_old = radius - p[C.P_TORQUE_LEVER] * s[S_ALPHA]
    torque = radius - p[C.P_TORQUE_LEVER] * alpha
    vx_half = s[S_VX] + 0.5 * h * s[S_FT] / m
    w_half = s[S_W] - 0.5 * h * torque_old * s[S_FT] / inertia
    slip = slip_velocity(p, alpha, vx_half, w_half, lever)
    f_t, f_s = friction(s, ot, p, code, h, scratch, alpha, a, f_n, slip, in_contact, scheme, ints[C.I_COULOMB],
                        lever)
    kick = f_t
    sliding = (st[T_HELD] >= 0.0 and ot[T_HELD] > 0.0        # on the same side of the Coulomb cone at both ends
               and s[S_FT] * f_t >= 0.0)                     # (a dashpot-held force may cross to the other side)
    if PAPER and scheme == C.INTEGRATOR_PAPER and sliding and f_n > 0.0 and not TANGENTIAL_VISCOUS[code]:
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
