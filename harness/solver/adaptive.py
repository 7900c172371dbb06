"""Adaptive Dormand-Prince 5(4) integration of the paper scheme's contact ODE for the converged mode.

Between changes of regime the impact is a smooth ODE in y = (alpha, alpha_dot, v_x, omega_y, F_s):
m alpha'' = m g - F_n with F_n = F_el(alpha, alpha_max) + c0 alpha^p alpha_dot (MODELS 2); m v_x' = F_t and
I omega' = -R F_t; while sticking F_t = F_s with F_s' = -k_t(a) V_s (+ F_s a'/a for Mindlin's eq. 18b rescale while
a shrinks, always for the total form), V_s = v_x - R omega; while sliding F_t = sigma mu |F_n| (MODELS 3). Every
change of regime is an event on which a step lands (Illinois false position on the length of the step): the turn
(alpha' = 0: unloading from alpha_max), the yield kink of the loading curve, the start of sliding (|F_s| reaches
mu |F_n|), its end (the trial spring moves inward faster than mu |F_n| shrinks), the peak of a damped F_n and the
release (alpha = 0, or F_n = 0 without tension). The step size is controlled by the embedded fourth-order error
(Dormand & Prince 1980), which also refines towards the power-law singularities at first touch and release.
This is the h -> 0 limit of kernel.step, the second-order paper scheme, integrated at fifth order.
"""
import math

import numpy as np
from numba import njit, prange

from . import codes as C
from .kernel import damping_power, illinois, loading_kink
from .normal_kernels import normal_elastic, residual_overlap
from .tangential_kernels import stiffness

Y_ALPHA, Y_RATE, Y_VX, Y_W, Y_FS = 0, 1, 2, 3, 4
N_Y = 5
M_LOADING, M_AMAX, M_TANGENTIAL, M_SIGN, M_DENT = 0, 1, 2, 3, 4   # mode: loading?, alpha_max once unloading,
N_MODE = 5                                                       # stick/slide, its sign, residual overlap
STICK, SLIDE = 1.0, 2.0
A_FN, A_DFN, A_TRIAL, A_FT = 0, 1, 2, 3                  # forces at a state: F_n, dF_n/dt, trial dF_s/dt, F_t
N_AUX = 4
E_RELEASE, E_TURN, E_YIELD, E_PEAK, E_SLIP, E_STICK = 0, 1, 2, 3, 4, 5
N_EVENTS = 6
INACTIVE = -math.inf
SUPPORTED_NORMAL = (C.NORMAL_LINEAR, C.NORMAL_HERTZ, C.NORMAL_WALTON_BRAUN, C.NORMAL_THORNTON, C.NORMAL_STRONGE)
SUPPORTED_TANGENTIAL = (C.TANGENTIAL_NONE, C.TANGENTIAL_LINEAR, C.TANGENTIAL_MINDLIN_INCREMENTAL,
                        C.TANGENTIAL_MINDLIN_RESCALE, C.TANGENTIAL_MINDLIN_TOTAL)

# Dormand-Prince 5(4) (the ODE is autonomous: no nodes needed): stage coefficients, whose last row holds the
# fifth-order weights (FSAL), and the error weights b - b* of the embedded fourth-order solution
DP_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
    [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
    [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0]])
DP_E = np.array([71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0,
                 -1.0 / 40.0])
STAGES = 7
SAFETY, GROW, SHRINK = 0.9, 5.0, 0.2
LOCATE_ITERATIONS = 60
EVENT_ROUND_OFF = 1e-13     # |event function| (dimensionless) at which an event counts as located ...
EVENT_SHARE = 1e-3          # ... or this share of the tolerance: its misplacement is then negligible
STEP_CAP = 10 ** 7          # trial steps per impact at most (a stick that rings ~1000 times a contact needs 1e5)
FIRST_STEP = 1e-6           # first trial step, in contact times
RELEASE_TIE = 1e-9          # step fraction within which an event next to the release counts as the release
ONSET_PROBE = 1e-9          # overlap, in alpha_ref, at which the first touch's stick-or-slide is decided


def supports(ints, params):
    """Rows this integrator covers: the paper scheme with the normal laws and tangential springs it models, without
    a tangential dashpot or an engine's slip form (the rest stays on the graded Richardson ladder). Walton-Braun's
    spring is not among them: its stiffness k_t0 x^(1/3) rides just under a rising mu N at x ~ (mu N'/k_t0 V_s)^3,
    a relaxation so stiff at grazing incidence (rate ~ x^(-2/3)) that explicit steps take 10^5-10^8 evaluations,
    and its cube root at x = 0 defeats Newton in an implicit (Radau IIA) step (README, Design notes)."""
    return (np.isin(ints[:, C.I_NORMAL], SUPPORTED_NORMAL) & np.isin(ints[:, C.I_TANGENTIAL], SUPPORTED_TANGENTIAL)
            & (ints[:, C.I_INTEGRATOR] == C.INTEGRATOR_PAPER) & (params[:, C.P_TDAMP] == 0.0)
            & (params[:, C.P_SLIP_R1] == 0.0) & (params[:, C.P_BIG_R] == 0.0))


@njit(cache=True)
def normal_ode(ints, p, alpha, amax):
    """F_el, dF_el/dalpha and the contact radius a with d(ln a)/dalpha, on the branch (alpha, alpha_max) selects:
    a ~ F^(1/3) on Hertz branches (original or unloading radius), a = a_y (F/F_y)^(1/2) on Stronge's plastic line,
    a = sqrt(R alpha) otherwise (MODELS 2). At the yield overlap itself the slope is the plastic one: the loading
    curve's kink is an event that lands on or just past it, and the rates must be those that follow."""
    code, radius = ints[C.I_NORMAL], p[C.P_RADIUS]
    if alpha <= 0.0:
        return (p[C.P_N1] * alpha if code == C.NORMAL_LINEAR else 0.0), 0.0, 0.0, 0.0
    f, a = normal_elastic(code, p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius, alpha, amax)
    if a <= 0.0:                                      # below the residual dent: normal_elastic returns F = delta < 0
        return f, 1.0, 0.0, 0.0
    plain = 0.5 / alpha                               # a = sqrt(R alpha)
    loading = alpha >= amax
    if code == C.NORMAL_LINEAR:
        return f, p[C.P_N1], a, plain
    if code == C.NORMAL_WALTON_BRAUN:
        return f, (p[C.P_N1] if loading else p[C.P_N2]), a, plain
    hertz_slope = 2.0 * p[C.P_N1] * a
    if code == C.NORMAL_THORNTON and loading and alpha >= p[C.P_N3]:
        return f, math.pi * p[C.P_N2] * radius, a, plain
    if code == C.NORMAL_STRONGE and loading and alpha >= p[C.P_N2]:
        slope = 2.0 * p[C.P_N3] / p[C.P_N2]
        return f, slope, a, slope / (2.0 * f)
    return f, hertz_slope, a, hertz_slope / (3.0 * f)


@njit(cache=True)
def coulomb_cone(p, ints, f_n):
    """mu |F_n|; without tension mu max(F_n, 0), so that the cone stays closed beyond the release."""
    if ints[C.I_END] == C.END_FORCE and f_n < 0.0:
        return 0.0
    return p[C.P_MU] * abs(f_n)


@njit(cache=True)
def evaluate(p, ints, y, mode, dy, aux):
    """dy/dt at y in `mode`, and the forces the events read (aux: F_n, dF_n/dt, trial spring rate, F_t)."""
    m, inertia, radius = p[C.P_MASS], p[C.P_INERTIA], p[C.P_RADIUS]
    alpha, rate = y[Y_ALPHA], y[Y_RATE]
    amax = alpha if mode[M_LOADING] > 0.0 else mode[M_AMAX]
    f_el, slope, a, log_slope = normal_ode(ints, p, alpha, amax)
    c0, power = p[C.P_DAMP_C0], p[C.P_DAMP_POWER]
    c, c_slope = 0.0, 0.0
    if c0 != 0.0 and power == 0.0:
        c = c0                                        # a constant dashpot acts from first touch
    elif c0 != 0.0 and alpha > 0.0:
        c = c0 * damping_power(alpha, power)
        c_slope = power * c / alpha
    f_n = f_el + c * rate
    accel = p[C.P_GRAVITY] - f_n / m
    aux[A_FN] = f_n
    aux[A_DFN] = slope * rate + c_slope * rate * rate + c * accel
    dy[Y_ALPHA], dy[Y_RATE] = rate, accel
    dy[Y_VX], dy[Y_W], dy[Y_FS], aux[A_TRIAL], aux[A_FT] = 0.0, 0.0, 0.0, 0.0, 0.0
    if mode[M_TANGENTIAL] == 0.0:
        return
    code = ints[C.I_TANGENTIAL]
    lever = radius - p[C.P_LEVER] * alpha
    slide = mode[M_TANGENTIAL] == SLIDE
    f_t = mode[M_SIGN] * coulomb_cone(p, ints, f_n) if slide else y[Y_FS]
    trial = -stiffness(code, p[C.P_T1], a) * (y[Y_VX] - lever * y[Y_W])
    shrinking = rate < 0.0 and code == C.TANGENTIAL_MINDLIN_RESCALE
    if (shrinking or code == C.TANGENTIAL_MINDLIN_TOTAL) and f_t != 0.0:
        trial += f_t * log_slope * rate               # F_s a'/a
    aux[A_TRIAL], aux[A_FT] = trial, f_t
    dy[Y_VX], dy[Y_W] = f_t / m, -lever * f_t / inertia
    dy[Y_FS] = 0.0 if slide else trial


@njit(cache=True)
def events(p, ints, y, mode, aux, scale, g):
    """Event functions at y, each rising through 0 at its event (INACTIVE where it cannot happen in this mode);
    scale = (alpha_ref, V_ref, F_ref, t_ref) makes them dimensionless."""
    alpha_ref, v_ref, f_ref, t_ref = scale[0], scale[1], scale[2], scale[3]
    f_n, alpha = aux[A_FN], y[Y_ALPHA]
    loading = mode[M_LOADING] > 0.0
    if ints[C.I_END] == C.END_ALPHA:
        g[E_RELEASE] = -alpha / alpha_ref
    elif p[C.P_DAMP_C0] == 0.0:                       # F_el ~ (alpha - dent)^3/2: the overlap crosses, F is flat
        g[E_RELEASE] = INACTIVE if loading else (mode[M_DENT] - alpha) / alpha_ref
    else:
        g[E_RELEASE] = -min(f_n / f_ref, alpha / alpha_ref)
    g[E_TURN] = -y[Y_RATE] / v_ref if loading else INACTIVE
    kink = loading_kink(p, ints)
    g[E_YIELD] = (alpha - kink) / alpha_ref if loading and kink > 0.0 else INACTIVE
    g[E_PEAK] = -aux[A_DFN] * t_ref / f_ref if p[C.P_DAMP_C0] != 0.0 else INACTIVE
    cone = coulomb_cone(p, ints, f_n)
    g[E_SLIP] = (abs(y[Y_FS]) - cone) / f_ref if mode[M_TANGENTIAL] == STICK else INACTIVE
    cone_rate = p[C.P_MU] * (-aux[A_DFN] if f_n < 0.0 and ints[C.I_END] == C.END_ALPHA else aux[A_DFN])
    g[E_STICK] = (cone_rate - mode[M_SIGN] * aux[A_TRIAL]) * t_ref / f_ref if mode[M_TANGENTIAL] == SLIDE else INACTIVE


@njit(cache=True)
def dp_step(p, ints, y, mode, h, k, y_new, stage, aux, scale, tol):
    """One Dormand-Prince step of length h from y (k[0] = dy/dt at y) into y_new, k[6] = dy/dt at y_new (FSAL),
    aux the forces at y_new; returns the error norm: max over components of |error| / (tol x its scale)."""
    for s in range(1, STAGES):
        for i in range(N_Y):
            acc = 0.0
            for j in range(s):
                acc += DP_A[s, j] * k[j, i]
            stage[i] = y[i] + h * acc
        evaluate(p, ints, stage, mode, k[s], aux)
    for i in range(N_Y):
        y_new[i] = stage[i]                           # the last stage is the fifth-order solution (FSAL)
    err = 0.0
    for i in range(N_Y):
        e = 0.0
        for j in range(STAGES):
            e += DP_E[j] * k[j, i]
        e = abs(h * e) / (tol * scale[4 + i])
        if not e <= err:
            err = e if e == e else math.inf
    return err


@njit(cache=True)
def hermite(y, y_end, f_start, f_end, h, theta, out):
    """State at step fraction theta on the cubic Hermite interpolant of the step (values and rates at both ends)."""
    h00, h10 = (1.0 + 2.0 * theta) * (1.0 - theta) ** 2, theta * (1.0 - theta) ** 2
    h01, h11 = theta * theta * (3.0 - 2.0 * theta), theta * theta * (theta - 1.0)
    for i in range(N_Y):
        out[i] = h00 * y[i] + h10 * h * f_start[i] + h01 * y_end[i] + h11 * h * f_end[i]


@njit(cache=True)
def interpolated_root(kind, p, ints, y, y_end, f_start, f_end, mode, h, state, dy, aux, scale, g, g_start, g_end):
    """Step fraction of event `kind` on the step's Hermite interpolant (one force evaluation per trial): a cheap,
    O(h^4) first estimate for `locate`; returns (fraction, slope of the event function there, evaluations)."""
    lo, hi, g_lo, g_hi, side, trials = 0.0, 1.0, g_start, g_end, 0, 0
    mid = 1.0
    while trials < LOCATE_ITERATIONS and hi - lo > 1e-13 * hi:
        mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        if not lo < mid < hi:
            mid = 0.5 * (lo + hi)
        hermite(y, y_end, f_start, f_end, h, mid, state)
        evaluate(p, ints, state, mode, dy, aux)
        events(p, ints, state, mode, aux, scale, g)
        trials += 1
        if abs(g[kind]) <= EVENT_ROUND_OFF:
            break
        lo, hi, g_lo, g_hi, side = illinois(lo, hi, g_lo, g_hi, side, mid, g[kind], g[kind] < 0.0)
    return mid, (g_end - g_start) if hi - lo <= 0.0 else (g_hi - g_lo) / (hi - lo), trials


@njit(cache=True)
def locate(kind, p, ints, y, mode, h, k, y_new, stage, aux, scale, g_start, g_end, g, tol, guess, slope):
    """Step fraction in (0, 1] at which event `kind` happens inside the step of length h from y: secant steps on the
    event function after real trial steps, from `guess` with `slope` (the interpolant's), kept inside the bracket
    (Illinois false position when a secant leaves it), until the function is within round-off or a share of the
    tolerance of 0 and not below it (the rates after a kink must be the new ones); returns it and the number of
    trial steps taken."""
    lo, hi, g_lo, g_hi = 0.0, 1.0, g_start, g_end
    side, trials = 0, 0
    last, g_last = -1.0, 0.0
    mid = guess
    while trials < LOCATE_ITERATIONS and hi - lo > 1e-13 * hi:
        if not lo < mid < hi:
            mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
            if not lo < mid < hi:
                mid = 0.5 * (lo + hi)
        dp_step(p, ints, y, mode, mid * h, k, y_new, stage, aux, scale, tol)
        events(p, ints, y_new, mode, aux, scale, g)
        trials += 1
        value = g[kind]
        close = abs(value) <= max(EVENT_ROUND_OFF, EVENT_SHARE * tol)
        if close and value >= 0.0:                    # located, on or just past the event
            return mid, trials
        lo, hi, g_lo, g_hi, side = illinois(lo, hi, g_lo, g_hi, side, mid, value, value < 0.0)
        if last >= 0.0 and mid != last:
            slope = (value - g_last) / (mid - last)
        last, g_last = mid, value
        mid = mid - (2.0 if close else 1.0) * value / slope if slope > 0.0 else -1.0   # just short: step past it
    return hi, trials


@njit(cache=True, inline="always")
def crosses(e, g_start, g_end):
    """Event e happens inside the step: its function rises through 0. Stick and slip also from exactly 0 (a contact
    that just stuck has its spring on the cone), the others strictly from below (first touch starts at 0)."""
    if e == E_SLIP or e == E_STICK:
        return g_start <= 0.0 < g_end
    return g_start < 0.0 <= g_end


@njit(cache=True)
def settle_friction(p, ints, y, mode, g, f_n):
    """At a step's start: a slide whose cone outgrows the spring sticks, a stick whose spring is beyond the cone
    slides. Needed after events at which the rates jump (the yield kink: no crossing to locate); elsewhere a safety
    net. Returns whether the mode changed."""
    if mode[M_TANGENTIAL] == SLIDE and g[E_STICK] > 0.0:
        start_stick(p, ints, y, mode, f_n)
        return True
    if mode[M_TANGENTIAL] == STICK and g[E_SLIP] > 0.0:
        start_slide(y, mode)
        return True
    return False


@njit(cache=True, inline="always")
def start_slide(y, mode):
    """The spring reaches the Coulomb cone: slide, on the side of the spring force."""
    mode[M_TANGENTIAL], mode[M_SIGN] = SLIDE, (1.0 if y[Y_FS] > 0.0 else -1.0)


@njit(cache=True, inline="always")
def start_stick(p, ints, y, mode, f_n):
    """The spring leaves the Coulomb cone: stick, the spring starting on the cone."""
    mode[M_TANGENTIAL] = STICK
    y[Y_FS] = mode[M_SIGN] * coulomb_cone(p, ints, f_n)


@njit(cache=True)
def onset_mode(p, ints, y, mode, dy, aux, scale):
    """Stick or slide at first touch: stick while mu |F_n| > 0 there; where both start from 0 (undamped laws, whose
    spring and cone grow alike), slide if the trial spring outgrows the cone, judged at a tiny overlap."""
    if ints[C.I_TANGENTIAL] == C.TANGENTIAL_NONE:
        mode[M_TANGENTIAL] = 0.0
        return
    mode[M_TANGENTIAL] = STICK
    evaluate(p, ints, y, mode, dy, aux)
    if p[C.P_MU] * abs(aux[A_FN]) > 0.0:
        return
    probe = y.copy()
    probe[Y_ALPHA] = ONSET_PROBE * scale[0]
    evaluate(p, ints, probe, mode, dy, aux)
    if abs(aux[A_TRIAL]) > p[C.P_MU] * aux[A_DFN]:
        mode[M_TANGENTIAL] = SLIDE
        mode[M_SIGN] = 1.0 if aux[A_TRIAL] > 0.0 else -1.0


@njit(cache=True)
def impact(p, ints, tol, t_ref, row_out):
    """One impact from first touch to release at tolerance `tol`; fills row_out like kernel.integrate, with O_STEPS
    the number of force evaluations."""
    m, radius = p[C.P_MASS], p[C.P_RADIUS]
    v_n = abs(p[C.P_VZ0])                            # the normalised outcomes divide by the incident normal and
    v_t = abs(p[C.P_VX0]) + radius * abs(p[C.P_W0])  # tangential speeds: errors are measured against each
    if v_t == 0.0:
        v_t = v_n
    alpha_ref, f_ref = v_n * t_ref, m * v_n / t_ref
    scale = np.array([alpha_ref, v_n, f_ref, t_ref, alpha_ref, v_n, v_t, v_t / radius, m * v_t / t_ref])
    y = np.array([0.0, -p[C.P_VZ0], p[C.P_VX0], p[C.P_W0], 0.0])
    mode = np.zeros(N_MODE)
    mode[M_LOADING] = 1.0
    k = np.zeros((STAGES, N_Y))
    y_new, stage, dy, aux, aux_new = np.zeros(N_Y), np.zeros(N_Y), np.zeros(N_Y), np.zeros(N_AUX), np.zeros(N_AUX)
    g_start, g_end, g = np.zeros(N_EVENTS), np.zeros(N_EVENTS), np.zeros(N_EVENTS)
    onset_mode(p, ints, y, mode, k[0], aux, scale)
    evaluate(p, ints, y, mode, k[0], aux)
    events(p, ints, y, mode, aux, scale, g_start)
    evaluations, accepted = 2, 0
    t, h = 0.0, FIRST_STEP * t_ref
    f_peak, a_peak = aux[A_FN], 0.0
    status = C.STATUS_NO_SEPARATION
    t_cap = p[C.P_MAXSTEPS] * p[C.P_DT]               # the kernel's time limit: the same slowed contact times
    for _ in range(STEP_CAP):
        if t >= t_cap:
            break
        err = dp_step(p, ints, y, mode, h, k, y_new, stage, aux_new, scale, tol)
        evaluations += STAGES - 1
        if not err <= 1.0:
            h *= max(SHRINK, SAFETY * err ** -0.2) if err < math.inf else SHRINK
            if h < 1e-15 * t_ref:
                status = C.STATUS_NONFINITE
                break
            continue
        events(p, ints, y_new, mode, aux_new, scale, g_end)
        first, frac, slope, release, release_rise = -1, 1.0, 0.0, 2.0, 0.0
        for e in range(N_EVENTS):                     # the first event of the step, on its interpolant
            if crosses(e, g_start[e], g_end[e]):
                at, rise, trials = interpolated_root(e, p, ints, y, y_new, k[0], k[STAGES - 1], mode, h, stage, dy,
                                                     aux, scale, g, g_start[e], g_end[e])
                evaluations += trials
                if e == E_RELEASE:
                    release, release_rise = at, rise
                if first < 0 or at < frac:
                    first, frac, slope = e, at, rise
        if release <= frac + RELEASE_TIE:             # an event at the release itself (F_n's sign) is none
            first, frac, slope = E_RELEASE, release, release_rise
        step = h
        if first >= 0:                                # land on it: located on real steps, then the landing step
            frac, trials = locate(first, p, ints, y, mode, h, k, y_new, stage, aux_new, scale, g_start[first],
                                  g_end[first], g, tol, frac, slope)
            evaluations += trials * (STAGES - 1)
            step = frac * h
            err = dp_step(p, ints, y, mode, step, k, y_new, stage, aux_new, scale, tol)
            evaluations += STAGES - 1
            if not err <= 1.0:                        # a singular end (alpha^3/2 at release): refine towards it
                h = step * max(SHRINK, SAFETY * err ** -0.2) if err < math.inf else step * SHRINK
                continue
        t += step
        accepted += 1
        y[:] = y_new
        f_n = aux_new[A_FN]
        f_peak = max(f_peak, f_n)                     # exact at the located turn (undamped) or peak (damped)
        a_peak = max(a_peak, y[Y_ALPHA])
        if first == E_RELEASE:
            status = C.STATUS_OK
            break
        if first == E_TURN:
            mode[M_LOADING], mode[M_AMAX] = 0.0, y[Y_ALPHA]
            mode[M_DENT] = residual_overlap(ints[C.I_NORMAL], p[C.P_N1], p[C.P_N2], p[C.P_N3], p[C.P_N4], radius,
                                            y[Y_ALPHA])
        elif first == E_SLIP:
            start_slide(y, mode)
        elif first == E_STICK:
            start_stick(p, ints, y, mode, f_n)
        if first == E_TURN or first == E_SLIP or first == E_STICK:
            evaluate(p, ints, y, mode, k[0], aux)     # the new regime's rates
            evaluations += 1
        else:
            k[0, :] = k[STAGES - 1, :]
            aux[:] = aux_new
        events(p, ints, y, mode, aux, scale, g_start)
        if settle_friction(p, ints, y, mode, g_start, aux[A_FN]):
            evaluate(p, ints, y, mode, k[0], aux)
            events(p, ints, y, mode, aux, scale, g_start)
            evaluations += 1
        h *= min(GROW, SAFETY * err ** -0.2) if err > 0.0 else GROW
    row_out[C.O_VZ], row_out[C.O_VX], row_out[C.O_W] = -y[Y_RATE], y[Y_VX], y[Y_W]
    row_out[C.O_TC], row_out[C.O_FMAX], row_out[C.O_AMAX] = t, f_peak, a_peak
    row_out[C.O_STEPS], row_out[C.O_STATUS], row_out[C.O_ACCEPTED] = evaluations, status, accepted


@njit(cache=True, parallel=True)
def integrate_adaptive(params, ints, tol, t_ref, out):
    """Every row of params/ints at tolerance tol (rows in parallel); t_ref per row: the contact-time estimate."""
    for i in prange(params.shape[0]):
        impact(params[i], ints[i], tol, t_ref[i], out[i])
