"""Simulate: run a law over a scene in the compiled batch kernel and return the results table."""
import time

import numpy as np
import pandas as pd

from ..infra.version import __version__
from ..scenes.kinematics import rebound_quantities
from ..data.results import impact_frame
from ..data.states import attach, gather, states_frame
from .stability import UnstableTimeStep
from . import codes as C
from . import layout as L
from .adaptive import integrate_adaptive, stepper_names, supports
from .extension import table as extension_table
from .kernel import integrate
from .mesh import graded_largest_step
from .resolution import FixedTimeStep, run_spec
from .batch import batch_of
from .states import kernel_markers, states

CONVERGED_START = 64             # steps per contact of the first level of the converged ladder
CONVERGED_LIMIT = 2 ** 20        # finest level tried
CONVERGED_TOLERANCE = 1e-6       # between successive Richardson values (v/V, R omega/V, relative t_c and F_max)
STATUS_TEXT = {C.STATUS_OK: "ok", C.STATUS_NO_SEPARATION: "no-separation", C.STATUS_NONFINITE: "non-finite"}


def batch_at(law, scene, e_n, resolution, **spec_options):
    """The kernel rows of `law` on the scene at target e_n and a resolution (its RunSpec: harness.solver.resolution)."""
    return batch_of(law, scene, run_spec(law, scene, e_n, resolution, **spec_options))


def run_kernel(batch, history_points=0, rows=None, times=()):
    """Integrate the batch (or the given rows of it); returns (out, history, wall seconds): the history of
    `history_points` points, or with `times` the kernel's records of the states at them (states.py)."""
    params, ints = batch.params, batch.ints
    if rows is not None:
        params, ints = params[rows], ints[rows]
    stride = 0
    history = np.zeros((len(params), history_points, 4))
    if history_points:
        stride = max(1, int(batch.steps_per_contact * 3 // history_points))   # ~3 contact times recorded
    elif len(times):
        stride, history = -1, kernel_markers(batch, times)[slice(None) if rows is None else rows]
    out = np.zeros((len(params), C.N_OUT))
    start = time.perf_counter()
    integrate(params, ints, out, history, stride, extension_table())
    return out, history, time.perf_counter() - start


KEPT = [C.O_VZ, C.O_VX, C.O_W, C.O_TC, C.O_FMAX, C.O_AMAX]     # outcome columns the converged mode extrapolates


def _change(a, b, scene, batch, rows):
    """Largest difference per row of the normalised outcomes e_n, e_t, R omega/(mu (1 + e) V_n) (absolute; they are
    O(1) and amplify velocity errors at grazing and near-normal angles) and of t_c and F_max (relative)."""
    def normalised(x):
        q = rebound_quantities(scene.contact, scene.mu, batch.v_n0[rows], batch.v_t0[rows], batch.omega0[rows],
                               x[:, 0], x[:, 1], x[:, 2])
        return np.column_stack([q["e_n"], q["e_t"], 0.5 * q["omega_star"]])   # R omega/(mu (1 + e) V_n)
    diff = np.abs(normalised(a) - normalised(b))
    diff = np.where(np.isnan(normalised(b)) & np.isnan(normalised(a)), 0.0, diff)   # e_t of a normal impact
    relative = np.abs(a[:, 3:5] - b[:, 3:5]) / np.abs(b[:, 3:5])
    return np.column_stack([diff, relative]).max(axis=1)


GRADE_MARGIN = 1e-4             # relative floor of the gap between the release and the graded mesh's end


def release_bound(t_half, t_full):
    """End of the graded mesh, just beyond the release: t_c extrapolated from uniform runs at n/2 and n steps per
    contact, plus its change (an upper bound of its error) and a relative floor."""
    change = np.abs(t_full - t_half) / 3.0
    return t_full + (t_full - t_half) / 3.0 + change + GRADE_MARGIN * t_full


def richardson(fine, coarse):
    """R = f_n + (f_n - f_n/2)/3: the c h^2 term of a second-order scheme removed (the converged mode's estimate)."""
    return fine + (fine - coarse) / 3.0


def graded_rows(law, scene, e_n, n, span, rows):
    """Integrate the given rows with n graded steps over [0, span] (mesh.graded_time): steps shrink like s^3 at
    first touch and towards span, just beyond the release, so that the onset and release singularities
    (alpha^(1/4), alpha^(1/2), alpha^(3/2)) become smooth in the step and the error expands in powers of 1/n.
    The stability limit is checked at the largest graded step."""
    batch = batch_at(law, scene, e_n, FixedTimeStep(float(np.max(graded_largest_step(n, span)))), bounded=False)
    batch.params[:, L.GRADE_T] = span
    batch.params[:, L.GRADE_N] = n
    return run_kernel(batch, rows=rows)


def graded_span(law, scene, e_n):
    """Where every impact's graded mesh ends: release_bound from uniform runs at 32 and 64 steps per contact (64 and
    128 where 32 is above the stability limit); returns (the 64-step batch, spans, wall seconds)."""
    n = CONVERGED_START
    batch = batch_at(law, scene, e_n, n)
    out, _, wall = run_kernel(batch)
    try:
        coarse, _, seconds = run_kernel(batch_at(law, scene, e_n, n // 2))
        span = release_bound(coarse[:, C.O_TC], out[:, C.O_TC])
    except UnstableTimeStep:                    # a stiff tangential spring: place the release from n and 2n
        finer, _, seconds = run_kernel(batch_at(law, scene, e_n, 2 * n))
        span = release_bound(out[:, C.O_TC], finer[:, C.O_TC])
    return batch, span, wall + seconds


def simulate_extrapolated(law, scene, n):
    """Results table of one rung of the converged ladder, R_n = f_n + (f_n - f_n/2)/3 on n/2 and n graded steps
    per contact, for every impact (harness cost draws these as a curve). wall_s includes the runs that place the
    release; `dt` is the mean graded step."""
    frames = []
    for e_n in scene.e_n:
        batch, span, wall = graded_span(law, scene, e_n)
        rows = np.arange(len(batch.v_n0))
        half, _, seconds_half = graded_rows(law, scene, e_n, n // 2, span, rows)
        out, _, seconds = graded_rows(law, scene, e_n, n, span, rows)
        out[:, KEPT] = richardson(out[:, KEPT], half[:, KEPT])
        frames.append(results_frame(law, scene, batch, out, wall + seconds_half + seconds, n, span / n,
                                    [f"Richardson on {n // 2} and {n} graded steps/contact"] * len(out)))
    return pd.concat(frames, ignore_index=True)


def results_frame(law, scene, batch, out, wall, steps, dt, messages):
    """The results table of one batch from the kernel's output rows (harness/data/results.py columns)."""
    return impact_frame(
        scene, batch, model=law.name, dialect=law.dialect, engine="reference", engine_version=__version__, dt=dt,
        steps_per_contact=steps, v_n1=out[:, C.O_VZ], v_t1=out[:, C.O_VX], omega1=out[:, C.O_W],
        t_contact=out[:, C.O_TC], f_n_max=out[:, C.O_FMAX], overlap_max=out[:, C.O_AMAX], wall_s=wall / len(out),
        status=[STATUS_TEXT[int(s)] for s in out[:, C.O_STATUS]], message=messages)


def uses_extrapolation(law, extrapolate=None):
    """The graded, extrapolated ladder for the paper scheme (where the adaptive integrator does not cover a row, or
    when asked for: extrapolate=True); plain doubling for the engines' first-order schemes (or extrapolate=False)."""
    return law.integrator == "paper" if extrapolate is None else extrapolate


ADAPTIVE_FIRST = 1e-2           # first tolerance of the adaptive integrator, relative to the converged tolerance
ADAPTIVE_FLOOR = 1e-12          # tightest tolerance tried (round-off of the error estimate below)


def adaptive_batch(law, scene, e_n):
    """Kernel rows for the adaptive integrator (no time step to check) and which of them it covers."""
    batch = batch_at(law, scene, e_n, CONVERGED_START, check_stability=False)
    return batch, supports(batch.ints, batch.params)


def run_adaptive(batch, rows, tol):
    """The adaptive integrator on the given rows at tolerance tol; returns (out, wall seconds)."""
    out = np.zeros((len(rows), C.N_OUT))
    t_ref = np.full(len(rows), batch.dt * batch.steps_per_contact)    # the contact-time estimate
    start = time.perf_counter()
    integrate_adaptive(batch.params[rows], batch.ints[rows], tol, t_ref, out, extension_table())
    return out, time.perf_counter() - start


def simulate_adaptive(law, scene, tol):
    """Results table of one adaptive run at tolerance tol for every impact (harness cost draws these as a curve);
    steps_per_contact counts force evaluations, dt is the mean accepted step."""
    frames = []
    for e_n in scene.e_n:
        batch, covered = adaptive_batch(law, scene, e_n)
        if not covered.all():
            raise ValueError(f"{law.name}: the adaptive integrator does not cover these sub-models")
        out, wall = run_adaptive(batch, np.arange(len(covered)), tol)
        frames.append(results_frame(law, scene, batch, out, wall, out[:, C.O_STEPS], adaptive_dt(out),
                                    [f"adaptive {name} at tol {tol:.0e}" for name in stepper_names(batch.ints)]))
    return pd.concat(frames, ignore_index=True)


def adaptive_dt(out):
    """Mean accepted step of adaptive rows."""
    return out[:, C.O_TC] / np.maximum(out[:, C.O_ACCEPTED], 1.0)


def adaptive_converged(batch, scene, rows, tolerance):
    """The adaptive integrator at tol = tolerance/100 and tol/10: their change bounds the error of the first, so the
    second is taken once it is below `tolerance`; rows still changing go on at tol/10 (down to ADAPTIVE_FLOOR).
    Returns (out, change, last tol, force evaluations of all runs per row, wall seconds)."""
    tol = tolerance * ADAPTIVE_FIRST
    coarse, wall = run_adaptive(batch, rows, tol)
    evaluations = coarse[:, C.O_STEPS].copy()
    out, change, tols = coarse.copy(), np.full(len(rows), np.inf), np.full(len(rows), tol)
    pending = np.arange(len(rows))
    while len(pending) and tol / 10.0 >= ADAPTIVE_FLOOR:
        tol /= 10.0
        fine, seconds = run_adaptive(batch, rows[pending], tol)
        wall += seconds
        evaluations[pending] += fine[:, C.O_STEPS]
        diff = _change(fine[:, KEPT], coarse[pending][:, KEPT], scene, batch, rows[pending])
        failed = fine[:, C.O_STATUS] != C.STATUS_OK
        settled = failed & (fine[:, C.O_STATUS] == coarse[pending][:, C.O_STATUS])   # e.g. no release, twice
        out[pending], coarse[pending], tols[pending] = fine, fine, tol
        change[pending] = np.where(np.isnan(diff) | failed, np.inf, diff)
        pending = pending[~((change[pending] < tolerance) | settled)]
    return out, change, tols, evaluations, wall


def adaptive_message(row, stepper, tol, change, tolerance):
    """What the converged mode says of one adaptive row."""
    if row[C.O_STATUS] != C.STATUS_OK:
        status = STATUS_TEXT[int(row[C.O_STATUS])]
        return f"{status}: no release within {row[C.O_TC]:.3g} s (adaptive {stepper} at tol {tol:.0e})"
    if change < tolerance:
        return f"converged: adaptive {stepper} at tol {tol:.0e} against {tol * 10:.0e}, change {change:.1e}"
    return f"not converged at tol {tol:.0e} (change {change:.1e})"


def converged_batch(law, scene, e_n, tolerance=CONVERGED_TOLERANCE, extrapolate=None):
    """Converged results of every impact at target e_n: the adaptive integrator on the rows it covers (the paper
    scheme's laws), the ladder (run_converged) on the others and on rows whose adaptive step underflowed;
    returns (batch, out, steps per contact, dt, messages, wall seconds). Steps per contact count force evaluations
    for adaptive rows (a plain step costs one)."""
    covered = None
    if uses_extrapolation(law, extrapolate) and extrapolate is None:
        batch, covered = adaptive_batch(law, scene, e_n)
    if covered is None or not covered.all():
        return ladder_batch(law, scene, e_n, tolerance, extrapolate)
    rows = np.arange(len(covered))
    out, change, tols, evaluations, wall = adaptive_converged(batch, scene, rows, tolerance)
    dt = adaptive_dt(out)
    messages = [adaptive_message(row, stepper, tol, ch, tolerance)
                for row, stepper, tol, ch in zip(out, stepper_names(batch.ints), tols, change)]
    stuck = out[:, C.O_STATUS] == C.STATUS_NONFINITE
    if stuck.any():             # e.g. a stick under a tangential speed 1e-20 of the normal one, up to the release
        try:
            _, ladder_out, levels, ladder_dt, ladder_messages, seconds = ladder_batch(law, scene, e_n, tolerance,
                                                                                      True)
        except UnstableTimeStep as exc:
            for i in np.flatnonzero(stuck):
                messages[i] = f"non-finite: the adaptive step underflowed or stalled, and the ladder is refused: {exc}"
            return batch, out, evaluations, dt, messages, wall
        out[stuck], evaluations[stuck], dt[stuck] = ladder_out[stuck], levels[stuck], ladder_dt[stuck]
        for i in np.flatnonzero(stuck):
            messages[i] = f"{ladder_messages[i]} (the adaptive step underflowed or stalled)"
        wall += seconds
    return batch, out, evaluations, dt, messages, wall


def ladder_batch(law, scene, e_n, tolerance, extrapolate):
    """run_converged's results with their messages; (batch, out, steps per contact, dt, messages, wall)."""
    batch, out, levels, change, dt, wall = run_converged(law, scene, e_n, tolerance, extrapolate)
    how = ("Richardson on {} and {} graded steps/contact" if uses_extrapolation(law, extrapolate) else
           "{} and {} steps/contact agree")
    messages = [f"converged: {how.format(lv // 2, lv)}, last change {ch:.1e}" if ch <= tolerance else
                f"not converged at {lv} steps/contact (change {ch:.1e})" for lv, ch in zip(levels, change)]
    return batch, out, levels, dt, messages, wall


def run_converged(law, scene, e_n, tolerance=CONVERGED_TOLERANCE, extrapolate=None):
    """Richardson-extrapolated ladder on graded meshes: two uniform runs (32 and 64 steps per contact) place the
    release; then n graded steps over [0, span], n doubling from 64. The paper scheme's error is then ~c h^2 with
    a smooth expansion (onset and release on the graded ends, turning point, yield and stick-slip transitions
    located inside their steps), so R_n = f_n + (f_n - f_n/2)/3 removes it; a row stops when R_n and R_n/2 differ
    by less than `tolerance`, twice in a row (one agreement can be a crossing). Engine schemes (first order) double
    uniform steps without extrapolating (extrapolate=False does the same for any law: plain refinement)."""
    extrapolate = uses_extrapolation(law, extrapolate)
    n = CONVERGED_START
    span = None
    if extrapolate:
        batch, span, wall = graded_span(law, scene, e_n)
        out, _, seconds = graded_rows(law, scene, e_n, n, span, np.arange(len(batch.v_n0)))
        wall += seconds
    else:
        batch = batch_at(law, scene, e_n, n)
        out, _, wall = run_kernel(batch)
    every = np.arange(len(out))
    plain = out[:, KEPT]
    best = np.full_like(plain, np.nan)          # R needs two levels: nothing to compare with at the first
    levels = np.full(len(out), n)
    change = np.full(len(out), np.inf)
    pending = every
    passes = np.zeros(len(out), dtype=int)
    while len(pending) and n < CONVERGED_LIMIT:
        n *= 2
        if extrapolate:
            finer, _, seconds = graded_rows(law, scene, e_n, n, span, pending)
        else:
            finer, _, seconds = run_kernel(batch_at(law, scene, e_n, n), rows=pending)
        wall += seconds
        new = finer[:, KEPT]
        estimate = richardson(new, plain[pending]) if extrapolate else new
        out[pending] = finer
        plain[pending] = new
        diff = _change(estimate, best[pending], scene, batch, pending)
        best[pending] = estimate
        levels[pending] = n
        diff = np.where(np.isnan(diff), np.inf, diff)
        passes[pending] = np.where(diff < tolerance, passes[pending] + 1, 0)
        change[pending] = diff
        pending = pending[passes[pending] < 2]
    out[:, KEPT] = best
    dt = span / levels if extrapolate else batch.dt * CONVERGED_START / levels
    return batch, out, levels, change, dt, wall


def simulate(law, scene, steps_per_contact=1000, converged=False, history_points=0, extrapolate=None,
             tolerance=CONVERGED_TOLERANCE):
    """Results table of `law` over every (e_n, impact) of `scene`; histories {e_n: array} if points are asked for."""
    frames, histories = [], {}
    for e_n in scene.e_n:
        reason = law.undefined(scene.contact, e_n, scene.speed)
        if reason:
            batch, out, steps, dt, messages, wall = undefined_batch(law, scene, e_n, reason, converged,
                                                                    steps_per_contact)
        elif converged:
            batch, out, steps, dt, messages, wall = converged_batch(law, scene, e_n, tolerance, extrapolate)
        else:
            batch = batch_at(law, scene, e_n, steps_per_contact)
            out, history, wall = run_kernel(batch, 0 if scene.at_times else history_points, times=scene.at_times)
            if history_points and not scene.at_times:
                histories[e_n] = history
            messages = ["" if status == C.STATUS_OK else
                        f"{STATUS_TEXT[int(status)]} after {int(steps)} steps ({steps * batch.dt:.3g} s of contact)"
                        for status, steps in zip(out[:, C.O_STATUS], out[:, C.O_STEPS])]
            steps, dt = batch.steps_per_contact, batch.dt
        frame = results_frame(law, scene, batch, out, wall, steps, dt, messages)
        if scene.at_times and not converged and not reason:
            attach(frame, states_frame(frame, states(batch, out, history, scene.at_times, scene.gap)))
        frames.append(frame)
    table = pd.concat(frames, ignore_index=True)
    return attach(table, gather(frames)), histories


def undefined_batch(law, scene, e_n, reason, converged, steps_per_contact):
    """Every impact of a composition whose contact force is not a number at e_n (law.undefined: a sub-model's 0/0):
    not finite from the first contact step, so not stepped; (batch, out, steps per contact, dt, messages, wall)."""
    steps = CONVERGED_START if converged else steps_per_contact
    batch = batch_at(law, scene, e_n, steps, check_stability=False)
    out = np.zeros((len(batch.v_n0), C.N_OUT))
    out[:, KEPT] = np.nan
    out[:, C.O_STATUS] = C.STATUS_NONFINITE
    return batch, out, batch.steps_per_contact, batch.dt, [f"non-finite: {reason}"] * len(out), 0.0
