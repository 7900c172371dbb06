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
from numba import njit

from ..submodels.stepping import GEOMETRIES, INTEGRATORS, STEPPERS
from ..submodels.tangential.state import N_TSTATE, T_HELD, T_MARGIN
from ..submodels.tangential.viscous import friction as viscous_friction
from . import codes as C
from .compile_notice import announce_compiling
from .switches import (LEAPFROG, LEAPFROG_PAIR, LEAPFROG_SCALAR_PAIR, LEAPFROG_SPHERE, PAPER, VELOCITY_VERLET,
                       VERLET_PAIR)
from .dispatch import N_NORMAL, TANGENTIAL_NONE, TANGENTIAL_VISCOUS, tangential_stiffness
from .events import locate_release, split_at_event
from .friction import normal_share
from .mesh import PEAK_POINTS, graded_step, parabola_peak, polynomial_peak
from .pair import step_leapfrog_pair, step_leapfrog_scalar_pair, step_verlet_pair
from .schemes import paper_first_touch, step, step_leapfrog, step_leapfrog_sphere, step_velocity_verlet
from .specialise import specialised
from .spring import cap
from .state import N_STATE, S_ALPHA, S_C, S_FN, S_FT, S_U, S_VX, S_VZ, S_W, S_Z, reset_history
from .threads import in_threads

S_END = 4 * N_STATE                     # work row: four states, five tangential states, four sample vectors
T_END = S_END + 5 * N_TSTATE
WORK = T_END + 4 * PEAK_POINTS
CONE_BAND = 1e-9          # relative: a tangential force this close to mu F_n counts as on the Coulomb cone


@njit(cache=True, nogil=True)
def integrate_rows(first, last, params, ints, out, history, stride, ext, work):
    """Integrate rows first..last-1 of `params`/`ints`, each with its scheme's step (among the steppers this copy of
    the solver compiles: switches.py) and, for the paper scheme, its located events, release and first touch; fill
    `out` and, if stride > 0, `history`. `work`: a row of WORK floats per row, the states and samples it steps
    through."""
    n_hist = history.shape[1]
    for i in range(first, last):
        w = work[i]
        for j in range(WORK):
            w[j] = 0.0
        s, o, lo, at_event = w[0:N_STATE], w[N_STATE:2 * N_STATE], w[2 * N_STATE:3 * N_STATE], w[3 * N_STATE:S_END]
        st, ot, lot = w[S_END:S_END + N_TSTATE], w[S_END + N_TSTATE:S_END + 2 * N_TSTATE], \
            w[S_END + 2 * N_TSTATE:S_END + 3 * N_TSTATE]
        at_event_t, scratch = w[S_END + 3 * N_TSTATE:S_END + 4 * N_TSTATE], w[S_END + 4 * N_TSTATE:T_END]
        sample_t, sample_f = w[T_END:T_END + PEAK_POINTS], w[T_END + PEAK_POINTS:T_END + 2 * PEAK_POINTS]
        peak_x, peak_coef = w[T_END + 2 * PEAK_POINTS:T_END + 3 * PEAK_POINTS], w[T_END + 3 * PEAK_POINTS:WORK]
        p = params[i]
        row_ints = ints[i]
        scheme, geometry = row_ints[C.I_INTEGRATOR], row_ints[C.I_GEOMETRY]
        paper = scheme == C.INTEGRATOR_PAPER
        h = p[C.P_DT]
        s[S_VZ], s[S_VX], s[S_W] = p[C.P_VZ0], p[C.P_VX0], p[C.P_W0]
        s[S_U] = -p[C.P_MASS] * p[C.P_VZ0]
        reset_history(row_ints[C.I_NORMAL], s)
        s[S_Z] = p[C.P_RADIUS]                        # stand-in sphere: centre at R above its apex
        touch_gap = row_ints[C.I_TOUCH] == C.TOUCH_GAP        # else gap 0 is no contact: no force at first touch
        if p[C.P_DAMP_POWER] == 0.0 and touch_gap:
            s[S_FN] = -p[C.P_DAMP_C0] * p[C.P_VZ0]   # a constant dashpot acts from first touch
            s[S_C] = p[C.P_DAMP_C0]
        # the spring starts at 0, inside the Coulomb cone (strictly: a slide starting in the first step is an event)
        st[T_MARGIN] = st[T_HELD] = -p[C.P_MU] * abs(s[S_FN]) - 1e-300
        setup = scheme == C.INTEGRATOR_VELOCITY_VERLET and geometry == C.GEOMETRY_WALL and touch_gap
        if VELOCITY_VERLET and setup and row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE:
            # the setup force at first touch (gap 0 counts as contact): the tangential dashpot alone; the Coulomb
            # rule 'total' drops it when it exceeds mu |F_n|, its spring being empty, 'spring-first' caps it there
            code = row_ints[C.I_TANGENTIAL]
            slip0 = p[C.P_VX0] - p[C.P_RADIUS] * p[C.P_W0]
            if TANGENTIAL_VISCOUS[code]:
                s[S_FT] = viscous_friction(tangential_stiffness(code, p[C.P_T1], 0.0), p[C.P_TDAMP], slip0,
                                           p[C.P_MU] * abs(s[S_FN]))
            else:
                s[S_FT] = -p[C.P_TDAMP] * math.sqrt(tangential_stiffness(code, p[C.P_T1], 0.0)) * slip0
            if p[C.P_TSHARE] != 0.0 and p[C.P_DAMP_POWER] == 0.0:     # a share of the constant normal dashpot
                if TANGENTIAL_VISCOUS[code]:
                    s[S_FT] = viscous_friction(1.0, normal_share(p, 0.0), slip0, p[C.P_MU] * abs(s[S_FN]))
                else:
                    s[S_FT] -= normal_share(p, 0.0) * slip0
            if row_ints[C.I_COULOMB] == C.COULOMB_TOTAL and abs(s[S_FT]) > p[C.P_MU] * abs(s[S_FN]):
                s[S_FT] = 0.0
            elif row_ints[C.I_COULOMB] == C.COULOMB_SPRING_FIRST:
                s[S_FT] = cap(s[S_FT], p[C.P_MU] * abs(s[S_FN]))
        elif (PAPER and paper and p[C.P_TDAMP] != 0.0
              and row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE and not TANGENTIAL_VISCOUS[row_ints[C.I_TANGENTIAL]]):
            paper_first_touch(s, st, p, row_ints, ext)
        stick_steps = 0
        f_prev2, f_prev1 = 0.0, 0.0
        h_prev = h
        a_prev2, a_prev1 = 0.0, 0.0
        f_peak, a_peak = s[S_FN], 0.0
        status = C.STATUS_NO_SEPARATION
        t_end = 0.0
        k_rec = 0
        steps = 0
        max_steps = int(p[C.P_MAXSTEPS])
        t_now = 0.0
        grade_n = int(p[C.P_GRADE_N])
        f_sampled = not (paper and p[C.P_DAMP_C0] == 0.0)      # else F_max is F at the turn, located
        for k in range(max_steps):
            if grade_n > 0:
                h = graded_step(k, grade_n, p[C.P_GRADE_T])
            if PAPER and paper:
                indicator = step(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif VELOCITY_VERLET and scheme == C.INTEGRATOR_VELOCITY_VERLET and geometry == C.GEOMETRY_WALL:
                indicator = step_velocity_verlet(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif LEAPFROG and scheme == C.INTEGRATOR_LEAPFROG and geometry == C.GEOMETRY_WALL:
                indicator = step_leapfrog(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif LEAPFROG_SPHERE and scheme == C.INTEGRATOR_LEAPFROG and geometry == C.GEOMETRY_STAND_IN_SPHERE:
                indicator = step_leapfrog_sphere(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif VERLET_PAIR and scheme == C.INTEGRATOR_VELOCITY_VERLET and geometry == C.GEOMETRY_PAIR:
                indicator = step_verlet_pair(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif LEAPFROG_PAIR and scheme == C.INTEGRATOR_LEAPFROG and geometry == C.GEOMETRY_PAIR_VECTOR:
                indicator = step_leapfrog_pair(s, st, o, ot, p, row_ints, h, scratch, ext)
            elif LEAPFROG_SCALAR_PAIR and scheme == C.INTEGRATOR_LEAPFROG and geometry == C.GEOMETRY_PAIR:
                indicator = step_leapfrog_scalar_pair(s, st, o, ot, p, row_ints, h, scratch, ext)
            else:                                  # a scheme this copy does not compile (never planned)
                indicator = math.nan
            h_last = h
            if PAPER and indicator > 0.0 and paper:
                a_peak, f_peak, indicator, _ = split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p,
                                                              row_ints, h, scratch, a_peak, f_peak, h, indicator, ext)
            steps = k + 1
            if indicator <= 0.0 and not paper:
                t_end = t_now + h                          # the engine ends contact at the step, not inside it
                status = C.STATUS_OK
            elif PAPER and indicator <= 0.0:               # release inside the step; a regime change before it too
                a_peak, f_peak, indicator, h_last = paper_release(s, st, o, ot, lo, lot, at_event, at_event_t, p,
                                                                  row_ints, h, scratch, a_peak, f_peak, indicator,
                                                                  ext)
                if indicator <= 0.0:
                    t_end = t_now + h_last
                    status = C.STATUS_OK
            f_now, a_now = o[S_FN], o[S_ALPHA]
            if row_ints[C.I_TANGENTIAL] != TANGENTIAL_NONE and f_now > 0.0 and \
                    (abs(o[S_FT]) < (1.0 - CONE_BAND) * p[C.P_MU] * f_now or o[S_FT] * s[S_FT] < 0.0):
                stick_steps += 1                       # inside the cone, or across it to its other side
            if paper:                                  # the last samples of F_n, for its interpolated peak
                for j in range(PEAK_POINTS - 1):
                    sample_t[j], sample_f[j] = sample_t[j + 1], sample_f[j + 1]
                sample_t[PEAK_POINTS - 1], sample_f[PEAK_POINTS - 1] = t_now + h_last, f_now
            if f_sampled and f_prev1 >= f_prev2 and f_prev1 > f_now and f_prev1 >= f_peak and k >= 2:
                if paper and k >= PEAK_POINTS:
                    f_peak = polynomial_peak(sample_t, sample_f, peak_x, peak_coef)
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
            for j in range(N_STATE):
                s[j] = o[j]
            for j in range(N_TSTATE):
                st[j] = ot[j]
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


@njit(cache=True, inline="always")
def paper_release(s, st, o, ot, lo, lot, at_event, at_event_t, p, ints, h, scratch, a_peak, f_peak, indicator, ext):
    """The paper scheme's release inside its step: located, stepped to, and any regime change before it split."""
    h_release = h * locate_release(s, st, lo, lot, p, ints, h, scratch, indicator, ext)
    step(s, st, o, ot, p, ints, h_release, scratch, ext)
    return split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p, ints, h_release, scratch, a_peak, f_peak, h,
                          -1.0, ext)


def kernel_of_batch(params, ints):
    """The compiled integrator of a batch (one scheme per batch: its law's), from a copy of the solver that compiles
    only that scheme's stepper and, for a batch of one normal and one tangential kernel (not registered at run time),
    only those kernels; the integrator of this module (every stepper and kernel) where no copy can be written.
    Returns (integrator, its stepper)."""
    schemes = set(zip(ints[:, C.I_INTEGRATOR].tolist(), ints[:, C.I_GEOMETRY].tolist()))
    if len(schemes) != 1:
        raise ValueError(f"a batch holds one scheme, got {sorted(schemes)}")
    stepper = stepper_of(*schemes.pop())
    copy = specialised("kernel", stepper, *law_kernels(ints))
    return (integrate_rows if copy is None else copy.integrate_rows), stepper


def law_kernels(ints):
    """(normal, tangential) kernel codes of a batch of one law (normal not registered at run time), else ()."""
    normal, tangential = set(ints[:, C.I_NORMAL].tolist()), set(ints[:, C.I_TANGENTIAL].tolist())
    if len(normal) == 1 and len(tangential) == 1 and min(normal) < N_NORMAL:
        return normal.pop(), tangential.pop()
    return ()


def stepper_of(integrator, geometry):
    """The stepper (switches.STEPPERS) of a batch of the integrator and geometry codes given."""
    names = ({k.code: k.name for k in INTEGRATORS}[integrator], {k.code: k.name for k in GEOMETRIES}[geometry])
    return STEPPERS[names][0]


def integrate(params, ints, out, history, stride, ext, threads=None):
    """Integrate every row (fill `out` and, if stride > 0, `history`), rows split between threads."""
    if len(params):
        kernel, stepper = kernel_of_batch(params, ints)
        announce_compiling(kernel, f"the {stepper.lower().replace('_', ' ')} integrator")
        work = np.empty((len(params), WORK))
        in_threads(kernel, len(params), params, ints, out, history, stride, ext, work, threads=threads)
