"""The paper scheme's contact ODE in its h -> 0 limit, for the adaptive integrator: rates and event functions.

Between changes of regime the impact is a smooth ODE in y = (alpha, alpha_dot, v_x, omega_y, F_s):
m alpha'' = m g - F_n with F_n = F_el(alpha, alpha_max) + c0 alpha^p alpha_dot; m v_x' = F_t and
I omega' = -R F_t; while sticking F_t = F_s with F_s' = -k_t(a) V_s (+ F_s a'/a for Mindlin's eq. 18b rescale while
a shrinks, always for the total form), V_s = v_x - R omega; while sliding F_t = sigma mu |F_n|.
Walton-Braun's spring (docs/laws.md): T = -F_s rises in the direction d = sign(V_s) as T' = k_t0 x^(1/3) V_s with
x = (mu N - d T)/(mu N - d T*), T* = sigma* mu N (T* scales with N) and sigma* set to T/(mu N) at each reversal
of V_s. Its state is also known by w = x^(1/3): F_s = -d mu N (1 - (1 - d sigma*) w^3) and F_s' = -k_t0 w V_s,
smooth in w where they are singular in F_s (the implicit step solves for w).
"""
import math

from numba import njit

from ..infra.jit import compiled
from . import layout as L
from .dispatch import (END_PULLS, TANGENTIAL_ANY_IMPLICIT, TANGENTIAL_IMPLICIT, TANGENTIAL_LOG_RATE, normal_below,
                       normal_force, normal_slope, tangential_edge_w, tangential_force_from_w, tangential_stiffness,
                       tangential_w_from_force)
from .schemes import damping_power, loading_kink

Y_ALPHA, Y_RATE, Y_VX, Y_W, Y_FS = 0, 1, 2, 3, 4
N_Y = 5
M_LOADING, M_AMAX, M_TANGENTIAL, M_SIGN, M_DENT = 0, 1, 2, 3, 4   # mode: loading?, alpha_max once unloading,
M_DIR, M_STAR = 5, 6                                             # stick/slide, its sign, residual overlap;
M_STICKS = 7                                                     # Walton-Braun: d and sigma* = T*/(mu N);
N_MODE = 8                                                       # stick phases begun (onset included)
STICK, SLIDE = 1.0, 2.0
A_FN, A_DFN, A_TRIAL, A_FT = 0, 1, 2, 3                  # forces at a state: F_n, dF_n/dt, trial dF_s/dt, F_t
N_AUX = 4
E_RELEASE, E_TURN, E_YIELD, E_PEAK, E_SLIP, E_STICK, E_REVERSAL = 0, 1, 2, 3, 4, 5, 6
N_EVENTS = 7
INACTIVE = -math.inf

@compiled
def normal_ode(ints, p, alpha, amax, ext):
    """F_el, dF_el/dalpha and the contact radius a with d(ln a)/dalpha, on the branch (alpha, alpha_max) selects
    (the kernel's slope: a ~ F^(1/3) on Hertzian branches, a = sqrt(R alpha) on linear ones). At the yield overlap
    itself the slope is the plastic one: the loading curve's kink is an event that lands on or just past it, and
    the rates must be those that follow."""
    code, radius = ints[L.I_NORMAL], p[L.RADIUS]
    if alpha <= 0.0:
        return normal_below(code, p, alpha, ext), 0.0, 0.0, 0.0
    f, a = normal_force(code, p, radius, alpha, amax, ext)
    if a <= 0.0:                                      # below the residual dent: the force is delta < 0
        return f, 1.0, 0.0, 0.0
    slope, log_slope = normal_slope(code, p, radius, alpha, alpha >= amax, f, a, ext)
    return f, slope, a, log_slope


@compiled
def coulomb_cone(p, ints, f_n):
    """mu |F_n|; without tension mu max(F_n, 0), so that the cone stays closed beyond the release."""
    if not END_PULLS[ints[L.I_END]] and f_n < 0.0:
        return 0.0
    return p[L.MU] * abs(f_n)


@compiled
def evaluate(p, ints, y, mode, w, dy, aux, ext):
    """dy/dt at y in `mode`, and the forces the events read (aux: F_n, dF_n/dt, trial spring rate, F_t). For
    Walton-Braun's sticking spring a given w (not NaN) sets y's F_s; otherwise w is read from it."""
    m, inertia, radius = p[L.MASS], p[L.INERTIA], p[L.RADIUS]
    alpha, rate = y[Y_ALPHA], y[Y_RATE]
    amax = alpha if mode[M_LOADING] > 0.0 else mode[M_AMAX]
    f_el, slope, a, log_slope = normal_ode(ints, p, alpha, amax, ext)
    c0, power = p[L.DAMPING_C0], p[L.DAMPING_POWER]
    c, c_slope = 0.0, 0.0
    if c0 != 0.0 and power == 0.0:
        c = c0                                        # a constant dashpot acts from first touch
    elif c0 != 0.0 and alpha > 0.0:
        c = c0 * damping_power(alpha, power)
        c_slope = power * c / alpha
    f_n = f_el + c * rate
    accel = p[L.GRAVITY] - f_n / m
    aux[A_FN] = f_n
    aux[A_DFN] = slope * rate + c_slope * rate * rate + c * accel
    dy[Y_ALPHA], dy[Y_RATE] = rate, accel
    dy[Y_VX], dy[Y_W], dy[Y_FS], aux[A_TRIAL], aux[A_FT] = 0.0, 0.0, 0.0, 0.0, 0.0
    if mode[M_TANGENTIAL] == 0.0:
        return
    code = ints[L.I_TANGENTIAL]
    lever = radius - p[L.LEVER] * alpha
    slide = mode[M_TANGENTIAL] == SLIDE
    v_s = slip_velocity(p, y)
    if TANGENTIAL_ANY_IMPLICIT and TANGENTIAL_IMPLICIT[code]:
        trial = implicit_rate(code, p, y, mode, w, coulomb_cone(p, ints, f_n), v_s)
    else:
        trial = -tangential_stiffness(code, p, a) * v_s
    f_t = mode[M_SIGN] * coulomb_cone(p, ints, f_n) if slide else y[Y_FS]
    log_rate = TANGENTIAL_LOG_RATE[code]                # F_s a'/a: eq. 18b while a shrinks, the total form always
    if ((log_rate == 1 and rate < 0.0) or log_rate == 2) and f_t != 0.0:
        trial += f_t * log_slope * rate
    aux[A_TRIAL], aux[A_FT] = trial, f_t
    dy[Y_VX], dy[Y_W] = f_t / m, -lever * f_t / inertia
    dy[Y_FS] = 0.0 if slide else trial


@njit(cache=True, inline="always")
def implicit_rate(code, p, y, mode, w, cone, v_s):
    """A spring integrated in its hidden variable w (Walton-Braun's x^(1/3)): trial dF_s/dt = -k_t0 w V_s. Sticking:
    w given sets F_s, else w from F_s; sliding: w of the spring held on the cone's edge."""
    if mode[M_TANGENTIAL] == SLIDE:
        return -tangential_stiffness(code, p, 0.0) * edge_w(code, mode) * v_s
    if w == w:
        y[Y_FS] = tangential_force_from_w(code, mode[M_DIR], mode[M_STAR], cone, w)
    else:
        w = spring_w_of(code, y, mode, cone)
    return -tangential_stiffness(code, p, 0.0) * w * v_s


@njit(cache=True, inline="always")
def edge_w(code, mode):
    """w of the implicit spring held on the cone's edge (0 on the loading side)."""
    return tangential_edge_w(code, mode[M_DIR], mode[M_STAR], mode[M_SIGN])


@njit(cache=True, inline="always")
def spring_w_of(code, y, mode, cone):
    """w of the sticking implicit spring from its F_s."""
    return tangential_w_from_force(code, mode[M_DIR], mode[M_STAR], cone, y[Y_FS])


@njit(cache=True, inline="always")
def slip_velocity(p, y):
    """V_s = v_x - (R - c alpha) omega: the lever R, shortened by the overlap in engine dialects (c: column LEVER)."""
    return y[Y_VX] - (p[L.RADIUS] - p[L.LEVER] * y[Y_ALPHA]) * y[Y_W]


@njit(cache=True, inline="always")
def cone_rate(p, ints, aux):
    """d(mu |F_n|)/dt."""
    return p[L.MU] * (-aux[A_DFN] if aux[A_FN] < 0.0 and END_PULLS[ints[L.I_END]] else aux[A_DFN])


@compiled
def events(p, ints, y, mode, aux, scale, g, ext):
    """Event functions at y, each rising through 0 at its event (INACTIVE where it cannot happen in this mode);
    scale = (alpha_ref, V_n, F_ref, t_ref, then the error scales, V_t at 6) makes them dimensionless."""
    alpha_ref, v_ref, f_ref, t_ref = scale[0], scale[1], scale[2], scale[3]
    f_n, alpha = aux[A_FN], y[Y_ALPHA]
    loading = mode[M_LOADING] > 0.0
    if END_PULLS[ints[L.I_END]]:
        g[E_RELEASE] = -alpha / alpha_ref
    elif p[L.DAMPING_C0] == 0.0:                       # F_el ~ (alpha - dent)^3/2: the overlap crosses, F is flat
        g[E_RELEASE] = INACTIVE if loading else (mode[M_DENT] - alpha) / alpha_ref
    else:
        g[E_RELEASE] = -min(f_n / f_ref, alpha / alpha_ref)
    g[E_TURN] = -y[Y_RATE] / v_ref if loading else INACTIVE
    kink = loading_kink(p, ints, ext)
    g[E_YIELD] = (alpha - kink) / alpha_ref if loading and kink > 0.0 else INACTIVE
    g[E_PEAK] = -aux[A_DFN] * t_ref / f_ref if p[L.DAMPING_C0] != 0.0 else INACTIVE
    cone = coulomb_cone(p, ints, f_n)
    g[E_SLIP] = (abs(y[Y_FS]) - cone) / f_ref if mode[M_TANGENTIAL] == STICK else INACTIVE
    v_s = slip_velocity(p, y)
    reversible = TANGENTIAL_ANY_IMPLICIT and TANGENTIAL_IMPLICIT[ints[L.I_TANGENTIAL]] and mode[M_TANGENTIAL] != 0.0
    g[E_REVERSAL] = -mode[M_DIR] * v_s / scale[6] if reversible else INACTIVE
    inward = cone_rate(p, ints, aux) - mode[M_SIGN] * aux[A_TRIAL]
    g[E_STICK] = inward * t_ref / f_ref if mode[M_TANGENTIAL] == SLIDE else INACTIVE
