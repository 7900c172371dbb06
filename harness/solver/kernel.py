"""Compiled batch integrator: one sphere-wall impact per row, from first touch to separation.

Scheme (paper dialect): velocity Verlet (kick-drift-kick) on the normal momentum u = m alpha_dot + D(alpha), whose
rate is the elastic force alone (D' = c, the dashpot), with a linearised implicit-midpoint drift and midpoint
tangential increments, a sliding step's friction impulse mu times its normal impulse: second order, unconditionally
stable in the dashpot. The release (alpha = 0, or F = 0 without tension) and every change of regime (turn, yield,
start and end of sliding) are located inside their step by false position on the step fraction, and the step is
split there. Steps are uniform, or graded (graded_time) for the converged mode. Only the branches a row needs run:
rows with TANGENTIAL_NONE never touch the tangential model or the rotation, gravity 0 skips its term.
Frame: wall z = 0 below, sphere moving in x-z, spin omega_y; contact-point slip V_s = v_x - R omega_y.
"""
import math

import numpy as np
from numba import njit, prange

from ..submodels.tangential.state import N_TSTATE, T_AOLD, T_HELD, T_MARGIN, T_STEP
from ..submodels.tangential.viscous import friction as viscous_friction
from . import codes as C
from .dispatch import (N_NORMAL, NORMAL_HISTORY, NORMAL_RESET, TANGENTIAL_IMPLICIT, TANGENTIAL_NONE,
                       TANGENTIAL_VISCOUS, normal_force, normal_kink, normal_step, tangential_after_cap,
                       tangential_stiffness)
from .spring import cap, spring_force

S_ALPHA, S_VZ, S_VX, S_W, S_AMAX, S_FN, S_FT, S_FS, S_NOLD, S_U, S_FEL, S_C = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11
S_HISTORY = 12                               # an incremental normal law's history (NORMAL_HISTORY slots)
S_X = S_HISTORY + NORMAL_HISTORY             # stand-in sphere: position, normal, shear force
S_Z, S_NX, S_NZ, S_SX, S_SZ = S_X + 1, S_X + 2, S_X + 3, S_X + 4, S_X + 5
N_STATE = S_X + 6
RELEASE_ITERATIONS = 100


@njit(cache=True)
def damping_power(alpha, power):
    """alpha^p for the dashpot exponents in use (0, 1/4, 1/2) without the cost of a general pow."""
    if power == 0.0:
        return 1.0
    if power == 0.5:
        return math.sqrt(alpha)
    if power == 0.25:
        return math.sqrt(math.sqrt(alpha))
    return alpha ** power


@njit(cache=True)
def dashpot_potential(c0, power, alpha):
    """D(alpha) = c0 alpha^(p+1)/(p+1): dD/dt = c(alpha) alpha_dot, so the dashpot impulse depends on positions only."""
    if alpha <= 0.0 or c0 == 0.0:
        return 0.0
    return c0 * alpha * damping_power(alpha, power) / (power + 1.0)


@njit(cache=True)
def drift(alpha, rate0, c_alpha, h):
    """Linearised implicit midpoint for alpha' = (u_half - D(alpha))/m, u frozen: D(mid) = D(alpha_n) + c_n (x - alpha)/2
    gives x = alpha + h rate0 / (1 + h c_n/(2m)); c_alpha = h c_n/(2m). Unconditionally stable, O(h^3) locally."""
    return alpha + h * rate0 / (1.0 + c_alpha)


@njit(cache=True, inline="always")
def friction(s, ot, p, code, h, scratch, alpha, a, f_n, slip, in_contact, scheme, lever):
    """Tangential force for this step and the spring force kept in history: spring increment from the slip,
    Coulomb cap, tangential dashpot. The paper's dashpot is implicit and capped again; the engines' is explicit
    and added after the Coulomb test only (LIGGGHTS and YADE alike, MODELS 5). History cleared out of contact."""
    paper = scheme == C.INTEGRATOR_PAPER
    f_t, f_s = 0.0, 0.0
    if TANGENTIAL_VISCOUS[code] and alpha > 0.0:
        f_t = viscous_friction(tangential_stiffness(code, p[C.P_T1], a), p[C.P_TDAMP], slip, p[C.P_MU] * abs(f_n))
    elif in_contact:
        limit = p[C.P_MU] * abs(f_n)
        f_s = spring_force(code, s[S_FS], slip * h, a, p[C.P_T1], p[C.P_MU], abs(f_n), s[S_NOLD], ot, scratch, paper)
        ot[T_MARGIN] = ot[T_HELD] = abs(f_s) - limit
        if paper and p[C.P_TDAMP] != 0.0:
            f_t, f_s = damped_friction(ot, p, code, h, a, f_s, slip, limit, lever)
        elif abs(f_s) > limit:
            f_s = cap(f_s, limit)
            tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
            f_t = f_s
        elif p[C.P_TDAMP] == 0.0:
            f_t = f_s
        else:
            f_t = f_s - p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) * slip
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
    return f_t, f_s


@njit(cache=True, inline="always")
def damped_friction(ot, p, code, h, a, f_s, slip, limit, lever):
    """The paper scheme's spring and tangential dashpot: the spring is held within the Coulomb cone, and the total
    F_s - c_t V_s, with V_s at the step's end (implicit: V_s(end) = V_s(half) + h/2 F_t (1/m + lever^2/I)), is the
    tangential force clipped to mu F_n: the dashpot acts while the contact sticks, and its share shrinks
    continuously to nothing in gross sliding (docs/laws.md#tangential-dashpot). Returns (F_t, F_s); T_HELD =
    |total| - mu F_n."""
    if abs(f_s) > limit:
        f_s = cap(f_s, limit)
        tangential_after_cap(code, f_s, p[C.P_T1], a, ot)
    c_t = p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a))
    trial = (f_s - c_t * slip) / (1.0 + 0.5 * h * c_t * (1.0 / p[C.P_MASS] + lever * lever / p[C.P_INERTIA]))
    ot[T_HELD] = abs(trial) - limit
    return cap(trial, limit), f_s


@njit(cache=True, inline="always")
def slip_velocity(p, alpha, vx, w, lever):
    """Contact-point slip: V_t - lever omega, or YADE's noRatch form alpha_f V_t - R omega with
    alpha_f = (r1 + R)/(r1 + R - d) (r1 the wall's reference radius)."""
    r1 = p[C.P_SLIP_R1]
    if r1 == 0.0:
        return vx - lever * w
    radius = p[C.P_RADIUS]
    return (r1 + radius) / (r1 + radius - alpha) * vx - radius * w


@njit(cache=True, inline="always")
def tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, in_contact, scheme):
    """Tangential half of a Verlet step: half kick with the previous force, slip at the half step, friction,
    closing half kick (paper and LIGGGHTS schemes)."""
    for k in range(N_TSTATE):
        ot[k] = st[k]
    code = ints[C.I_TANGENTIAL]
    if code == TANGENTIAL_NONE:                       # normal impact without spin, or mu = 0: nothing to do
        o[S_VX], o[S_W], o[S_FT], o[S_FS], o[S_NOLD] = s[S_VX], s[S_W], 0.0, 0.0, f_n
        return
    m, inertia, radius = p[C.P_MASS], p[C.P_INERTIA], p[C.P_RADIUS]
    lever_old = radius - p[C.P_LEVER] * s[S_ALPHA]
    lever = radius - p[C.P_LEVER] * alpha
    vx_half = s[S_VX] + 0.5 * h * s[S_FT] / m
    w_half = s[S_W] - 0.5 * h * lever_old * s[S_FT] / inertia
    slip = slip_velocity(p, alpha, vx_half, w_half, lever)
    f_t, f_s = friction(s, ot, p, code, h, scratch, alpha, a, f_n, slip, in_contact, scheme, lever)
    kick = f_t
    sliding = (st[T_HELD] >= 0.0 and ot[T_HELD] > 0.0        # on the same side of the Coulomb cone at both ends
               and s[S_FT] * f_t >= 0.0)                     # (a dashpot-held force may cross to the other side)
    if scheme == C.INTEGRATOR_PAPER and sliding and f_n > 0.0 and not TANGENTIAL_VISCOUS[code]:
        kick = sliding_kick(s, o, m, h, f_t / f_n)
    o[S_VX] = vx_half + 0.5 * h * kick / m
    o[S_W] = w_half - 0.5 * h * lever * kick / inertia
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


@njit(cache=True, inline="always")
def step_leapfrog(s, st, o, ot, p, ints, h, scratch, ext):
    """YADE NewtonIntegrator: forces from the overlap at x(t) and the half-step velocities v(t - h/2), then
    v(t + h/2) = v(t - h/2) + h F/m and x(t + h) = x(t) + h v(t + h/2). A contact exists while the overlap is
    >= 0 (a sphere placed touching starts in contact with zero force); the first step with a negative overlap
    applies no force and ends it (returns -1)."""
    m, inertia, radius, g = p[C.P_MASS], p[C.P_INERTIA], p[C.P_RADIUS], p[C.P_GRAVITY]
    alpha = s[S_ALPHA]
    amax = s[S_AMAX] if s[S_AMAX] > alpha else alpha
    in_contact = alpha >= 0.0
    f_n, a = 0.0, 0.0
    for k in range(NORMAL_HISTORY):
        o[S_HISTORY + k] = s[S_HISTORY + k]
    if in_contact:                                    # from overlap 0: a constant dashpot acts at first touch
        f_el, a = normal_step(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, alpha, s[S_ALPHA],
                              s[S_FEL], amax, s[S_HISTORY:S_HISTORY + NORMAL_HISTORY],
                              o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        c = p[C.P_DAMP_C0] * damping_power(alpha, p[C.P_DAMP_POWER]) if p[C.P_DAMP_C0] != 0.0 else 0.0
        f_n = f_el - c * s[S_VZ]
        if f_n < 0.0 and ints[C.I_END] == C.END_FORCE:
            f_n = 0.0
    for k in range(N_TSTATE):
        ot[k] = st[k]
    code = ints[C.I_TANGENTIAL]
    f_t, f_s = 0.0, 0.0
    lever = radius - p[C.P_LEVER] * alpha
    if code != TANGENTIAL_NONE:
        slip = slip_velocity(p, alpha, s[S_VX], s[S_W], lever)
        f_t, f_s = friction(s, ot, p, code, h, scratch, alpha, a, f_n, slip, in_contact, C.INTEGRATOR_LEAPFROG, lever)
    vz = s[S_VZ] + h * (f_n / m - g)
    o[S_VZ], o[S_FN], o[S_AMAX] = vz, f_n, amax
    o[S_VX] = s[S_VX] + h * f_t / m
    o[S_W] = s[S_W] - h * lever * f_t / inertia
    o[S_FT], o[S_FS], o[S_NOLD] = f_t, f_s, abs(f_n)
    o[S_ALPHA] = alpha - h * vz
    return 1.0 if in_contact else -1.0


@njit(cache=True, inline="always")
def step(s, st, o, ot, p, ints, h, scratch, ext):
    """Advance state (s, st) by h into (o, ot); returns the end-of-contact indicator (contact while > 0).

    Normal direction in u = m alpha_dot + D(alpha), u' = -F_el(alpha) + m g (Strang splitting: kick, midpoint
    drift, kick), which stays second order although c(alpha) = c0 alpha^p is singular at first touch.
    """
    m, radius, g = p[C.P_MASS], p[C.P_RADIUS], p[C.P_GRAVITY]
    c0, power = p[C.P_DAMP_C0], p[C.P_DAMP_POWER]
    u_shift = -0.5 * h * (s[S_FEL] - m * g)
    alpha = drift(s[S_ALPHA], -s[S_VZ] + u_shift / m, 0.5 * h * s[S_C] / m, h)
    amax = s[S_AMAX]
    c, d_pot = 0.0, 0.0
    if alpha > 0.0:
        f_el, a = normal_force(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, alpha, amax, ext)
        if c0 != 0.0:
            q = damping_power(alpha, power)
            c, d_pot = c0 * q, c0 * alpha * q / (power + 1.0)
    else:
        f_el, a = 0.0, 0.0
    u = s[S_U] + u_shift - 0.5 * h * (f_el - m * g)
    alpha_dot = (u - d_pot) / m
    f_n = f_el + c * alpha_dot
    indicator = alpha
    if alpha > 0.0 and ints[C.I_END] == C.END_FORCE:
        indicator = f_n if f_n < alpha else alpha
    if alpha <= 0.0:
        f_n = 0.0
    o[S_ALPHA], o[S_VZ], o[S_FN], o[S_U], o[S_FEL], o[S_C] = alpha, -alpha_dot, f_n, u, f_el, c
    o[S_AMAX] = alpha if alpha > amax else amax
    tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n,
                      f_n > 0.0 or (alpha > 0.0 and ints[C.I_END] == C.END_ALPHA), C.INTEGRATOR_PAPER)
    return indicator


@njit(cache=True, inline="always")
def step_velocity_verlet(s, st, o, ot, p, ints, h, scratch, ext):
    """LIGGGHTS nve/sphere + wall/gran: half kick, drift, forces from the half-step velocities, half kick.

    The normal dashpot and the tangential increment see v(t + h/2); the tangential dashpot is added after the
    Coulomb test and is not capped again; the contact ends at the first step with alpha <= 0 (MODELS 5).
    """
    m, radius, g = p[C.P_MASS], p[C.P_RADIUS], p[C.P_GRAVITY]
    vz_half = s[S_VZ] + 0.5 * h * (s[S_FN] / m - g)
    alpha = s[S_ALPHA] - h * vz_half
    amax = s[S_AMAX]
    f_n, f_el, a = 0.0, 0.0, 0.0
    reset_history(ints[C.I_NORMAL], o)                      # history cleared when out of contact
    if alpha > 0.0:
        f_el, a = normal_step(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, alpha, s[S_ALPHA],
                              s[S_FEL], amax, s[S_HISTORY:S_HISTORY + NORMAL_HISTORY],
                              o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        c = p[C.P_DAMP_C0] * damping_power(alpha, p[C.P_DAMP_POWER]) if p[C.P_DAMP_C0] != 0.0 else 0.0
        f_n = f_el - c * vz_half
        if f_n < 0.0 and ints[C.I_END] == C.END_FORCE:
            f_n = 0.0
    o[S_ALPHA], o[S_VZ], o[S_FN], o[S_FEL] = alpha, vz_half + 0.5 * h * (f_n / m - g), f_n, f_el
    o[S_AMAX] = alpha if alpha > amax else amax
    tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, alpha > 0.0, C.INTEGRATOR_VELOCITY_VERLET)
    return alpha


@njit(cache=True, inline="always")
def step_leapfrog_sphere(s, st, o, ot, p, ints, h, scratch, ext):
    """YADE Luding against a fixed sphere of radius R_big standing in for the wall, with YADE's own geometry:
    overlap (R_big + R) - |x2 - x1|, normal along x2 - x1, contact point in the middle of the overlap, shear force
    rotated with the normal (ScGeom::rotate), forces and torque from the contact-point branch; leapfrog as above."""
    m, inertia, radius, big = p[C.P_MASS], p[C.P_INERTIA], p[C.P_RADIUS], p[C.P_BIG_R]
    dx, dz = s[S_X], s[S_Z] + big
    norm = math.sqrt(dx * dx + 0.0 + dz * dz)
    delt = (big + radius) - norm
    for k in range(N_STATE):
        o[k] = s[k]
    if delt < 0.0:                                    # contact over: no force this step, history erased
        fx, fz, torque = 0.0, 0.0, 0.0
        in_contact = False
    else:
        in_contact = True
        nx, nz = dx / norm, dz / norm
        if s[S_NX] != 0.0 or s[S_NZ] != 0.0:          # ScGeom::rotate about prevNormal x normal (no twist in-plane)
            axis = s[S_NZ] * nx - s[S_NX] * nz        # y component of prevNormal x normal
            sx, sz = s[S_SX], s[S_SZ]
            sx, sz = sx + axis * sz, sz - axis * sx
        else:
            sx, sz = 0.0, 0.0
        f_hys, _ = normal_step(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, delt, s[S_ALPHA],
                               s[S_FEL], s[S_AMAX], s[S_HISTORY:S_HISTORY + NORMAL_HISTORY],
                               o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        reach = big - 0.5 * delt                      # contact point: big sphere centre + reach n
        cx, cz = reach * nx - s[S_X], (-big + reach * nz) - s[S_Z]
        wy = s[S_W]
        rvx, rvz = -(s[S_VX] + wy * cz), -(s[S_VZ] - wy * cx)
        vn = nx * rvx + nz * rvz
        svx, svz = rvx - vn * nx, rvz - vn * nz
        sx, sz = sx + p[C.P_T1] * h * svx, sz + p[C.P_T1] * h * svz
        g0 = p[C.P_DAMP_C0]
        normal = f_hys + g0 * vn
        max_fs = normal * normal * p[C.P_MU] * p[C.P_MU]
        visc_x, visc_z = 0.0, 0.0
        if sx * sx + sz * sz > max_fs:
            ratio = math.sqrt(max_fs) / math.sqrt(sx * sx + sz * sz)
            sx, sz = sx * ratio, sz * ratio
        else:
            visc_x, visc_z = g0 * svx, g0 * svz
        fx = normal * nx + sx + visc_x
        fz = normal * nz + sz + visc_z
        torque = cz * fx - cx * fz
        o[S_NX], o[S_NZ], o[S_SX], o[S_SZ] = nx, nz, sx, sz
        o[S_FN] = normal
    if not in_contact:
        o[S_NX], o[S_NZ], o[S_SX], o[S_SZ], o[S_FN] = 0.0, 0.0, 0.0, 0.0, 0.0
    o[S_VX] = s[S_VX] + h * fx / m
    o[S_VZ] = s[S_VZ] + h * fz / m
    o[S_W] = s[S_W] + h * torque / inertia
    o[S_X] = s[S_X] + h * o[S_VX]
    o[S_Z] = s[S_Z] + h * o[S_VZ]
    o[S_ALPHA] = delt
    for k in range(N_TSTATE):
        ot[k] = st[k]
    return 1.0 if in_contact else -1.0


@njit(cache=True, inline="always")
def advance(s, st, o, ot, p, ints, h, scratch, ext):
    """One step of the row's integrator."""
    if ints[C.I_INTEGRATOR] == C.INTEGRATOR_VELOCITY_VERLET:
        return step_velocity_verlet(s, st, o, ot, p, ints, h, scratch, ext)
    if ints[C.I_INTEGRATOR] == C.INTEGRATOR_LEAPFROG and p[C.P_BIG_R] > 0.0:
        return step_leapfrog_sphere(s, st, o, ot, p, ints, h, scratch, ext)
    if ints[C.I_INTEGRATOR] == C.INTEGRATOR_LEAPFROG:
        return step_leapfrog(s, st, o, ot, p, ints, h, scratch, ext)
    return step(s, st, o, ot, p, ints, h, scratch, ext)


EVENT_NONE, EVENT_TURN, EVENT_SLIP, EVENT_STICK, EVENT_YIELD, EVENT_SATURATE = 0, 1, 2, 3, 4, 5
EVENT_ITERATIONS = 60


@njit(cache=True, inline="always")
def event_kind(s, st, o, ot, p, ints, ext):
    """A change of regime inside the step (paper scheme): the normal motion turns (alpha_dot through 0), the loading
    curve's kink is passed (yield), the contact starts to slide (trial spring force reaches mu F_n) or stops sliding
    (the spring leaves the Coulomb cone)."""
    if s[S_VZ] < 0.0 <= o[S_VZ] and s[S_ALPHA] > 0.0:
        return EVENT_TURN
    kink = loading_kink(p, ints, ext)
    if s[S_ALPHA] < kink <= o[S_ALPHA] and s[S_ALPHA] >= s[S_AMAX]:
        return EVENT_YIELD
    code = ints[C.I_TANGENTIAL]
    if code == TANGENTIAL_NONE or TANGENTIAL_VISCOUS[code] or s[S_FN] <= 0.0 or o[S_FN] <= 0.0:
        return EVENT_NONE
    if TANGENTIAL_IMPLICIT[code]:             # a stiff spring (k_t -> 0 at full mobilisation) meets mu F_n
        return EVENT_NONE                     # tangentially, and locating that only amplifies round-off
    if st[T_HELD] < 0.0 < ot[T_HELD] and p[C.P_TDAMP] != 0.0:   # spring and tangential dashpot reach the cone
        return EVENT_SATURATE
    if st[T_MARGIN] < 0.0 < ot[T_MARGIN]:
        return EVENT_SLIP
    if st[T_HELD] > 0.0 >= ot[T_HELD]:
        return EVENT_STICK
    if st[T_STEP] > 0.0 and ot[T_STEP] > 0.0:      # still sliding at the step's end, but the margin per unit time
        rate, rate_before = ot[T_HELD] / ot[T_STEP], st[T_HELD] / st[T_STEP]       # falls fast: it may stick inside
        if 0.0 < rate < 2.0 * (rate_before - rate):
            return EVENT_STICK
    return EVENT_NONE


@njit(cache=True, inline="always")
def loading_kink(p, ints, ext):
    """Overlap at which the loading curve bends (yield of Stronge and Thornton, d_lim of LIGGGHTS' hysteresis);
    0 for the smooth curves."""
    return normal_kink(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], ext)


@njit(cache=True, inline="always")
def reset_history(code, state):
    """An incremental normal law's history at first touch and after a contact (none for the other laws)."""
    if code < N_NORMAL:
        for k in range(NORMAL_HISTORY):
            state[S_HISTORY + k] = NORMAL_RESET[code, k]


STICK_PROBE = 1e-4          # step fraction of the probe step that tells whether a contact on the cone still slides


@njit(cache=True)
def event_value(kind, f, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext):
    """The quantity that rises through zero at the event, after a trial step of fraction f from (s, st) (into lo, lot):
    -alpha_dot at the turn; alpha - alpha_y at yield; the trial spring margin |F_s| - mu F_n where sliding starts;
    where sliding stops, minus the margin's rate for a contact that starts on the Coulomb cone at f (a short probe
    step from there, into probe, probe_t): the spring leaves the cone when it moves inward faster than mu F_n
    shrinks, at a slip reversal only when F_n is constant."""
    if kind == EVENT_TURN or kind == EVENT_YIELD:
        at = s
        if f > 0.0:
            step(s, st, lo, lot, p, ints, f * h, scratch, ext)
            at = lo
        return at[S_VZ] if kind == EVENT_TURN else at[S_ALPHA] - loading_kink(p, ints, ext)
    if kind == EVENT_SLIP or kind == EVENT_SATURATE:
        which = T_MARGIN if kind == EVENT_SLIP else T_HELD
        return st[which] if f == 0.0 else margin_at(f, s, st, lo, lot, p, ints, h, scratch, which, ext)
    if f == 0.0:
        step(s, st, probe, probe_t, p, ints, STICK_PROBE * h, scratch, ext)
    else:
        step(s, st, lo, lot, p, ints, f * h, scratch, ext)
        step(lo, lot, probe, probe_t, p, ints, STICK_PROBE * h, scratch, ext)
    return -probe_t[T_HELD] / STICK_PROBE


@njit(cache=True)
def margin_at(f, s, st, lo, lot, p, ints, h, scratch, which, ext):
    """The margin `which` (T_MARGIN: |F_s| - mu F_n; T_HELD: what holds the cone) after a trial step of fraction
    f > 0 (at f = 0 the start's own margin holds: a step of length 0 would end the contact at first touch, where a
    constant dashpot already pushes)."""
    step(s, st, lo, lot, p, ints, f * h, scratch, ext)
    return lot[which]


@njit(cache=True)
def locate_event(kind, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext):
    """Step fraction at which the event happens in the step from (s, st) (Illinois false position on the event
    value, trial steps in lo, lot and probe, probe_t); -1 if the value does not change sign over the step."""
    g_lo = event_value(kind, 0.0, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
    g_hi = event_value(kind, 1.0, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
    if not (g_lo < 0.0 < g_hi):
        return -1.0
    lo_f, hi_f, side = 0.0, 1.0, 0
    for _ in range(EVENT_ITERATIONS):
        if hi_f - lo_f <= 1e-14:
            break
        mid = (lo_f * g_hi - hi_f * g_lo) / (g_hi - g_lo) if g_hi > g_lo else 0.5 * (lo_f + hi_f)
        if not lo_f < mid < hi_f:
            mid = 0.5 * (lo_f + hi_f)
        g_mid = event_value(kind, mid, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
        lo_f, hi_f, g_lo, g_hi, side = illinois(lo_f, hi_f, g_lo, g_hi, side, mid, g_mid, g_mid < 0.0)
    return hi_f


@njit(cache=True, inline="always")
def illinois(lo_f, hi_f, g_lo, g_hi, side, mid, g_mid, on_low_side):
    """One Illinois false-position update of the bracket [lo_f, hi_f] with values g_lo, g_hi: the new point
    replaces the end on its side, and the other end's value is halved when it was kept twice in a row."""
    if on_low_side:
        lo_f, g_lo = mid, g_mid
        if side == 1:
            g_hi *= 0.5
        return lo_f, hi_f, g_lo, g_hi, 1
    hi_f, g_hi = mid, g_mid
    if side == -1:
        g_lo *= 0.5
    return lo_f, hi_f, g_lo, g_hi, -1


@njit(cache=True)
def parabola_peak(y0, y1, y2, h1, h2):
    """Peak of the parabola through (-h1, y0), (0, y1), (h2, y2) with y1 the largest sample."""
    c = ((y0 - y1) / h1 + (y2 - y1) / h2) / (h1 + h2)
    if c >= 0.0:
        return y1
    b = (y2 - y1) / h2 - c * h2
    return y1 - b * b / (4.0 * c)


@njit(cache=True)
def locate_release(s, st, lo, lot, p, ints, h, scratch, indicator, ext):
    """Step fraction of the release (alpha = 0, or F = 0 without tension) in the step from (s, st) whose end value is
    `indicator` <= 0: Illinois false position; the fraction returned still has contact."""
    frac_lo, frac_hi = 0.0, 1.0
    g_lo, g_hi = s[S_ALPHA] if s[S_ALPHA] > 0.0 else 1.0, indicator
    if ints[C.I_END] == C.END_FORCE:
        g_lo = min(s[S_FN], s[S_ALPHA]) if s[S_ALPHA] > 0.0 else s[S_FN]
    side = 0
    for _ in range(RELEASE_ITERATIONS):
        if frac_hi - frac_lo <= 1e-15:
            break
        mid = (frac_lo * g_hi - frac_hi * g_lo) / (g_hi - g_lo) if g_lo > 0.0 > g_hi else 0.5 * (frac_lo + frac_hi)
        if not frac_lo < mid < frac_hi:
            mid = 0.5 * (frac_lo + frac_hi)
        g_mid = step(s, st, lo, lot, p, ints, mid * h, scratch, ext)
        frac_lo, frac_hi, g_lo, g_hi, side = illinois(frac_lo, frac_hi, g_lo, g_hi, side, mid, g_mid, g_mid > 0.0)
    return frac_lo


@njit(cache=True)
def split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p, ints, h, scratch, a_peak, f_peak, h_full,
                   indicator, ext):
    """Redo the step (s, st) -> (o, ot) of length h in two at a change of regime inside it, so that the error stays
    smooth in h. A step that ended at the release (h < h_full) is continued from the event to the release again,
    within what is left of h_full. Returns alpha_max and F_max (found at a turn), the end indicator (`indicator`
    if nothing happened) and the time the step took."""
    kind = event_kind(s, st, o, ot, p, ints, ext)
    if kind == EVENT_NONE:
        return a_peak, f_peak, indicator, h
    frac = locate_event(kind, s, st, lo, lot, at_event, at_event_t, p, ints, h, scratch, ext)
    if not 0.0 < frac < 1.0:
        return a_peak, f_peak, indicator, h
    step(s, st, at_event, at_event_t, p, ints, frac * h, scratch, ext)
    if kind == EVENT_TURN:                  # alpha_max itself; F_max too when undamped
        a_peak = max(a_peak, at_event[S_ALPHA])
        if p[C.P_DAMP_C0] == 0.0:
            f_peak = max(f_peak, at_event[S_FN])
    rest = h_full - frac * h
    indicator = step(at_event, at_event_t, o, ot, p, ints, rest, scratch, ext)
    if h < h_full and indicator <= 0.0:
        rest *= locate_release(at_event, at_event_t, lo, lot, p, ints, rest, scratch, indicator, ext)
        step(at_event, at_event_t, o, ot, p, ints, rest, scratch, ext)
    return a_peak, f_peak, indicator, frac * h + rest


GRADE_ZONE = 0.1            # share of the graded steps spent at each end of [0, T]
RAMP_AREA = 4.0 / 7.0      # integral of the ramp over [0, 1]


@njit(cache=True)
def ramp_integral(x):
    """Integral of the step-size ramp x^3 (20 - 45 x + 36 x^2 - 10 x^3), which rises from 0 like x^3 and meets 1 with
    three vanishing derivatives."""
    return x ** 4 * (5.0 + x * (-9.0 + x * (6.0 - x * (10.0 / 7.0))))


@njit(cache=True)
def graded_time(s):
    """Time fraction Phi(s) of the graded mesh at uniform s in [0, 1]: Phi ~ s^4 at both ends, so that alpha^(1/4),
    alpha^(1/2) and alpha^(3/2) at first touch and at release become smooth in s and the error expands in powers
    of the step (Richardson), uniform in the middle."""
    q = GRADE_ZONE
    total = 1.0 - 2.0 * q + 2.0 * q * RAMP_AREA
    if s <= q:
        g = q * ramp_integral(s / q)
    elif s >= 1.0 - q:
        g = total - q * ramp_integral((1.0 - s) / q)
    else:
        g = q * RAMP_AREA + (s - q)
    return g / total


def graded_largest_step(n, span):
    """The largest of n graded steps over span: the uniform middle step, span / (n (1 - 2 q (1 - RAMP_AREA)))."""
    return span / (n * (1.0 - 2.0 * GRADE_ZONE * (1.0 - RAMP_AREA)))


@njit(cache=True)
def graded_step(k, n, span):
    """Step k of n graded steps over [0, span]; beyond the span (a release later than foreseen), uniform span/n."""
    if k >= n:
        return span / n
    if 2 * k < n:
        return span * (graded_time((k + 1.0) / n) - graded_time(k / n))
    return span * (graded_time((n - k) / n) - graded_time((n - k - 1.0) / n))   # mirrored: no cancellation near 1


PEAK_POINTS = 5           # samples of F_n through which its peak is interpolated (paper scheme)
CONE_BAND = 1e-9          # relative: a tangential force this close to mu F_n counts as on the Coulomb cone
ONSET_OVERLAP = 1e-12     # overlap, in units of V_n dt, at which first touch's friction is judged


@njit(cache=True)
def paper_first_touch(s, st, p, ints, ext):
    """The paper scheme's tangential force at first touch with a tangential dashpot: -c_t V_s capped by mu F_n
    (finite where both start finite: a constant normal dashpot and a constant k_t), and whether spring and dashpot
    start on the Coulomb cone, judged at a tiny overlap where both rise from 0 (Tsuji's c ~ alpha^1/4 against
    Mindlin's c_t ~ alpha^1/4): a contact that slides from first touch starts with margin 0 and gets the exact
    friction impulse (sliding_kick) from its first step, where the trapezoid of a force ~ t^p loses an order."""
    code, radius, mu = ints[C.I_TANGENTIAL], p[C.P_RADIUS], p[C.P_MU]
    slip0 = p[C.P_VX0] - radius * p[C.P_W0]
    v_n = -p[C.P_VZ0]
    s[S_FT] = cap(-p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], 0.0)) * slip0, mu * abs(s[S_FN]))
    alpha = ONSET_OVERLAP * v_n * p[C.P_DT]
    f_el, a = normal_force(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, alpha, alpha, ext)
    f_n = f_el + p[C.P_DAMP_C0] * damping_power(alpha, p[C.P_DAMP_POWER]) * v_n
    if p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], a)) * abs(slip0) > mu * f_n:
        st[T_HELD] = 0.0


@njit(cache=True)
def newton_value(coef, x, u):
    """Value and slope at u of the Newton-form polynomial with nodes x and divided differences coef."""
    value, slope = coef[len(coef) - 1], 0.0
    for i in range(len(coef) - 2, -1, -1):
        slope = slope * (u - x[i]) + value
        value = value * (u - x[i]) + coef[i]
    return value, slope


@njit(cache=True)
def polynomial_peak(times, values):
    """Largest value of the polynomial through the samples (times, values), the second newest sample being the
    largest, between the third newest and the newest: O(h^5) where the parabola's error, O(h^3) with a phase that
    jumps with h, would spoil the extrapolation of F_max."""
    m = len(times)
    x = times - times[m - 2]
    coef = values.copy()
    for j in range(1, m):
        for i in range(m - 1, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (x[i] - x[i - j])
    lo, hi = x[m - 3], x[m - 1]
    slope_lo = newton_value(coef, x, lo)[1]
    if not (slope_lo > 0.0 and newton_value(coef, x, hi)[1] < 0.0):
        return values[m - 2]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if newton_value(coef, x, mid)[1] > 0.0:
            lo = mid
        else:
            hi = mid
    return max(values[m - 2], newton_value(coef, x, 0.5 * (lo + hi))[0])


@njit(cache=True, parallel=True)
def integrate(params, ints, out, history, stride, ext):
    """Integrate every row of `params`/`ints` (rows in parallel); fill `out` and, if stride > 0, `history`."""
    n = params.shape[0]
    n_hist = history.shape[1]
    for i in prange(n):
        s = np.zeros(N_STATE)
        o = np.zeros(N_STATE)
        st = np.zeros(N_TSTATE)
        ot = np.zeros(N_TSTATE)
        lo = np.zeros(N_STATE)
        lot = np.zeros(N_TSTATE)
        at_event = np.zeros(N_STATE)
        at_event_t = np.zeros(N_TSTATE)
        scratch = np.zeros(N_TSTATE)
        p = params[i]
        row_ints = ints[i]
        h = p[C.P_DT]
        s[S_VZ], s[S_VX], s[S_W] = p[C.P_VZ0], p[C.P_VX0], p[C.P_W0]
        s[S_U] = -p[C.P_MASS] * p[C.P_VZ0]
        reset_history(row_ints[C.I_NORMAL], s)
        s[S_Z] = p[C.P_RADIUS]                        # stand-in sphere: centre at R above its apex
        if p[C.P_DAMP_POWER] == 0.0:
            s[S_FN] = -p[C.P_DAMP_C0] * p[C.P_VZ0]   # a constant dashpot acts from first touch
            s[S_C] = p[C.P_DAMP_C0]
        # the spring starts at 0, inside the Coulomb cone (strictly: a slide starting in the first step is an event)
        st[T_MARGIN] = st[T_HELD] = -p[C.P_MU] * abs(s[S_FN]) - 1e-300
        if row_ints[C.I_INTEGRATOR] == C.INTEGRATOR_VELOCITY_VERLET and row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE:
            # LIGGGHTS' setup force at first touch (gap 0 counts as contact): the tangential dashpot alone
            code = row_ints[C.I_TANGENTIAL]
            slip0 = p[C.P_VX0] - p[C.P_RADIUS] * p[C.P_W0]
            if TANGENTIAL_VISCOUS[code]:
                s[S_FT] = viscous_friction(tangential_stiffness(code, p[C.P_T1], 0.0), p[C.P_TDAMP], slip0,
                                           p[C.P_MU] * abs(s[S_FN]))
            else:
                s[S_FT] = -p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], 0.0)) * slip0
        elif (row_ints[C.I_INTEGRATOR] == C.INTEGRATOR_PAPER and p[C.P_TDAMP] != 0.0
              and row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE and not TANGENTIAL_VISCOUS[row_ints[C.I_TANGENTIAL]]):
            paper_first_touch(s, st, p, row_ints, ext)
        stick_steps = 0
        f_prev2, f_prev1 = 0.0, 0.0
        h_prev = h
        sample_t = np.zeros(PEAK_POINTS)
        sample_f = np.zeros(PEAK_POINTS)
        a_prev2, a_prev1 = 0.0, 0.0
        f_peak, a_peak = s[S_FN], 0.0
        status = C.STATUS_NO_SEPARATION
        t_end = 0.0
        k_rec = 0
        steps = 0
        max_steps = int(p[C.P_MAXSTEPS])
        t_now = 0.0
        grade_n = int(p[C.P_GRADE_N])
        paper = row_ints[C.I_INTEGRATOR] == C.INTEGRATOR_PAPER
        f_sampled = not (paper and p[C.P_DAMP_C0] == 0.0)      # else F_max is F at the turn, located
        for k in range(max_steps):
            if grade_n > 0:
                h = graded_step(k, grade_n, p[C.P_GRADE_T])
            indicator = advance(s, st, o, ot, p, row_ints, h, scratch, ext)
            h_last = h
            if indicator > 0.0 and paper:
                a_peak, f_peak, indicator, _ = split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p, row_ints,
                                                              h, scratch, a_peak, f_peak, h, indicator, ext)
            steps = k + 1
            if indicator <= 0.0 and not paper:
                t_end = t_now + h                          # the engine ends contact at the step, not inside it
                status = C.STATUS_OK
            elif indicator <= 0.0:                         # release inside the step; a regime change before it too
                h_release = h * locate_release(s, st, lo, lot, p, row_ints, h, scratch, indicator, ext)
                step(s, st, o, ot, p, row_ints, h_release, scratch, ext)
                a_peak, f_peak, indicator, h_last = split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p,
                                                                   row_ints, h_release, scratch, a_peak, f_peak, h,
                                                                   -1.0, ext)
                if indicator <= 0.0:
                    t_end = t_now + h_last
                    status = C.STATUS_OK
            f_now, a_now = o[S_FN], o[S_ALPHA]
            if row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE and f_now > 0.0 and \
                    abs(o[S_FT]) < (1.0 - CONE_BAND) * p[C.P_MU] * f_now:
                stick_steps += 1
            if paper:                                  # the last samples of F_n, for its interpolated peak
                for j in range(PEAK_POINTS - 1):
                    sample_t[j], sample_f[j] = sample_t[j + 1], sample_f[j + 1]
                sample_t[PEAK_POINTS - 1], sample_f[PEAK_POINTS - 1] = t_now + h_last, f_now
            if f_sampled and f_prev1 >= f_prev2 and f_prev1 > f_now and f_prev1 >= f_peak and k >= 2:
                if paper and k >= PEAK_POINTS:
                    f_peak = polynomial_peak(sample_t, sample_f)
                else:
                    f_peak = parabola_peak(f_prev2, f_prev1, f_now, h_prev, h_last)
            if not paper and a_prev1 >= a_prev2 and a_prev1 > a_now and a_prev1 >= a_peak and k >= 2:
                a_peak = parabola_peak(a_prev2, a_prev1, a_now, h_prev, h_last)
            h_prev = h_last
            f_peak = max(f_peak, f_now)
            a_peak = max(a_peak, a_now)
            f_prev2, f_prev1, a_prev2, a_prev1 = f_prev1, f_now, a_prev1, a_now
            t_now += h
            if stride > 0 and k % stride == 0 and k_rec < n_hist:
                history[i, k_rec, 0] = t_now
                history[i, k_rec, 1] = o[S_ALPHA]
                history[i, k_rec, 2] = o[S_FN]
                history[i, k_rec, 3] = o[S_FT]
                k_rec += 1
            s[:] = o
            st[:] = ot
            if status == C.STATUS_OK:
                break
            if not (math.isfinite(o[S_VZ]) and math.isfinite(o[S_VX]) and math.isfinite(o[S_W])):
                status = C.STATUS_NONFINITE
                break
        out[i, C.O_VZ], out[i, C.O_VX], out[i, C.O_W] = s[S_VZ], s[S_VX], s[S_W]
        out[i, C.O_TC] = t_end if status == C.STATUS_OK else t_now
        out[i, C.O_FMAX], out[i, C.O_AMAX] = f_peak, a_peak
        out[i, C.O_STEPS], out[i, C.O_STATUS], out[i, C.O_STICKING] = steps, status, stick_steps
        for k in range(k_rec, n_hist):
            history[i, k, 0] = math.nan
