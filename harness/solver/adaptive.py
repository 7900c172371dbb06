"""Adaptive integration of the paper scheme's contact ODE (contact_ode.py) for the converged mode.

Every change of regime is an event on which a step lands (Illinois false position on the length of the step): the
turn (alpha' = 0: unloading from alpha_max), the yield kink of the loading curve, the start of sliding (|F_s|
reaches mu |F_n|), its end (the trial spring moves inward faster than mu |F_n| shrinks), the peak of a damped F_n
and the release (alpha = 0, or F_n = 0 without tension). The step size is controlled by the embedded error of a
Dormand-Prince 5(4) pair (steppers.py), which also refines towards the power-law singularities at first touch and
release. This is the h -> 0 limit of kernel.step, the second-order paper scheme, integrated at fifth order.
"""
import math

import numpy as np
from numba import njit, prange

from . import codes as C
from .contact_ode import (A_DFN, A_FN, A_TRIAL, E_RELEASE, E_SLIP, E_STICK, E_TURN, M_AMAX, M_DENT, M_LOADING,
                          M_SIGN, M_TANGENTIAL, N_AUX, N_EVENTS, N_MODE, N_Y, SLIDE, STICK, Y_ALPHA, Y_FS, Y_RATE,
                          Y_VX, Y_W, coulomb_cone, evaluate, events)
from .kernel import illinois
from .normal_kernels import residual_overlap
from .steppers import STAGES, dp_step, hermite

SUPPORTED_NORMAL = (C.NORMAL_LINEAR, C.NORMAL_HERTZ, C.NORMAL_WALTON_BRAUN, C.NORMAL_THORNTON, C.NORMAL_STRONGE)
SUPPORTED_TANGENTIAL = (C.TANGENTIAL_NONE, C.TANGENTIAL_LINEAR, C.TANGENTIAL_MINDLIN_INCREMENTAL,
                        C.TANGENTIAL_MINDLIN_RESCALE, C.TANGENTIAL_MINDLIN_TOTAL)

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
