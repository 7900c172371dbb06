"""Adaptive integration of the paper scheme's contact ODE (contact_ode.py) for the converged mode.

Every change of regime is an event on which a step lands (Illinois false position on the length of the step): the
turn (alpha' = 0: unloading from alpha_max), the yield kink of the loading curve, the start of sliding (|F_s|
reaches mu |F_n|), its end (the trial spring moves inward faster than mu |F_n| shrinks), the peak of a damped F_n
and the release (alpha = 0, or F_n = 0 without tension); under Walton-Braun's spring also each reversal of the slip
(T* = T). The step size is controlled by the embedded error of a Dormand-Prince 5(4) pair, or for Walton-Braun's
spring of the L-stable SDIRK4(3) (steppers.py): that spring rides just under a rising mu N at
x ~ (mu N'/(k_t0 V_s))^3 and relaxes there at a rate ~ x^(-2/3), far too stiff for explicit steps at grazing
incidence. The error control also refines towards the power-law singularities at first touch and release. This is
the h -> 0 limit of schemes.step, the second-order paper scheme, integrated at fifth (fourth) order.
"""
import math

import numpy as np
from numba import njit

from ..infra.jit import compiled
from . import codes as C
from . import layout as L
from .adaptive_work import copy_into, row_work, work_arrays
from .compile_notice import announce_compiling
from .contact_ode import (A_DFN, A_FN, A_TRIAL, E_RELEASE, E_REVERSAL, E_SLIP, E_STICK, E_TURN, M_AMAX, M_DENT,
                          M_DIR, M_LOADING, M_SIGN, M_STAR, M_STICKS, M_TANGENTIAL, N_EVENTS, N_Y, SLIDE, STICK,
                          Y_ALPHA, Y_FS, Y_RATE, Y_VX, Y_W, cone_rate, coulomb_cone, edge_w, evaluate, events,
                          slip_velocity)
from .dispatch import TANGENTIAL_ANY_IMPLICIT, TANGENTIAL_IMPLICIT, TANGENTIAL_NONE, normal_residual, tangential_onset_w
from .events import illinois
from .steppers import J_END, J_START, STAGES, dp_step, hermite, sdirk_step
from .threads import in_threads


SAFETY, GROW, SHRINK = 0.9, 5.0, 0.2
LOCATE_ITERATIONS = 60
EVENT_ROUND_OFF = 1e-13     # |event function| (dimensionless) at which an event counts as located ...
EVENT_SHARE = 1e-3          # ... or this share of the tolerance: its misplacement is then negligible
STEP_CAP = 10 ** 7          # trial steps per impact at most (a stick that rings ~1000 times a contact needs 1e5)
FIRST_STEP = 1e-6           # first trial step, in contact times
RELEASE_TIE = 1e-9          # step fraction within which an event next to the release counts as the release
CONE_ROUND_OFF = 1e-12      # relative band of |F_s| around mu |F_n| within which the spring counts as on the cone
STALL_STEP, STALL_COUNT = 1e-9, 10 ** 4   # that many accepted steps in a row below this share of a contact: stalled
SETTLE_ROUNDS = 3           # changes of regime settled at one step's start at most (a turn, a slip, a reversal)
ONSET_PROBE = 1e-9          # overlap, in alpha_ref, at which the first touch's stick-or-slide is decided


def supports(ints, params):
    """Rows this integrator covers: the kernels, integrator (the paper scheme, whose h -> 0 limit it is) and geometry
    (a wall) that declare it, without a tangential dashpot or an engine's slip form (the rest stays on the graded
    Richardson ladder)."""
    from ..submodels.registry import kernels
    covered = np.ones(len(ints), dtype=bool)
    for family, column in (("normal", L.I_NORMAL), ("tangential", L.I_TANGENTIAL), ("integrator", L.I_INTEGRATOR),
                           ("geometry", L.I_GEOMETRY)):
        covered &= np.array([k.adaptive for k in kernels(family)])[ints[:, column]]
    dashpot = (params[:, L.TANGENTIAL_DAMPING_PREFACTOR] != 0.0) | (params[:, L.TANGENTIAL_DAMPING_SHARE] != 0.0)
    return covered & ~dashpot & (params[:, L.SLIP_RADIUS] == 0.0)


def stepper_names(ints):
    """Which stepper each row takes: the implicit one for Walton-Braun's spring, Dormand-Prince otherwise."""
    return np.where(TANGENTIAL_IMPLICIT[ints[:, L.I_TANGENTIAL]], "SDIRK4(3)", "DP5(4)")


@compiled
def interpolated_root(kind, p, ints, wk, h, ext):
    """Step fraction of event `kind` on the Hermite interpolant of the step of length h from wk.y to wk.y_new (one
    force evaluation per trial, at wk.stage): a cheap, O(h^4) first estimate for `locate`; returns (fraction, slope
    of the event function there, evaluations)."""
    g_start, g_end, g = wk.g_start[kind], wk.g_end[kind], wk.g
    lo, hi, g_lo, g_hi, side, trials = 0.0, 1.0, g_start, g_end, 0, 0
    mid = 1.0
    while trials < LOCATE_ITERATIONS and hi - lo > 1e-13 * hi:
        mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        if not lo < mid < hi:
            mid = 0.5 * (lo + hi)
        hermite(wk.y, wk.y_new, wk.k[0], wk.k[STAGES - 1], h, mid, wk.stage)
        evaluate(p, ints, wk.stage, wk.mode, math.nan, wk.dy, wk.aux, ext)
        events(p, ints, wk.stage, wk.mode, wk.aux, wk.scale, g, ext)
        trials += 1
        if abs(g[kind]) <= EVENT_ROUND_OFF:
            break
        lo, hi, g_lo, g_hi, side = illinois(lo, hi, g_lo, g_hi, side, mid, g[kind], g[kind] < 0.0)
    return mid, (g_end - g_start) if hi - lo <= 0.0 else (g_hi - g_lo) / (hi - lo), trials


@compiled
def advance(implicit, p, ints, wk, h, tol, ext):
    """One step of length h from wk.y into wk.y_new with the row's stepper, wk.aux_new the forces there (spring[0]:
    w at y, spring[1]: at y_new); returns (error norm, force evaluations)."""
    if TANGENTIAL_ANY_IMPLICIT and implicit:
        return sdirk_step(p, ints, wk.y, wk.spring[0], wk.mode, h, wk.k, wk.y_new, wk.rows, wk.jac, wk.lu, wk.pivot,
                          wk.aux_new, wk.scale, tol, wk.spring[1:], ext)
    return dp_step(p, ints, wk.y, wk.mode, h, wk.k, wk.y_new, wk.stage, wk.aux_new, wk.scale, tol, ext), STAGES - 1


@compiled
def locate(kind, implicit, p, ints, wk, h, tol, guess, slope, ext):
    """Step fraction in (0, 1] at which event `kind` happens inside the step of length h from wk.y (its event
    function wk.g_start[kind] there, wk.g_end[kind] at the step's end): secant steps on the
    event function after real trial steps, from `guess` with `slope` (the interpolant's), kept inside the bracket
    (Illinois false position when a secant leaves it), until the function is within round-off or a share of the
    tolerance of 0 and not below it (the rates after a kink must be the new ones); returns it and the number of
    force evaluations."""
    lo, hi, g_lo, g_hi = 0.0, 1.0, wk.g_start[kind], wk.g_end[kind]
    side, trials, evaluations = 0, 0, 0
    last, g_last = -1.0, 0.0
    mid = guess
    while trials < LOCATE_ITERATIONS and hi - lo > 1e-13 * hi:
        if not lo < mid < hi:
            mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
            if not lo < mid < hi:
                mid = 0.5 * (lo + hi)
        _, spent = advance(implicit, p, ints, wk, mid * h, tol, ext)
        events(p, ints, wk.y_new, wk.mode, wk.aux_new, wk.scale, wk.g, ext)
        trials += 1
        evaluations += spent
        value = wk.g[kind]
        close = abs(value) <= max(EVENT_ROUND_OFF, EVENT_SHARE * tol)
        if close and value >= 0.0:                    # located, on or just past the event
            return mid, evaluations
        lo, hi, g_lo, g_hi, side = illinois(lo, hi, g_lo, g_hi, side, mid, value, value < 0.0)
        if last >= 0.0 and mid != last:
            slope = (value - g_last) / (mid - last)
        last, g_last = mid, value
        mid = mid - (2.0 if close else 1.0) * value / slope if slope > 0.0 else -1.0   # just short: step past it
    return hi, evaluations


@njit(cache=True, inline="always")
def crosses(e, g_start, g_end):
    """Event e happens inside the step: its function rises through 0. Stick and slip also from exactly 0 (a contact
    that just stuck has its spring on the cone), the others strictly from below (first touch starts at 0)."""
    if e == E_SLIP or e == E_STICK:
        return g_start <= 0.0 < g_end
    return g_start < 0.0 <= g_end


@compiled
def settle(p, ints, y, mode, g, aux, spring, ext):
    """At a step's start: a turn already passed unloads; a slide whose cone outgrows the spring sticks, a stick
    whose spring is beyond the cone, or on it within round-off and moving out, slides; a
    Walton-Braun spring whose slip has turned reverses. Needed after events at which the rates jump (the yield
    kink: no crossing to locate) or that come with another (a Walton-Braun spring riding the cone slips at the
    turn, where mu N' changes sign: landing on one passes or all but reaches the other); elsewhere a safety net.
    Returns whether the mode changed."""
    f_n = aux[A_FN]
    if g[E_TURN] > 0.0:
        start_unloading(p, ints, y, mode, ext)
        return True
    if mode[M_TANGENTIAL] == SLIDE and g[E_STICK] > 0.0:
        start_stick(p, ints, y, mode, f_n, spring)
        return True
    if mode[M_TANGENTIAL] == STICK and beyond_cone(p, ints, y, aux):
        start_slide(y, mode)
        return True
    if g[E_REVERSAL] > 0.0:
        reverse(p, ints, y, mode, f_n, spring)
        return True
    return False


@njit(cache=True, inline="always")
def beyond_cone(p, ints, y, aux):
    """The sticking spring is beyond the Coulomb cone, or on it within round-off and moving out."""
    cone, held = coulomb_cone(p, ints, aux[A_FN]), abs(y[Y_FS])
    if held > cone * (1.0 + CONE_ROUND_OFF):
        return True
    outward = cone_rate(p, ints, aux) < (1.0 if y[Y_FS] > 0.0 else -1.0) * aux[A_TRIAL]
    return held >= cone * (1.0 - CONE_ROUND_OFF) and outward


@njit(cache=True, inline="always")
def start_unloading(p, ints, y, mode, ext):
    """The normal motion turns: unloading from alpha_max, towards its residual dent."""
    mode[M_LOADING], mode[M_AMAX] = 0.0, y[Y_ALPHA]
    mode[M_DENT] = normal_residual(ints[L.I_NORMAL], p, p[L.RADIUS], y[Y_ALPHA], ext)


@njit(cache=True, inline="always")
def start_slide(y, mode):
    """The spring reaches the Coulomb cone: slide, on the side of the spring force."""
    mode[M_TANGENTIAL], mode[M_SIGN] = SLIDE, (1.0 if y[Y_FS] > 0.0 else -1.0)


@njit(cache=True, inline="always")
def start_stick(p, ints, y, mode, f_n, spring):
    """The spring leaves the Coulomb cone: stick, the spring starting on the cone (Walton-Braun's at its x there)."""
    mode[M_TANGENTIAL] = STICK
    mode[M_STICKS] += 1.0
    y[Y_FS] = mode[M_SIGN] * coulomb_cone(p, ints, f_n)
    spring[0] = edge_w(ints[L.I_TANGENTIAL], mode)


@njit(cache=True, inline="always")
def reverse(p, ints, y, mode, f_n, spring):
    """Walton-Braun: the slip turns: T* = T (sigma* = T/(mu N)), the direction flips; x = 1 while sticking."""
    cone = coulomb_cone(p, ints, f_n)
    f_t = mode[M_SIGN] * cone if mode[M_TANGENTIAL] == SLIDE else y[Y_FS]
    mode[M_STAR] = -f_t / cone if cone > 0.0 else 0.0
    mode[M_DIR] = -mode[M_DIR]
    spring[0] = 1.0


@compiled
def implicit_onset(p, ints, y, mode, dy, aux, scale, spring, ext):
    """An implicit spring (Walton-Braun's) at first touch: sticking in the direction of V_s from T* = 0. Where mu N
    starts from 0
    at a finite rate, x starts at its self-similar value, 1 - x = beta x^(1/3) with beta = k_t0 |V_s|/(mu N'):
    the h -> 0 limit of the scheme's first steps; from 0 where N' starts from 0 (the spring rides the cone)."""
    v_s = slip_velocity(p, y)
    mode[M_TANGENTIAL], mode[M_DIR], mode[M_STAR] = STICK, (1.0 if v_s >= 0.0 else -1.0), 0.0
    evaluate(p, ints, y, mode, 1.0, dy, aux, ext)
    w = 1.0
    if coulomb_cone(p, ints, aux[A_FN]) == 0.0 and v_s != 0.0:
        evaluate_just_after_touch(p, ints, y, mode, 1.0, dy, aux, scale, ext)   # N' (0 at alpha = 0 itself)
        rise = p[L.MU] * aux[A_DFN]
        w = tangential_onset_w(ints[L.I_TANGENTIAL], p, v_s, rise)           # w^3 + beta w = 1
    spring[0] = w


@njit(cache=True, inline="always")
def evaluate_just_after_touch(p, ints, y, mode, w, dy, aux, scale, ext):
    """The rates at a tiny overlap (ONSET_PROBE), where first touch's stick-or-slide is decided (at y, its overlap
    restored after: evaluate only reads it)."""
    alpha = y[Y_ALPHA]
    y[Y_ALPHA] = ONSET_PROBE * scale[0]
    evaluate(p, ints, y, mode, w, dy, aux, ext)
    y[Y_ALPHA] = alpha


@compiled
def onset_mode(p, ints, y, mode, dy, aux, scale, spring, ext):
    """Stick or slide at first touch: stick while mu |F_n| > 0 there; where both start from 0 (undamped laws, whose
    spring and cone grow alike), slide if the trial spring outgrows the cone, judged at a tiny overlap."""
    if ints[L.I_TANGENTIAL] == TANGENTIAL_NONE or p[L.MU] == 0.0:
        mode[M_TANGENTIAL] = 0.0
        return
    if TANGENTIAL_ANY_IMPLICIT and TANGENTIAL_IMPLICIT[ints[L.I_TANGENTIAL]]:
        implicit_onset(p, ints, y, mode, dy, aux, scale, spring, ext)
        return
    mode[M_TANGENTIAL] = STICK
    evaluate(p, ints, y, mode, math.nan, dy, aux, ext)
    if p[L.MU] * abs(aux[A_FN]) > 0.0:
        mode[M_STICKS] = 1.0
        return
    evaluate_just_after_touch(p, ints, y, mode, math.nan, dy, aux, scale, ext)
    if abs(aux[A_TRIAL]) > p[L.MU] * aux[A_DFN]:
        mode[M_TANGENTIAL] = SLIDE
        mode[M_SIGN] = 1.0 if aux[A_TRIAL] > 0.0 else -1.0
    else:
        mode[M_STICKS] = 1.0


@njit(cache=True, inline="always")
def spring_w(ints, mode, spring):
    """w to evaluate with: the sticking Walton-Braun spring's own, NaN (read from F_s) otherwise."""
    if TANGENTIAL_ANY_IMPLICIT and TANGENTIAL_IMPLICIT[ints[L.I_TANGENTIAL]] and mode[M_TANGENTIAL] == STICK:
        return spring[0]
    return math.nan


@compiled
def impact(p, ints, tol, t_ref, row_out, ext, wk):
    """One impact from first touch to release at tolerance `tol`; fills row_out like kernel.integrate, with O_STEPS
    the number of force evaluations. Walton-Braun's spring takes the implicit stepper (stiff where it rides the
    cone), every other row Dormand-Prince. wk: the row's zeroed work arrays (adaptive_work.Work)."""
    m, radius = p[L.MASS], p[L.RADIUS]
    v_n = abs(p[L.VZ0])                            # the normalised outcomes divide by the incident normal and
    v_t = abs(p[L.VX0]) + radius * abs(p[L.W0])  # tangential speeds: errors are measured against each
    if v_t == 0.0:
        v_t = v_n
    alpha_ref, f_ref = v_n * t_ref, m * v_n / t_ref
    scale, y, mode, y_new, aux, aux_new, g_start, g_end = wk.scale, wk.y, wk.mode, wk.y_new, wk.aux, wk.aux_new, \
        wk.g_start, wk.g_end
    k, jac, spring = wk.k, wk.jac, wk.spring
    for i, value in enumerate((alpha_ref, v_n, f_ref, t_ref, alpha_ref, v_n, v_t, v_t / radius, m * v_t / t_ref)):
        scale[i] = value
    y[1], y[2], y[3] = -p[L.VZ0], p[L.VX0], p[L.W0]
    mode[M_LOADING] = 1.0
    implicit = TANGENTIAL_IMPLICIT[ints[L.I_TANGENTIAL]]
    exponent = -0.25 if implicit else -0.2            # 1/(order + 1) of the embedded estimate
    spring[0] = spring[1] = math.nan                  # w = x^(1/3) of Walton-Braun's sticking spring: now, step's end
    onset_mode(p, ints, y, mode, k[0], aux, scale, spring, ext)
    evaluate(p, ints, y, mode, spring_w(ints, mode, spring), k[0], aux, ext)
    events(p, ints, y, mode, aux, scale, g_start, ext)
    evaluations, accepted, stalled = 2, 0, 0
    t, h = 0.0, FIRST_STEP * t_ref
    f_peak, a_peak = aux[A_FN], 0.0
    status = C.STATUS_NO_SEPARATION
    t_cap = p[L.MAX_STEPS] * p[L.DT]               # the kernel's time limit: the same slowed contact times
    for _ in range(STEP_CAP):
        if t >= t_cap:
            break
        err, spent = advance(implicit, p, ints, wk, h, tol, ext)
        evaluations += spent
        if not err <= 1.0:
            h *= max(SHRINK, SAFETY * err ** exponent) if err < math.inf else SHRINK
            if h < 1e-15 * t_ref:
                status = C.STATUS_NONFINITE
                break
            continue
        events(p, ints, y_new, mode, aux_new, scale, g_end, ext)
        first, frac, slope, release, release_rise = -1, 1.0, 0.0, 2.0, 0.0
        for e in range(N_EVENTS):                     # the first event of the step, on its interpolant
            if crosses(e, g_start[e], g_end[e]):
                at, rise, trials = interpolated_root(e, p, ints, wk, h, ext)
                evaluations += trials
                if e == E_RELEASE:
                    release, release_rise = at, rise
                if first < 0 or at < frac:
                    first, frac, slope = e, at, rise
        if release <= frac + RELEASE_TIE:             # an event at the release itself (F_n's sign) is none
            first, frac, slope = E_RELEASE, release, release_rise
        step = h
        if first >= 0:                                # land on it: located on real steps, then the landing step
            frac, spent = locate(first, implicit, p, ints, wk, h, tol, frac, slope, ext)
            evaluations += spent
            step = frac * h
            err, spent = advance(implicit, p, ints, wk, step, tol, ext)
            evaluations += spent
            if not err <= 1.0:                        # a singular end (alpha^3/2 at release): refine towards it
                h = step * max(SHRINK, SAFETY * err ** exponent) if err < math.inf else step * SHRINK
                continue
        t += step
        accepted += 1
        stalled = stalled + 1 if step < STALL_STEP * t_ref else 0
        if stalled > STALL_COUNT:                     # creeping: the step cannot grow (an implicit stage that
            status = C.STATUS_NONFINITE               # Newton solves only at ~1e-13 of a contact); the converged
            break                                     # mode takes such a row from the ladder
        copy_into(y, y_new)                           # (element loops: a slice assignment compiles its shape
        spring[0] = spring[1]                         # error's message, seconds of a first run)
        if TANGENTIAL_ANY_IMPLICIT and implicit:
            for a in range(jac.shape[1]):             # the implicit stepper's Jacobian at the new start
                for i in range(N_Y):
                    copy_into(jac[J_START, a, i], jac[J_END, a, i])
        f_n = aux_new[A_FN]
        f_peak = max(f_peak, f_n)                     # exact at the located turn (undamped) or peak (damped)
        a_peak = max(a_peak, y[Y_ALPHA])
        if first == E_RELEASE:
            status = C.STATUS_OK
            break
        if first == E_TURN:
            start_unloading(p, ints, y, mode, ext)
        elif first == E_SLIP:
            start_slide(y, mode)
        elif first == E_STICK:
            start_stick(p, ints, y, mode, f_n, spring)
        elif first == E_REVERSAL:
            reverse(p, ints, y, mode, f_n, spring)
        if first == E_TURN or first == E_SLIP or first == E_STICK or first == E_REVERSAL:
            jac[J_START, 2, 0, 0] = 0.0               # a new regime: a new Jacobian
            evaluate(p, ints, y, mode, spring_w(ints, mode, spring), k[0], aux, ext)     # the new regime's rates
            evaluations += 1
        else:
            copy_into(k[0], k[STAGES - 1])
            copy_into(aux, aux_new)
        events(p, ints, y, mode, aux, scale, g_start, ext)
        for _ in range(SETTLE_ROUNDS):
            if not settle(p, ints, y, mode, g_start, aux, spring, ext):
                break
            jac[J_START, 2, 0, 0] = 0.0
            evaluate(p, ints, y, mode, spring_w(ints, mode, spring), k[0], aux, ext)
            events(p, ints, y, mode, aux, scale, g_start, ext)
            evaluations += 1
        h *= min(GROW, SAFETY * err ** exponent) if err > 0.0 else GROW
    row_out[C.O_VZ], row_out[C.O_VX], row_out[C.O_W] = -y[Y_RATE], y[Y_VX], y[Y_W]
    row_out[C.O_TC], row_out[C.O_FMAX], row_out[C.O_AMAX] = t, f_peak, a_peak
    row_out[C.O_STEPS], row_out[C.O_STATUS], row_out[C.O_ACCEPTED] = evaluations, status, accepted
    row_out[C.O_STICKING] = mode[M_STICKS] + (1.0 if implicit else 0.0)   # an implicit spring is never on the cone


@njit(cache=True, nogil=True)
def adaptive_rows(first, last, params, ints, tol, t_ref, out, ext, vec, k, work, jac, lu, pivot):
    """Rows first..last-1 of params/ints at tolerance tol; t_ref per row: the contact-time estimate; the rest: each
    row's work arrays (adaptive_work.work_arrays)."""
    for i in range(first, last):
        impact(params[i], ints[i], tol, t_ref[i], out[i], ext, row_work(vec[i], k[i], work[i], jac[i], lu[i], pivot[i]))


def integrate_adaptive(params, ints, tol, t_ref, out, ext):
    """Every row of params/ints at tolerance tol, rows split between threads; a batch of one law on the copy of the
    solver that compiles only its kernels (specialise.py)."""
    from .kernel import law_kernels
    from .specialise import specialised
    copy = specialised("adaptive", "PAPER", *law_kernels(ints))
    rows = adaptive_rows if copy is None else copy.adaptive_rows
    announce_compiling(rows, "the adaptive integrator")
    in_threads(rows, len(params), params, ints, tol, t_ref, out, ext, *work_arrays(len(params)))
