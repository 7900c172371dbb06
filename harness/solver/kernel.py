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
from collections import namedtuple

import numpy as np
from numba import njit

from ..infra.jit import compiled
from ..submodels.stepping import STEPPER_NAMES
from ..submodels.tangential.state import N_TSTATE, T_HELD, T_MARGIN
from . import codes as C
from . import layout as L
from .compile_notice import announce_compiling
from .dispatch import INTEGRATOR_EVENTS, N_NORMAL, TANGENTIAL_NONE, touch_contact
from .events import locate_release, split_at_event
from .mesh import PEAK_POINTS, graded_step, parabola_peak, polynomial_peak
from .schemes import step_paper
from .specialise import specialised
from .state import N_STATE, S_ALPHA, S_C, S_FN, S_FT, S_U, S_VX, S_VZ, S_W, S_X, S_Z, reset_history
from .switches import PAPER, first_touch_with, step_with
from .threads import in_threads

S_END = 4 * N_STATE                     # work row: four states, five tangential states, four sample vectors
T_END = S_END + 5 * N_TSTATE
WORK = T_END + 4 * PEAK_POINTS
CONE_BAND = 1e-9          # relative: a tangential force this close to mu F_n counts as on the Coulomb cone

Work = namedtuple("Work", ("s", "o", "lo", "at_event", "st", "ot", "lot", "at_event_t", "scratch", "sample_t",
                           "sample_f", "peak_x", "peak_coef"))


@njit(cache=True, nogil=True)
def integrate_rows(first, last, params, ints, out, history, stride, ext, work):
    """Integrate rows first..last-1 of `params`/`ints`, each with its stepper (among those this copy of the solver
    compiles: switches.py); fill `out` and, if stride > 0, `history`. `work`: a row of WORK floats per row, the
    states and samples it steps through."""
    for i in range(first, last):
        integrate_row(params[i], ints[i], out[i], history[i], stride, ext, work[i])


@compiled
def integrate_row(p, row, out, hist, stride, ext, w):
    """One impact from first touch to separation or the step cap: its outcomes into `out`, every stride-th step
    into `hist` (stride < 0: the states at the steps hist[:, 0] names, states.py). The paper integrator locates its
    events and release inside their step (INTEGRATOR_EVENTS); the engines' end the contact at the step. Compiled
    apart and without reference counting, so that reading its work record (Work) costs no count."""
    v = work_views(w)
    start(v, p, row, ext)
    located = INTEGRATOR_EVENTS[row[L.I_INTEGRATOR]]
    h = p[L.DT]
    stick_steps = 0
    f_prev2, f_prev1 = 0.0, 0.0
    h_prev = h
    a_prev2, a_prev1 = 0.0, 0.0
    f_peak, a_peak = v.s[S_FN], 0.0
    status = C.STATUS_NO_SEPARATION
    t_end = 0.0
    k_rec = 0
    steps = 0
    t_now = 0.0
    grade_n = int(p[L.GRADE_N])
    f_sampled = not (located and p[L.DAMPING_C0] == 0.0)      # else F_max is F at the turn, located
    for k in range(int(p[L.MAX_STEPS])):
        if grade_n > 0:
            h = graded_step(k, grade_n, p[L.GRADE_T])
        elif k < 2 and p[L.FIRST_H] > 0.0:       # from a touch between two steps of the grid onto the grid
            h = p[L.FIRST_H] if k == 0 else p[L.DT]
        indicator, h_last, a_peak, f_peak = advance(v, p, row, h, located, a_peak, f_peak, ext)
        steps = k + 1
        if indicator <= 0.0:
            t_end = t_now + h_last                 # the release, at the step (engines) or located inside it
            status = C.STATUS_OK
        f_now, a_now = v.o[S_FN], v.o[S_ALPHA]
        if sticks(v, p, row, f_now):
            stick_steps += 1
        if located:                                # the last samples of F_n, for its interpolated peak
            sample(v, t_now + h_last, f_now)
        if f_sampled and f_prev1 >= f_prev2 and f_prev1 > f_now and f_prev1 >= f_peak and k >= 2:
            if located and k >= PEAK_POINTS:
                f_peak = polynomial_peak(v.sample_t, v.sample_f, v.peak_x, v.peak_coef)
            else:
                f_peak = parabola_peak(f_prev2, f_prev1, f_now, h_prev, h_last)
        if not located and a_prev1 >= a_prev2 and a_prev1 > a_now and a_prev1 >= a_peak and k >= 2:
            a_peak = parabola_peak(a_prev2, a_prev1, a_now, h_prev, h_last)
        h_prev = h_last
        f_peak = max(f_peak, f_now)
        a_peak = max(a_peak, a_now)
        f_prev2, f_prev1, a_prev2, a_prev1 = f_prev1, f_now, a_prev1, a_now
        t_now += h
        if stride > 0 and k % stride == 0 and k_rec < hist.shape[0]:
            record(hist[k_rec], t_now, v.o)
            k_rec += 1
        elif stride < 0:
            k_rec = record_states(hist, k_rec, steps, v.o)
        accept(v)
        if status == C.STATUS_OK:
            break
        if not (math.isfinite(v.o[S_VZ]) and math.isfinite(v.o[S_VX]) and math.isfinite(v.o[S_W])):
            status = C.STATUS_NONFINITE
            break
    out[C.O_VZ], out[C.O_VX], out[C.O_W] = v.s[S_VZ], v.s[S_VX], v.s[S_W]
    out[C.O_TC] = t_end if status == C.STATUS_OK else t_now
    if p[L.ALPHA0] < 0.0:                       # its first step began apart: in contact from the step after
        out[C.O_TC] -= p[L.DT]
    out[C.O_FMAX], out[C.O_AMAX] = f_peak, a_peak
    out[C.O_STEPS], out[C.O_STATUS], out[C.O_STICKING] = steps, status, stick_steps
    out[C.O_ALPHA], out[C.O_X], out[C.O_Z] = v.s[S_ALPHA], v.s[S_X], v.s[S_Z]
    if stride > 0:
        for k in range(k_rec, hist.shape[0]):
            hist[k, 0] = math.nan


@njit(cache=True, inline="always")
def work_views(w):
    """The states and samples a row steps through (Work), as views of its work row, zeroed."""
    for j in range(WORK):
        w[j] = 0.0
    t = S_END
    return Work(w[0:N_STATE], w[N_STATE:2 * N_STATE], w[2 * N_STATE:3 * N_STATE], w[3 * N_STATE:S_END],
                w[t:t + N_TSTATE], w[t + N_TSTATE:t + 2 * N_TSTATE], w[t + 2 * N_TSTATE:t + 3 * N_TSTATE],
                w[t + 3 * N_TSTATE:t + 4 * N_TSTATE], w[t + 4 * N_TSTATE:T_END], w[T_END:T_END + PEAK_POINTS],
                w[T_END + PEAK_POINTS:T_END + 2 * PEAK_POINTS], w[T_END + 2 * PEAK_POINTS:T_END + 3 * PEAK_POINTS],
                w[T_END + 3 * PEAK_POINTS:WORK])


@njit(cache=True, inline="always")
def start(v, p, row, ext):
    """The state at the row's start (first touch, or the last step of a free approach before it, apart and
    force-free): the incident velocities, an incremental law's history, the stand-in sphere's
    centre, the force of a constant normal dashpot where the touch rule puts a sphere at gap 0 in contact, and its
    stepper's own first touch (switches.first_touch_with)."""
    s, st = v.s, v.st
    s[S_VZ], s[S_VX], s[S_W] = p[L.VZ0], p[L.VX0], p[L.W0]
    s[S_U] = -p[L.MASS] * p[L.VZ0]
    reset_history(row[L.I_NORMAL], s)
    s[S_ALPHA], s[S_X] = p[L.ALPHA0], p[L.X0]     # 0 at first touch, else where the free approach left it
    s[S_Z] = p[L.RADIUS] + p[L.Z0]                # stand-in sphere: centre at R above its apex at touch
    if p[L.ALPHA0] < 0.0:                         # apart: no force before the first step
        st[T_MARGIN] = st[T_HELD] = -1e-300
        return
    touch_gap = touch_contact(row[L.I_TOUCH], p, 0.0)        # else gap 0 is no contact: no force at first touch
    if p[L.DAMPING_POWER] == 0.0 and touch_gap:
        s[S_FN] = -p[L.DAMPING_C0] * p[L.VZ0]   # a constant dashpot acts from first touch
        s[S_C] = p[L.DAMPING_C0]
    # the spring starts at 0, inside the Coulomb cone (strictly: a slide starting in the first step is an event)
    st[T_MARGIN] = st[T_HELD] = -p[L.MU] * abs(s[S_FN]) - 1e-300
    first_touch_with(row[L.I_STEPPER], s, st, p, row, ext)


@njit(cache=True, inline="always")
def advance(v, p, row, h, located, a_peak, f_peak, ext):
    """One step of the row's stepper; for the paper scheme (located), a change of regime inside it split there and
    a release inside it located and stepped to. Returns (end indicator, the step's length, alpha_max, F_max)."""
    indicator = step_with(row[L.I_STEPPER], v.s, v.st, v.o, v.ot, p, row, h, v.scratch, ext)
    h_last = h
    if PAPER and located and indicator > 0.0:
        a_peak, f_peak, indicator, _ = split_at_event(v.s, v.st, v.o, v.ot, v.lo, v.lot, v.at_event, v.at_event_t, p,
                                                      row, h, v.scratch, a_peak, f_peak, h, indicator, ext)
    if PAPER and located and indicator <= 0.0:
        a_peak, f_peak, indicator, h_last = paper_release(v, p, row, h, a_peak, f_peak, indicator, ext)
    return indicator, h_last, a_peak, f_peak


@njit(cache=True, inline="always")
def paper_release(v, p, ints, h, a_peak, f_peak, indicator, ext):
    """The paper scheme's release inside its step: located, stepped to, and any regime change before it split."""
    h_release = h * locate_release(v.s, v.st, v.lo, v.lot, p, ints, h, v.scratch, indicator, ext)
    step_paper(v.s, v.st, v.o, v.ot, p, ints, h_release, v.scratch, ext)
    return split_at_event(v.s, v.st, v.o, v.ot, v.lo, v.lot, v.at_event, v.at_event_t, p, ints, h_release, v.scratch,
                          a_peak, f_peak, h, -1.0, ext)


@njit(cache=True, inline="always")
def sticks(v, p, row, f_n):
    """The step ends with the tangential force strictly inside the Coulomb cone (F_n > 0), or across it from the
    step before (a dashpot can carry it there)."""
    o, s = v.o, v.s
    return (row[L.I_TANGENTIAL] != TANGENTIAL_NONE and f_n > 0.0
            and (abs(o[S_FT]) < (1.0 - CONE_BAND) * p[L.MU] * f_n or o[S_FT] * s[S_FT] < 0.0))


@njit(cache=True, inline="always")
def sample(v, t, f_n):
    """Keep the last PEAK_POINTS samples (t, F_n), for the interpolated peak."""
    for j in range(PEAK_POINTS - 1):
        v.sample_t[j], v.sample_f[j] = v.sample_t[j + 1], v.sample_f[j + 1]
    v.sample_t[PEAK_POINTS - 1], v.sample_f[PEAK_POINTS - 1] = t, f_n


@njit(cache=True, inline="always")
def record(point, t, o):
    """One history point: t, alpha, F_n, F_t."""
    point[0], point[1], point[2], point[3] = t, o[S_ALPHA], o[S_FN], o[S_FT]


@njit(cache=True, inline="always")
def record_states(states, k_rec, steps, o):
    """After step `steps`: the state (overlap, F_n, F_t, v_z, v_x, omega) into each row of `states` whose column 0
    names this step (rows naming earlier steps, before the row's start, skipped); returns the next row."""
    while k_rec < states.shape[0] and states[k_rec, 0] < steps:
        k_rec += 1
    while k_rec < states.shape[0] and states[k_rec, 0] == steps:
        point = states[k_rec]
        point[1], point[2], point[3] = o[S_ALPHA], o[S_FN], o[S_FT]
        point[4], point[5], point[6] = o[S_VZ], o[S_VX], o[S_W]
        k_rec += 1
    return k_rec


@njit(cache=True, inline="always")
def accept(v):
    """The step's end becomes the next step's start."""
    for j in range(N_STATE):
        v.s[j] = v.o[j]
    for j in range(N_TSTATE):
        v.st[j] = v.ot[j]


def kernel_of_batch(params, ints):
    """The compiled integrator of a batch (one stepper per batch: its law's), from a copy of the solver that compiles
    only that stepper and, for a batch of one normal and one tangential kernel (not registered at run time), only
    those kernels; the integrator of this module (every stepper and kernel) where no copy can be written. Returns
    (integrator, its stepper)."""
    steppers = set(ints[:, L.I_STEPPER].tolist())
    if len(steppers) != 1:
        raise ValueError(f"a batch holds one stepper, got {sorted(steppers)}")
    stepper = STEPPER_NAMES[steppers.pop()]
    copy = specialised("kernel", stepper, *law_kernels(ints))
    return (integrate_rows if copy is None else copy.integrate_rows), stepper


def law_kernels(ints):
    """(normal, tangential) kernel codes of a batch of one law (normal not registered at run time), else ()."""
    normal, tangential = set(ints[:, L.I_NORMAL].tolist()), set(ints[:, L.I_TANGENTIAL].tolist())
    if len(normal) == 1 and len(tangential) == 1 and min(normal) < N_NORMAL:
        return normal.pop(), tangential.pop()
    return ()


def integrate(params, ints, out, history, stride, ext, threads=None):
    """Integrate every row (fill `out` and, if stride > 0, `history`), rows split between threads."""
    if len(params):
        kernel, stepper = kernel_of_batch(params, ints)
        announce_compiling(kernel, f"the {stepper.lower().replace('_', ' ')} integrator")
        work = np.empty((len(params), WORK))
        in_threads(kernel, len(params), params, ints, out, history, stride, ext, work, threads=threads)
